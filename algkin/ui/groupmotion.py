"""A scene with points solved together (``unknown = true``), for drawing: its parts, its modes and their paths.

Nothing here solves anew. The configurations at an input are ``algkin solve``'s (certified), or,
where ``solve`` cannot decide them (an input a hair from a toggle), the end of a certified
continuation to it (``algkin follow``). A mode's path over the input's range is
``follow``'s: from a start where ``solve`` finds the mode (evenly spaced inputs), each way to
the range's ends or to where the mode meets another (a toggle, reported by ``follow`` and never
crossed). Between the certified steps' ends the path is filled in for drawing by float Newton
steps on the group's own equations from the straight line between them: inside one certified
step there is exactly one solution near that line, so the filling stays on the mode.

>>> motion = GroupMotion("3rpr")
>>> motion.input.name, motion.ground, [(c.kind, c.points) for c in motion.legs][:1]
('r1', ('A1', 'A2', 'A3'), [('dist', ('A1', 'P1'))])
>>> [c.label for c in motion.configurations(6)]
['---', '+++']
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from fractions import Fraction
from functools import cached_property
from typing import Any

import attrs
import numpy as np
import sympy
from numpy.typing import NDArray

from ..errors import AlgkinError, ComputationError, UsageError
from ..scene import Input, Scene
from ..scene.constraints import Constraint
from ..scene.constructions import Crank, Fixed, Frame
from ..scene.groups import Groups, compile_groups
from ..scene.load import as_scene

__all__ = ["GroupMotion", "ModePath", "Placed"]

SEEDS = 8
"""Evenly spaced pieces of a length input's range whose ends are tried as starts (an angle's multiples of 90 degrees)."""
DENSITY = 360
"""Samples of a path over the whole range, at least: the drawn path is this smooth."""
NEWTON = 8
SAME = 1e-3
"""Relative distance under which a configuration found at a start is one a path already holds (the
path interpolated there: far below the distance between two modes, far above the filling's error)."""

Floats = NDArray[np.float64]


@attrs.frozen
class Placed:
    """One configuration at an input: its mode's ``label`` (``solve``'s), every point's (x, y)
    as floats, and how it was found (``certified``: ``solve``; ``followed``: the end of ``follow``)."""

    label: str
    points: Mapping[str, tuple[float, float]]
    how: str


@attrs.frozen(eq=False)
class ModePath:
    """One mode over the input: ``label`` (``solve``'s at ``start``), the ascending ``inputs``
    (the input's unit), each point's ``(n, 2)`` positions, and each end's ``meets``: the input
    where it meets another mode, or None where the path reaches the range's end; ``name`` the
    label shown (with its start where two paths start with the same label)."""

    label: str
    start: Fraction
    inputs: Floats
    points: Mapping[str, Floats]
    meets: tuple[float | None, float | None]
    name: str = ""

    def covers(self, value: float) -> bool:
        return bool(self.inputs[0] <= value <= self.inputs[-1])

    def at(self, value: float) -> dict[str, tuple[float, float]]:
        """Each point at ``value`` (inside the path), interpolated between the samples."""
        return {p: (float(np.interp(value, self.inputs, xy[:, 0])), float(np.interp(value, self.inputs, xy[:, 1])))
                for p, xy in self.points.items()}


class GroupMotion:
    """A scene with points solved together, moved by its one input: its parts (``ground``,
    ``cranks``, ``legs``, ``rails``, ``platforms``), ``configurations`` at an input and each
    mode's path (``paths``)."""

    def __init__(self, scene: Scene | str) -> None:
        self.scene = as_scene(scene)
        if not self.scene.unknown_points:
            raise UsageError("scene", self.scene.name, "has no points solved together (unknown = true)")
        self.compiled: Groups = compile_groups(self.scene)
        self.input: Input = self._input()
        self.variables = self.compiled.inputs[self.input.name]
        self.unknowns = tuple(u for g in self.compiled.groups for u in g.unknowns)
        points = self.scene.points
        self.ground = tuple(n for n, c in points.items() if isinstance(c, Fixed))
        self.cranks = tuple((c.center, n) for n, c in points.items() if isinstance(c, Crank))
        self.platforms = tuple((*c.bases, n) for n, c in points.items() if isinstance(c, Frame))
        constraints = list(self.scene.constraints.values())
        self.legs: tuple[Constraint, ...] = tuple(c for c in constraints if c.kind in ("dist", "dist2"))
        self.rails: tuple[Constraint, ...] = tuple(c for c in constraints if c.kind == "on")
        self.moving = tuple(n for n, xy in self.compiled.coordinates.items()
                            if {str(s) for v in xy for s in sympy.sympify(v).free_symbols} & set(self.unknowns))
        self.built = tuple(n for n in self.compiled.coordinates if n not in self.moving)  # known from the input alone
        named = [p for o in self.scene.outputs.values() if o.kind == "point" for p in o.points]
        self.traced = tuple(p for p in self.moving if p in named) or self.moving[-1:]  # whose paths are drawn

    def _input(self) -> Input:
        """The one input the points move with (a UsageError for none or several)."""
        held = {str(s) for e in (*(e for g in self.compiled.groups for e in g.equations),
                                 *(v for xy in self.compiled.coordinates.values() for v in xy))
                for s in sympy.sympify(e).free_symbols}
        used = [n for n, names in self.compiled.inputs.items() if set(names) & held]
        if len(used) != 1:
            raise UsageError("scene", self.scene.name, f"moves with {len(used)} inputs ({', '.join(used) or 'none'}): "
                             "plot and export take points solved together that move with one input, for now")
        return self.scene.inputs[used[0]]

    # -- floats, for filling in and drawing

    @cached_property
    def _numeric(self) -> tuple[Any, Any, Any]:  # lambdified: equations, Jacobian, coordinates
        unknowns = [sympy.Symbol(u, real=True) for u in self.unknowns]
        variables = [sympy.Symbol(v, real=True) for v in self.variables]
        rename = {sympy.Symbol(n): sympy.Symbol(n, real=True) for n in (*self.unknowns, *self.variables)}
        equations = sympy.Matrix([e.xreplace(rename) for g in self.compiled.groups for e in g.equations])
        jacobian = equations.jacobian(unknowns)
        arguments = (unknowns, variables)
        coordinates = [sympy.sympify(v).xreplace(rename) for xy in self.compiled.coordinates.values() for v in xy]
        return (sympy.lambdify(arguments, equations, "numpy"), sympy.lambdify(arguments, jacobian, "numpy"),
                sympy.lambdify(arguments, coordinates, "numpy"))

    def input_values(self, value: float) -> list[float]:
        """The input's variables at ``value``: an angle's cos and sin, a length itself."""
        if not self.input.is_angle:
            return [value]
        radians = math.radians(value)
        return [math.cos(radians), math.sin(radians)]

    def place(self, unknowns: Sequence[float] | Floats, value: float) -> dict[str, tuple[float, float]]:
        """Every point's (x, y) from the unknowns' values at the input ``value``."""
        flat = self._numeric[2](list(unknowns), self.input_values(value))
        return {p: (float(flat[2 * k]), float(flat[2 * k + 1])) for k, p in enumerate(self.compiled.coordinates)}

    def newton(self, guess: Sequence[float], value: float) -> Floats:
        """Float Newton steps on the groups' equations at ``value`` from ``guess`` (fill-in only)."""
        F, J = self._numeric[0], self._numeric[1]
        x = np.array(guess, dtype=float)
        at = self.input_values(value)
        for _ in range(NEWTON):
            jacobian = np.asarray(J(list(x), at), dtype=np.float64)
            residual = np.asarray(F(list(x), at), dtype=np.float64).ravel()
            step = np.linalg.lstsq(jacobian, -residual, rcond=None)[0]
            x = x + step
            if np.max(np.abs(step)) <= 1e-15 * (1 + np.max(np.abs(x))):
                break
        return x

    # -- configurations and paths

    def configurations(self, value: float | Fraction | str) -> list[Placed]:
        """Every real configuration at the input ``value``: ``solve``'s where it takes the input,
        else each path's covering the input followed to it (``follow``, certified)."""
        from ..analyses.solve import solve

        exact = _exact(value)
        try:
            found = solve(self.scene, {self.input.name: exact}, digits=17)
        except UsageError as err:
            if err.argument != "at":  # an angle solve cannot take yet: follow there instead
                raise
            return self._followed_to(exact)
        return [Placed(c.mode, {p: (float(x), float(y)) for p, (x, y) in c.points.items()}, "certified")
                for c in found.configurations]

    def _followed_to(self, value: Fraction) -> list[Placed]:
        from ..analyses.follow import follow

        placed = []
        for path in self.paths:
            if path.covers(float(value)) and path.start != value:
                ended = follow(self.scene, mode=path.label, start={self.input.name: path.start}, stop=value, digits=17)
                if ended.ended == "reached":
                    last = ended.samples[-1].points
                    placed.append(Placed(path.name, {p: (float(x), float(y)) for p, (x, y) in last.items()},
                                         "followed"))
        return placed

    def seeds(self) -> list[Fraction]:
        """The starts tried: a length's range cut evenly, an angle's multiples of 90 degrees in it."""
        lo, hi = (Fraction(v).limit_denominator(10**6) for v in self.input.span)
        if self.input.is_angle:
            found = [Fraction(90 * k) for k in range(math.ceil(lo / 90), math.floor(hi / 90) + 1)]
            return found or [lo]
        return [lo + (hi - lo) * k / SEEDS for k in range(SEEDS + 1)]

    @cached_property
    def paths(self) -> tuple[ModePath, ...]:
        """Every mode found at a start, followed both ways to the range's ends or a meeting."""
        from ..analyses.solve import solve

        paths: list[ModePath] = []
        for seed in self.seeds():
            for configuration in solve(self.scene, {self.input.name: seed}, digits=17).configurations:
                points = {p: (float(x), float(y)) for p, (x, y) in configuration.points.items()}
                if not any(path.covers(float(seed)) and _same(path.at(float(seed)), points) for path in paths):
                    paths.append(self._path(configuration.mode, seed))
        labels = [p.label for p in paths]
        return tuple(attrs.evolve(p, name=f"{p.label} (from {self.input.name} = {self.input.shown(float(p.start))})"
                                  if labels.count(p.label) > 1 else p.label) for p in paths)

    def _path(self, label: str, seed: Fraction) -> ModePath:
        from ..analyses.follow import follow

        lo, hi = (Fraction(v).limit_denominator(10**6) for v in self.input.span)
        legs: list[tuple[list[float], list[list[float]], float | None]] = []
        for stop in (lo, hi):
            if stop == seed:
                legs.append(([], [], None))
                continue
            ended = follow(self.scene, mode=label, start={self.input.name: seed}, stop=stop, digits=17)
            inputs = [float(Fraction(s.at)) for s in ended.samples]
            values = [[float(s.values[u].mid()) for u in self.unknowns] for s in ended.samples]
            meets = None if ended.meeting is None else float(Fraction(ended.meeting["from"]) + Fraction(ended.meeting["to"])) / 2
            legs.append((inputs, values, meets))
        (back, back_x, low), (ahead, ahead_x, high) = legs
        inputs = back[::-1] + ahead[1:] if back else ahead
        values = back_x[::-1] + ahead_x[1:] if back else ahead_x
        if not inputs:  # the range is one point
            raise ComputationError(f"{self.scene.name}: {self.input.name}'s range is a single value")
        filled_t, filled_x = self._filled(inputs, values, float(hi - lo))
        placed = [self.place(x, t) for t, x in zip(filled_t, filled_x)]
        points = {p: np.array([q[p] for q in placed]) for p in self.compiled.coordinates}
        return ModePath(label, seed, np.array(filled_t), points, (low, high))

    def _filled(self, inputs: Sequence[float], values: Sequence[Sequence[float]],
                span: float) -> tuple[list[float], list[Floats]]:
        """The certified steps' ends with float Newton points between them, ``DENSITY`` over the span."""
        filled_t, filled_x = [inputs[0]], [np.array(values[0])]
        for (ta, xa), (tb, xb) in zip(zip(inputs, values), zip(inputs[1:], values[1:])):
            pieces = max(1, math.ceil((tb - ta) / span * DENSITY))
            for k in range(1, pieces):
                t = ta + (tb - ta) * k / pieces
                guess = np.array(xa) + (np.array(xb) - np.array(xa)) * k / pieces
                filled_t.append(t)
                filled_x.append(self.newton(guess, t))
            filled_t.append(tb)
            filled_x.append(np.array(xb))
        return filled_t, filled_x

    def start(self) -> Fraction:
        """The input drawn by default: the start where the most modes were found."""
        counts = {s: sum(p.covers(float(s)) for p in self.paths) for s in self.seeds()}
        return max(counts, key=lambda s: counts[s])


def _exact(value: float | Fraction | str) -> Fraction:
    try:
        return Fraction(str(value))
    except (ValueError, ZeroDivisionError):
        raise AlgkinError(f"not a number: {value!r}") from None


def _same(a: Mapping[str, tuple[float, float]], b: Mapping[str, tuple[float, float]]) -> bool:
    scale = 1 + max(abs(v) for xy in b.values() for v in xy)
    return max(abs(a[p][k] - b[p][k]) for p in b for k in (0, 1)) <= SAME * scale
