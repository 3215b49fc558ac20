"""Speed against error: the stabilised form is as accurate as the problem allows, on hard cases too."""

from fractions import Fraction

import mpmath
import numpy as np
import pytest
from hypothesis import assume, given, settings, strategies as st

from algkin.accuracy import accuracy
from algkin.branches.stable import heron_area

from .test_toggles import four_bar

EPS = 2.0**-53


@pytest.fixture(scope="module")
def rows():
    return accuracy(four_bar(3, 4, 2, "5/2"), samples=400, seed=1).rows


def test_every_case_of_the_spec_is_measured(rows):
    cases = {r["case"] for r in rows}
    assert {"uniform", "toggle-1e-06", "toggle-1e-10", "toggle-1e-14", "far-1e7"} <= cases
    assert {r["strategy"] for r in rows} == {"closed-form", "stabilised", "numeric", "reference"}


def test_stabilised_is_within_ten_kappa_eps_everywhere(rows):
    for row in rows:
        if row["strategy"] == "stabilised":
            assert row["max_rel_error"] <= 10 * row["condition"] * EPS, row


def test_ill_conditioning_near_toggles_is_reported(rows):
    # The half-chord is a square root of the distance to the toggle: kappa ~ 1/sqrt(offset)... at
    # least 1e5 times worse 1e-14 away than 1e-6 away is what sqrt scaling gives (1e4) and more.
    kappa = {r["case"]: r["condition"] for r in rows if r["strategy"] == "stabilised"}
    assert kappa["toggle-1e-14"] > 1e3 * kappa["toggle-1e-06"] > 1e3 * kappa["uniform"] / 100


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
