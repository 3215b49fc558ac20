"""Angles as algebra: the tangent half-angle ``t = tan(theta/2)`` and back.

On the circle ``c**2 + s**2 = 1`` every point but ``theta = 180 deg`` is
``c = (1 - t**2)/(1 + t**2)``, ``s = 2t/(1 + t**2)``, so a polynomial condition in ``c, s``
becomes one in ``t`` alone; ``theta = 180 deg`` is ``t`` at infinity, checked apart.

>>> import sympy
>>> c, s, t = sympy.symbols("c s t")
>>> half_angle_numerator(c - s, c, s, t)
-t**2 - 2*t + 1
>>> import flint
>>> tangent_to_degrees(flint.arb(1)).contains(90)
True
"""

from __future__ import annotations

import flint
import sympy

__all__ = ["half_angle_numerator", "tangent_to_degrees", "vanishes_at_half_turn"]


def half_angle_numerator(expr: sympy.Expr, c: sympy.Symbol, s: sympy.Symbol, t: sympy.Symbol) -> sympy.Expr:
    """The numerator, in ``t``, of ``expr`` with ``c``, ``s`` in the half-angle form."""
    half = {c: (1 - t**2) / (1 + t**2), s: 2 * t / (1 + t**2)}
    return sympy.expand(sympy.numer(sympy.together(sympy.expand(expr).xreplace(half))))


def vanishes_at_half_turn(expr: sympy.Expr, c: sympy.Symbol, s: sympy.Symbol) -> bool:
    """Whether the condition holds at ``theta = 180 deg`` (``t`` at infinity)."""
    return sympy.expand(expr.xreplace({c: -1, s: 0})) == 0


def tangent_to_degrees(t: flint.arb) -> flint.arb:
    """``2 atan(t)`` in degrees, for an arb ball ``t``: in (-180, 180)."""
    return 2 * t.atan() * 180 / flint.arb.pi()
