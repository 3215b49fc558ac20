"""Where two lines meet: the line through A and B, and the line through C and D (each may move).

``X`` lies on both lines: ``cross(u, X - A) = 0`` and ``cross(v, X - C) = 0`` with ``u = B - A``
and ``v = D - C``, two equations linear in ``X``. By Cramer's rule
``X = A + cross(v, C - A) / cross(v, u) * u``: rational in the four points, one point, no
assembly mode. It exists where ``cross(u, v) != 0``; where the lines turn parallel it runs
off to infinity. Its closed form and stable floats: ``algkin.branches.constructions.meet``.
"""

from collections.abc import Sequence
from dataclasses import dataclass

import sympy

from .base import FloatArray, FloatPoint, ImplicitSpec, Point

__all__ = ["MeetSpec", "meet_equations"]


def meet_equations(x: Point, first: tuple[Point, Point], second: tuple[Point, Point]) -> list[sympy.Expr]:
    """``cross(B - A, X - A)`` and ``cross(D - C, X - C)``: zero where ``x`` is on both lines."""
    return [(b[0] - a[0]) * (x[1] - a[1]) - (b[1] - a[1]) * (x[0] - a[0]) for a, b in (first, second)]


@dataclass(frozen=True)
class MeetSpec(ImplicitSpec):
    """A compiled meet: the points A, B of the first line and C, D of the second, in system variables."""

    first: tuple[Point, Point]
    second: tuple[Point, Point]
    labels = ()  # one point: no mode of its own
    never_meets = "its two lines are parallel"

    def determinant(self) -> sympy.Expr:
        """``cross(B - A, D - C)``: zero where the lines are parallel (the point is then at infinity)."""
        (a, b), (c, d) = self.first, self.second
        return (b[0] - a[0]) * (d[1] - c[1]) - (b[1] - a[1]) * (d[0] - c[0])

    def written(self) -> list[sympy.Expr]:
        return meet_equations(self.unknown_symbols(), self.first, self.second)

    def start_parts(self) -> tuple[sympy.Expr, ...]:
        (a, b), (c, d) = self.first, self.second
        return (*a, *b, *c, *d)

    @staticmethod
    def start(parts: Sequence[FloatArray], sigma: float) -> FloatPoint:
        """Cramer's rule in floats (``sigma`` plays no part)."""
        ax, ay, bx, by, cx, cy, dx, dy = parts
        ux, uy, vx, vy = bx - ax, by - ay, dx - cx, dy - cy
        along = (vx * (cy - ay) - vy * (cx - ax)) / (vx * uy - vy * ux)
        return ax + along * ux, ay + along * uy
