"""sympy <-> flint conversion round-trips exactly."""

import re

import pytest
from hypothesis import given, strategies as st
import sympy

from algkin.system.convert import flint_context, to_flint, to_sympy

NAMES = ["x", "y", "z"]
GENS = [sympy.Symbol(n, real=True) for n in NAMES]

terms = st.lists(
    st.tuples(st.fractions(max_denominator=10**6), st.tuples(*[st.integers(0, 5)] * 3)),
    max_size=12,
)


@given(terms)
def test_round_trip(term_list):
    expr = sum((sympy.Rational(q.numerator, q.denominator) * sympy.Mul(*[g**e for g, e in zip(GENS, exps)])
                for q, exps in term_list), sympy.Integer(0))
    ctx = flint_context(NAMES)
    assert sympy.expand(to_sympy(to_flint(expr, ctx), ctx) - expr) == 0


@given(terms, terms)
def test_product_matches_sympy(a, b):
    def build(term_list):
        return sum((sympy.Rational(q.numerator, q.denominator) * sympy.Mul(*[g**e for g, e in zip(GENS, exps)])
                    for q, exps in term_list), sympy.Integer(0))

    ctx = flint_context(NAMES)
    fa, fb = build(a), build(b)
    assert sympy.expand(to_sympy(to_flint(fa, ctx) * to_flint(fb, ctx), ctx) - fa * fb) == 0


def test_a_root_or_an_absolute_value_is_no_polynomial():
    ctx = flint_context(NAMES)
    x = GENS[0]
    for expr, shown in ((sympy.sqrt(x), "sqrt("), (sympy.Abs(x - 1), "Abs(")):
        with pytest.raises(TypeError, match=rf"not a polynomial: {re.escape(shown)}"):
            to_flint(expr, ctx)
