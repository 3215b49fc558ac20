"""Extrema of angle outputs against the textbook.

A four-bar with crank a, ground d, coupler l and rocker m has the transmission angle mu (at B,
between the coupler BA and the rocker BD) with, by the law of cosines in the triangles ABD and
AOD, ``cos(mu) = (l**2 + m**2 - a**2 - d**2 + 2*a*d*cos(theta)) / (2*l*m)``; where the crank
turns fully its extremes are at theta = 0 and 180 degrees, ``(l**2 + m**2 - (d -+ a)**2)/(2*l*m)``.
The expected numbers are worked out here from that formula alone (fractions, mpmath).
"""

from fractions import Fraction

import mpmath
import pytest
import sympy
from hypothesis import HealthCheck, given, settings

from algkin.analyses.extremum import extremum
from algkin.errors import UsageError
from algkin.testing import strategies



@pytest.fixture(autouse=True)
def digits():
    """Expected values worked out at 40 digits, as the critical points are (no global change)."""
    with mpmath.workdps(40):
        yield


def textbook_cos(a, d, l, m, cos_theta):
    return (l**2 + m**2 - a**2 - d**2 + 2 * a * d * cos_theta) / (2 * l * m)


def degrees(cos_mu):
    return mpmath.degrees(mpmath.acos(mpmath.mpf(cos_mu.numerator) / cos_mu.denominator))


def dims(a, d, l, m):
    return {k: str(Fraction(v)) for k, v in dict(a=a, d=d, l=l, m=m).items()}


def close(value, expected, tol=mpmath.mpf(10) ** -25):
    return abs(mpmath.mpf(value) - expected) <= tol * (1 + abs(expected))


# s + w <= u + v with the crank (a) the shortest: a crank-rocker; with the ground (d) the
# shortest: a double-crank (drag link). Both turn fully: extremes at theta = 0 and 180.
TURNING = {
    "crank-rocker": (Fraction(2), Fraction(7), Fraction(6), Fraction(5)),        # 2 + 7 <= 6 + 5
    "crank-rocker (catalog defaults)": (Fraction(1), Fraction(4), Fraction(3), Fraction(7, 2)),
    "double-crank": (Fraction(5), Fraction(2), Fraction(6), Fraction(4)),        # 2 + 6 <= 5 + 4
}


@pytest.mark.parametrize("name", list(TURNING))
def test_transmission_angle_extremes_of_turning_four_bars_are_the_textbook_ones(name):
    a, d, l, m = TURNING[name]
    found = extremum("fourbar", "angle(A, B, D)", set=dims(a, d, l, m))
    least, most = textbook_cos(a, d, l, m, 1), textbook_cos(a, d, l, m, -1)  # cos is largest at theta = 0
    assert close(found.minimum.value, degrees(least)), (found.minimum, degrees(least))
    assert close(found.maximum.value, degrees(most)), (found.maximum, degrees(most))
    assert float(found.minimum.input_deg) % 360 == 0 and float(found.maximum.input_deg) == 180
    # exact algebraic numbers: the cosines themselves, and the angles as acos of them
    assert sympy.Rational(found.exact["minimum"][1]) == sympy.Rational(least.numerator, least.denominator)
    assert sympy.Rational(found.exact["maximum"][1]) == sympy.Rational(most.numerator, most.denominator)
    document = found.to_json()
    assert sympy.parse_expr(document["minimum"]["exact"]) == \
        180 * sympy.acos(sympy.Rational(least.numerator, least.denominator)) / sympy.pi
    assert document["angle"]["via"] == "cos_angle_A_B_D" and document["angle"]["unit"] == "deg"


def test_transmission_angle_of_a_triple_rocker_reaches_180_at_its_dead_centres():
    # Non-Grashof (2 + 4 > 3 + 5/2): no link turns fully. The input assembles while
    # |AD| <= l + m, i.e. cos(theta) >= (a**2 + d**2 - (l + m)**2) / (2*a*d) = 19/96; there A, B
    # and D are in line, B between them: mu = 180. Inside, cos(mu) grows with cos(theta): the
    # least mu is at theta = 0, where it still assembles (|d - a| = 1 >= |l - m|).
    a, d, l, m = Fraction(3), Fraction(4), Fraction(2), Fraction(5, 2)
    found = extremum("fourbar", "angle(A, B, D)", set=dims(a, d, l, m))
    assert close(found.minimum.value, degrees(textbook_cos(a, d, l, m, 1)))
    assert float(found.minimum.input_deg) % 360 == 0
    dead = (a**2 + d**2 - (l + m) ** 2) / (2 * a * d)
    assert dead == Fraction(19, 96)
    assert found.maximum.kind == "dead centre"
    assert close(found.maximum.value, mpmath.mpf(180), mpmath.mpf(10) ** -12)
    assert close(mpmath.cos(mpmath.radians(found.maximum.input_deg)), mpmath.mpf(19) / 96)
    assert sympy.Rational(found.exact["maximum"][1]) == -1
    assert all(p.value != p.value for p in found.critical_points if abs(p.input_deg - 180) < 1)  # no assembly


def test_minimum_transmission_angle_in_a_symbolic_crank_is_the_textbook_formula():
    a = sympy.Symbol("a", real=True)
    l, m, d = 3, sympy.Rational(7, 2), 4
    found = extremum("fourbar", "angle(A, B, D)", params=["a"])
    expected = 180 * sympy.acos((l**2 + m**2 - (d - a) ** 2) / (2 * l * m)) / sympy.pi
    assert sympy.simplify(found.closed_form.value - expected) == 0
    assert found.closed_form.input == 0
    greatest = extremum("fourbar", "angle(A, B, D)", params=["a"], largest=True).closed_form
    assert sympy.simplify(greatest.value - 180 * sympy.acos((l**2 + m**2 - (d + a) ** 2) / (2 * l * m)) / sympy.pi) == 0


@settings(max_examples=6, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(strategies.four_bars("crank-rocker") | strategies.four_bars("double-crank"))
def test_transmission_angle_extremes_hold_for_random_turning_four_bars(scene):
    # Any origin, any ground direction: the extremes are where A is on the line OD.
    a, g, l, m = (Fraction(str(scene.parameters[n])) for n in "aglm")
    found = extremum(scene, "angle(A, B, D)")
    assert close(found.minimum.value, degrees(textbook_cos(a, g, l, m, 1)), mpmath.mpf(10) ** -20)
    assert close(found.maximum.value, degrees(textbook_cos(a, g, l, m, -1)), mpmath.mpf(10) ** -20)


def test_rocker_swings_between_its_limit_positions():
    # The crank-rocker's rocker angle (direction D -> B) is extreme where crank and coupler are in
    # line: |OB| = l + a (extended) or l - a (folded). In the triangle O D B, the angle at D has
    # cos = (d**2 + m**2 - |OB|**2) / (2*d*m), and B is above the ground: phi = 180 - that angle.
    a, d, l, m = 1, 4, 3, mpmath.mpf(7) / 2
    at_d = lambda ob: mpmath.degrees(mpmath.acos((d**2 + m**2 - ob**2) / (2 * d * m)))  # noqa: E731
    found = extremum("fourbar", "angle(D, B)")
    assert close(found.minimum.value, 180 - at_d(l + a))
    assert close(found.maximum.value, 180 - at_d(l - a))
    assert found.problem.scale.quarter_turns is not None
    swing = found.maximum.value - found.minimum.value
    assert 34 < swing < 34.1
    exact = sympy.N(sympy.parse_expr(found.to_json()["minimum"]["exact"]), 30)
    assert close(exact, 180 - at_d(l + a), mpmath.mpf(10) ** -25)


def test_coupler_angle_extremes_are_stationary_and_consistent():
    found = extremum("fourbar", "angle(A, B)")
    values = [p.value for p in found.critical_points if p.value == p.value]
    assert found.minimum.value == min(values) and found.maximum.value == max(values)
    assert found.minimum.kind == "minimum" and found.maximum.kind == "maximum"


def test_a_direction_that_turns_full_circle_has_no_extremum():
    with pytest.raises(UsageError, match="full circle"):
        extremum("fourbar", "angle(O, A)")
    # over a narrower range it has: the crank's own angle
    found = extremum("fourbar", "angle(O, A)", (10, 100))
    assert close(found.minimum.value, mpmath.mpf(10), mpmath.mpf(10) ** -20)
    assert close(found.maximum.value, mpmath.mpf(100), mpmath.mpf(10) ** -20)
