"""Scene files read from disk (``algkin.scene.load``): what an editor may put around the text."""

from algkin.catalog import catalog_path
from algkin.scene import load_scene


def test_a_scene_with_a_byte_order_mark_reads_as_without(tmp_path):
    # Windows' Notepad starts UTF-8 with EF BB BF; it was "TOML syntax error: Invalid statement (at line 1, column 1)"
    text = open(catalog_path("arm-string"), "rb").read()
    marked, plain = tmp_path / "marked.toml", tmp_path / "plain.toml"
    marked.write_bytes(b"\xef\xbb\xbf" + text)
    plain.write_bytes(text)
    read, expected = load_scene(marked), load_scene(plain)
    assert (read.name, read.points, read.parameters, read.outputs) == \
        (expected.name, expected.points, expected.parameters, expected.outputs)
