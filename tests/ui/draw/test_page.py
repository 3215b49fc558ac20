"""The .html page against hostile scene text: nothing from a scene becomes markup or script."""

import copy
import json
import unicodedata

import attrs
import html5lib
import pytest
from hypothesis import given, settings, strategies as st

from algkin.ui.html import page, write
from algkin.analyses.motion import Motion

HOSTILE = ["{{script}}", "{{title}}", "{{description}}", "{{style}}", "</script>", "<script>", "<!--", "-->",
           "<img src=x onerror=alert(2)>", "</title>", "</p><h1>", "</style>", '"', "'", "&amp;", "&", "$x$",
           "\x00", "\u2028", "\u2029", "\\", "`${1}`", "]]>", "<!--<script>"]
TEXTS = st.lists(st.one_of(st.sampled_from(HOSTILE), st.text(max_size=4)), max_size=6).map("".join)


@pytest.fixture(scope="module")
def motion():
    return Motion("chebyshev-lambda")


@pytest.fixture(scope="module")
def benign(motion):
    """The structure of a page whose scene text is plain."""
    return structure(html5lib.parse(page_of(motion, "benign", "benign"), namespaceHTMLElements=False))


def page_of(motion, name, description):
    """The page of ``motion`` with the scene's name and description replaced (closed forms reused)."""
    hostile = copy.copy(motion)
    hostile.scene = attrs.evolve(motion.scene, name=name, description=description)
    return page(hostile)


def structure(tree):
    """Every element's tag and attribute names, in document order (comments included)."""
    return [(str(e.tag), sorted(e.attrib)) for e in tree.iter()]


def plain(text):
    """Text the HTML parser reads back as it is: no control characters, no non-characters."""
    return not any(unicodedata.category(c) in ("Cc", "Cn") for c in text)


@settings(max_examples=25, deadline=None)
@given(name=TEXTS, description=TEXTS)
def test_scene_text_never_becomes_markup_or_script(motion, benign, name, description):
    text = page_of(motion, name, description)
    tree = html5lib.parse(text, namespaceHTMLElements=False)
    assert structure(tree) == benign
    if plain(name) and plain(description):
        shown = ["".join(tree.find(f".//{tag}").itertext()) for tag in ("title", "h1")]
        assert shown == [f"algkin: {name}"] * 2
        assert "".join(tree.find(".//p[@class='description']").itertext()) == description
    script = tree.find(".//script").text
    assert script == text[text.index("<script>") + len("<script>"):text.rindex("</script>")]  # read whole
    data = script[script.index("const MODEL = ") + len("const MODEL = "):script.index(";\n")]
    model = json.loads(data)
    assert (model["scene"], model["description"]) == (name, description)


def test_an_interrupted_page_write_leaves_the_earlier_page_and_no_temporary(motion, tmp_path, interrupted_writes):
    out = tmp_path / "lambda.html"
    out.write_text("a good page")
    with pytest.raises(KeyboardInterrupt):
        write(motion, out)
    assert out.read_text() == "a good page" and list(tmp_path.iterdir()) == [out]
