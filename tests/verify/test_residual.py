"""A polynomial in balls at a point: the exact value (python-flint rationals) lies in the ball."""

import flint
import numpy as np
import sympy
from hypothesis import given, settings, strategies as st

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
        assert ball.contains(flint.arb(flint.fmpq(int(exact.p), int(exact.q))))
        assert ball.rad() <= 1e-50 * (1 + abs(float(exact)))


def test_the_magnitude_is_the_sum_of_the_terms_absolute_values():
    polynomial = Polynomial(CURVE, ["x", "y"], {"a": 2})
    points = {"x": np.array([1.0, -2.0]), "y": np.array([0.5, 1.0])}
    terms = sympy.expand(CURVE.subs(a, 2)).as_ordered_terms()
    expected = [sum(abs(float(t.subs({x: p, y: q}))) for t in terms) for p, q in zip(points["x"], points["y"])]
    assert np.allclose(polynomial.magnitude(points), expected)
