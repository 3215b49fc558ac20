"""algkin.verify.pencil: two circles' pencil, its coefficients those sympy's polynomials give, term for term."""

import sympy
from hypothesis import given, strategies as st

from algkin.system import symbol
from algkin.verify.pencil import MONOMIALS, Pencil

x, y, a, b = symbol("x"), symbol("y"), symbol("a"), symbol("b")
rationals = st.fractions(-9, 9, max_denominator=7).map(sympy.Rational)
coordinates = st.sampled_from([a, b, a - b, 2 * a + 1, sympy.Integer(0)]) | rationals


def _circle(centre, radius, scale):
    return sympy.expand(scale * ((x - centre[0]) ** 2 + (y - centre[1]) ** 2 - radius**2))


@given(st.tuples(coordinates, coordinates), st.tuples(coordinates, coordinates), coordinates, coordinates,
       rationals.filter(bool), rationals.filter(bool))
def test_a_pencils_coefficients_are_sympys(centre, other, r1, r2, k1, k2):
    first, second = _circle(centre, r1, k1), _circle(other, r2, k2)
    pencil = Pencil.of([first, second], [x, y], ["a", "b"])
    assert pencil is not None
    q1, q2 = (sympy.Poly(e, x, y).coeff_monomial(x**2) for e in (first, second))
    polys = sympy.Poly(first, x, y), sympy.Poly(q2 * first - q1 * second, x, y)
    expected = ([polys[0].coeff_monomial(x**i * y**j) for i, j in MONOMIALS],
                [polys[1].coeff_monomial(x**i * y**j) for i, j in MONOMIALS[3:]])
    written = pencil.first.source[0], pencil.line.source[0]  # type: ignore[attr-defined]
    for got, want in zip(written, expected):
        assert list(got) == want and [str(g) for g in got] == [str(w) for w in want]


def test_a_circle_and_a_parabola_are_no_pencil():
    assert Pencil.of([x**2 + y**2 - 4, y - x**2], [x, y], []) is None
    assert Pencil.of([x**2 + y**2 - a, a * x**2 + a * y**2 - 1], [x, y], ["a"]) is None  # not numbers
