"""sympy <-> flint conversion round-trips exactly."""

import re
from fractions import Fraction

import flint
import pytest
from hypothesis import given, strategies as st
import sympy

from algkin.system import convert
from algkin.system.convert import (coefficients as coefficients_of, expanded, flint_context, from_terms, sympy_text, to_flint,
                                   to_sympy)

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
    for expr, shown in ((sympy.sqrt(x), "sqrt("), (sympy.Abs(x - 1), "Abs("), (1 / (x + 1), "1/(x + 1)")):
        with pytest.raises(TypeError, match=rf"not a polynomial: {re.escape(shown)}"):
            to_flint(expr, ctx)


# names whose sympy order is not their order in the context, nor their order as written
TEXT_NAMES = ["P_y", "P_x", "x10", "x2", "B_x", "c_theta", "Z"]
coefficients = st.one_of(st.sampled_from([1, -1, 2, -3]), st.integers(-10**40, 10**40).filter(bool),
                         st.fractions(max_denominator=7).filter(bool),
                         st.sampled_from([Fraction(1, 10**400), Fraction(-7 * 10**400, 3), -10**400]))


@given(st.lists(st.sampled_from(TEXT_NAMES), min_size=1, max_size=4, unique=True), st.booleans(),
       st.lists(st.tuples(coefficients, st.lists(st.integers(0, 4), min_size=4, max_size=4)), max_size=10))
def test_sympy_text_is_how_sympy_writes_the_polynomial(names, in_sympys_order, term_list):
    if in_sympys_order:  # as sympy sorts its symbols: FLINT's own text is taken where the coefficients are integers
        names = sorted(names, key=lambda n: sympy.Symbol(n).sort_key())
    ctx = flint_context(names)
    poly = ctx.from_dict({tuple(exps[:len(names)]): flint.fmpq(c.numerator, c.denominator) for c, exps in term_list})
    assert sympy_text(poly, ctx) == str(to_sympy(poly, ctx))


def test_sympy_text_keeps_sympys_exception_for_a_number_and_a_negative_multiple():
    ctx = flint_context(["x", "y"])
    x, y = ctx.gens()
    assert [sympy_text(p, ctx) for p in (1 - 2 * x, 1 - x * y, 2 - y**2, -x - 1)] == \
        ["1 - 2*x", "-x*y + 1", "2 - y**2", "-x - 1"]


@given(terms, st.permutations(GENS + [sympy.Symbol("B_x"), sympy.Symbol("x10", positive=True)]))
def test_from_terms_is_the_expression_of_sympys_poly(term_list, gens):
    gens = gens[:3]  # in an order that is not sympy's, with or without assumptions
    as_dict = {exps: flint.fmpq(q.numerator, q.denominator) for q, exps in term_list}
    nonzero = {exps: q for exps, q in as_dict.items() if q}
    expected = sympy.Poly.from_dict({e: sympy.Rational(int(q.p), int(q.q)) for e, q in nonzero.items()}, *gens,
                                    domain=sympy.QQ).as_expr() if nonzero else sympy.Integer(0)
    built = from_terms(as_dict, gens)  # zero coefficients given too: dropped
    # the same tree, not only the same value: its arguments in sympy's order, its hash, its text
    assert built == expected and built.args == expected.args
    assert hash(built) == hash(expected) and sympy.srepr(built) == sympy.srepr(expected) and str(built) == str(expected)


@given(terms, st.integers(1, 2))
def test_coefficients_are_sympys_polys_terms(term_list, power):
    # a polynomial in x, y over the polynomials in z, raised to a power: unexpanded, as closed forms hold them
    expr = sum((sympy.Rational(q.numerator, q.denominator) * sympy.Mul(*[g**e for g, e in zip(GENS, exps)])
                for q, exps in term_list), sympy.Integer(0)) ** power
    expected = sympy.Poly(expr, *GENS[:2]).as_dict() if expr != 0 else {}
    assert coefficients_of(expr, GENS[:2]) == {e: sympy.sympify(c) for e, c in expected.items()}


def test_coefficients_refuse_two_symbols_of_one_name():
    with pytest.raises(TypeError, match="two symbols of one name"):
        coefficients_of(GENS[0] + sympy.Symbol("x"), GENS[:1])


def test_sympy_text_writes_rational_coefficients_without_sympy(monkeypatch):
    ctx = flint_context(["y", "x"])
    y, x = ctx.gens()
    polys = [x**2 / 3 - 2 * x * y / 5 - flint.fmpq(1, 2), flint.fmpq(1, 2) - x / 3, -x * y**2 / 7 + 4 * y / 3]
    expected = [str(to_sympy(p, ctx)) for p in polys]
    assert expected == ["x**2/3 - 2*x*y/5 - 1/2", "1/2 - x/3", "-x*y**2/7 + 4*y/3"]  # as sympy writes them
    monkeypatch.setattr(convert, "to_sympy", _refuse_sympy)
    assert [sympy_text(p, ctx) for p in polys] == expected


def _refuse_sympy(poly, ctx):
    raise AssertionError(f"converted to sympy: {poly}")


class _WrittenWhole:
    """A polynomial whose terms refuse to be read one by one in Python: only FLINT writes it."""

    def __init__(self, poly):
        self.poly = poly

    def __str__(self):
        return str(self.poly)

    def __len__(self):
        return len(self.poly)

    def to_dict(self):
        raise AssertionError("its terms read one by one")


def test_sympy_text_of_integer_coefficients_in_sympys_order_is_flints_own_text():
    ctx = flint_context(["P_x", "P_y", "c_theta"])  # sympy's order: capitals first
    px, py, c = ctx.gens()
    poly = 3 * px**2 * c - px * py**3 + 10**30 * c - 1
    expected = str(to_sympy(poly, ctx))
    assert expected == "3*P_x**2*c_theta - P_x*P_y**3 + 1000000000000000000000000000000*c_theta - 1"
    assert sympy_text(_WrittenWhole(poly), ctx) == expected


A = sympy.Symbol("a")  # no assumptions, beside GENS' real ones
# names sympy sorts otherwise than written (capitals first, x10 before x2), numbers of 400 digits
ODD = [sympy.Symbol("B_x", real=True), sympy.Symbol("x10", real=True), sympy.Symbol("x2"), sympy.Symbol("Z")]
HUGE = sympy.Integer(10) ** 400
LEAVES = st.sampled_from([*GENS, A, *ODD, sympy.sqrt(2), sympy.Float(0.5), HUGE, -3 / HUGE]) | st.fractions(
    -7, 7, max_denominator=5).map(lambda q: sympy.Rational(q.numerator, q.denominator))
EXPRESSIONS = st.recursive(LEAVES, lambda children: (
    st.tuples(children, children).map(lambda p: p[0] + p[1]) | st.tuples(children, children).map(lambda p: p[0] * p[1])
    | st.tuples(children, st.integers(-2, 4)).filter(lambda p: p[0] != 0 or p[1] > 0).map(lambda p: p[0] ** p[1])
    | children.map(lambda e: e / 3)), max_leaves=12)


@given(EXPRESSIONS)
def test_expanded_is_sympys_expansion(expr):
    ours, sympys = expanded(expr), sympy.expand(expr)
    assert ours == sympys and str(ours) == str(sympys)


INTEGER_RING = flint.fmpz_mpoly_ctx.get(("t", "u"), "lex")
small_factors = st.lists(st.tuples(st.dictionaries(st.tuples(st.integers(0, 2), st.integers(0, 2)), st.integers(-9, 9),
                                                   min_size=1, max_size=4), st.integers(1, 3)), min_size=1, max_size=3)


@given(small_factors)
def test_the_factors_over_the_rationals_are_python_flints_own_in_its_order(factors):
    """Where python-flint's ordering works (coefficients within C ints), the fallback gives its very list."""
    poly = INTEGER_RING.from_dict({(0, 0): 1})
    for terms, power in factors:
        poly *= INTEGER_RING.from_dict(terms) ** power
    if poly.is_zero():
        return
    assert convert.factored_over_rationals(poly) == list(poly.factor()[1])


def test_factors_tied_but_for_coefficients_past_a_c_int_are_found():
    """python-flint 0.9 raises OverflowError ordering (t + 2**40) after (t + 3): built from its factors."""
    t, u = INTEGER_RING.gens()
    big = 2**40 + 1
    poly = -7 * (t * u + big) * (t * u + 3) * (big * t - u) ** 2
    with pytest.raises(OverflowError):
        poly.factor()
    assert convert.integer_factors(poly) == [(t * u + 3, 1), (t * u + big, 1), (big * t - u, 2)]
