"""What a synthesis starts from: exact angles, poses of a moving plane, angle pairs, points.

Every number is exact (python-flint ``fmpq``), so the systems synthesis solves are over QQ and
its counts are of the problem, not of rounding. An angle is its cos and sin, exactly on the
unit circle; an angle given in degrees is replaced by the nearest angle whose half-angle tangent
is a 60-digit rational (``approximate`` says so: within 1e-58 degrees).

>>> half = Angle.of_tan_half(flint.fmpq(1, 2))
>>> str(half.cos), str(half.sin), half.approximate
('3/5', '4/5', False)
>>> pose = Pose(flint.fmpq(1), flint.fmpq(0), half)
>>> [str(c) for c in pose.place(flint.fmpq(5), flint.fmpq(0))]       # (1, 0) + 5 * (3/5, 4/5)
['4', '4']
>>> Angle.of_degrees(90) == Angle(flint.fmpq(0), flint.fmpq(1)), Angle.of_degrees(30).approximate
(True, True)
>>> Angle.of_cos_sin(flint.fmpq(1, 2), flint.fmpq(1, 2))
Traceback (most recent call last):
...
ValueError: cos**2 + sin**2 is 1/2, not 1
"""

from __future__ import annotations

from collections.abc import Sequence
from decimal import Decimal, localcontext
from typing import TypeVar

import attrs
import flint
import mpmath

__all__ = ["Angle", "Pose", "AnglePair", "Point", "DIGITS", "dyad_poses"]

DIGITS = 60
"""Digits of an angle given in degrees (its half-angle tangent's)."""

T = TypeVar("T", flint.fmpq, flint.arb, flint.fmpq_mpoly)
Point = tuple[flint.fmpq, flint.fmpq]
"""A point of the plane, exactly."""


@attrs.frozen
class Angle:
    """An angle by its exact ``cos`` and ``sin`` (``cos**2 + sin**2 == 1``); ``approximate``
    when it stands for an angle in degrees whose cos and sin are irrational."""

    cos: flint.fmpq
    sin: flint.fmpq
    approximate: bool = False

    def __attrs_post_init__(self) -> None:
        norm = self.cos**2 + self.sin**2
        if norm != 1:
            raise ValueError(f"cos**2 + sin**2 is {norm}, not 1")

    @classmethod
    def of_cos_sin(cls, cos: flint.fmpq, sin: flint.fmpq) -> Angle:
        return cls(flint.fmpq(cos), flint.fmpq(sin))

    @classmethod
    def of_tan_half(cls, t: flint.fmpq) -> Angle:
        """The angle whose half has tangent ``t``: cos = (1 - t**2)/(1 + t**2), sin = 2t/(1 + t**2)."""
        t = flint.fmpq(t)
        return cls((1 - t**2) / (1 + t**2), 2 * t / (1 + t**2))

    @classmethod
    def of_degrees(cls, degrees: int | flint.fmpq | str) -> Angle:
        """Exact at multiples of 90 degrees; otherwise within 1e-58 degrees, ``approximate``."""
        value = flint.fmpq(degrees) if not isinstance(degrees, str) else _decimal(degrees)
        quarter = value / 90
        if quarter.q == 1:
            cos, sin = [(1, 0), (0, 1), (-1, 0), (0, -1)][int(quarter.p) % 4]
            return cls(flint.fmpq(cos), flint.fmpq(sin))
        with mpmath.workdps(DIGITS + 20):
            half = mpmath.tan(mpmath.mpf(int(value.p)) / int(value.q) * mpmath.pi / 360)
            with localcontext() as context:
                context.prec = DIGITS + 20
                digits = Decimal(mpmath.nstr(half, DIGITS, min_fixed=-mpmath.inf, max_fixed=mpmath.inf))
        numerator, denominator = digits.as_integer_ratio()
        return attrs.evolve(cls.of_tan_half(flint.fmpq(numerator, denominator)), approximate=True)

    def rotate(self, x: T, y: T) -> tuple[T, T]:
        """``(x, y)`` turned by the angle."""
        return self.cos * x - self.sin * y, self.sin * x + self.cos * y

    def degrees(self) -> float:
        return float(mpmath.degrees(mpmath.atan2(_mpf(self.sin), _mpf(self.cos))))


@attrs.frozen
class Pose:
    """A position of a moving plane: its origin at ``(x, y)``, turned by ``angle``."""

    x: flint.fmpq
    y: flint.fmpq
    angle: Angle

    def place(self, x: T, y: T) -> tuple[T, T]:
        """Where the moving plane's point ``(x, y)`` is in this pose: the origin plus it turned."""
        dx, dy = self.angle.rotate(x, y)
        return self.x + dx, self.y + dy


@attrs.frozen
class AnglePair:
    """A precision pair of function generation: the crank's ``input`` and the rocker's
    ``output`` angle (absolute, or offsets from unknown starting angles)."""

    input: Angle
    output: Angle


def dyad_poses(crank: Sequence[Angle], plane: Sequence[Angle], *, circle: Point, centre: Point,
               radius: flint.fmpq) -> list[Pose]:
    """Poses that the dyad (``circle`` in the moving plane, ``centre`` fixed, ``radius`` apart)
    reaches, exactly: its circle point on the circle about the centre at each ``crank`` angle, the
    plane turned by the matching ``plane`` angle (test data with a known answer).

    >>> half = lambda t: Angle.of_tan_half(flint.fmpq(t))
    >>> pose, = dyad_poses([half(0)], [half(1)], circle=(flint.fmpq(1), flint.fmpq(0)),
    ...                    centre=(flint.fmpq(0), flint.fmpq(0)), radius=flint.fmpq(2))
    >>> [str(c) for c in pose.place(flint.fmpq(1), flint.fmpq(0))]      # at (2, 0), 2 from the centre
    ['2', '0']
    """
    poses = []
    for turn, angle in zip(crank, plane):
        point = (centre[0] + radius * turn.cos, centre[1] + radius * turn.sin)
        moved = angle.rotate(circle[0], circle[1])
        poses.append(Pose(point[0] - moved[0], point[1] - moved[1], angle))
    return poses


def _decimal(text: str) -> flint.fmpq:
    numerator, denominator = Decimal(text).as_integer_ratio()
    return flint.fmpq(numerator, denominator)


def _mpf(value: flint.fmpq) -> mpmath.mpf:
    return mpmath.mpf(int(value.p)) / int(value.q)
