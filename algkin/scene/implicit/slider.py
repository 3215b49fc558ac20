"""A slider: the point on the line through P with direction d at distance l from Q, ahead or behind.

Closed form. ``X = P + (dot(d, w) + sigma*sqrt(disc)) / |d|**2 * d`` with ``w = Q - P`` and
``disc = l**2*|d|**2 - cross(d, w)**2``. Since ``dot(d, X - Q) = sigma*sqrt(disc)``,
``sigma = +1`` is the point ahead of the foot of the perpendicular from Q, along d.

Toggles: *tangent* where the circle about Q touches the line, ``cross(d, w)**2 = l**2 |d|**2``.

Stable floats: the root of the quadratic that cannot cancel, the other from their product,
``(|w|**2 - l**2) / |d|**2``.
"""

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np
import sympy

from .algebra import Circles, reducer, tidy_product
from .base import Fix, HalfAngle, ImplicitSpec, Point, StableEvaluator
from .floats import FloatArray

__all__ = ["SliderSpec"]


@dataclass(frozen=True)
class SliderSpec(ImplicitSpec):
    """A compiled slider: the line (a point on it, direction), the circle's centre and radius."""

    through: Point
    direction: tuple[sympy.Expr, sympy.Expr]
    center: Point
    length: sympy.Expr
    labels = ("ahead", "behind")
    never_meets = "the circle never meets the slider's line"

    def closed_form(self, substitution: Mapping[sympy.Symbol, sympy.Expr], sigma: int,
                    inputs: Circles) -> tuple[Point, sympy.Expr]:
        reduce = reducer(substitution, inputs)
        px, py = (reduce(v) for v in self.through)
        qx, qy = (reduce(v) for v in self.center)
        dx, dy = self.direction
        wx, wy = reduce(qx - px), reduce(qy - py)
        norm2 = dx**2 + dy**2
        dot, cross = reduce(dx * wx + dy * wy), reduce(dx * wy - dy * wx)
        norm = sympy.sqrt(norm2)
        if norm.is_rational:  # a difference of squares: (l|d| - cross)(l|d| + cross)
            disc = tidy_product(reduce(self.length * norm - cross), reduce(self.length * norm + cross))
        else:
            disc = tidy_product(reduce(self.length**2 * norm2 - cross**2))
        along = (dot + sigma * sympy.sqrt(disc)) / norm2
        return (px + along * dx, py + along * dy), disc

    def toggle_conditions(self) -> dict[str, sympy.Expr]:
        (px, py), (qx, qy), (dx, dy) = self.through, self.center, self.direction
        cross = dx * (qy - py) - dy * (qx - px)
        return {"tangent": cross**2 - self.length**2 * (dx**2 + dy**2)}

    def stable_evaluator(self, fix: Fix, arguments: list[sympy.Symbol], half_angles: Circles,
                         sigma: float) -> StableEvaluator:
        return _Stable(self, fix, arguments, sigma)


class _Stable:
    """One slider's evaluator: the root of its quadratic that cannot cancel, the other from their product.

    On the line ``X = P + a d`` at distance l from Q (``w = Q - P``):
    ``a |d|**2 = dot(d, w) + sigma sqrt(disc)``, ``disc = l**2 |d|**2 - cross(d, w)**2``;
    the two roots multiply to ``(|w|**2 - l**2) / |d|**2``.
    """

    def __init__(self, slider: SliderSpec, fix: Fix, arguments: list[sympy.Symbol], sigma: float) -> None:
        (px, py), (qx, qy) = slider.through, slider.center
        base = [fix(e) for e in (px, py, qx - px, qy - py)]
        self.unknowns = slider.unknowns
        self.base = sympy.lambdify(arguments, base, "numpy", cse=True)
        dx, dy = (fix(v) for v in slider.direction)
        length, norm = fix(slider.length), sympy.sqrt(dx**2 + dy**2)
        self.dx, self.dy, self.norm2, self.sigma = float(dx), float(dy), float(dx**2 + dy**2), sigma
        self.reach, self.length2 = float(length * norm), float(length**2)

    def __call__(self, values: Sequence[FloatArray], half: Sequence[HalfAngle]) -> tuple[FloatArray, FloatArray]:
        px, py, wx, wy = self.base(*values)
        dot, cross = self.dx * wx + self.dy * wy, self.dx * wy - self.dy * wx
        with np.errstate(invalid="ignore"):
            root = np.sqrt((self.reach - cross) * (self.reach + cross))
        larger = dot + np.copysign(root, dot)  # no cancellation: both terms of one sign
        with np.errstate(divide="ignore", invalid="ignore"):
            along = np.where(np.copysign(1.0, dot) == self.sigma, larger / self.norm2,
                             (wx * wx + wy * wy - self.length2) / larger)
        return px + along * self.dx, py + along * self.dy
