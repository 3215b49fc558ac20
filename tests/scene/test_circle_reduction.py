"""reduce_exact_on_circles and reduce_on_circles: python-flint's reduction on the inputs' circles, the same
as sympy's remainder."""

import flint
import sympy
from hypothesis import given, settings, strategies as st

from algkin.scene.implicit import algebra
from algkin.scene.implicit.algebra import _reduced_in_sympy, reduce_exact_on_circles, reduce_on_circles
from algkin.system import symbol
from algkin.system.convert import to_sympy

RING = flint.fmpq_mpoly_ctx.get(("c_a", "s_a", "c_b", "s_b", "x"), "lex")
CIRCLES = [(symbol("c_a"), symbol("s_a")), (symbol("c_b"), symbol("s_b"))]  # the symbols to_sympy gives


def test_by_hand():
    # s**4 = (1 - c**2)**2 and s**3 = s (1 - c**2) where c**2 + s**2 = 1
    ca, sa, _, _, x = RING.gens()
    reduced = reduce_exact_on_circles(sa**4 + 3 * sa**3 * x - flint.fmpq(1, 2), CIRCLES)
    assert reduced == (1 - ca**2) ** 2 + 3 * sa * (1 - ca**2) * x - flint.fmpq(1, 2)


def test_as_sympys_remainder_on_two_circles():
    ca, sa, cb, sb, x = RING.gens()
    poly = (sa**3 * cb - 2 * sb**2 * x + flint.fmpq(3, 7) * ca * sa**2) ** 3 + sb**5 * sa**4 - 11
    expected = reduce_on_circles(to_sympy(poly, RING), CIRCLES)
    assert to_sympy(reduce_exact_on_circles(poly, CIRCLES), RING) == expected


def test_a_sine_without_its_cosine_is_left_to_sympy():
    ring = flint.fmpq_mpoly_ctx.get(("s_a", "x"), "lex")
    s, x = ring.gens()
    assert reduce_exact_on_circles(s**2 + x, CIRCLES) is None
    x = flint.fmpq_mpoly_ctx.get(("c_a", "x"), "lex").gens()[1]
    assert reduce_exact_on_circles(x**2, CIRCLES) == x**2  # no sine: nothing to reduce


_TERMS = st.sampled_from([*(v for circle in CIRCLES for v in circle), symbol("x"), sympy.Symbol("y"),
                          sympy.Dummy("root")])  # a closed form's stand-in for a root (str: _root)


@st.composite
def _unexpanded(draw, depth=3):
    """A sympy expression as closed forms hold one: sums and products of powers, unexpanded."""
    if depth == 0 or draw(st.booleans()):
        return draw(_TERMS) if draw(st.booleans()) else sympy.Rational(draw(st.integers(-9, 9)), draw(st.integers(1, 5)))
    parts = draw(st.lists(_unexpanded(depth - 1), min_size=2, max_size=3))
    combined = sympy.Add(*parts) if draw(st.booleans()) else sympy.Mul(*parts)
    return combined ** draw(st.integers(1, 2))


@settings(max_examples=150, deadline=None)
@given(_unexpanded(), st.sampled_from([sympy.Integer(1), sympy.sqrt(2), 1 / symbol("x"), sympy.sqrt(symbol("c_a"))]))
def test_in_flint_the_very_expression_sympys_remainder_gives(polynomial, times):
    # the other factor makes some draws no polynomial (a root, a quotient), left to sympy as before
    expr = polynomial * times
    assert reduce_on_circles(expr, CIRCLES) == _reduced_in_sympy(expr, CIRCLES)


def test_two_symbols_of_one_name_are_left_to_sympy():
    for one, other in [(sympy.Symbol("x"), symbol("x")), (sympy.Dummy("x"), symbol("x"))]:
        assert one != other
        expr = (one + other + CIRCLES[0][1]) ** 2
        assert reduce_on_circles(expr, CIRCLES) == _reduced_in_sympy(expr, CIRCLES)


def test_a_root_goes_to_sympy_without_python_flint_reading_the_rest(monkeypatch):
    # a later dyad's closed form holds an earlier one's root: python-flint would refuse it only after
    # evaluating everything else (tens of milliseconds on a six-bar)
    def unexpected(expr, ring):
        raise AssertionError(f"python-flint asked to read {expr}")

    monkeypatch.setattr(algebra, "to_flint", unexpected)
    c, s = CIRCLES[0]
    expr = (s * sympy.sqrt(5 - 4 * c) + c) ** 2 / (8 * c - 17)
    assert reduce_on_circles(expr, CIRCLES) == sympy.expand(expr)


_MONOMIAL_SUMS = [5 - 4 * CIRCLES[0][0], 128 * CIRCLES[0][0] - 272, CIRCLES[0][0] * symbol("x") + CIRCLES[0][1] / 3 - 1,
                  16384 * CIRCLES[0][0] ** 2 - 69632 * CIRCLES[0][0] + 73984]


@st.composite
def _shifted_closed_form(draw):
    """A later dyad's coordinate as reduce_on_circles meets it: terms with roots and reciprocals of sums,
    expanded by sympy or not, then maybe negated and shifted by a number."""
    terms = []
    for _ in range(draw(st.integers(1, 5))):
        factors = draw(st.lists(st.sampled_from([*(v for circle in CIRCLES for v in circle), symbol("x")]), max_size=3))
        factors += [sympy.sqrt(b) for b in draw(st.lists(st.sampled_from(_MONOMIAL_SUMS), max_size=2))]
        factors += [1 / b for b in draw(st.lists(st.sampled_from(_MONOMIAL_SUMS), max_size=2))]
        k = sympy.Rational(draw(st.integers(-40, 40)), draw(st.sampled_from([1, 1, 2, 3])))
        terms.append(sympy.Mul(k, *factors))
    total = sympy.Add(*terms)
    total = sympy.expand(total) if draw(st.booleans()) else total
    return draw(st.sampled_from([1, -1])) * total + sympy.Rational(draw(st.integers(-9, 9)), draw(st.integers(1, 4)))


@settings(max_examples=200, deadline=None)
@given(_shifted_closed_form())
def test_what_is_expanded_already_is_given_back_as_sympy_would(expr):
    assert reduce_on_circles(expr, CIRCLES) == _reduced_in_sympy(expr, CIRCLES)
    if algebra._expanded_already(expr):
        assert sympy.expand(expr) == expr


_SQUARE_RING = flint.fmpq_mpoly_ctx.get(("u", "r", "w"), "lex")
_EXPONENTS = st.tuples(st.integers(0, 3), st.integers(0, 5), st.integers(0, 3))
_POLYNOMIALS = st.dictionaries(_EXPONENTS, st.fractions(max_denominator=9).filter(bool), max_size=12)


@settings(max_examples=100, deadline=None)
@given(_POLYNOMIALS, _POLYNOMIALS.map(lambda terms: {(u, 0, w): c for (u, _, w), c in terms.items()}))
def test_square_reduced_is_sympys_remainder_by_the_square(terms, square_terms):
    # r**2 taken as a radicand free of r: the remainder of the division by r**2 - radicand, as sympy gives it
    poly, square = (_SQUARE_RING.from_dict({e: flint.fmpq(c.numerator, c.denominator) for e, c in t.items()})
                    for t in (terms, square_terms))
    r = to_sympy(_SQUARE_RING.gens()[1], _SQUARE_RING)
    expected = sympy.rem(to_sympy(poly, _SQUARE_RING), r**2 - to_sympy(square, _SQUARE_RING), r)
    assert sympy.expand(to_sympy(algebra.square_reduced(poly, 1, square), _SQUARE_RING) - expected) == 0
