"""``algkin export`` on scenes with points solved together: the numpy code (a root of the eliminant
found by a root finder, the mode followed by continuation from where ``solve`` labels it, the other
unknowns rational in it) gives ``algkin solve``'s coordinates; a hostile scene name stays data."""

import contextlib
import importlib.util
import json
import math
from importlib import resources

import numpy as np
import pytest

from algkin.analyses.solve import solve
from algkin.ui.export import export

from .cli.in_process import run_main
from .test_export_hostile import PAYLOADS


def module(code, path):
    path.write_text(code)
    spec = importlib.util.spec_from_file_location("exported", path)
    loaded = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(loaded)
    return loaded


@pytest.mark.parametrize("scene, inputs, radians", [
    ("3rpr", ["5", "6", "7", "23/2", "12"], False),
    pytest.param("stephenson-iii-triad", ["0", "360"], True, marks=pytest.mark.slow),
])
def test_the_numpy_code_gives_solve_s_modes(tmp_path, scene, inputs, radians):
    loaded = module(export(scene, ["P1"] if scene == "3rpr" else ["A", "P"], "numpy"), tmp_path / "m.py")
    functions = [getattr(loaded, n) for n in dir(loaded) if n.startswith(scene.replace("-", "_").replace("3", "x3"))]
    values = np.array([float(eval(v)) for v in inputs])  # noqa: S307 - our own literals
    computed = [np.array(f(np.radians(values) if radians else values)) for f in functions]
    name = "theta" if radians else "r1"
    for k, value in enumerate(inputs):
        found = solve(scene, {name: value}, digits=20).configurations
        points = ["P1"] if scene == "3rpr" else ["A", "P"]
        expected = sorted(tuple(float(v) for p in points for v in c.points[p]) for c in found)
        here = sorted(tuple(c[:, k]) for c in computed if not math.isnan(c[0, k]))
        assert len(here) == len(expected), (value, here, expected)
        np.testing.assert_allclose(here, expected, atol=1e-9)


@pytest.mark.parametrize("hostile", [
    'x"""\nimport pathlib; pathlib.Path("PWNED_py").touch()\n#',
    pytest.param("\u2028".join(PAYLOADS), marks=pytest.mark.slow),
    pytest.param("int", marks=pytest.mark.slow),
])
def test_a_hostile_scene_name_stays_data(tmp_path, hostile):
    source = resources.files("algkin.catalog").joinpath("3rpr.toml").read_text()
    scene = tmp_path / "hostile.toml"
    scene.write_text(source.replace('name = "3rpr"', f"name = {json.dumps(hostile)}"))
    done = run_main(["export", str(scene), "--to", "numpy", "--out", "m.py"], tmp_path)  # the code is the question
    assert done.returncode == 0, done.stderr
    code = (tmp_path / "m.py").read_text()
    assert all(32 <= ord(c) < 127 for line in code.splitlines() for c in line)
    with contextlib.chdir(tmp_path):  # a payload run on import would write its file here, where it is looked for
        loaded = module(code, tmp_path / "m2.py")
    assert not list(tmp_path.glob("PWNED*"))
    functions = [n for n in dir(loaded) if callable(getattr(loaded, n)) and not n.startswith(("algkin_", "_"))]
    assert len(functions) == 4 and all(n.isidentifier() for n in functions)
    x, y = getattr(loaded, functions[0])([6.0])  # the code still computes the platform
    assert np.isfinite(x).all() or np.isnan(x).all()
