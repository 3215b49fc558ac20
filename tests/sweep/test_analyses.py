"""The sweep's analyses against hand geometry: Grashof classes from the four lengths, toggles and
transmission angles by the law of cosines, limit positions from crank and coupler in line, and
the coupler curve vanishing on hand-computed coupler points."""

import json
import math
from fractions import Fraction

import pytest
import sympy
from hypothesis import given
from hypothesis import strategies as st

from algkin.scene import load_scene
from algkin.sweep.analyses import _float_of
from algkin.sweep.design import Job, evaluate_design

from ..hand_linkages import fourbar
from .hand import hand_grashof

FOURBAR = load_scene("fourbar")
DEFAULTS = dict(a=1, d=4, l=3, m=3.5, p=0.5, q=0.5)


def row(analyses, **values):
    return evaluate_design(Job(FOURBAR, tuple(analyses), "P"), 0, {k: Fraction(v) for k, v in values.items()})


@pytest.mark.parametrize("a, d, l, m", [
    ("1", "4", "3", "7/2"),      # crank shortest, 1 + 4 < 3 + 7/2
    ("3", "2", "3", "7/2"),      # ground shortest: both side links turn fully
    ("3", "4", "2", "7/2"),      # coupler shortest
    ("3", "4", "3", "7/2"),      # 3 + 4 > 3 + 7/2: no link turns fully
    ("3", "7/2", "3", "7/2"),    # 3 + 7/2 = 3 + 7/2: the change point
    ("3", "4", "7/2", "5/2"),    # rocker shortest
])
def test_grashof_classes_by_hand(a, d, l, m):
    found = row(["grashof"], a=a, d=d, l=l, m=m)
    assert found["status"] == "ok", found["reason"]
    expected = hand_grashof(*(Fraction(v) for v in (a, d, l, m)))
    assert found["grashof_class"] == expected
    s = sorted(Fraction(v) for v in (a, d, l, m))
    assert Fraction(found["grashof_margin"]) == s[1] + s[2] - s[0] - s[3]
    assert found["grashof_margin_float"] == float(s[1] + s[2] - s[0] - s[3])


@given(st.fractions(max_denominator=2**70) | st.integers(-2**1100, 2**1100).map(Fraction))
def test_margin_float_is_sympys_float_of_its_text(margin):
    """A margin's float read from its text as the rational it is: sympy's own float, past a float's range too."""
    text = str(sympy.Rational(margin.numerator, margin.denominator))
    assert _float_of(text) == float(sympy.sympify(text))


def test_irrational_margin_float():
    """A ground of sqrt(...) makes the margin a radical: its float still comes from its text."""
    assert _float_of("-3 + 2*sqrt(5)") == pytest.approx(-3 + 2 * math.sqrt(5), rel=1e-15)


def test_toggles_of_a_double_rocker_by_the_law_of_cosines():
    a, d, l, m = 3, 4, 2, 3.5
    found = row(["toggles"], a=a, d=d, l=l, m=Fraction(7, 2))
    # |AD|**2 = a**2 + d**2 - 2 a d cos(theta) is (l + m)**2 (extended) or (l - m)**2 (folded)
    extended = math.degrees(math.acos((a * a + d * d - (l + m) ** 2) / (2 * a * d)))
    folded = math.degrees(math.acos((a * a + d * d - (l - m) ** 2) / (2 * a * d)))
    assert found["toggles_count"] == 4
    assert found["toggles_deg"] == pytest.approx(sorted([folded, extended, 360 - extended, 360 - folded]), abs=1e-9)


def test_transmission_angle_extremes_of_a_crank_rocker_by_hand():
    a, d, l, m = 1, 4, 3, 3.5
    found = row(["transmission"], l=3)
    # the angle at B between BA and BD: cos mu = (l**2 + m**2 - |AD|**2) / (2 l m); |AD| from d - a to d + a
    cos_mu = [(l * l + m * m - ad ** 2) / (2 * l * m) for ad in (d - a, d + a)]
    assert found["transmission_of"] == "angle(A, B, D)"
    assert found["transmission_min_deg"] == pytest.approx(math.degrees(math.acos(cos_mu[0])), abs=1e-9)
    assert found["transmission_max_deg"] == pytest.approx(math.degrees(math.acos(cos_mu[1])), abs=1e-9)
    assert (found["transmission_min_at_deg"], found["transmission_max_at_deg"]) == (0.0, 180.0)
    assert float(sympy.sympify(found["transmission_min_exact"])) == pytest.approx(found["transmission_min_deg"])


def test_limit_positions_and_time_ratio_by_hand():
    a, d, l, m = 1, 4, 3, 3.5
    found = row(["limits"], a=1)
    # The rocker's limits: crank and coupler in line, |OB| = l + a (extended) or l - a (folded);
    # B's angle about O by the law of cosines in triangle O, D, B (B above the ground line: left)
    angle = lambda ob: math.degrees(math.acos((ob * ob + d * d - m * m) / (2 * ob * d)))  # noqa: E731
    extended, folded = angle(l + a), angle(l - a) + 180  # folded: the crank points away from B
    assert found["limits_count"] == 2
    assert found["limits_deg"] == pytest.approx([extended, folded], abs=1e-9)
    swept = folded - extended
    assert found["limits_time_ratio"] == pytest.approx(max(swept, 360 - swept) / min(swept, 360 - swept), abs=1e-12)


def test_the_coupler_curve_vanishes_on_hand_computed_coupler_points():
    found = row(["curve"], a=Fraction(3, 2), m=Fraction(4))
    assert (found["curve_degree"], found["curve_circularity"]) == (6, 3)  # the tricircular sextic
    x, y = sympy.symbols("P_x P_y")
    polynomial = sympy.sympify(found["curve_polynomial"], locals={"P_x": x, "P_y": y})
    size = max(abs(c) for c in sympy.Poly(polynomial, x, y).coeffs())
    dims = dict(DEFAULTS, a=1.5, m=4)
    for theta in (10, 97, 200, 311):
        for branch in ("left", "right"):
            P = fourbar(theta, **dims, branch=branch)["P"]
            assert abs(float(polynomial.subs({x: P[0], y: P[1]}))) < 1e-9 * float(size)


def test_a_four_bar_that_never_assembles_has_no_values():
    found = row(["grashof", "curve"], d=10)  # |AD| >= 9 > l + m = 6.5 at every crank angle
    assert found["status"] == "does-not-assemble" and "never assemble" in found["reason"]
    assert found["grashof_class"] is None and found["curve_degree"] is None


def test_a_four_bar_that_assembles_at_one_angle_only_is_a_structure():
    # a = 5/6, d = 22/3: |AD| >= d - a = 13/2 = l + m, equal at theta = 0 only: no motion, no curve
    found = row(["grashof", "curve"], a="5/6", d="22/3")
    assert found["status"] == "structure" and "assembles only at theta = 0°" in found["reason"]
    assert found["grashof_class"] is None and found["curve_degree"] is None


def test_a_failing_analysis_is_named_and_the_others_kept():
    scene = load_scene("slider-crank")  # no ground pivot for a rocker: no Grashof class
    found = evaluate_design(Job(scene, ("grashof", "toggles"), "B"), 3, {})
    assert found["status"] == "failed" and found["reason"].startswith("grashof: ComputationError: not a four-bar")
    assert found["toggles_count"] is not None and found["design"] == 3


def test_singular_points_of_a_designed_coupler_curve():
    """A coupler point at the instant centre (3, 4) traces a cusp, and at the change point the
    two assembly modes' paths cross at (11/5, 12/5) (a = 1, d = 3, l = 5/2, m = 3/2: 1 + 3 = 5/2
    + 3/2), as constructed by hand in tests/analyses/singular/test_coupler.py."""
    found = row(["curve", "singular"], a=1, d=3, l="5/2", m="3/2", p="32/25", q="24/25")
    assert found["status"] == "ok", found["reason"]
    assert found["singular_cusps"] >= 1 and found["singular_crunodes"] >= 1
    assert found["singular_count"] >= found["singular_cusps"] + found["singular_crunodes"]
    places = {(p["kind"], p["exact"]["x"], p["exact"]["y"]) for p in json.loads(found["singular_points"])}
    assert ("cusp", "3", "4") in places and ("crunode", "11/5", "12/5") in places


def test_a_design_past_its_budget_says_which_analysis_was_cut_short(monkeypatch):
    from ..clocks import late_budgets

    late_budgets(monkeypatch, doing="running the curve")  # the deadline passes once the curve is begun
    found = evaluate_design(Job(FOURBAR, ("grashof", "curve"), "P", 30.0), 0, {})
    assert (found["status"], found["reason"]) == \
        ("failed", "budget: max_seconds=30: stopped after 3600.00 s while running the curve analysis")
