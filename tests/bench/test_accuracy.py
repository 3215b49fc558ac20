"""Speed against error: the stabilised form is as accurate as the problem allows, on hard cases too."""

from fractions import Fraction

import mpmath
import numpy as np
import pytest
from hypothesis import assume, given, settings, strategies as st

from algkin.bench.accuracy import REFERENCE, accuracy
from algkin.errors import UsageError
from algkin.scene.settings import with_values
from algkin.branches.constructions.floats import heron_area

from algkin.scene import load_scene

from ..analyses.test_toggles import four_bar

EPS = 2.0**-53


@pytest.fixture(scope="module")
def rows():
    return accuracy(four_bar(3, 4, 2, "5/2"), samples=400, seed=1).rows


def test_every_case_of_the_spec_is_measured(rows):
    cases = {r["case"] for r in rows}
    assert {"uniform", "toggle-1e-06", "toggle-1e-10", "toggle-1e-14", "far-1e7"} <= cases
    assert {r["strategy"] for r in rows} == {"closed-form", "stabilised", "compiled", "numeric", "reference"}
    assert all("unsolved" in r for r in rows if r["strategy"] == "numeric")


def test_stabilised_is_within_ten_kappa_eps_everywhere(rows):
    for row in rows:
        if row["strategy"] == "stabilised":
            assert row["max_rel_error"] <= 10 * row["condition"] * EPS, row


def test_ill_conditioning_near_toggles_is_reported(rows):
    # The half-chord is a square root of the distance to the toggle, so kappa ~ 1/sqrt(offset):
    # 1e-14 away is sqrt(1e8) = 1e4 times worse than 1e-6 away; at least 1e3 of it must show.
    kappa = {r["case"]: r["condition"] for r in rows if r["strategy"] == "stabilised"}
    assert kappa["toggle-1e-14"] > 1e3 * kappa["toggle-1e-06"]
    assert kappa["toggle-1e-06"] > 10 * kappa["uniform"]


def test_raw_closed_form_loses_digits_far_from_the_origin(rows):
    far = {r["strategy"]: r["max_rel_error"] for r in rows if r["case"] == "far-1e7"}
    assert far["closed-form"] > 3 * far["stabilised"]


def _heron_exact(a, b, c):
    """The area from exact rational sides: 16 A**2 = q(a, b, c) in fractions, then one sqrt."""
    a, b, c = (Fraction(float(v)) for v in (a, b, c))
    q = 2 * (a * a * b * b + b * b * c * c + c * c * a * a) - a**4 - b**4 - c**4
    with mpmath.workdps(60):
        return mpmath.sqrt(mpmath.mpf(q.numerator) / q.denominator) / 4


sides = st.floats(min_value=1e-4, max_value=1e4)


def _area_condition(a, b, c):
    """Relative condition of the area in its sides, from 16 A**2 = q(a, b, c) (exact, 60 digits)."""
    with mpmath.workdps(60):
        a, b, c = (mpmath.mpf(float(v)) for v in (a, b, c))
        q = 2 * (a * a * b * b + b * b * c * c + c * c * a * a) - a**4 - b**4 - c**4
        slopes = [4 * x * (y * y + z * z - x * x) for x, y, z in ((a, b, c), (b, c, a), (c, a, b))]
        return 1 + sum(abs(v * d) for v, d in zip((a, b, c), slopes)) / (2 * abs(q))


@settings(max_examples=200)
@given(sides, sides, st.floats(min_value=0.0, max_value=1.0))
def test_sorted_heron_is_accurate_for_every_closable_triangle(a, b, fraction):
    c = abs(a - b) + fraction * (a + b - abs(a - b))  # any third side that closes
    assume(abs(Fraction(a) - Fraction(b)) <= Fraction(c) <= Fraction(a) + Fraction(b))  # closes, exactly
    exact = _heron_exact(a, b, c)
    computed = heron_area(np.float64(a), np.float64(b), np.float64(c))
    if exact == 0:
        assert computed == 0
    else:
        # Kahan's ordering: within a few ulps times what the sides' own rounding allows.
        assert abs(computed - exact) / exact <= 16 * EPS * float(_area_condition(a, b, c))


@pytest.fixture(scope="module")
def near_change_point_rows():
    return accuracy("fourbar-near-toggle", samples=400, seed=2).rows


def test_near_change_point_four_bar_is_sampled_at_its_closest_approach(near_change_point_rows):
    # Crank 1, ground 4, coupler 3, rocker 2.001: |AD| = 5 at 180 deg, 1/1000 short of folding.
    cases = {r["case"] for r in near_change_point_rows}
    assert {"uniform", "near-fold", "far-1e7"} <= cases


def test_stabilised_beats_the_raw_closed_form_near_the_fold(near_change_point_rows):
    by = {(r["strategy"], r["case"]): r for r in near_change_point_rows}
    for case in ("uniform", "near-fold", "far-1e7"):
        assert by["stabilised", case]["max_rel_error"] <= 10 * by["stabilised", case]["condition"] * EPS
    # (l + m)**2 - |AD|**2 = 0.010001 + 16 cos(theta/2)**2 in the stabilised form; expanded,
    # 8.010001 + 8 cos(theta) loses three digits to cancellation at 180 deg.
    assert by["closed-form", "near-fold"]["max_rel_error"] > 3 * by["stabilised", "near-fold"]["max_rel_error"]


def test_chebyshev_lambda_stabilised_within_ten_kappa_eps():
    for row in accuracy("chebyshev-lambda", samples=400, seed=3).rows:
        if row["strategy"] == "stabilised":
            assert row["max_rel_error"] <= 10 * row["condition"] * EPS, row


def test_stabilised_is_at_most_the_raw_error_or_says_why(rows):
    by = {(r["strategy"], r["case"]): r for r in rows}
    for (strategy, case), row in by.items():
        if strategy == "stabilised" and row["max_rel_error"] > by["closed-form", case]["max_rel_error"]:
            assert "kappa*eps" in row.get("note", ""), row


def _by(result):
    return {(r["strategy"], r["case"]): r for r in result.rows}


# Hard cases (near toggles, far from the origin: docs/cli/accuracy.md), against the certified reference (never the closed form). Bound:
# err <= C kappa eps with C = 10 (a few roundings, each at most an eps of the input), or an
# absolute bound where kappa says nothing.
C = 10


def test_the_reference_is_named_and_independent():
    result = accuracy("arm-string", samples=10, seed=0, of="AB")
    assert result.to_json()["reference"] == REFERENCE and "Krawczyk" in REFERENCE and result.point == "AB"


def test_change_point_four_bar_where_the_branches_meet():
    # crank 1 + ground 4 = coupler 3 + rocker 2: at 180 deg |AD| = 5 = 3 + 2, both branches meet
    # in B = (4, 0) - 2 * (1, 0)... the coupler and rocker lie along the ground: B = (2, 0) +- 0.
    from algkin.bench.accuracy import Subject

    subject = Subject(four_bar(1, 4, 3, 2), "B")
    theta = np.array([np.pi, np.pi * (1 - 1e-12), np.pi * (1 + 1e-12)])
    truth, _ = subject.reference(theta[:1])
    assert abs(truth[0, 0] - 2) < 1e-15 and abs(truth[1, 0]) < 1e-15  # by hand: B = (2, 0)
    truth, _ = subject.reference(theta)
    stable = subject.stable(theta)
    # |B - (2, 0)| ~ |theta - pi| there: an absolute bound of a few eps of the 4-long ground
    assert np.max(np.abs(stable - truth)) <= C * 4 * EPS


def test_change_point_four_bar_rows_within_kappa_eps():
    by = _by(accuracy(four_bar(1, 4, 3, 2), samples=40, seed=4))
    assert ("stabilised", "toggle-1e-14") in by or ("stabilised", "toggle-1e-06") in by
    for (strategy, case), row in by.items():
        if strategy == "stabilised":
            assert row["max_rel_error"] <= C * row["condition"] * EPS, row


@pytest.mark.parametrize("k", [1, 4, 8, 12])
def test_arm_with_b_to_zero(k):
    by = _by(accuracy(with_values(load_scene("arm-string"), {"b": f"1e-{k}"}), samples=20, seed=k, of="AB"))
    for strategy in ("stabilised", "closed-form"):
        for case in ("uniform", "far-1e7"):
            row = by[strategy, case]
            assert row["max_rel_error"] <= C * row["condition"] * EPS, row


def test_needle_dyad():
    # coupler 1e4 times the rocker: |AD| stays in [9999.5, 10000.5] inside [9999, 10001]
    by = _by(accuracy(four_bar("1/2", 10000, 10000, 1), samples=40, seed=5))
    for case in ("uniform", "far-1e7"):
        row = by["stabilised", case]
        assert row["max_rel_error"] <= C * row["condition"] * EPS, row


def test_translated_1e7_absolute_bound(rows):
    # 1e7 away the coordinates are 1e7 large, but the mechanism is 4 long: the stabilised form
    # keeps the offset out of the rounding, so the error is a few eps of the offset's own ulp.
    row = {r["strategy"]: r for r in rows if r["case"] == "far-1e7"}["stabilised"]
    assert row["max_abs_error"] <= 2 * np.spacing(2e7), row


# The numeric strategy: float Newton to convergence, checked against the label, or unsolved.

def test_numeric_reaches_the_labelled_root_or_counts_the_sample_unsolved():
    # Non-Grashof: six float Newton steps from the neighbour's construction used to end
    # unconverged or on the other branch (err/(kappa eps) 1.6e11 on uniform samples, 1.8e11
    # near the toggles). 1e7 away the float equations themselves lose 7 digits: not compared.
    by = _by(accuracy("fourbar-nongrashof", samples=200, seed=6))
    numeric = {case: row for (strategy, case), row in by.items() if strategy == "numeric" and case != "far-1e7"}
    assert {"uniform", "toggle-1e-14"} <= set(numeric)
    for row in numeric.values():
        assert row["error_over_kappa_eps"] <= C and row["unsolved"] <= row["samples"] // 10, row


def test_numeric_marks_a_sample_that_ends_on_the_other_branch():
    from algkin.bench.accuracy import Subject

    # Continuation from -120 deg to +120 deg starts from the mirror image of the answer: Newton
    # converges there, on the other branch, and the label's check says so.
    subject = Subject(load_scene("fourbar-nongrashof"), "B")
    theta = np.radians([-120.0, 120.0])
    truth, _ = subject.reference(theta)
    estimate = subject.newton(theta)
    assert np.abs(estimate[:, 0] - truth[:, 0]).max() < 1e-14 and np.isnan(estimate[:, 1]).all()


def test_numeric_row_counts_unsolved_samples_and_leaves_them_out():
    from algkin.bench.accuracy import _numeric_row

    truth = np.array([[1.0, 2.0, 3.0]])
    estimate = np.array([[1.0, np.nan, 3.0 + 4 * EPS]])
    row = _numeric_row("uniform", np.array([0.1, 0.2, 0.3]), estimate, 3e-6, truth, np.ones(3))
    assert (row["samples"], row["unsolved"], row["max_abs_error"]) == (3, 1, 4 * EPS)
    assert row["ns_per_sample"] == pytest.approx(1000) and "1 of 3 samples unsolved" in row["note"]
    nothing = _numeric_row("uniform", np.array([0.1]), np.array([[np.nan]]), 1e-6, truth[:, :1], np.ones(1))
    assert nothing["unsolved"] == 1 and nothing["max_rel_error"] == float("inf")


def test_compiled_rows_have_the_stabilised_errors(rows):
    by = {(r["strategy"], r["case"]): r for r in rows}
    compiled = [case for strategy, case in by if strategy == "compiled"]
    assert set(compiled) == {case for strategy, case in by if strategy == "stabilised"}
    for case in compiled:
        assert by["compiled", case]["max_rel_error"] <= by["stabilised", case]["max_rel_error"] + 4 * EPS, case


def test_without_numba_the_compiled_row_says_it_is_numpy(monkeypatch):
    import sys

    monkeypatch.setitem(sys.modules, "numba", None)
    rows = accuracy("chebyshev-lambda", samples=10, seed=2).rows
    by = {(r["strategy"], r["case"]): r for r in rows}
    assert "numba is not installed" in by["compiled", "uniform"]["note"]
    assert by["compiled", "uniform"]["max_rel_error"] == by["stabilised", "uniform"]["max_rel_error"]


@pytest.mark.parametrize("scene, of, said", [
    ("chebyshev-lambda", "O", "of='O': does not move with the input"),  # a fixed point: no input at all
    ("chebyshev-lambda", "dist(D, O)", "of='dist(D, O)': does not move with the input"),  # of two fixed points
    ("chebyshev-lambda", "dist(A, A)", "of='dist(A, A)': dist(A, A) is always 0"),  # refused as the scene's outputs are
    ("five-bar", None, "of='P': moves with 2 inputs (t1, t2)"),
])
def test_an_output_that_does_not_move_with_one_input_is_refused(scene, of, said):
    # once a traceback (no input to unpack, or two), or numpy's warnings on stderr and rows of NaN
    with pytest.raises(UsageError) as caught:
        accuracy(scene, samples=10, of=of)
    assert str(caught.value).startswith(said)


def test_a_scene_naming_a_mode_by_a_configuration_is_measured_far_away_too():
    # hart-inversor names C's mode by where C is at angle 0: the far case moves that place with the scene
    # (before: refused as bad input, C's named place 1.41e7 from the moved mechanism)
    far = [r for r in accuracy("hart-inversor", samples=10).rows if r["case"] == "far-1e7"]
    assert {r["strategy"] for r in far} >= {"closed-form", "stabilised", "reference"}
    assert max(r["max_rel_error"] for r in far if r["strategy"] == "stabilised") < 1e-12
