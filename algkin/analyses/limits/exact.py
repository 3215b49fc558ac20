"""Exact forms, tidied: the shortest of a few equal rewritings, and a point's coordinates in
radicals at a root whose angle has them.

>>> import sympy
>>> tidy(sympy.sqrt(3 + 2 * sympy.sqrt(2)))
1 + sqrt(2)
"""

from __future__ import annotations

import sympy

from ...branches import Branch
from .isolation import Root

__all__ = ["TIDY_OPS", "tidy", "exact_point"]

TIDY_OPS = 80  # an exact position longer than this (sympy's count_ops) is left out


def tidy(expr: sympy.Expr) -> sympy.Expr:
    """The shortest of a few equal forms of ``expr`` (rewritings that keep its value); a root of a
    polynomial of degree above 2 (``CRootOf``) is left as it is."""
    if expr.has(sympy.CRootOf) or sympy.count_ops(expr) > 4 * TIDY_OPS:
        return expr
    forms = [expr]
    for rewrite in (sympy.radsimp, sympy.sqrtdenest, sympy.simplify):
        forms.append(rewrite(expr))
    return min(forms, key=sympy.count_ops)


def exact_point(branch: Branch, unknowns: tuple[sympy.Symbol, sympy.Symbol], root: Root, c: sympy.Symbol,
                s: sympy.Symbol) -> tuple[sympy.Expr, sympy.Expr] | None:
    """The point's coordinates at the root in radicals, when its angle has them and they stay short."""
    if root.t_value is None and root.factor is not None:
        return None
    if root.factor is None:  # theta = 180
        cosine, sine = sympy.Integer(-1), sympy.Integer(0)
    else:
        t = root.t_value
        assert t is not None
        cosine, sine = sympy.radsimp((1 - t**2) / (1 + t**2)), sympy.radsimp(2 * t / (1 + t**2))
    coordinates = tuple(tidy(branch.values[str(u)].xreplace({c: cosine, s: sine})) for u in unknowns)
    if any(sympy.count_ops(v) > TIDY_OPS for v in coordinates):
        return None
    return coordinates[0], coordinates[1]
