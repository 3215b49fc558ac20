"""tidy_ratio's cancellation in python-flint (``cancelled``): the very expression sympy's ``cancel`` path gives,
or None (sympy's path then)."""

import pytest
import sympy
from hypothesis import given, settings, strategies as st

from algkin.branches.algebra import _tidy_ratio_in_sympy, tidy_ratio
from algkin.branches.ratio import cancelled
from algkin.system import symbol

C, S, X = symbol("c_a"), symbol("s_a"), symbol("x")
SYMBOLS = [C, S, X, symbol("c_b"), sympy.Symbol("y", positive=True)]


def test_a_later_dyads_ratio_in_flint():
    # the shape of a six-bar's second dyad: an earlier closed form's root in the numerators of
    # terms over polynomials (sympy.expand's output), the whole over such a sum
    root = sympy.sqrt(-1024 * C**2 - 1088 * C + 6767)
    dist2 = sympy.expand(C**2 + (S * root + 3 * C - 1) ** 2 / (128 * C - 272) + 5 * S * root / (16 * (17 - 8 * C)))
    expr = (sympy.Rational(7, 4) + dist2) / (2 * dist2)
    assert cancelled(expr) is not None
    assert tidy_ratio(expr) == _tidy_ratio_in_sympy(expr)


def test_a_ratio_that_is_a_number_in_flint():
    # the lambda's dyad, of equal bars: (l1**2 - l2**2 + dist2) / (2 dist2) is 1/2 (by hand)
    for expr, value in [((5 - 4 * C) / (10 - 8 * C), sympy.Rational(1, 2)), ((4 * C - 5) / (30 - 24 * C), sympy.Rational(-1, 6))]:
        assert cancelled(expr) is not None
        assert tidy_ratio(expr) == _tidy_ratio_in_sympy(expr) == value


def test_what_the_argument_does_not_cover_is_left_to_sympy():
    root = sympy.sqrt(5 - 4 * C)
    assert cancelled(C / (S * root + 1) + 1) is None  # a root in a denominator of a sum's term
    assert cancelled(X / (root + 1) + 1 / (root - 1) + C) is None  # sympy's common denominator matters
    assert cancelled(X / sympy.sqrt(C + 1)) is None  # a root's inverse
    assert cancelled(sympy.sqrt(2) * X / (X + 1)) is None  # a number's root
    assert cancelled(sympy.sqrt(2 * C + 2) * X / (X + 1)) is None  # a radicand sympy's preparation rewrites
    assert cancelled(sympy.sqrt((C + 1) * (C - 2)) * X / (X + 1)) is None  # a radicand not expanded
    assert cancelled(sympy.Symbol("x", positive=True) / (X + 1)) is None  # two symbols of one name
    assert cancelled(X / (X + 1) - X / (X + 1)) is None  # zero
    assert cancelled((X**2 - 1) / (2 * X + 2)) is None  # a denominator that is no sum: sympy writes it


def _radicand(draw):
    """A polynomial radicand as closed forms hold them (expanded, or not: then left to sympy)."""
    terms = draw(st.lists(st.tuples(st.integers(-40, 40), st.sampled_from([1, C, S, C**2, C * S, X])), min_size=2, max_size=4))
    poly = sympy.Add(*[k * m for k, m in terms])
    return poly if draw(st.booleans()) or not poly.is_Add else sympy.factor(poly)


@st.composite
def _closed_form(draw, depth=2):
    """Sums, products and integer powers of symbols, rationals and square roots of polynomials."""
    if depth == 0 or draw(st.integers(0, 3)) == 0:
        kind = draw(st.integers(0, 3))
        if kind == 0:
            return sympy.Rational(draw(st.integers(-9, 9)), draw(st.integers(1, 6)))
        if kind == 1:
            return sympy.sqrt(_radicand(draw))
        return draw(st.sampled_from(SYMBOLS))
    parts = draw(st.lists(_closed_form(depth - 1), min_size=2, max_size=3))
    combined = sympy.Add(*parts) if draw(st.booleans()) else sympy.Mul(*parts)
    return combined ** draw(st.sampled_from([1, 1, 2, -1] if depth < 2 else [1, -1]))


ROOTS = [-1024 * C**2 - 1088 * C + 6767, 5 - 4 * C, C * X + S - 3, 2 * C + 2]  # the last: rewritten by sympy
ROOTED = [sympy.sqrt(5 - 4 * C) + 1, sympy.sqrt(5 - 4 * C) - 1]  # roots in a term's denominator: sympy's path


@st.composite
def _terms_over_polynomials(draw):
    """A sum as reduce_on_circles leaves a later dyad's coordinate: each term a number times a monomial,
    maybe a root, maybe over a polynomial (one with a root: sympy's path); maybe squared, unexpanded."""
    terms = []
    for _ in range(draw(st.integers(1, 4))):
        monomial = sympy.Mul(*draw(st.lists(st.sampled_from(SYMBOLS), max_size=2)))
        root = sympy.sqrt(draw(st.sampled_from(ROOTS))) if draw(st.booleans()) else 1
        over = draw(st.sampled_from([1, 1, 8 * C - 17, 128 * C - 272, X + 1, C**2 - 2 * X + 3, *ROOTED]))
        terms.append(sympy.Rational(draw(st.integers(-20, 20)), draw(st.integers(1, 4))) * monomial * root / over)
    total = sympy.Add(*terms)
    # squared only up to three terms: sympy's cancel of a squared four-term sum, expanded, took seconds a draw
    return total ** draw(st.sampled_from([1, 1, 2] if len(terms) < 4 else [1]))


@pytest.mark.slow  # about 15 s: sympy's cancel on each draw
@settings(max_examples=150, deadline=None)
@given(_terms_over_polynomials(), _terms_over_polynomials(), st.booleans(), st.booleans(), st.integers(-3, 3))
def test_the_very_expression_sympys_cancel_gives_on_closed_forms(top, bottom, expand_top, expand_bottom, shift):
    # the dyad's ratio (l1**2 - l2**2 + dist2) / (2 * dist2): top and bottom often share a sum
    top = sympy.expand(top) if expand_top else top
    bottom = sympy.expand(bottom) if expand_bottom else bottom
    if bottom == 0:
        return
    for expr in (top / bottom, (shift + bottom) / (2 * bottom)):
        assert tidy_ratio(expr) == _tidy_ratio_in_sympy(expr)


@settings(max_examples=150, deadline=None)
@given(_closed_form(), _closed_form(), st.booleans(), st.booleans())
def test_the_very_expression_sympys_cancel_gives(top, bottom, expand_top, expand_bottom):
    # expanded as reduce_on_circles leaves a closed form: terms over polynomials, roots in numerators
    top = sympy.expand(top) if expand_top else top
    bottom = sympy.expand(bottom) if expand_bottom else bottom
    if bottom == 0:
        return
    expr = top / bottom
    assert tidy_ratio(expr) == _tidy_ratio_in_sympy(expr)
