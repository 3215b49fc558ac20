"""algkin.system.order: a PrintOrder orders a sum's terms and a product's factors, and keys expressions,
exactly as sympy's own methods do, for every expression of one document in turn (each order kept)."""

import pytest
import sympy
from hypothesis import given, settings, strategies as st
from sympy.core.sorting import default_sort_key

from algkin.system.order import PrintOrder

from .closed_forms import CLOSED_FORMS, c, s


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
