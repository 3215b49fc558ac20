"""A slider: the point on the line through P with direction d at distance l from Q, ahead or behind.

The direction is fixed (``direction = [dx, dy]``) or moves (``toward = R``: ``d = R - P``, in
system variables when P or R moves). ``ahead`` is the point with ``dot(d, X - Q) > 0``: ahead
of the foot of the perpendicular from Q, along d. Its closed form, toggles and stable floats:
``algkin.branches.constructions.slider``.
"""

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import sympy

from .base import FloatArray, FloatPoint, ImplicitSpec, Point

__all__ = ["SliderSpec"]


@dataclass(frozen=True)
class SliderSpec(ImplicitSpec):
    """A compiled slider: the line (a point on it, its direction), the circle's centre and radius, all
    in system variables (a direction ``toward`` a point moves with it)."""

    through: Point
    direction: tuple[sympy.Expr, sympy.Expr]
    center: Point
    length: sympy.Expr
    labels = ("ahead", "behind")
    never_meets = "the circle never meets the slider's line"

    def written(self) -> list[sympy.Expr]:
        (px, py), (dx, dy), (qx, qy) = self.through, self.direction, self.center
        x, y = self.unknown_symbols()
        return [dx * (y - py) - dy * (x - px), (x - qx) ** 2 + (y - qy) ** 2 - self.length**2]

    def start_parts(self) -> tuple[sympy.Expr, ...]:
        return (*self.through, *self.direction, *self.center, self.length)

    @staticmethod
    def start(parts: Sequence[FloatArray], sigma: float) -> FloatPoint:
        """The line through P along d meets the circle about Q: ``X = P + a d``, ahead or behind Q's
        foot (where they miss, by the discriminant's size, as for a dyad)."""
        px, py, dx, dy, qx, qy, length = parts
        wx, wy = qx - px, qy - py
        d2 = dx * dx + dy * dy
        foot = (dx * wx + dy * wy) / d2
        half = np.sqrt(np.abs(length * length / d2 - (dx * wy - dy * wx) ** 2 / d2**2))
        along = foot + sigma * half
        return px + along * dx, py + along * dy

