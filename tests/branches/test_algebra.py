"""``branches.algebra``: a root written without sympy's questions is the root sympy writes."""

from fractions import Fraction

import sympy
from hypothesis import assume, example, given, strategies as st

from sympy.core.mul import _keep_coeff

from algkin.branches.algebra import (factored_terms, primitive_sum, product, product_root, times, total,
                                    unsplit_root)

C, S = sympy.symbols("c s", real=True)
numbers = st.fractions(min_value=0, max_value=10**6, max_denominator=10**6).filter(bool) | st.sampled_from(
    [Fraction(10**400), Fraction(1, 10**400), Fraction(3, 10**401)])  # surds and squares, of 400 digits too
# sums of monomials in c and s: real, of a sign sympy does not know (a positive one, c**2 + 1, it splits out)
sums = st.lists(st.tuples(st.integers(-50, 50).filter(bool), st.integers(0, 4), st.integers(0, 3)),
                min_size=2, max_size=6).map(
    lambda terms: sympy.Add(*[k * C**i * S**j for k, i, j in terms])).filter(
    lambda p: p.is_Add and p.is_extended_nonnegative is None and p.is_extended_nonpositive is None)


@given(numbers, st.lists(sums, min_size=1, max_size=3, unique=True))
def test_a_root_of_a_product_of_unknown_sign_is_sympys(number, factors):
    expr = sympy.Mul(sympy.Rational(number.numerator, number.denominator), *factors)
    assume(expr.is_extended_nonnegative is None)  # not a square: sqrt(p**2) is sympy's Abs(p)
    written, sympys = unsplit_root(expr), sympy.sqrt(expr)
    assert written == sympys and written.args == sympys.args and str(written) == str(sympys)


# sums of monomials of any sign, sympy's known or not (c**2 + s**2 + 1 > 0, -c**2 <= 0), and their squares
any_sums = st.lists(st.tuples(st.integers(-50, 50).filter(bool), st.integers(0, 4), st.integers(0, 3)),
                    min_size=1, max_size=5).map(lambda terms: sympy.Add(*[k * C**i * S**j for k, i, j in terms])
                                                ).filter(lambda p: not p.is_number)
L = sympy.Symbol("l", positive=True)  # sympy knows l > 0: 5 - 4*l could be taken for either sign


@given(numbers, st.lists(st.one_of(any_sums, any_sums.map(lambda p: p**2), st.sampled_from([5 - 4 * L, L + 1])),
                         min_size=1, max_size=3, unique=True))
@example(4, [5 - 4 * C, C + 5])  # the Chebyshev lambda's dyad
@example(4, [C**2 + 1, C + 5])  # a factor sympy proves positive is taken out of the root
def test_a_root_of_a_product_is_sympys(number, factors):
    expr = sympy.Mul(sympy.Rational(number.numerator, number.denominator), *factors)
    written, sympys = product_root(expr), sympy.sqrt(expr)
    assert written == sympys and written.args == sympys.args and str(written) == str(sympys)


A, B = sympy.symbols("a b")  # no assumptions
monomials = st.tuples(st.sampled_from([1, 2, 3]), st.integers(0, 3), st.integers(0, 2), st.integers(0, 1)).map(
    lambda p: p[0] * C**p[1] * S**p[2] * A**p[3])
terms = st.tuples(st.integers(-60, 60).filter(bool) | st.fractions(-5, 5, max_denominator=4).filter(bool).map(
    lambda q: sympy.Rational(q.numerator, q.denominator)), monomials).map(lambda p: p[0] * p[1])


@given(st.lists(terms, min_size=1, max_size=5) | st.lists(terms, min_size=1, max_size=3).map(
    lambda ts: [sympy.sqrt(2) * B * t for t in ts]))
@example([5, -4 * C])
@example([-4 * C, -5])
@example([C * S, C])
@example([6, -4 * C])
def test_factored_terms_is_sympys(summands):
    expr = sympy.Add(*summands)
    ours, sympys = factored_terms(expr), sympy.factor_terms(expr)
    assert ours == sympys and str(ours) == str(sympys)


X = sympy.Symbol("x")  # no assumptions: sympy asks nothing of its sign
surds = st.sampled_from([sympy.sqrt(2), sympy.sqrt(3), sympy.sqrt(6), 1 / sympy.sqrt(5)])
atoms = st.one_of(st.sampled_from([C, S, X, C**2, 1 / S, X**3]), sums, sums.map(lambda p: 1 / p))
roots = sums.map(lambda p: sympy.Pow(p, sympy.S.Half, evaluate=False))
factor = st.one_of(numbers.map(lambda q: sympy.Rational(q.numerator, q.denominator)), st.integers(-5, 5).map(sympy.Integer),
                   surds, atoms, roots,
                   st.tuples(numbers, atoms, roots).map(lambda t: sympy.Mul(sympy.Rational(t[0].numerator,
                                                                                           t[0].denominator),
                                                                              t[1], t[2])))


@given(st.lists(factor, max_size=5))
@example([sympy.Integer(2), C + 1])  # sympy spreads a number over a sum
@example([sympy.sqrt(2), sympy.sqrt(3)])  # and gathers surds
def test_a_product_is_sympys(factors):
    built, sympys = product(*factors), sympy.Mul(*factors)
    assert built == sympys and built.args == sympys.args and str(built) == str(sympys)


@given(st.lists(st.one_of(factor, st.lists(factor, max_size=3).map(lambda f: sympy.Mul(*f)), sums), max_size=6))
@example([C + 1, -C, sympy.Integer(3)])  # alike terms, numbers: sympy's own
def test_a_sum_is_sympys(terms):
    built, sympys = total(*terms), sympy.Add(*terms)
    assert built == sympys and built.args == sympys.args and str(built) == str(sympys)


def _same_tree(built, sympys):
    """The same expression, node by node in the same order and of the same classes (sympy finds some
    numbers of other types equal, and ``srepr`` sorts a sum's terms)."""
    return type(built) is type(sympys) and built == sympys and len(built.args) == len(sympys.args) \
        and all(_same_tree(b, s) for b, s in zip(built.args, sympys.args))


coefficients = st.one_of(st.fractions(-10**4, 10**4, max_denominator=10**3).map(sympy.Rational),
                         st.sampled_from([sympy.S.One, sympy.S.NegativeOne, sympy.Float(1.5), sympy.sqrt(2)]))
powers = st.tuples(st.sampled_from([C, S, X, sympy.Symbol("l", positive=True)]), st.integers(-3, 4)).map(
    lambda p: p[0] ** p[1])


@given(coefficients, st.one_of(powers, factor, sums))
@example(sympy.Rational(3, 4), X**2)
@example(sympy.Integer(2), sympy.sqrt(2))  # a number's root: sympy's own
@example(sympy.Integer(3), sympy.Pow(sympy.Mul(C**2 + 1, C - 2), sympy.S.Half, evaluate=False))  # sympy splits it
def test_a_coefficient_times_a_part_is_sympys(coefficient, part):
    assert _same_tree(times(coefficient, part), _keep_coeff(coefficient, part))


@given(st.lists(st.tuples(coefficients, st.one_of(powers, factor)), min_size=2, max_size=6).map(
    lambda terms: sympy.Add(*[k * p for k, p in terms])).filter(lambda p: p.is_Add))
@example(sympy.Rational(3, 4) * C + sympy.Rational(9, 2) * C**2)
@example(6 * C - 4)  # the number stays first
@example(9 * C + sympy.Rational(3, 2) * S)  # 6*c + s: the terms put in sympy's order again
def test_a_sums_content_and_primitive_part_are_sympys(add):
    (content, part), (sympys_content, sympys_part) = primitive_sum(add), add.primitive()
    assert _same_tree(content, sympys_content) and _same_tree(part, sympys_part)
