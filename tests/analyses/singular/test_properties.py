"""Curves built to cross at a chosen rational point: the crossing is found there, exactly.

Two curves through p0 with independent gradients there cross transversally: their product has
a node at p0 with two real tangents (a crunode). Three lines through p0 with distinct slopes
make an ordinary triple point with three real tangents.
"""

from fractions import Fraction

import sympy
from hypothesis import assume, given, settings, strategies as st

from algkin.analyses.singular import singular_points

x, y = sympy.symbols("x y")
rationals = st.fractions(min_value=-4, max_value=4, max_denominator=5)
small = st.integers(min_value=-3, max_value=3)


@st.composite
def conic_through(draw, x0, y0):
    """A conic (or line) through (x0, y0), with its gradient there."""
    a, b, c, d, e = (draw(small) for _ in range(5))
    form = a * x**2 + b * x * y + c * y**2 + d * x + e * y
    conic = form - form.subs({x: x0, y: y0})
    return conic, (2 * a * x0 + b * y0 + d, b * x0 + 2 * c * y0 + e)


@st.composite
def crossing(draw):
    x0, y0 = (sympy.Rational(draw(rationals)) for _ in range(2))
    first, (g1x, g1y) = draw(conic_through(x0, y0))
    second, (g2x, g2y) = draw(conic_through(x0, y0))
    assume(g1x * g2y - g1y * g2x != 0)  # transversal at p0 (both gradients nonzero and apart)
    assume(sympy.gcd(first, second).is_number)  # no common component: the product stays squarefree
    return x0, y0, sympy.expand(first * second)


@settings(max_examples=25)
@given(crossing())
def test_two_curves_crossing_at_a_point_make_a_crunode_there(case):
    x0, y0, curve = case
    found = {(p.x.exact, p.y.exact): p for p in singular_points(curve).points}
    assert (x0, y0) in found
    node = found[x0, y0]
    assert (node.kind, node.local["tangents"]) == ("crunode", {"distinct": 2, "real": 2})


@settings(max_examples=15)
@given(rationals, rationals, st.lists(rationals, min_size=3, max_size=3, unique=True))
def test_three_lines_through_a_point_make_a_triple_point(x0, y0, slopes):
    x0, y0 = Fraction(x0), Fraction(y0)
    curve = sympy.expand(sympy.Mul(*(y - y0 - sympy.Rational(k) * (x - x0) for k in slopes)))
    point, = singular_points(curve).points
    assert (point.x.exact, point.y.exact) == (sympy.Rational(x0), sympy.Rational(y0))
    assert (point.kind, point.local["tangents"]) == ("triple point", {"distinct": 3, "real": 3})
