"""The sweep on a scene with points solved together: its modes and toggles per design, checked
against the independent numeric solver; the analyses that do not apply refused in one line."""

from fractions import Fraction

import flint
import numpy as np
import pytest

from algkin.errors import UsageError
from algkin.scene import load_scene
from algkin.scene.groups import compile_groups
from algkin.scene.settings import with_values
from algkin.sweep import plan
from algkin.sweep.design import Job, evaluate_design
from algkin.ui.cli import main
from algkin.verify.groups import STARTS, real_solutions

RPR = load_scene("3rpr")


def real_count(r2, r1):
    """Real assembly modes of the 3-RPR at legs r1, r2 by Newton from many starts, each proved in balls."""
    compiled = compile_groups(with_values(RPR, {"r2": r2}))
    (group,) = compiled.groups
    roots, = real_solutions(group.unknowns, group.equations, {"r1": ("r1",)},
                            [{"r1": flint.fmpq(r1.numerator, r1.denominator)}], np.random.default_rng(0),
                            starts=4 * STARTS)
    return len(roots)


@pytest.mark.parametrize("r2", [Fraction(9), Fraction(10)])
def test_modes_and_toggles_per_design_match_the_numeric_solver(r2):
    row = evaluate_design(Job(RPR, ("modes", "toggles"), "P3"), 0, {"r2": r2})
    assert row["status"] == "ok" and row["modes_complex"] == 6  # Gosselin, Sefrioui and Richard: a sextic
    assert row["modes_real"] == real_count(r2, Fraction(row["modes_reference"])) > 0
    assert row["toggles_count"] == len(row["toggles_deg"]) > 0
    for toggle in row["toggles_deg"]:  # two modes meet there: the count of real ones changes by two across it
        before, after = (real_count(r2, Fraction(toggle + side).limit_denominator(10**4)) for side in (-0.01, 0.01))
        assert abs(before - after) == 2


@pytest.mark.parametrize("scene, analysis, takes", [
    ("3rpr", "curve", "this scene takes toggles, modes"),
    ("fourbar", "modes", "this scene takes curve, grashof, toggles, limits, transmission, singular"),
])
def test_an_analysis_that_does_not_apply_is_refused_naming_those_that_do(scene, analysis, takes):
    grid = ["r2=8:10:3"] if scene == "3rpr" else ["a=1:2:2"]
    with pytest.raises(UsageError, match=takes):
        plan(scene, grid=grid, analyses=[analysis])


def test_sweep_command_on_a_group_scene(tmp_path, capsys):
    argv = ["sweep", "3rpr", "--grid", "r2=8:10:2", "--executor", "serial", "--out", str(tmp_path / "out")]
    assert main([*argv, "--analyses", "modes,toggles"]) == 0
    assert main([*argv[:-1], str(tmp_path / "other"), "--analyses", "curve"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--analyses" in err and "toggles, modes" in err
    assert not (tmp_path / "other").exists()  # refused before anything is written
