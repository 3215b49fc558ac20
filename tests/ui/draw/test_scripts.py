"""The interactive pages' JavaScript: what a scene's page (page.js) and the page of points solved
together (groups.js) both draw with is written once, in draw.js, and read by both."""

import re
from importlib import resources

import pytest

SCRIPTS = resources.files("algkin.ui.html")


def text(name):
    return SCRIPTS.joinpath(name).read_text(encoding="utf-8")


def declared(script):
    """The names a script declares at its top level: functions, constants, variables."""
    return set(re.findall(r"^(?:function|const|let|var) (\w+)", script, re.MULTILINE))


SHARED = declared(text("draw.js"))


@pytest.mark.parametrize("name", ["page.js", "groups.js"])
def test_a_page_declares_nothing_of_draw_js_again(name):
    # the page's script follows draw.js in one <script>: a function declared again would silently replace it
    assert not SHARED & declared(text(name))


@pytest.mark.parametrize("name", ["page.js", "groups.js"])
def test_every_function_of_draw_js_serves_both_pages(name):
    script = text(name)
    functions = set(re.findall(r"^function (\w+)", text("draw.js"), re.MULTILINE))
    assert functions and {f for f in functions if not re.search(rf"\b{f}\(", script)} == set()
