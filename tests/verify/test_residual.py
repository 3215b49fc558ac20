"""A polynomial in balls at a point: the exact value (python-flint rationals) lies in the ball."""

from fractions import Fraction

import flint
import numpy as np
import pytest
import sympy
from hypothesis import example, given, settings, strategies as st

from algkin.verify.residual import Polynomial

x, y, a = sympy.symbols("x y a", real=True)
CURVE = (x**2 + y**2) ** 3 - 4 * a * x**2 * y**3 + sympy.Rational(7, 3) * x * y - a**2


@settings(max_examples=40, deadline=None)
@given(st.fractions(-3, 3, max_denominator=50), st.fractions(-3, 3, max_denominator=50),
       st.fractions(1, 4, max_denominator=20))
def test_balls_hold_the_exact_value(p, q, dimension):
    polynomial = Polynomial(CURVE, ["x", "y"], {"a": dimension})
    exact = CURVE.subs({x: sympy.Rational(p), y: sympy.Rational(q), a: sympy.Rational(dimension)})
    with flint.ctx.workprec(200):
        ball = polynomial.balls({"x": flint.arb(flint.fmpq(p.numerator, p.denominator)),
                                 "y": flint.arb(flint.fmpq(q.numerator, q.denominator))})
        scaled = flint.fmpq(int(exact.p), int(exact.q)) / polynomial.scale  # balls are of p / scale
        assert holds(ball, scaled)
        assert ball.rad() <= 1e-50 * (1 + abs(float(scaled)))


def holds(ball, value):
    """Whether the exact rational ``value`` lies in ``ball``: ``ball - value`` (an enclosure of the
    difference) holds 0. Not ``ball.contains(arb(value))``: a rational of no finite binary expansion
    is rounded to a ball of its own, which may be wider than ``ball`` that holds it."""
    return (ball - value).contains(0)


def test_the_magnitude_is_the_sum_of_the_terms_absolute_values():
    polynomial = Polynomial(CURVE, ["x", "y"], {"a": 2})
    points = {"x": np.array([1.0, -2.0]), "y": np.array([0.5, 1.0])}
    terms = sympy.expand(CURVE.subs(a, 2)).as_ordered_terms()
    expected = [sum(abs(float(t.subs({x: p, y: q}))) for t in terms) for p, q in zip(points["x"], points["y"])]
    assert np.allclose(polynomial.magnitude(points) * float(polynomial.scale), expected)


def test_the_scale_is_a_power_of_two_within_a_factor_two_of_the_largest_coefficient():
    polynomial = Polynomial(CURVE, ["x", "y"], {"a": 2})  # coefficients 1, 3, 3, 1, -8, 7/3, -4: the largest 8
    assert polynomial.scale in (4, 8, 16)


def test_coefficients_past_a_float_give_finite_residuals():
    """The curve times 10**400 (what a dimension of 90-digit numerator and denominator makes of a
    primitive curve): its floats overflowed; scaled, its residual |p| / sum |terms| is the curve's."""
    big = Polynomial(sympy.Integer(10) ** 400 * CURVE, ["x", "y"], {"a": 2})
    points = {"x": np.array([0.5]), "y": np.array([1.25])}
    with flint.ctx.workprec(200):
        value = big.balls({"x": flint.arb(0.5), "y": flint.arb(1.25)})
    ratio = float(abs(value).mid()) / float(big.magnitude(points)[0])
    at = {x: sympy.Rational(1, 2), y: sympy.Rational(5, 4), a: 2}
    terms = sympy.expand(CURVE.subs(a, 2)).as_ordered_terms()
    assert ratio == pytest.approx(abs(float(CURVE.subs(at))) / sum(abs(float(t.subs(at))) for t in terms), rel=1e-12)


z, w = sympy.symbols("z w", real=True)
# a table per monomial of the rest: z and w past the two variables of highest degree (x, y)
FOUR = CURVE * (z**2 - 3 * w) + x**5 * z * w**2 - sympy.Rational(5, 7) * y**4 * z**3 + 11 * w - 2
SHAPES = {"four variables": (FOUR, ["x", "y", "z", "w"]), "three": (FOUR.subs(w, 1), ["x", "y", "z"]),
          "one": (CURVE.subs(y, 2), ["x"]), "none": (CURVE.subs({x: 1, y: 2}), [])}


@pytest.mark.parametrize("shape", SHAPES)
@settings(max_examples=25, deadline=None)
@given(point=st.lists(st.fractions(-3, 3, max_denominator=50), min_size=4, max_size=4),
       dimension=st.fractions(1, 4, max_denominator=20))
# x = 3/7 on CURVE(y = 2) at a = 1: the value's ball is narrower than the exact value rounded to a ball
@example(point=[Fraction(3, 7), Fraction(0), Fraction(0), Fraction(0)], dimension=Fraction(1))
def test_balls_in_any_number_of_variables_hold_the_exact_value(shape, point, dimension):
    expr, names = SHAPES[shape]
    polynomial = Polynomial(expr, names, {"a": dimension})
    values = dict(zip(names, point))
    exact = expr.subs({**{sympy.Symbol(n, real=True): sympy.Rational(v) for n, v in values.items()},
                       a: sympy.Rational(dimension)})
    with flint.ctx.workprec(200):
        # balls of radius 1e-60 about the point: the exact value lies in the result
        ball = polynomial.balls({n: flint.arb(flint.fmpq(v.numerator, v.denominator), 1e-60) for n, v in values.items()})
        scaled = flint.fmpq(int(exact.p), int(exact.q)) / polynomial.scale
        assert holds(ball, scaled)
        assert ball.rad() <= 1e-40 * (1 + abs(float(scaled)))


@pytest.mark.parametrize("shape", SHAPES)
def test_the_magnitude_in_any_number_of_variables_is_the_sum_of_the_terms_absolute_values(shape):
    expr, names = SHAPES[shape]
    polynomial = Polynomial(expr, names, {"a": 2})
    points = {n: np.array([1.5, -0.25, 2.0])[: 3] * (k + 1) for k, n in enumerate(names)}
    terms = sympy.expand(expr.subs(a, 2)).as_ordered_terms()
    expected = [sum(abs(float(t.subs({sympy.Symbol(n, real=True): points[n][i] for n in names}))) for t in terms)
                for i in range(3)]
    assert np.allclose(np.broadcast_to(polynomial.magnitude(points), (3,)) * float(polynomial.scale), expected)
