"""Random expressions of the shapes algkin writes for closed forms: polynomials in an input's cosine and
sine with rational coefficients, quadratic roots over products (a square root of a product with a
negative exponent, as sympy evaluates it and as ``unsplit_root`` builds it unevaluated), a root nested in
another, surds in front (``sqrt(6)*...``), terms equal but for their numbers (``c + sqrt(2)*c``); numbers
of 400 digits, and a symbol sympy sorts before the input's (a capital) as a dimension would be."""

import sympy
from hypothesis import strategies as st

c, s = sympy.symbols("c_theta s_theta", real=True)
l = sympy.Symbol("l", positive=True)
B = sympy.Symbol("B_x", real=True)

HUGE = sympy.Integer(10) ** 400
RATIONALS = st.fractions(-60, 60, max_denominator=16).filter(bool).map(sympy.Rational) | st.sampled_from(
    [HUGE, 1 / HUGE, -7 / HUGE, -3 * HUGE / 7])
SURDS = st.sampled_from([sympy.Integer(1), sympy.sqrt(2), sympy.sqrt(3), sympy.sqrt(6), sympy.sqrt(15) / 4])
MONOMIALS = st.tuples(st.integers(0, 3), st.integers(0, 1), st.integers(0, 1), st.integers(0, 1)).map(
    lambda e: c ** e[0] * s ** e[1] * l ** e[2] * B ** e[3])


def _polynomial(terms):
    return sympy.Add(*[k * m for k, m in terms])


POLYNOMIALS = st.lists(st.tuples(RATIONALS, MONOMIALS), min_size=1, max_size=4).map(_polynomial)
FACTORS = POLYNOMIALS.filter(lambda p: not p.is_Number)


def _root(parts):
    """A square root of ``numerator / denominator``: sympy's ``sqrt`` or ``unsplit_root``'s unevaluated one."""
    numerator, denominator, unevaluated = parts
    radicand = sympy.Mul(numerator, 1 / denominator)
    if unevaluated and radicand.is_Mul:
        return sympy.Pow(radicand, sympy.S.Half, evaluate=False)
    return sympy.sqrt(radicand)


ROOTS = st.tuples(st.lists(FACTORS, min_size=1, max_size=2).map(lambda f: sympy.Mul(*f)),
                  FACTORS, st.booleans()).map(_root)
NESTED = st.tuples(FACTORS, RATIONALS, ROOTS, FACTORS, st.booleans()).map(
    lambda p: _root((p[0] + p[1] * p[2], p[3], p[4])))
RADICALS = ROOTS | NESTED | st.just(sympy.S.One)


def _term(parts):
    """``k * surd * polynomial * root / denominator``, multiplied as sympy multiplies."""
    k, surd, polynomial, radical, denominator = parts
    return k * surd * polynomial * radical / denominator


TERMS = st.tuples(RATIONALS, SURDS, POLYNOMIALS | MONOMIALS, RADICALS, FACTORS | st.just(sympy.S.One)).map(_term)


def _tied(term):
    """The term with a surd of its own beside it: two terms of one monomial, which their numbers order."""
    return term + sympy.sqrt(2) * term


CLOSED_FORMS = (st.lists(TERMS, min_size=1, max_size=4).map(lambda t: sympy.Add(*t))
                | TERMS.map(_tied)
                | st.tuples(TERMS, TERMS).map(lambda p: p[0] / (1 + p[1])))
