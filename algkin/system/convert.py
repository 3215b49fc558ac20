"""The one crossing between sympy and python-flint: convert in, compute, convert out.

>>> import sympy
>>> x, y = sympy.symbols("x y")
>>> ctx = flint_context(["x", "y"])
>>> p = to_flint(x**2 - y/3, ctx)
>>> p
x^2 - 1/3*y
>>> to_sympy(p * p, ctx)
x**4 - 2*x**2*y/3 + y**2/9
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from typing import NoReturn

import flint
import sympy

from ..evaluate import NumberKind, evaluate
from .core import symbol

__all__ = ["flint_context", "to_flint", "to_sympy", "to_flint_integer", "fmpq_to_rational", "univariate"]


def flint_context(names: Iterable[str], ordering: str = "lex") -> flint.fmpq_mpoly_ctx:
    """A python-flint rational polynomial context over ``names`` (order matters for lex)."""
    return flint.fmpq_mpoly_ctx.get(tuple(names), ordering)


def to_flint(expr: sympy.Expr | sympy.Poly, ctx: flint.fmpq_mpoly_ctx) -> flint.fmpq_mpoly:
    """A sympy polynomial (expression or Poly) as an ``fmpq_mpoly`` in ``ctx``.

    The expression tree is evaluated with flint's own arithmetic (``evaluate``): building a
    sympy ``Poly`` first costs milliseconds on a dozen generators, more than most
    eliminations.
    """
    zero = ctx.from_dict({})
    kind = NumberKind("flint polynomial", number=lambda p, q: zero + flint.fmpq(p, q),
                      sqrt=lambda v: _not_polynomial(f"sqrt({v})"), absolute=lambda v: _not_polynomial(f"Abs({v})"))
    expr = expr.as_expr() if isinstance(expr, sympy.Poly) else expr
    return evaluate(expr, dict(zip((str(n) for n in ctx.names()), ctx.gens())), kind)


def _not_polynomial(value: str) -> NoReturn:
    raise TypeError(f"not a polynomial: {value}")


def to_flint_integer(poly: flint.fmpq_mpoly, ctx: flint.fmpz_mpoly_ctx) -> flint.fmpz_mpoly:
    """An ``fmpq_mpoly`` with denominators cleared, as an ``fmpz_mpoly`` in ``ctx``."""
    terms = poly.to_dict()
    if not terms:
        return ctx.from_dict({})
    lcm = math.lcm(*(int(c.q) for c in terms.values()))
    return ctx.from_dict({m: int(c.p) * (lcm // int(c.q)) for m, c in terms.items()})


def fmpq_to_rational(value: flint.fmpq | flint.fmpz | int) -> sympy.Rational:
    """A python-flint rational (or integer) as a sympy Rational."""
    value = flint.fmpq(value)
    return sympy.Rational(int(value.p), int(value.q))


def to_sympy(poly: flint.fmpq_mpoly | flint.fmpz_mpoly,
             ctx: flint.fmpq_mpoly_ctx | flint.fmpz_mpoly_ctx) -> sympy.Expr:
    """An ``fmpq_mpoly`` or ``fmpz_mpoly`` of ``ctx`` as a sympy expression."""
    gens = [symbol(str(n)) for n in ctx.names()]
    terms = {m: fmpq_to_rational(c) for m, c in poly.to_dict().items()}
    if not terms:
        return sympy.Integer(0)
    return sympy.Poly.from_dict(terms, *gens, domain=sympy.QQ).as_expr()


def univariate(expr: sympy.Expr, var: sympy.Symbol) -> flint.fmpq_poly:
    """A sympy polynomial in ``var`` alone, with rational coefficients, as an ``fmpq_poly``.

    >>> t = sympy.Symbol("t")
    >>> univariate(t**2 / 2 - 3, t)
    1/2*x^2 + (-3)
    """
    coefficients = sympy.Poly(expr, var).all_coeffs()
    return flint.fmpq_poly([_fmpq(sympy.Rational(a)) for a in reversed(coefficients)])


def _fmpq(value: sympy.Rational) -> flint.fmpq:
    return flint.fmpq(int(value.p), int(value.q))
