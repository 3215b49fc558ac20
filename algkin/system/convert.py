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

__all__ = ["flint_context", "to_flint", "to_sympy", "sympy_text", "to_flint_integer", "fmpq_to_rational", "univariate"]


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


def sympy_text(poly: flint.fmpq_mpoly | flint.fmpz_mpoly, ctx: flint.fmpq_mpoly_ctx | flint.fmpz_mpoly_ctx) -> str:
    """``str(to_sympy(poly, ctx))``, written directly where every coefficient is an integer (a
    primitive eliminant's): sympy's terms in lex order of its sorted symbols, without building
    and printing the expression, a few milliseconds on a sextic. Rational coefficients go through sympy.

    >>> ctx = flint_context(["y", "x"])
    >>> y, x = ctx.gens()
    >>> sympy_text(3*x**2*y - x*y**3 + 5 - y, ctx), str(to_sympy(3*x**2*y - x*y**3 + 5 - y, ctx))
    ('3*x**2*y - x*y**3 - y + 5', '3*x**2*y - x*y**3 - y + 5')
    """
    terms = poly.to_dict()
    if not terms or any(flint.fmpq(c).q != 1 for c in terms.values()):
        return str(to_sympy(poly, ctx))
    names = [str(n) for n in ctx.names()]
    order = sorted(range(len(names)), key=lambda k: symbol(names[k]).sort_key())  # sympy's order of symbols
    ordered = sorted(((tuple(int(m[k]) for k in order), int(flint.fmpq(c).p)) for m, c in terms.items()), reverse=True)
    if len(ordered) == 2 and not any(ordered[1][0]) and ordered[1][1] > 0 and ordered[0][1] < 0 \
            and sum(1 for e in ordered[0][0] if e) == 1:
        ordered.reverse()  # sympy's one exception: ``1 - 2*x``, a positive number before a negative multiple
    text: list[str] = []
    for exponents, coefficient in ordered:
        factors = [names[k] if e == 1 else f"{names[k]}**{e}" for k, e in zip(order, exponents) if e]
        magnitude = abs(coefficient)
        term = "*".join(([str(magnitude)] if magnitude != 1 or not factors else []) + factors)
        sign = "-" if coefficient < 0 else "+"
        text.append((" - " if sign == "-" else " + ") + term if text else ("-" if sign == "-" else "") + term)
    return "".join(text)


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
