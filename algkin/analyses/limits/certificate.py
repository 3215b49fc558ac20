"""Certificates that a root of the eliminant is a limit position on a branch, in ball arithmetic.

On an interval around the root holding no other root of the eliminant, the branch assembles
(every discriminant > 0) and the condition on it changes sign: it has a zero there, the root.

>>> import sympy
>>> with flint.ctx.workprec(CHECK_BITS):
...     lo, hi = interval(Root(flint.arb(30), None, sympy.Integer(30), None), [flint.arb(30), flint.arb(31)])
...     lo < 30 < hi, hi - lo < 3e-20
(True, True)
"""

from __future__ import annotations

from collections.abc import Sequence

import flint
import sympy

from ...branches import Branch
from ...evaluate import ARB, evaluate
from ...system import symbol
from .isolation import Root

__all__ = ["CHECK_BITS", "HALF_WIDTH_DEG", "interval", "angle_values", "certify"]

CHECK_BITS = 320  # ball arithmetic of the certificates, far finer than the interval they check
HALF_WIDTH_DEG = sympy.Rational(1, 10**20)  # half the interval each certificate covers, at most


def interval(root: Root, others: Sequence[flint.arb]) -> tuple[flint.arb, flint.arb] | None:
    """``(lo, hi)`` in degrees around ``root`` holding no other root; None if it cannot be had."""
    middle = root.degrees.mid()
    half = flint.arb(str(HALF_WIDTH_DEG))
    for other in others:
        if other.overlaps(root.degrees):  # itself, or the same root of another polynomial
            continue
        gap = abs(other - middle)
        gap = 360 - gap if gap > 180 else gap
        if not gap > 0:
            return None
        half = min(half, gap.lower() / 4, key=float)
    lo, hi = middle - half, middle + half
    if not (lo < root.degrees.lower() and root.degrees.upper() < hi) or not half > 0:
        return None
    return lo, hi


def angle_values(degrees: flint.arb, c: str, s: str) -> dict[str, flint.arb]:
    """The input's cosine and sine at ``degrees``, by name."""
    radians = degrees * flint.arb.pi() / 180
    return {c: radians.cos(), s: radians.sin()}


def certify(condition: sympy.Expr, branch: Branch, around: tuple[flint.arb, flint.arb],
            c: str, s: str) -> tuple[str, str]:
    """``(verdict, why)``: is the condition, on ``branch``, zero inside the interval ``around``?"""
    lo, hi = around
    whole = angle_values(lo.union(hi), c, s)  # a ball holding the whole interval
    discriminants = [evaluate(d, whole, ARB) for d in branch.discriminants.values()]
    if any(d < 0 for d in discriminants):
        return "no", "the branch does not assemble there"
    if not all(d > 0 for d in discriminants):
        return "undecided", "a dead centre is in the interval"
    on_branch = condition.xreplace({symbol(u): v for u, v in branch.values.items()})
    ends = [evaluate(on_branch, angle_values(end, c, s), ARB) for end in around]
    if (ends[0] < 0 and ends[1] > 0) or (ends[0] > 0 and ends[1] < 0):
        return "yes", "changes sign"
    value = evaluate(on_branch, whole, ARB)
    if value > 0 or value < 0:
        return "no", "bounded away from zero"
    return "undecided", "no sign change shown"
