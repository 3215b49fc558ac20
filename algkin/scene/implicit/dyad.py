"""A dyad: the point at distance l1 from P and l2 from Q, left or right of P -> Q.

``left`` is the point with ``cross(Q - P, X - P) > 0``: the label is the geometry, not the
sign in a quadratic formula. Its closed form, toggles and stable floats:
``algkin.branches.constructions.dyad``.
"""

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import sympy

from .base import FloatArray, FloatPoint, ImplicitSpec, Point

__all__ = ["DyadSpec"]


@dataclass(frozen=True)
class DyadSpec(ImplicitSpec):
    """A compiled dyad: its base coordinates and lengths in system variables."""

    base_p: Point
    base_q: Point
    lengths: tuple[sympy.Expr, sympy.Expr]
    labels = ("left", "right")
    never_meets = "the two circles never meet"

    def written(self) -> list[sympy.Expr]:
        (px, py), (qx, qy), (l1, l2) = self.base_p, self.base_q, self.lengths
        x, y = self.unknown_symbols()
        return [(x - px) ** 2 + (y - py) ** 2 - l1**2, (x - qx) ** 2 + (y - qy) ** 2 - l2**2]

    def start_parts(self) -> tuple[sympy.Expr, ...]:
        return (*self.base_p, *self.base_q, *self.lengths)

    @staticmethod
    def start(parts: Sequence[FloatArray], sigma: float) -> FloatPoint:
        """Two circles meet: the foot on PQ, then the half-chord to the labelled side. Where they
        miss, the half-chord of the discriminant's size: a start off the fold, whose J is singular
        (Newton's first step from there would fly off, and take ~50 steps to come back)."""
        px, py, qx, qy, l1, l2 = parts
        dx, dy = qx - px, qy - py
        d2 = dx * dx + dy * dy
        along = (d2 + l1 * l1 - l2 * l2) / (2 * d2)
        across = sigma * np.sqrt(np.abs(l1 * l1 / d2 - along * along))
        return px + along * dx - across * dy, py + along * dy + across * dx

