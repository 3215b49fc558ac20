"""The half-angle form with symbols besides the angle's (a dimension, an output), by hand."""

import sympy

from algkin.system.angles import Parametrisation, half_angle_numerator, off_the_circle

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


def test_the_derivative_along_the_angle_by_hand():
    # d/dtheta of a c**2 s + u s = -s (2 a c s) + c (a c**2 + u)
    angle = Parametrisation((c, s), t)
    assert angle.derivative(a * c**2 * s + u * s) == sympy.expand(-2 * a * c * s**2 + a * c**3 + u * c)
    assert Parametrisation((t,), t).derivative(a * t**3 + u) == 3 * a * t**2


def test_off_the_circle_divides_as_often_as_it_divides():
    assert off_the_circle(sympy.expand((1 + t**2)**2 * (t - a)), t) == t - a
    assert off_the_circle(t**2 + a, t) == t**2 + a
