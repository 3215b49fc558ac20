"""Scene files read from disk (``algkin.scene.load``): what an editor may put around the text."""

import pytest

from algkin.catalog import catalog_path
from algkin.errors import SceneError
from algkin.scene import load_scene, load_scene_text


def test_a_scene_with_a_byte_order_mark_reads_as_without(tmp_path):
    # Windows' Notepad starts UTF-8 with EF BB BF; it was "TOML syntax error: Invalid statement (at line 1, column 1)"
    text = open(catalog_path("arm-string"), "rb").read()
    marked, plain = tmp_path / "marked.toml", tmp_path / "plain.toml"
    marked.write_bytes(b"\xef\xbb\xbf" + text)
    plain.write_bytes(text)
    read, expected = load_scene(marked), load_scene(plain)
    assert (read.name, read.points, read.parameters, read.outputs) == \
        (expected.name, expected.points, expected.parameters, expected.outputs)


def test_a_phase_of_309_digits_is_refused_in_a_short_line():
    # 1e308 degrees is no multiple of 90 (10**308 / 90 = 10**307 / 9); its 309 digits were the line's bulk
    text = '[inputs]\nt = { range = [0, 90] }\n[points]\nO = { fixed = [0, 0] }\n' \
           'A = { crank = "O", length = 1, input = "t", phase = 1e308 }\n[outputs]\nA = "A"\n'
    with pytest.raises(SceneError, match=r"^s\.toml: points\.A\.phase: phase 1000.*\(309 characters\) deg has no rational") \
            as raised:
        load_scene_text(text, "s.toml")
    assert len(str(raised.value)) < 300


@pytest.mark.parametrize("line, fraction", [
    ('a = { default = 1, range = [1/2, 2] }', '"1/2"'),  # SPEC section 2's own example, as written there
    ('a = 3 / 4', '"3/4"'),
    ('a = { default = 1, range = ["1/2", 2.5/3] }', '"2.5/3"'),
])
def test_a_fraction_written_bare_says_to_write_it_as_a_string(line, fraction):
    """TOML has no fractions: tomllib said only "Unclosed array (at line 2, column 30)"."""
    text = f"[parameters]\n{line}\n[points]\nO = {{ fixed = [0, 0] }}\n"
    with pytest.raises(SceneError) as caught:
        load_scene_text(text, "s.toml")
    said = str(caught.value)
    assert said.startswith("s.toml: TOML syntax error: ") and f"write the fraction as a string: {fraction}" in said
    assert "\n" not in said


def test_other_syntax_errors_are_said_as_before():
    with pytest.raises(SceneError) as caught:
        load_scene_text("[parameters]\na = [1, 2\n", "s.toml")
    assert "fraction" not in str(caught.value)
