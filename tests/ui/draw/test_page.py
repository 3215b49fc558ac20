"""The .html page against hostile scene text: nothing from a scene becomes markup or script."""

import copy
import json
import pathlib
import re
import unicodedata

import attrs
import html5lib
import pytest
from hypothesis import given, settings, strategies as st

from algkin.ui.atlas import atlas_page
from algkin.ui.cli import main
from algkin.ui.html import page, write
from algkin.analyses.motion import Motion

HOSTILE = ["{{script}}", "{{title}}", "{{description}}", "{{style}}", "</script>", "<script>", "<!--", "-->",
           "<img src=x onerror=alert(2)>", "</title>", "</p><h1>", "</style>", '"', "'", "&amp;", "&", "$x$",
           "\x00", "\u2028", "\u2029", "\\", "`${1}`", "]]>", "<!--<script>"]
CATALOG = pathlib.Path(__file__).parents[3] / "algkin" / "catalog"
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


# What a page writes out rather than leaves raw, as a terminal does: bidirectional marks and overrides,
# and the line and paragraph separators (the control characters are category Cc).
WRITTEN_OUT = set("\u061c\u200e\u200f\u2028\u2029\u202a\u202b\u202c\u202d\u202e\u2066\u2067\u2068\u2069")


def plain(text):
    """Text a page shows as it is: no control characters, bidi marks or separators (written out
    instead), no non-characters (which the HTML parser may not read back)."""
    return not any(unicodedata.category(c) in ("Cc", "Cn") or c in WRITTEN_OUT for c in text)


def raw_controls(text):
    """The control characters in ``text`` but newline and tab, and the bidi marks and separators."""
    return [c for c in text if (unicodedata.category(c) == "Cc" and c not in "\n\t") or c in WRITTEN_OUT]


@settings(max_examples=25, deadline=None)
@given(name=TEXTS, description=TEXTS)
def test_scene_text_never_becomes_markup_or_script(motion, benign, name, description):
    text = page_of(motion, name, description)
    tree = html5lib.parse(text, namespaceHTMLElements=False)
    assert structure(tree) == benign
    assert raw_controls(text) == []  # written out in the markup, \u-escaped in the script
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


# A scene file whose name and description hold an escape sequence, a bell, a NUL and a newline (TOML's
# \\u escapes): the page and the atlas write them out, as a terminal would, and no raw byte of them is in
# the file.
CONTROLS = (CATALOG / "fourbar.toml").read_text().replace(
    'name = "fourbar"', 'name = "four\\u001b[31mbar\\u0007\\u0000\\nx"').replace(
    'description = "', 'description = "bell\\u0007 nul\\u0000 ')
SHOWN_NAME = "four\\x1b[31mbar\\x07\\x00\\nx"  # by hand: each character as Python writes its escape


def test_a_scene_name_with_control_characters_is_written_out_in_the_page(tmp_path, capsys):
    (tmp_path / "controls.toml").write_text(CONTROLS)
    out = tmp_path / "page.html"
    assert main(["plot", str(tmp_path / "controls.toml"), "--out", str(out)]) == 0
    data = out.read_bytes()
    assert not re.search(rb"[\x00-\x08\x0b\x0c\x0e-\x1f\x7f]", data)
    tree = html5lib.parse(data.decode("utf-8"), namespaceHTMLElements=False)
    assert tree.find(".//title").text == tree.find(".//h1").text == f"algkin: {SHOWN_NAME}"
    assert tree.find(".//p[@class='description']").text.startswith("bell\\x07 nul\\x00 General four-bar")


def test_the_atlas_title_writes_out_control_characters():
    text = atlas_page({"scene": "four\x1b[31mbar\x07\x00\nx", "designs": []})
    assert raw_controls(text) == []
    tree = html5lib.parse(text, namespaceHTMLElements=False)
    assert tree.find(".//title").text == f"algkin atlas: {SHOWN_NAME}"
