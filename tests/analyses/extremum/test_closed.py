"""Closed forms of the arm's minimum in symbolic dimensions, against hand geometry and brute force."""


import mpmath
import numpy as np
import pytest
import sympy
from hypothesis import given, settings, strategies as st

from algkin.analyses.extremum import extremum

from .arm_by_hand import brute_minimum, hand_minimiser, hand_minimum

a, b = sympy.symbols("a b", real=True)


def at(expr_text, **values):
    expr = sympy.sympify(expr_text, locals={"a": a, "b": b})
    return float(expr.subs({sympy.Symbol(k, real=True): v for k, v in values.items()}))


@pytest.fixture(scope="module")
def in_b():
    return extremum("arm-string", "AB", (0, 180), params=["b"]).closed_form


@pytest.fixture(scope="module")
def in_a_b():
    return extremum("arm-string", "AB", (0, 180), params=["a", "b"]).closed_form


def test_value_in_b_is_the_hand_formula(in_b):
    assert sympy.simplify(in_b.value - (sympy.sqrt(b**2 + 160000) - 350)) == 0
    assert str(in_b.value) == "sqrt(b**2 + 160000) - 350"


def test_minimiser_never_leaves_0_180_for_any_b(in_b):
    # a = 400 > 0 keeps atan2(a, b) inside (0, 180) for every b.
    assert in_b.valid_when == (sympy.true,)
    assert in_b.valid_when_text == ("every real b",) and in_b.to_json()["valid_when"] == ["every real b"]
    assert [r["at"] for r in in_b.regions] == ["stationary"]


@pytest.mark.parametrize("b_value", [-500, -80, -1, 0, 1, 80, 300, 2000])
def test_closed_form_in_b_against_brute_force_and_hand(in_b, b_value):
    value, degrees = brute_minimum(400, b_value)
    assert at(in_b.to_json()["value"], b=b_value) == pytest.approx(value, abs=1e-9)
    assert at(in_b.to_json()["input"], b=b_value) == pytest.approx(degrees, abs=1e-6)
    assert at(in_b.to_json()["input"], b=b_value) == pytest.approx(hand_minimiser(400, b_value), abs=1e-9)


@settings(max_examples=25)
@given(st.fractions(min_value=-2000, max_value=2000, max_denominator=50))
def test_closed_form_in_b_is_the_minimum_everywhere(in_b, b_value):
    value, _ = brute_minimum(400, float(b_value))
    assert at(str(in_b.value), b=b_value) == pytest.approx(value, rel=1e-9, abs=1e-9)


def test_minimiser_leaving_the_range_is_reported_with_the_endpoint():
    # Over [0, 90] the minimiser atan2(400, b) leaves the range for b < 0; the minimum is then
    # at 90 deg, where A = (350, 0): |AB| = sqrt(50**2 + b**2).
    form = extremum("arm-string", "AB", (0, 90), params=["b"]).closed_form
    assert form.valid_when_text == ("b > 0",)
    (holds,) = form.valid_when  # a sympy relation, true exactly where the minimiser stays in range (b > 0)
    assert [bool(holds.subs(b, value)) for value in (-400, -0.5, 0, 0.5, 400)] == [False, False, False, True, True]
    below, above = form.regions
    assert (below["from"], below["to"], below["at"], below["input"]) == (None, 0.0, "endpoint", "90")
    assert sympy.simplify(sympy.sympify(below["value"], locals={"b": b}) - sympy.sqrt(b**2 + 2500)) == 0
    assert above["at"] == "stationary" and above["to"] is None
    for b_value in (-400, -80, -0.5):
        value, degrees = brute_minimum(400, b_value, 0, 90)
        assert at(below["value"], b=b_value) == pytest.approx(value, abs=1e-9)
        assert degrees == pytest.approx(90, abs=1e-6)


def test_value_in_a_and_b_is_the_hand_formula(in_a_b):
    assert sympy.simplify(in_a_b.value - (sympy.sqrt(a**2 + b**2) - 350)) == 0
    assert in_a_b.at == "stationary"


def test_conditions_in_a_and_b_are_the_geometric_ones(in_a_b):
    # In range needs a > 0 (atan2(a, b) in (0, 180)); |OB| - 350 is the distance only while
    # B is outside the arm's circle (else it is 350 - |OB|).
    assert sorted(in_a_b.valid_when_text) == ["a > 0", "a**2 + b**2 - 122500 > 0"]
    assert set(in_a_b.valid_when) == {a > 0, a**2 + b**2 - 122500 > 0}  # sympy relations, as written


@pytest.mark.parametrize("a_value, b_value", [(400, 80), (300, -500), (1, 400), (900, 0), (250, -250)])
def test_closed_form_in_a_b_where_valid(in_a_b, a_value, b_value):
    value, degrees = brute_minimum(a_value, b_value)
    assert at(str(in_a_b.value), a=a_value, b=b_value) == pytest.approx(value, abs=1e-9)
    assert at(str(in_a_b.input), a=a_value, b=b_value) == pytest.approx(degrees, abs=1e-6)
    assert value == pytest.approx(hand_minimum(a_value, b_value), abs=1e-9)


@pytest.mark.parametrize("a_value, b_value", [(-400, 80), (100, 100)])
def test_conditions_are_needed(in_a_b, a_value, b_value):
    # a < 0: the minimiser is out of [0, 180]; |OB| < 350: the value is 350 - |OB|.
    value, _ = brute_minimum(a_value, b_value)
    assert abs(at(str(in_a_b.value), a=a_value, b=b_value) - value) > 1


def slider_position(degrees, e, r=1, l=3):
    """The slider-crank's B.x by hand: A = r(cos, sin), B on y = e at distance l ahead of A."""
    t = np.radians(degrees)
    return r * np.cos(t) + np.sqrt(l**2 - (r * np.sin(t) - e) ** 2)


def test_the_offset_symbolic_gives_the_minimum_where_the_slider_reaches():
    # Far offsets (|e| > r + l = 4) put the line out of reach: there the output is real
    # nowhere, which must not stop the closed form valid where the mechanism assembles.
    found = extremum("slider-crank", "x", params=["e"])
    (e,) = found.problem.parameters
    grid = np.linspace(0, 360, 200001)
    assert float(found.minimum.value) == pytest.approx(slider_position(grid, 0.5).min(), abs=1e-9)
    for value in ("-3/2", "1/5", "1/2", "7/4"):  # inside the region of the defaults, both signs of e
        at = sympy.Rational(value)
        brute = slider_position(grid, float(at)).min()
        assert float(found.closed_form.value.xreplace({e: at})) == pytest.approx(brute, abs=1e-8)
    regions = found.closed_form.regions
    assert (regions[0]["to"], regions[0]["at"]) == (pytest.approx(-4), "nowhere")
    assert (regions[-1]["from"], regions[-1]["at"]) == (pytest.approx(4), "nowhere")


def test_offsets_past_the_crank_put_the_minimum_at_a_dead_centre():
    # For 2 < |e| < 4 the crank cannot turn: B is real only while |sin(t) - e| <= l, and its
    # lowest x is at the dead centre sin(t) = e - l (or e + l): x = cos(t) = -sqrt(1 - (e -+ l)**2)
    # by hand. Before, no dead centre was a candidate and the region's minimum was wrong.
    found = extremum("slider-crank", "x", params=["e"])
    (e,) = found.problem.parameters
    grid = np.linspace(0, 360, 2000001)
    for value in ("-7/2", "-5/2", "5/2", "7/2"):
        at = sympy.Rational(value)
        region, expr = next((r, v) for r, v in zip(found.closed_form.regions, found.closed_form.region_values)
                            if r["from"] is not None and r["to"] is not None and r["from"] < at < r["to"])
        hand = -np.sqrt(1 - (float(at) - np.sign(float(at)) * 3) ** 2)
        assert region["at"] == "dead centre"
        assert float(expr.xreplace({e: at})) == pytest.approx(hand, abs=1e-12)
        with np.errstate(invalid="ignore"):  # not real past the dead centres
            brute = np.nanmin(slider_position(grid, float(at)))
        assert brute == pytest.approx(hand, abs=1e-2)


@pytest.mark.slow
def test_the_closed_forms_written_do_not_depend_on_the_hash_seed(tmp_path):
    """A root's forms (as sympy gives it, denested, rationalised) were a set: where two are as short,
    the one written followed the process's hash seed (fourbar's B.y in a: seeds 4 and 5 differed)."""
    import os
    import subprocess
    import sys

    from tests.processes import ROOT

    documents = set()
    for seed in ("4", "5"):
        done = subprocess.run([sys.executable, "-m", "algkin", "extremum", "fourbar", "--of", "B.y", "--param", "a",
                               "--json"], cwd=tmp_path, capture_output=True, text=True, timeout=600,
                              env=dict(os.environ, PYTHONPATH=str(ROOT), PYTHONHASHSEED=seed))
        assert done.returncode == 0, done.stderr[-300:]
        documents.add(done.stdout)
    assert len(documents) == 1


def test_a_whitworth_rams_leftmost_in_its_lever_length_is_the_lever_tangent_to_the_crank_circle():
    # its discriminants hold sqrt(R**2), which sympy writes Abs(R): an internal error before
    found = extremum("whitworth-quick-return", "D.x", params=["R"]).closed_form
    # by hand: the lever leans furthest left where CA is tangent to the crank's circle (radius 3 about O,
    # C 5 below O): lever direction (-3/5, 4/5), so B = (-3R/5, -5 + 4R/5), at crank angle 180 + asin(3/5);
    # the ram D on y = 6 at 6 from B: D.x = B.x + sqrt(36 - (6 - B.y)**2)
    length = sympy.Symbol("R", real=True)
    with mpmath.workdps(30):
        assert abs(sympy.N(found.input, 30) - (180 + mpmath.degrees(mpmath.asin(mpmath.mpf(3) / 5)))) < 1e-25
        for value in (7, 10, 13, 16):
            by_hand = -mpmath.mpf(3) * value / 5 + mpmath.sqrt(36 - (11 - mpmath.mpf(4) * value / 5) ** 2)
            assert abs(sympy.N(found.value.xreplace({length: value}), 30) - by_hand) < 1e-25
