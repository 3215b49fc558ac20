"""The catalog as a whole: listed, loadable, each entry an ordinary scene file."""

from pathlib import Path

import pytest

from algkin.catalog import catalog_entries
from algkin.scene import catalog_names, compile_scene, load_scene
from algkin.scene.groups import compile_groups

from .geometry import run_process

CATALOG = Path(__file__).resolve().parents[2] / "algkin" / "catalog"


def test_list_shows_at_least_ten_scenes():
    listed = run_process("list")["scenes"]
    names = [s["name"] for s in listed]
    assert len(names) >= 10
    assert {"fourbar", "fourbar-nongrashof", "fourbar-near-toggle", "slider-crank", "watt-straight-line",
            "hoekens-straight-line", "chebyshev-straight-line", "watt-i", "stephenson-iii",
            "five-bar", "arm-string", "chebyshev-lambda", "whitworth-quick-return", "inverted-slider-crank"} <= set(names)
    assert all(s["description"] for s in listed)


def test_the_listed_names_and_descriptions_are_those_of_the_loaded_scenes():
    # `algkin list` reads them from the files without loading the scenes (no algebra imported)
    assert catalog_entries() == [(s.name, s.description) for s in map(load_scene, catalog_names())]


@pytest.mark.parametrize("name", catalog_names())
def test_each_entry_is_a_scene_file_that_compiles(name):
    path = CATALOG / f"{name}.toml"
    scene = load_scene(str(path))
    assert scene.name == name == load_scene(name).name
    if scene.unknown_points:  # solved together: its groups, each square (algkin solve)
        assert all(len(g.equations) == len(g.unknowns) > 0 for g in compile_groups(scene).groups)
        return
    compiled = compile_scene(scene)
    assert compiled.system.equations and compiled.system.unknowns
