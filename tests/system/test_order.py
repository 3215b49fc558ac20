"""algkin.system.order: a PrintOrder orders a sum's terms and a product's factors, and keys expressions,
exactly as sympy's own methods do, for every expression of one document in turn (each order kept)."""

import pytest
import sympy
from hypothesis import given, settings, strategies as st
from sympy.core.exprtools import decompose_power
from sympy.core.sorting import default_sort_key

from algkin.system import order
from algkin.system.order import PrintOrder
from algkin.system.text import ExpressionText

from .closed_forms import CLOSED_FORMS, RATIONALS, c, l, s


def _subexpressions(expr):
    return [e for e in sympy.preorder_traversal(expr) if isinstance(e, sympy.Expr)]


def _ordered_as_sympy_orders_them(exprs):
    order = PrintOrder()  # one for all: a subexpression met again is taken from what is kept
    for expr in [*exprs, *exprs]:
        for sub in _subexpressions(expr):
            assert order.sort_key(sub) == default_sort_key(sub)
            if isinstance(sub, sympy.Add):
                assert order.terms(sub) == sub.as_ordered_terms()
            if isinstance(sub, sympy.Mul):
                assert order.factors(sub) == sub.as_ordered_factors()


@settings(max_examples=25, deadline=None)
@given(st.lists(CLOSED_FORMS, min_size=1, max_size=2))
def test_every_sum_product_and_key_of_closed_forms_is_sympys(exprs):
    _ordered_as_sympy_orders_them(exprs)


@pytest.mark.slow
@settings(max_examples=300, deadline=None)
@given(st.lists(CLOSED_FORMS, min_size=1, max_size=3))
def test_every_sum_product_and_key_of_many_closed_forms_is_sympys(exprs):
    _ordered_as_sympy_orders_them(exprs)


def test_terms_of_one_monomial_are_ordered_by_their_numbers_as_sympy_orders_them():
    # c*(1 + sqrt(2)) spread: both terms read c, so sympy's complex coefficients decide (1 before sqrt(2))
    for expr in (c + sympy.sqrt(2) * c, 3 * c - sympy.sqrt(2) * c, sympy.sqrt(3) * c * s - 2 * c * s + s):
        assert PrintOrder().terms(expr) == expr.as_ordered_terms()


def test_a_positive_number_and_a_negative_multiple_keep_sympys_order():
    # sympy writes 1 - c with its number first (a special case of its order)
    expr = 1 - c
    assert PrintOrder().terms(expr) == expr.as_ordered_terms() == [sympy.Integer(1), -c]


def test_a_negative_rational_in_front_of_a_product_is_split_as_sympy_splits_it():
    # sympy's args_cnc: -3/4*c*s as -1, 3/4, c, s; -c keeps its -1
    for expr in (-sympy.Rational(3, 4) * c * s, -c * s, 2 * c * s, -2 * sympy.sqrt(c + 1) * s):
        assert PrintOrder().factors(expr) == expr.as_ordered_factors()


# A root of a product of factors whose signs sympy cannot know: sympy keeps it whole, after asking each
# factor's sign (tens of milliseconds for a six-bar's root over roots); a PrintOrder shows them unknowable
# at rational points and asks nothing. Factors of both signs, and one positive or not real (a nested root).
UNKNOWABLE = [(c - 2) * (s + 1), (3 + sympy.sqrt(c) * (c - 1)) * (c + s - 1) / (2 * c - 3),
              (1 + sympy.sqrt(c)) * (c - s)]
# Factors sympy knows the sign of (a number's among them): it takes them out of the root; a PrintOrder
# lets sympy answer, and where a symbol is assumed more than real (l > 0)
KNOWABLE = [(c**2 + 1) * (c - 2), (c - 2) * (s + 1) * c**2, sympy.sqrt(3) * (c - 2) * (s + 1)]


def _root(radicand, exponent=sympy.S.Half):
    return sympy.Pow(radicand, exponent, evaluate=False)  # as ``unsplit_root`` builds it


def _sum_over(root):
    return s * root + c**2 * root**3 + c / root + 1


def _asking_no_sign(monkeypatch):
    def refuse(factor):
        if factor.is_Pow and factor.base.is_Mul:
            raise AssertionError(f"sympy asked the signs of the factors of {factor}")
        return decompose_power(factor)
    monkeypatch.setattr(order, "decompose_power", refuse)


@pytest.mark.parametrize("radicand", UNKNOWABLE)
def test_a_root_of_factors_of_unknowable_signs_is_ordered_as_sympy_orders_it_asking_no_sign(radicand, monkeypatch):
    expr = sympy.expand(_sum_over(_root(radicand)), deep=False)
    expected = expr.as_ordered_terms(), str(expr)  # sympy's own printer, its own questions
    _asking_no_sign(monkeypatch)
    assert (PrintOrder().terms(expr), ExpressionText()(expr)) == expected


@pytest.mark.parametrize("radicand", KNOWABLE)
def test_a_root_of_factors_sympy_knows_the_sign_of_is_ordered_by_sympys_own_answer(radicand):
    root = _root(radicand)
    assert decompose_power(root)[0] != root  # sympy's root of the product is not the root kept whole
    expr = sympy.expand(_sum_over(root), deep=False)
    assert (PrintOrder().terms(expr), ExpressionText()(expr)) == (expr.as_ordered_terms(), str(expr))


def test_a_root_over_a_symbol_assumed_more_than_real_is_ordered_by_sympys_own_answer(monkeypatch):
    root = _root((c - 2) * (s - l))
    assert PrintOrder()._power(root) == decompose_power(root)
    _asking_no_sign(monkeypatch)
    with pytest.raises(AssertionError, match="asked the signs"):
        PrintOrder()._power(root)


PLAIN_MONOMIALS = st.tuples(st.integers(0, 3), st.integers(0, 2)).map(lambda e: c ** e[0] * s ** e[1])
PLAIN_FACTORS = st.lists(st.tuples(RATIONALS, PLAIN_MONOMIALS), min_size=1, max_size=4).map(
    lambda terms: sympy.Add(*[k * m for k, m in terms])).filter(lambda p: not p.is_Number)
NESTED_FACTORS = st.tuples(PLAIN_FACTORS, RATIONALS, PLAIN_FACTORS, PLAIN_FACTORS).map(
    lambda p: p[0] + p[1] * sympy.sqrt(p[2]) * p[3])
RADICANDS = st.lists(PLAIN_FACTORS | NESTED_FACTORS, min_size=2, max_size=3).map(lambda f: sympy.Mul(*f))


@settings(max_examples=40, deadline=None)
@given(RADICANDS, st.sampled_from([sympy.S.Half, -sympy.S.Half, sympy.Rational(3, 2)]))
def test_a_roots_generator_read_without_sympy_is_sympys(radicand, exponent):
    root = _root(radicand, exponent)
    assert PrintOrder()._power(root) == decompose_power(root)
