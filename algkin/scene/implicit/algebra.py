"""Reduction on the inputs' unit circles: the normal form compiling and the closed forms share."""

from collections.abc import Sequence

import sympy

__all__ = ["Circles", "reduce_on_circles"]

Circles = Sequence[tuple[sympy.Symbol, sympy.Symbol]]  # each input's (cos, sin) symbols


def reduce_on_circles(expr: sympy.Expr, inputs: Circles) -> sympy.Expr:
    """Normal form of a polynomial modulo ``c**2 + s**2 - 1`` for each input (s**2 -> 1 - c**2)."""
    expr = sympy.expand(expr)
    if not expr.is_polynomial():
        return expr
    for c, s in inputs:
        expr = sympy.expand(sympy.rem(expr, s**2 + c**2 - 1, s)) if expr.has(s) else expr
    return expr
