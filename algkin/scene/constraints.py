"""Constraints on points solved together: ``dist(P, Q) = L``, ``dist(P, Q)**2 = L2``, ``on(P, line(A, B))``.

A scene's ``[constraints]`` table holds one string per constraint, each one polynomial equation
(``equation``) in the points' coordinates; ``L`` is a number, a parameter, an expression of
parameters, or a length input.

>>> import sympy
>>> leg = parse_constraint("dist(A1, P1) = r1", names={"r1": sympy.Symbol("r1")}, points={"A1", "P1"})
>>> leg
Constraint(kind='dist', points=('A1', 'P1'), value=r1)
>>> x, y = sympy.symbols("x y")
>>> leg.equation({"A1": (0, 0), "P1": (x, y)})
-r1**2 + x**2 + y**2
>>> parse_constraint("on(P, line(A, B))", names={}, points="PAB").equation({"P": (x, y), "A": (0, 0), "B": (1, 1)})
-x + y
>>> parse_constraint("dist(P, Q) = ", names={}, points="PQ")
Traceback (most recent call last):
...
ValueError: expected dist(P, Q) = L, dist(P, Q)**2 = L2 or on(P, line(A, B))
"""

from __future__ import annotations

import re
from collections.abc import Container, Mapping

import attrs
import sympy

from .expr import parse
from .implicit.base import Point

__all__ = ["Constraint", "parse_constraint", "FORMS"]

FORMS = "dist(P, Q) = L, dist(P, Q)**2 = L2 or on(P, line(A, B))"
_DIST = re.compile(r"^\s*dist\s*\(\s*(\w+)\s*,\s*(\w+)\s*\)\s*(\*\*\s*2)?\s*=\s*(\S.*)$", re.DOTALL)
_ON = re.compile(r"^\s*on\s*\(\s*(\w+)\s*,\s*line\s*\(\s*(\w+)\s*,\s*(\w+)\s*\)\s*\)\s*$")


@attrs.frozen
class Constraint:
    """``kind`` 'dist' (``|PQ| = value``), 'dist2' (``|PQ|**2 = value``) or 'on' (P on the line
    through A and B: ``points`` = (P, A, B), no value)."""

    kind: str
    points: tuple[str, ...]
    value: sympy.Expr | None = None

    def equation(self, coords: Mapping[str, Point]) -> sympy.Expr:
        """The constraint as a polynomial ``= 0`` in the points' coordinates."""
        if self.kind == "on":
            (px, py), (ax, ay), (bx, by) = (coords[p] for p in self.points)
            return sympy.expand((bx - ax) * (py - ay) - (by - ay) * (px - ax))
        (px, py), (qx, qy) = (coords[p] for p in self.points)
        assert self.value is not None
        target = self.value ** 2 if self.kind == "dist" else self.value
        return sympy.expand((px - qx) ** 2 + (py - qy) ** 2 - target)

    @property
    def text(self) -> str:
        """The constraint as a scene file writes it."""
        if self.kind == "on":
            return f"on({self.points[0]}, line({self.points[1]}, {self.points[2]}))"
        square = "**2" if self.kind == "dist2" else ""
        return f"dist({self.points[0]}, {self.points[1]}){square} = {self.value}"


def parse_constraint(text: str, *, names: Mapping[str, object], points: Container[str]) -> Constraint:
    """A constraint's string; ValueError saying what is wrong (the loader names the element)."""
    if match := _DIST.match(text):
        p, q, square, value = match.groups()
        refs: tuple[str, ...] = (p, q)
        if p == q:
            raise ValueError(f"dist({p}, {q}): a point's distance to itself is 0")
        constraint = Constraint("dist2" if square else "dist", refs, parse(value.strip(), names))
        if constraint.value is not None and constraint.value.is_number and not constraint.value > 0:
            raise ValueError(f"the length must be positive, got {constraint.value}")
    elif match := _ON.match(text):
        refs = match.groups()
        if refs[1] == refs[2]:
            raise ValueError(f"line({refs[1]}, {refs[2]}) has no direction: name two different points")
        if refs[0] in refs[1:]:
            raise ValueError(f"{refs[0]} lies on every line through it")
        constraint = Constraint("on", refs)
    else:
        raise ValueError(f"expected {FORMS}")
    for ref in refs:
        if ref not in points:
            raise ValueError(f"unknown point {ref!r}")
    return constraint
