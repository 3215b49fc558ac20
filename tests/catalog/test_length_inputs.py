"""Scenes driven by a length (a string, a hydraulic cylinder, a piston) against hand geometry.

The expected values come from the definitions: the law of cosines, the seed's forward
relation |AB|(theta), and where a bar and a crank fall in line; none from algkin's forms.
"""

import flint
import os
import subprocess
import sys

import mpmath
import pytest
import sympy

from algkin import derive, extremum, rates
from algkin.analyses.limits import limits
from algkin.analyses.toggles import toggles
from algkin.errors import UsageError
from algkin.evaluate import MPMATH, evaluate
from algkin.scene import dump_scene, load_scene
from algkin.scene.load import load_scene_text

from .geometry import ROOT, run

LENGTH_SCENES = ("arm-by-string", "hydraulic-boom", "piston-driven-crank")


def _values(scene, output, s, name="s", digits=40):
    """The scene's branch values of ``output`` (unknown -> mpmath) at the length ``s``."""
    derived = derive(scene, [output], samples=0)
    branch = next(b for b in derived.branches if b.selected)
    with mpmath.workdps(digits):
        return {u: evaluate(v, {name: mpmath.mpf(s)}, MPMATH) for u, v in branch.values.items()}


def _direction(values, name):
    return mpmath.degrees(mpmath.atan2(values[f"sin_{name}"], values[f"cos_{name}"]))


@pytest.mark.parametrize("s", ["60", "123.5", "300", "451", "579.99"])
def test_the_arm_angle_over_the_string_length_gives_back_that_length(s):
    """The seed's arm, A = r (sin theta, -cos theta): at the derived theta, |AB| is s again."""
    values = _values("arm-by-string", "arm", s)
    with mpmath.workdps(40):
        theta = mpmath.radians(_direction(values, "arm") + 90)
        a, b, r = 400, 80, 350
        ab = mpmath.hypot(r * mpmath.sin(theta) - a, -r * mpmath.cos(theta) + b)
        assert abs(ab - mpmath.mpf(s)) < mpmath.mpf(10) ** -30
        # the scene's branch: the arm above the line OB (left of O -> B), theta past its minimum of |AB|
        assert mpmath.degrees(theta) > 78.69


def test_the_boom_and_its_cylinder_by_the_law_of_cosines():
    for s in ("0.8", "1.3", "2.1", "2.4"):
        values = _values("hydraulic-boom", "boom", s)
        tip = _values("hydraulic-boom", "T", s)
        transmission = _values("hydraulic-boom", "transmission", s)
        with mpmath.workdps(40):
            r, cx, cy, length = mpmath.mpf(1), mpmath.mpf(3) / 2, mpmath.mpf(1) / 2, 3
            oc = mpmath.hypot(cx, cy)
            s = mpmath.mpf(s)
            at_o = mpmath.acos((r**2 + oc**2 - s**2) / (2 * r * oc))  # the angle AOC
            boom = mpmath.degrees(mpmath.atan2(-cy, cx) + at_o)  # A left of O -> C: turned anticlockwise
            assert abs(_direction(values, "boom") - boom) < 1e-30
            assert abs(tip["T_x"] - length * mpmath.cos(mpmath.radians(boom))) < 1e-30
            assert abs(tip["T_y"] - length * mpmath.sin(mpmath.radians(boom))) < 1e-30
            # the transmission angle at A, between AO and AC
            assert abs(transmission["cos_transmission"] - (r**2 + s**2 - oc**2) / (2 * r * s)) < 1e-30


def test_the_boom_is_highest_where_the_cylinder_reaches_straight_above_the_pivot():
    """A.y = r at most, where A = (0, r): s = |C - (0, r)| = sqrt(cx**2 + (r + cy)**2) = 3/sqrt(2)."""
    result = extremum("hydraulic-boom", "A.y")
    assert result.maximum.kind == "maximum"
    assert abs(result.maximum.value - 1) < 1e-14
    with flint.ctx.workprec(200):
        assert result.maximum.enclosure.contains((flint.arb(9) / 2).sqrt())  # held in a certified ball
    s = sympy.Symbol("s", real=True)  # as algkin names its variables
    assert any(sympy.expand(f - (2 * s**2 - 9)) == 0 for f in result.stationary)  # and exactly so


def test_a_piston_cannot_turn_its_crank_at_the_ends_of_its_stroke():
    """The dead centres of a piston-driven crank: rod and crank in line at x = l - r and l + r."""
    found = toggles("piston-driven-crank")
    assert [(g.kind, g.point) for g in found.toggles] == [("folded", "A"), ("extended", "A")]
    assert found.toggles[0].enclosure.contains(2) and found.toggles[1].enclosure.contains(4)
    assert found.to_json()["unit"] == "length"
    assert {"input_length", "enclosure_length"} <= set(found.to_json()["toggles"][0])


@pytest.mark.parametrize("x", ["2.25", "2.5", "3", "3.75"])
def test_the_crank_angle_over_the_piston_position_by_the_law_of_cosines(x):
    values = _values("piston-driven-crank", "crank", x, name="x")
    with mpmath.workdps(40):
        x, r, l = mpmath.mpf(x), 1, 3
        expected = mpmath.degrees(mpmath.acos((r**2 + x**2 - l**2) / (2 * r * x)))
        assert abs(_direction(values, "crank") - expected) < 1e-30


@pytest.mark.parametrize("name", LENGTH_SCENES)
def test_each_length_scene_derives_verifies_and_certifies_its_labels(name):
    document = run("derive", name)
    assert document["verification"]["status"] == "passed"
    (variable,) = document["inputs"].values()
    assert set(variable) == {"value"}
    intervals = [i for b in document["branches"] for i in b["certified"]]
    assert intervals and all({"from_length", "to_length", "status"} == set(i) for i in intervals)
    assert any(i["status"] == "certified" for i in intervals)


@pytest.mark.parametrize("name", LENGTH_SCENES)
def test_a_length_scene_round_trips_through_its_toml(name):
    scene = load_scene(name)
    assert load_scene_text(dump_scene(scene)) == scene


def test_the_string_s_is_a_variable_of_the_system_not_an_angle():
    document = run("show", "arm-by-string")
    assert document["inputs"] == {"s": {"value": "s"}}
    assert not any(name.startswith(("c_s", "s_s")) for name in document["system"]["unknowns"])
    assert all("c_s" not in equation for equation in document["system"]["equations"])
    x = sympy.Symbol("s")
    assert any(sympy.parse_expr(e).has(x) for e in document["system"]["equations"])


def test_accuracy_is_laid_out_on_a_turning_input_and_refuses_a_length_in_one_line():
    done = subprocess.run([sys.executable, "-m", "algkin", "accuracy", "hydraulic-boom"], capture_output=True,
                          text=True, env=dict(os.environ, PYTHONPATH=str(ROOT)))
    assert done.returncode == 2 and done.stdout == ""
    assert len(done.stderr.splitlines()) == 1 and "s is a length" in done.stderr


def test_limit_positions_are_for_a_turning_input():
    with pytest.raises(UsageError, match="s is a length"):
        limits("hydraulic-boom")
    assert "limits" not in run("toggles", "hydraulic-boom")  # toggles still answer, without them


def test_the_boom_tip_rates_per_unit_of_cylinder_length_are_the_hand_triangle_differentiated():
    """dT/ds and d2T/ds2 against mpmath's derivatives of the law-of-cosines construction."""
    found = rates("hydraulic-boom", outputs=["T"], samples=6)
    assert found.verification.passed and found.to_json()["rates_input"] == {"name": "s", "per": "length"}
    left = next(b for b in found.branches if b.label == "left")

    def tip(s, k):
        oc = mpmath.hypot(mpmath.mpf(3) / 2, mpmath.mpf(1) / 2)
        boom = mpmath.atan2(-mpmath.mpf(1) / 2, mpmath.mpf(3) / 2) + mpmath.acos((1 + oc**2 - s**2) / (2 * oc))
        return 3 * (mpmath.cos(boom), mpmath.sin(boom))[k]

    with mpmath.workdps(40):
        for s in ("0.9", "1.5", "2.3"):
            at = {"s": mpmath.mpf(s)}
            for k, unknown in enumerate(("T_x", "T_y")):
                for order, form in ((1, left.velocity[unknown]), (2, left.acceleration[unknown])):
                    expected = mpmath.diff(lambda v: tip(v, k), mpmath.mpf(s), order)
                    assert abs(evaluate(form, at, MPMATH) - expected) < mpmath.mpf(10) ** -25, (s, unknown, order)
