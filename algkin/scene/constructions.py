"""The constructions a scene's points are built with: one small class each.

Each construction knows the points it refers to and how it turns into polynomial
terms: an *explicit* point is a polynomial in earlier coordinates; an *implicit* point
(dyad, slider) brings two unknowns, two equations, a branch indicator whose sign is
the geometric label, and its compiled spec (``implicit``: its geometry; its branch algebra
is in ``algkin.branches.constructions``).
"""

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Protocol

import sympy

from .implicit import DyadSpec, ImplicitSpec, MeetSpec, MirrorSpec, SliderSpec
from .implicit.algebra import reduce_on_circles
from .implicit.meet import meet_equations
from .implicit.mirror import mirror_equations
from .implicit.base import Point

__all__ = ["Construction", "Fixed", "Crank", "Dyad", "Slider", "Frame", "Meet", "Unknown", "Mode", "CONSTRUCTIONS",
           "Builder", "Indicator", "Unbuildable"]


class Unbuildable(ValueError):
    """A construction that cannot make a point of its own (compile names the scene and the point)."""


@dataclass(frozen=True)
class Indicator:
    """Sign of ``expr`` names the branch: > 0 is ``positive``, < 0 is ``negative``."""

    point: str
    expr: sympy.Expr
    positive: str
    negative: str
    chosen: str


@dataclass(frozen=True)
class Mode:
    """``mode = { at = v, near = [x, y] }``: the assembly mode meant is the one whose point lies
    nearest ``near`` when the inputs take the values ``at`` (input name -> exact value, in the
    input's unit); ``algkin.derivation.modes`` resolves and follows it along the motion."""

    at: tuple[tuple[str, sympy.Rational], ...]
    near: tuple[sympy.Rational, sympy.Rational]


class Builder:
    """Collects unknowns, equations, branch indicators and implicit points' specs while a scene compiles."""

    def __init__(self, inputs: Mapping[str, tuple[sympy.Symbol, sympy.Symbol]],
                 driven: Mapping[str, tuple[sympy.Expr, sympy.Expr]] | None = None) -> None:
        self.inputs = inputs  # input name -> (cos symbol, sin symbol)
        self.driven = driven or {}  # geared input name -> (cos, sin) polynomials in its root input's symbols
        self.unknowns: list[sympy.Symbol] = []
        self.equations: list[sympy.Expr] = []
        self.indicators: list[Indicator] = []
        self.implicit: dict[str, ImplicitSpec] = {}  # every implicit point's spec, in construction order
        self.distances: list[tuple[frozenset[str], sympy.Expr]] = []  # |PQ| = l, as the constructions impose it

    def unknown(self, name: str) -> sympy.Symbol:
        symbol = sympy.Symbol(name, real=True)
        self.unknowns.append(symbol)
        return symbol

    def angle(self, name: str) -> tuple[sympy.Expr, sympy.Expr]:
        """The cos and sin of the angle input ``name``: its symbols, or a geared input's polynomials in them."""
        return self.driven[name] if name in self.driven else self.inputs[name]

    def distance(self, p: str, q: str, length: sympy.Expr) -> None:
        """Record that the constructions hold ``|pq| = length``."""
        self.distances.append((frozenset((p, q)), length))

    def on_both_circles(self, centres: tuple[str, str], lengths: tuple[sympy.Expr, sympy.Expr]) -> list[str]:
        """The points already held at ``lengths`` from both ``centres``: intersections of the same two circles."""
        def held(p: str, length: sympy.Expr) -> set[str]:
            return {name for pair, known in self.distances if p in pair and sympy.expand(known - length) == 0
                    for name in pair - {p}}
        return sorted(held(centres[0], lengths[0]) & held(centres[1], lengths[1]))


class Construction(Protocol):
    """How a point is built: the points it refers to, its assembly modes (none if explicit), its terms."""

    @property
    def references(self) -> tuple[str, ...]: ...

    @property
    def labels(self) -> tuple[str, ...]: ...

    def build(self, name: str, coords: Mapping[str, Point], builder: Builder) -> Point:
        """The point's coordinates, adding its unknowns and equations to ``builder`` if it has any."""
        ...


def _rot90(v: Point) -> Point:
    return (-v[1], v[0])


@dataclass(frozen=True)
class Fixed:
    """``fixed = [x, y]``: a ground point."""

    x: sympy.Expr
    y: sympy.Expr
    references = ()
    labels = ()

    def build(self, name: str, coords: Mapping[str, Point], builder: Builder) -> Point:
        return (self.x, self.y)


QUARTER_TURNS = ((1, 0), (0, 1), (-1, 0), (0, -1))  # (cos, sin) of 0, 90, 180, 270 degrees


@dataclass(frozen=True)
class Crank:
    """``crank = P, length = L, input = t, phase = ...``: ``P + L*(cos(t+phase), sin(t+phase))``.

    The phase is kept as its exact cosine and sine (a multiple of 90 degrees, a rational point
    of the unit circle, or parameters), so that the coordinates stay polynomial over the rationals.
    """

    center: str
    length: sympy.Expr
    input: str
    phase: tuple[sympy.Expr, sympy.Expr] = (sympy.Integer(1), sympy.Integer(0))  # (cos, sin)
    labels = ()

    @property
    def references(self) -> tuple[str, ...]:
        return (self.center,)

    @property
    def quarter_turns(self) -> int | None:
        """The phase as a number of quarter turns, or None when it is no multiple of 90 degrees."""
        return next((k for k, pair in enumerate(QUARTER_TURNS) if self.phase == pair), None)

    def build(self, name: str, coords: Mapping[str, Point], builder: Builder) -> Point:
        c, s = builder.angle(self.input)
        cos_phase, sin_phase = self.phase
        px, py = coords[self.center]
        builder.distance(self.center, name, self.length)
        return (
            px + self.length * (cos_phase * c - sin_phase * s),
            py + self.length * (sin_phase * c + cos_phase * s),
        )


@dataclass(frozen=True)
class Dyad:
    """``dyad = [P, Q], lengths = [l1, l2], branch = left/right``: two circles meet."""

    bases: tuple[str, str]
    lengths: tuple[sympy.Expr, sympy.Expr]
    branch: str  # with a ``mode``: the mode's label at its ``at`` once resolved (the first label before)
    mode: Mode | None = None
    labels = DyadSpec.labels

    @property
    def references(self) -> tuple[str, ...]:
        return self.bases

    def build(self, name: str, coords: Mapping[str, Point], builder: Builder) -> Point:
        met = builder.on_both_circles(self.bases, self.lengths)
        for base, length in zip(self.bases, self.lengths):
            builder.distance(base, name, length)
        if met:  # the circles' other intersection: by Vieta, never the point already there
            return self._mirror(name, met, coords, builder)
        (px, py), (qx, qy) = coords[self.bases[0]], coords[self.bases[1]]
        x, y = builder.unknown(f"{name}_x"), builder.unknown(f"{name}_y")
        l1, l2 = self.lengths
        builder.equations += [
            (x - px) ** 2 + (y - py) ** 2 - l1**2,
            (x - qx) ** 2 + (y - qy) ** 2 - l2**2,
        ]
        # cross(Q - P, X - P) > 0: X lies left of the directed line P -> Q.
        cross = (qx - px) * (y - py) - (qy - py) * (x - px)
        builder.indicators.append(Indicator(name, cross, "left", "right", self.branch))
        spec = DyadSpec(point=name, unknowns=(x.name, y.name), branch=self.branch, base_p=(px, py),
                        base_q=(qx, qy), lengths=self.lengths)
        builder.implicit[name] = spec
        return (x, y)

    def _mirror(self, name: str, met: list[str], coords: Mapping[str, Point], builder: Builder) -> Point:
        if len(met) > 1:
            raise Unbuildable(f"its two circles meet only at {met[0]} and {met[1]}, both built already")
        u, v = coords[self.bases[0]], coords[self.bases[1]]
        x, y = builder.unknown(f"{name}_x"), builder.unknown(f"{name}_y")
        builder.equations += mirror_equations((x, y), coords[met[0]], u, v, self.lengths)
        builder.implicit[name] = MirrorSpec(point=name, unknowns=(x.name, y.name), branch=self.branch, base_p=u,
                                            base_q=v, lengths=self.lengths, other=met[0], other_at=coords[met[0]])
        return (x, y)


@dataclass(frozen=True)
class Slider:
    """``slider = {through = P, direction = [dx, dy]}, distance = {to = Q, length = l}``, or
    ``slider = {through = P, toward = R}``: the line through two points, moving with them.

    On the line through P with the direction d (fixed, or ``R - P``), at distance l from Q. The
    branch is ``ahead`` when ``dot(d, X - Q) > 0`` (X lies ahead of the foot of the perpendicular
    from Q, along d), ``behind`` when it is < 0: the same all along the motion. Exactly one of
    ``direction`` and ``toward`` is given.
    """

    through: str
    direction: tuple[sympy.Expr, sympy.Expr] | None
    to: str
    length: sympy.Expr
    branch: str
    toward: str | None = None
    mode: Mode | None = None  # as a dyad's
    labels = SliderSpec.labels

    @property
    def references(self) -> tuple[str, ...]:
        return (self.through, self.to) if self.toward is None else (self.through, self.toward, self.to)

    def line_direction(self, coords: Mapping[str, Point]) -> tuple[sympy.Expr, sympy.Expr]:
        """The line's direction: the fixed one, or ``R - P`` in system variables."""
        if self.toward is None:
            assert self.direction is not None
            return self.direction
        (px, py), (rx, ry) = coords[self.through], coords[self.toward]
        return (sympy.expand(rx - px), sympy.expand(ry - py))

    def build(self, name: str, coords: Mapping[str, Point], builder: Builder) -> Point:
        (px, py), (qx, qy) = coords[self.through], coords[self.to]
        dx, dy = self.line_direction(coords)
        if self.toward is not None and dx == 0 and dy == 0:
            raise Unbuildable(f"its line through {self.through} toward {self.toward} has no direction: "
                              "the two points coincide")
        builder.distance(self.to, name, self.length)
        x, y = builder.unknown(f"{name}_x"), builder.unknown(f"{name}_y")
        builder.equations += [
            dx * (y - py) - dy * (x - px),  # X - P is parallel to d
            (x - qx) ** 2 + (y - qy) ** 2 - self.length**2,
        ]
        along = dx * (x - qx) + dy * (y - qy)
        builder.indicators.append(Indicator(name, along, "ahead", "behind", self.branch))
        builder.implicit[name] = SliderSpec(point=name, unknowns=(x.name, y.name), branch=self.branch,
                                            through=(px, py), direction=(dx, dy), center=(qx, qy),
                                            length=self.length)
        return (x, y)


@dataclass(frozen=True)
class Frame:
    """``frame = [P, Q], at = [u, v]``: ``P + u*(Q-P) + v*rot90(Q-P)``, rigid with bar PQ."""

    bases: tuple[str, str]
    at: tuple[sympy.Expr, sympy.Expr]
    labels = ()

    @property
    def references(self) -> tuple[str, ...]:
        return self.bases

    def build(self, name: str, coords: Mapping[str, Point], builder: Builder) -> Point:
        (px, py), (qx, qy) = coords[self.bases[0]], coords[self.bases[1]]
        d = (qx - px, qy - py)
        n = _rot90(d)
        u, v = self.at
        return (px + u * d[0] + v * n[0], py + u * d[1] + v * n[1])


@dataclass(frozen=True)
class Meet:
    """``meet = [[A, B], [C, D]]``: where the line through A and B meets the line through C and D
    (a slot and a rod, two sliders' lines, a four-bar's instant centre); rational in the four
    points, one point, no branch. Where the lines turn parallel it does not assemble."""

    lines: tuple[tuple[str, str], tuple[str, str]]
    labels = ()

    @property
    def references(self) -> tuple[str, ...]:
        return (*self.lines[0], *self.lines[1])

    def build(self, name: str, coords: Mapping[str, Point], builder: Builder) -> Point:
        a, b, c, d = (coords[p] for p in self.references)
        first, second = (a, b), (c, d)
        for (start, end), line in zip((first, second), self.lines):
            if sympy.expand(end[0] - start[0]) == 0 and sympy.expand(end[1] - start[1]) == 0:
                raise Unbuildable(f"its line through {line[0]} and {line[1]} has no direction: the two points "
                                  "coincide")
        x, y = builder.unknown(f"{name}_x"), builder.unknown(f"{name}_y")
        spec = MeetSpec(point=name, unknowns=(x.name, y.name), branch="unique", first=first, second=second)
        if reduce_on_circles(spec.determinant(), list(builder.inputs.values())) == 0:
            raise Unbuildable(f"its lines {'-'.join(self.lines[0])} and {'-'.join(self.lines[1])} are parallel "
                              "for every input: they never meet in one point")
        builder.equations += meet_equations((x, y), first, second)
        builder.implicit[name] = spec
        return (x, y)


@dataclass(frozen=True)
class Unknown:
    """``unknown = true``: a point held by the scene's ``[constraints]``, solved together with the
    others of its group (``algkin.scene.groups``), never built on its own; a ``mode`` names the
    group's mode that ``algkin solve`` keeps."""

    mode: Mode | None = None
    references = ()
    labels = ()

    def build(self, name: str, coords: Mapping[str, Point], builder: Builder) -> Point:
        raise Unbuildable("it is solved together with others (unknown = true), not built on its own")


CONSTRUCTIONS: dict[str, type[Construction]] = {"fixed": Fixed, "crank": Crank, "dyad": Dyad, "frame": Frame,
                                                 "slider": Slider, "meet": Meet, "unknown": Unknown}
