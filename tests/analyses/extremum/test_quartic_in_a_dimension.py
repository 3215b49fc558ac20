"""A stationary input that is a root of a quartic whose coefficients hold a dimension: its radicals
(Ferrari's, 124,000 characters a root, then minutes of denesting) are not written; the extremum's
value still is, region by region. The four-bar's distance from O to its coupler point with the
crank a symbolic ran past four minutes before."""

import pytest
import sympy

import algkin


@pytest.mark.slow  # about 15 s: the closed form's regions in a
def test_the_four_bars_closest_coupler_point_in_a_is_where_o_a_and_p_line_up():
    found = algkin.extremum("fourbar", "dist(P, O)", params=["a"])
    closed = found.closed_form
    a = next(iter(closed.value.free_symbols))
    # P = A + (B - A)/2 + rot90(B - A)/2 with |AB| = 3: |PA| = 3 sqrt(2)/2, so at its closest to O
    # (O, A and P in line, A between) |PO| = 3 sqrt(2)/2 - a, while the crank is the shorter
    assert str(a) == "a" and sympy.simplify(closed.value - (3 * sympy.sqrt(2) / 2 - a)) == 0
    assert closed.input is None and closed.at == "stationary"  # the input: a root of its quartic in t
    assert sympy.degree(closed.input_polynomial, sympy.Symbol("t_theta", real=True)) == 4
    (here,) = [r for r in closed.regions if (r["from"] is None or r["from"] <= 1)
               and (r["to"] is None or 1 < r["to"])]
    assert (here["from"], here["to"]) == (0, pytest.approx(3 / 2**0.5))  # till the crank reaches |PA|
    assert found.minimum.value == pytest.approx(3 / 2**0.5 - 1)  # at a = 1, certified numerically
