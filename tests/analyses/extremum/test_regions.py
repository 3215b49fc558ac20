"""Regions of one symbolic dimension: a length's only where it is positive (a mechanism has no crank
of length -1), a coordinate's over every real value; a dead centre's value with its square root
written once. Against the catalog four-bar's geometry by hand: O = (0, 0), D = (d, 0) = (4, 0),
A = a (cos, sin), |AB| = l = 3, |DB| = m = 7/2."""

import mpmath
import pytest
import sympy

from algkin.analyses.extremum import extremum

DIGITS = 50
D, L, M = mpmath.mpf(4), mpmath.mpf(3), mpmath.mpf(7) / 2


@pytest.fixture(scope="module")
def crank():
    """B.y's minimum with the crank a symbolic (about 5 s)."""
    return extremum("fourbar", "B.y", params=["a"]).closed_form


def dead_centre_height(a, reach):
    """B.y where A, B and D line up with |DA| = ``reach``, the crank below the ground: by the cosine
    rule cos = (a**2 + d**2 - reach**2) / (2 a d); B = A + l (D - A)/|DA| when reach = l + m (B
    between), B = A + l (A - D)/|DA| when reach = m - l (A between): B.y = A.y * m / reach either way.
    None where the crank cannot reach it."""
    with mpmath.workdps(DIGITS):
        cos = (a**2 + D**2 - reach**2) / (2 * a * D)
        return None if abs(cos) > 1 else -a * mpmath.sqrt(1 - cos**2) * M / reach


def lowest_dead_centre(a):
    heights = [h for h in (dead_centre_height(a, L + M), dead_centre_height(a, M - L)) if h is not None]
    return min(heights)


def test_a_cranks_regions_start_at_zero_and_cut_where_by_hand(crank):
    # the crank-rocker while a + d <= l + m (Grashof): a = 5/2; then the lower dead centre is the
    # stretched one (|DA| = l + m) until the folded one (|DA| = m - l) is as low: with x = a**2,
    # (64x - (x - 105/4)**2) / 169 = 64x - (x + 63/4)**2, at x = 51/4
    regions = crank.to_json()["regions"]
    assert [r["from"] for r in regions][:3] == [0, 2.5, pytest.approx(float(mpmath.sqrt(51) / 2), abs=1e-12)]
    assert all(r["from"] is not None and r["from"] >= 0 for r in regions)
    with mpmath.workdps(DIGITS):
        at_cut = mpmath.sqrt(51) / 2
        assert abs(dead_centre_height(at_cut, L + M) - dead_centre_height(at_cut, M - L)) < 1e-45
    assert crank.valid_when_text == ("0 < a < 2.5",)


def test_a_rocker_holds_over_the_grashof_crank_rocker_range_alone():
    # a + d <= l + m: m >= 2; a + m <= d + l (m the longest): m <= 6. A rocker of -4 is no rocker.
    closed = extremum("fourbar", "B.y", params=["m"]).closed_form
    assert closed.valid_when_text == ("2 < m < 6",)
    assert closed.regions[0]["from"] == 0


def test_a_coordinate_keeps_every_real_value():
    # the slider's line y = e: any real e is a mechanism (out of reach past |e| = r + l = 4)
    regions = extremum("slider-crank", "x", params=["e"]).closed_form.regions
    assert regions[0]["from"] is None and (regions[0]["to"], regions[0]["at"]) == (pytest.approx(-4), "nowhere")
    assert any(r["at"] == "stationary" and r["from"] is not None and r["from"] < -1 for r in regions)


@pytest.mark.parametrize("a_value", ["13/5", "3", "7/2", "18/5", "19/5", "4"])
def test_a_dead_centres_value_has_one_root_and_is_the_lowest_dead_centre(crank, a_value):
    a = sympy.Rational(a_value)
    region, value = next((r, v) for r, v in zip(crank.regions, crank.region_values)
                         if r["from"] < a and (r["to"] is None or a < r["to"]))
    assert region["at"] == "dead centre"
    assert str(value).count("sqrt") == 1, value
    (symbol,) = value.free_symbols
    with mpmath.workdps(DIGITS):
        hand = lowest_dead_centre(mpmath.mpf(a.p) / a.q)
        assert abs(mpmath.mpf(str(sympy.N(value.xreplace({symbol: a}), DIGITS))) - hand) < mpmath.mpf(10) ** -45
