"""Exact algebra the closed forms share: earlier points substituted and reduced on the circles, tidy factors."""

from collections.abc import Callable, Mapping

import sympy

from ..scene.implicit.algebra import Circles, reduce_on_circles

__all__ = ["reducer", "tidy_ratio", "tidy_product", "tidy_sqrt"]


def reducer(substitution: Mapping[sympy.Symbol, sympy.Expr], inputs: Circles) -> Callable[[sympy.Expr], sympy.Expr]:
    """``e -> e`` with earlier points' unknowns substituted, reduced on the circles."""
    return lambda expr: reduce_on_circles(expr.xreplace(substitution), inputs)


def _primitive(expr: sympy.Expr) -> tuple[sympy.Expr, sympy.Expr]:
    """``(content, part)`` with ``expr = content * part`` and integer coprime numbers in ``part``:
    a factor reads ``23 - 16*c``, not ``23/4 - 4*c`` (sympy would spread the 1/4 back in)."""
    return expr.primitive() if expr.is_Add else (sympy.Integer(1), expr)


def tidy_ratio(expr: sympy.Expr) -> sympy.Expr:
    """A ratio of polynomials as ``k * p / q`` with ``p``, ``q`` primitive: ``(80*c - 103)/(8*(20*c - 29))``."""
    numerator, denominator = sympy.fraction(sympy.cancel(expr))
    (cn, pn), (cd, pd) = _primitive(numerator), _primitive(denominator)
    return sympy.Mul(cn / cd, pn, 1 / pd)  # one Mul: a product by a number would spread it back in


def tidy_product(*factors: sympy.Expr) -> sympy.Expr:
    """The product of ``factors`` with every numeric content gathered in front."""
    parts = [_primitive(sympy.expand(f)) for f in factors]
    return sympy.Mul(*[c for c, _ in parts], *[sympy.factor_terms(p) for _, p in parts])


def tidy_sqrt(expr: sympy.Expr) -> sympy.Expr:
    """``sqrt(expr)`` with the square part of its numeric content in front: ``10*sqrt(30*s + 34)``
    for ``sqrt(3000*s + 3400)`` (sympy does so for a product, never for a sum).

    >>> s = sympy.Symbol("s")
    >>> tidy_sqrt(3000*s + 3400), tidy_sqrt(s/8 + sympy.Rational(1, 8))
    (10*sqrt(30*s + 34), sqrt(2*s + 2)/4)
    """
    if not expr.is_Add:  # a product keeps its factors (sympy takes a number's squares out of one)
        return sympy.sqrt(expr)
    content, part = _primitive(expr)
    if not (content.is_Rational and content > 0 and content != 1):
        return sympy.sqrt(expr)
    outside, inside = sympy.sqrt(content).as_coeff_Mul()  # sqrt(200) = 10 * sqrt(2)
    return outside * sympy.sqrt(sympy.expand(inside**2 * part))
