"""The half-angle form with symbols besides the angle's (a dimension, an output), by hand."""

import pytest
import sympy

from algkin.system.angles import half_angle_degree, half_angle_numerator

c, s, t, a, u = sympy.symbols("c s t a u")


def test_a_parameter_rides_along_the_half_angle_numerator():
    # a c + s = (a (1 - t**2) + 2 t) / (1 + t**2)
    assert half_angle_numerator(a * c + s, c, s, t) == -a * t**2 + 2 * t + a


def test_lower_degree_terms_take_the_circle_to_the_full_degree():
    # c**2 + a u: degree 2, so a u takes (1 + t**2)**2
    assert half_angle_numerator(c**2 + a * u, c, s, t) == sympy.expand((1 - t**2)**2 + a * u * (1 + t**2)**2)


def test_denominators_are_cleared():
    # c/2 + s/3 = ((1 - t**2)/2 + 2t/3) / (1 + t**2): times 6
    assert half_angle_numerator(c / 2 + s / 3 + 0 * a, c, s, t) == -3 * t**2 + 4 * t + 3
    assert half_angle_numerator(a * c / 2, c, s, t) == a - a * t**2


@pytest.mark.parametrize("degrees", [0, 1, 5, 10, 12, 30, 45, 60, 72, 80, 90, 91, 120, 135, 200, "15/2", "45/4"])
def test_half_angle_degree_is_the_minimal_polynomials(degrees):
    angle = sympy.Rational(degrees)
    minimal = sympy.degree(sympy.minimal_polynomial(sympy.tan(sympy.pi * angle / 360), t), t)
    assert half_angle_degree(angle, limit=48) == minimal
    assert half_angle_degree(angle, limit=minimal - 1) is None
