"""The second intersection of two circles that already meet at an earlier point: an inversor's point.

Two dyads on the same two circles (a Peaucellier cell's B and D, a kite, a rhombus), or a
dyad whose circles pass through a point built before it (the cell's P, whose circles about
B and D meet at A), make a system with a spurious component: where the two points
coincide, or their bases do, the equations hold for a whole curve of positions, and every
resultant vanishes. The two intersections of the circles about ``U`` (radius ``l1``) and
``V`` (radius ``l2``) are the roots of one quadratic: by Vieta, they are symmetric about the
foot ``F = U + a d`` on the line ``U -> V`` (``d = V - U``, ``a = (l1**2 - l2**2 + |d|**2) / (2 |d|**2)``).
So the new point ``X`` is the mirror image of the earlier one ``Y``: ``X = 2 F - Y``, two
equations linear in ``X``,

    ``|d|**2 (X + Y - 2 U) - (l1**2 - l2**2 + |d|**2) d = 0``,

which hold for the other intersection only, never for ``Y`` itself (unless the circles
touch, where the two are one). ``X`` has no assembly mode of its own: its side of
``U -> V`` is the one ``Y`` is not on, and the scene's ``branch`` for it must say so
(``side``, checked where the mechanism assembles).

Its closed form and stable floats: ``algkin.branches.constructions.mirror``.
"""

from collections.abc import Sequence
from dataclasses import dataclass

import sympy

from .base import FloatArray, FloatPoint, ImplicitSpec, Point

__all__ = ["MirrorSpec", "mirror_equations", "mirror_parts"]


def mirror_equations(x: Point, y: Point, u: Point, v: Point,
                     lengths: tuple[sympy.Expr, sympy.Expr]) -> list[sympy.Expr]:
    """The two equations, linear in ``x``, of ``x = 2 F - y`` (``F`` the foot of the circles' chord)."""
    dx, dy = v[0] - u[0], v[1] - u[1]
    difference = sympy.expand(lengths[0] ** 2 - lengths[1] ** 2)
    if difference == 0:  # equal radii: F is the midpoint, and |d|**2 would be a common factor (zero where U = V)
        return [x[i] + y[i] - u[i] - v[i] for i in range(2)]
    span = dx**2 + dy**2
    return [span * (x[i] + y[i] - 2 * u[i]) - (difference + span) * d for i, d in enumerate((dx, dy))]


@dataclass(frozen=True)
class MirrorSpec(ImplicitSpec):
    """A compiled second intersection: the circles' centres and radii, and the earlier point ``other`` on them."""

    base_p: Point
    base_q: Point
    lengths: tuple[sympy.Expr, sympy.Expr]
    other: str
    other_at: Point
    labels = ()  # no mode of its own: it is the intersection ``other`` is not
    never_meets = "its two centres coincide"

    def side(self) -> tuple[sympy.Expr, str]:
        """``(expression, message)``: the expression is > 0 where the point is on its scene's side of ``U -> V``."""
        (px, py), (qx, qy) = self.base_p, self.base_q
        x, y = (sympy.Symbol(u, real=True) for u in self.unknowns)
        cross = (qx - px) * (y - py) - (qy - py) * (x - px)  # > 0: left of U -> V
        other = "right" if self.branch == "left" else "left"
        return (cross if self.branch == "left" else -cross,
                f"the {self.branch} intersection of its circles is {self.other} itself; the other one is on the "
                f"{other}: branch = \"{other}\"")

    def written(self) -> list[sympy.Expr]:
        return mirror_equations(self.unknown_symbols(), self.other_at, self.base_p, self.base_q, self.lengths)

    def start_parts(self) -> tuple[sympy.Expr, ...]:
        return mirror_parts(self)

    @staticmethod
    def start(parts: Sequence[FloatArray], sigma: float) -> FloatPoint:
        """``2 U + a d - Y``, the mirror image of the earlier point (``sigma`` plays no part)."""
        bx, by, dx, dy, along = parts
        return bx + along * dx, by + along * dy


def mirror_parts(mirror: MirrorSpec) -> tuple[sympy.Expr, ...]:
    """``(2 U - Y, d, a)``: ``X = 2 U - Y + a d`` with ``a = (l1**2 - l2**2) / |d|**2 + 1``."""
    (px, py), (qx, qy) = mirror.base_p, mirror.base_q
    ox, oy = mirror.other_at
    dx, dy = qx - px, qy - py
    l1, l2 = mirror.lengths
    return 2 * px - ox, 2 * py - oy, dx, dy, (l1**2 - l2**2) / (dx**2 + dy**2) + 1

