"""algkin.system.text: an ExpressionText writes every expression as sympy's ``str`` does, character for
character, however many subexpressions the expressions of one document share."""

import pytest
import sympy
from hypothesis import given, settings, strategies as st
from sympy.core.mul import _keep_coeff

from algkin.system import text as text_module
from algkin.system.text import ExpressionText

from .closed_forms import CLOSED_FORMS

c, s = sympy.symbols("c s", real=True)
LEAVES = (st.sampled_from([c, s, sympy.Symbol("l"), sympy.Symbol("l", positive=True)])
          | st.fractions(-9, 9, max_denominator=7).map(sympy.Rational)
          | st.floats(-1e3, 1e3, allow_nan=False).map(sympy.Float))


def _expressions(children):
    return (st.tuples(children, children).map(lambda p: p[0] + p[1])
            | st.tuples(children, children).map(lambda p: p[0] - p[1])
            | st.tuples(children, children).map(lambda p: p[0] * p[1])
            | st.tuples(children, children).map(lambda p: p[0] / p[1] if p[1] != 0 else p[0])
            | st.tuples(children, st.sampled_from([-2, -1, 2, 3, sympy.Rational(1, 2), sympy.Rational(-3, 2)]))
            .map(lambda p: p[0] ** p[1] if p[0] != 0 else p[0])
            | children.map(sympy.Abs))


EXPRESSIONS = st.recursive(LEAVES, _expressions, max_leaves=14)


@settings(max_examples=300, deadline=None)
@given(st.lists(EXPRESSIONS, min_size=1, max_size=6))
def test_one_text_for_many_expressions_writes_each_as_str_does(exprs):
    text = ExpressionText()
    # each also nested in the next: a subexpression seen first on its own, then inside another, and the reverse
    nested = [e * exprs[k - 1] + 1 for k, e in enumerate(exprs)]
    for expr in [*exprs, *nested, *exprs]:
        assert text(expr) == str(expr)


def test_a_float_on_its_own_and_inside_a_sum_is_written_as_str_writes_each():
    # sympy keeps a Float's trailing zeros at the top only
    half, text = sympy.Float("0.50"), ExpressionText()
    assert [text(half + c), text(half), text(half + c)] == [str(half + c), str(half), str(half + c)]


def _written_as_str_writes_them(exprs):
    text = ExpressionText()
    for expr in [*exprs, *[e / (c - 2) for e in exprs], *exprs]:
        assert text(expr) == str(expr)


@settings(max_examples=25, deadline=None)
@given(st.lists(CLOSED_FORMS, min_size=1, max_size=3))
def test_closed_forms_of_one_document_are_written_as_str_writes_them(exprs):
    # the shapes algkin writes: roots of products over products, nested and unevaluated, surds, rationals
    _written_as_str_writes_them(exprs)


@pytest.mark.slow
@settings(max_examples=250, deadline=None)
@given(st.lists(CLOSED_FORMS, min_size=1, max_size=4))
def test_many_closed_forms_of_one_document_are_written_as_str_writes_them(exprs):
    _written_as_str_writes_them(exprs)


def test_a_negative_product_and_its_parts_are_written_as_str_writes_them():
    root = sympy.Pow(sympy.Mul(3 - c, 1 / (c + 5)), sympy.S.Half, evaluate=False)
    exprs = [-3 * c * root / (c - 2), -root, 1 - c, -(c - 1) / (2 * (c + 1)), -sympy.sqrt(6) * root / 4,
             # an unevaluated product's inverse: sympy writes c/((s*(c + 1)))
             sympy.Mul(c, sympy.Pow(sympy.Mul(c + 1, s), -1, evaluate=False), evaluate=False)]
    text = ExpressionText()
    assert [text(e) for e in exprs] == [str(e) for e in exprs]


def test_a_negative_multiple_of_a_variable_or_its_power_is_written_without_sympys_product(monkeypatch):
    # sympy's product of the number and the power asks the power's assumptions, each term of a closed form
    exprs = [-3 * c**2 + s, -sympy.Rational(2, 7) * c * s - c**3 / 5 + 1, -c - sympy.Float(2.5) * s**4]
    expected = [str(e) for e in exprs]

    def refuse(coefficient, rest, *args, **kwargs):
        if not rest.is_Mul:  # a product's factors are taken as they are: no question asked
            raise AssertionError(f"sympy's product of {coefficient} and {rest}")
        return _keep_coeff(coefficient, rest, *args, **kwargs)

    monkeypatch.setattr(text_module, "_keep_coeff", refuse)
    assert [ExpressionText()(e) for e in exprs] == expected
