"""Every point of a scene as a closed form, per assembly mode, derived once for drawing.

A ``Motion`` compiles the whole scene with its dimensions symbolic (those that keep the
system polynomial), takes the closed-form branches, and substitutes them into every
point's construction. Moving a slider, drawing a frame or writing the browser page only
*evaluates* these expressions; nothing is derived again. Where a branch's dyad or slider
discriminant is negative the configuration cannot assemble: its points are ``None`` (or
nan in a sweep) and ``blocked`` names the points that fail.

>>> motion = Motion("chebyshev-lambda")
>>> [b.label for b in motion.branches], motion.traced
(['left', 'right'], ['P'])
>>> frame = motion.at({"angle": 0})
>>> [round(v, 12) for v in frame.points["B"]], [round(v, 12) for v in frame.points["P"]]
([1.5, 2.449489742783], [2.0, 4.898979485566])
>>> motion.bars
[('O', 'A'), ('A', 'B'), ('D', 'B'), ('A', 'P'), ('B', 'P')]
"""

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import TypeVar

import numpy as np
import sympy
from numpy.typing import ArrayLike, NDArray

from ..runtime import suggest, validation
from ..branches import closed_forms
from ..errors import UsageError
from ..evaluate import NUMPY, evaluate
from ..derivation.prepared import Prepared, given
from ..scene import Scene, compile_scene, load_scene
from ..scene.compile import Compiled
from ..scene.implicit.base import FloatArray
from ..scene.load import SceneLike
from ..scene.constructions import Crank, Dyad, Fixed, Frame, Meet, Slider
from ..system import input_values, symbol

__all__ = ["Motion", "Pose", "symbolic_parameters", "Trajectories"]

_V = TypeVar("_V")
XY = tuple[FloatArray, FloatArray]
Trajectories = dict[str, XY]  # point -> its x and y over the samples (nan where it cannot assemble)
Blocked = dict[str, NDArray[np.bool_]]  # point -> where its discriminant is negative


@dataclass(frozen=True)
class Pose:
    """One configuration: point -> (x, y) floats, or ``None`` everywhere if it cannot assemble."""

    inputs: dict[str, float]  # input name -> degrees (a length input: its length)
    parameters: dict[str, float]  # symbolic dimension -> value
    branch: str
    points: dict[str, tuple[float, float] | None]
    blocked: tuple[str, ...]  # points whose discriminant is negative

    @property
    def assembles(self) -> bool:
        return not self.blocked


def symbolic_parameters(scene: Scene, wanted: Sequence[str] | None = None) -> tuple[tuple[str, ...], Compiled]:
    """The dimensions that can stay symbolic while the scene compiles to polynomials.

    By default every dimension is tried, and one under a division (the arm's ``g/r``) takes
    its default; dimensions named in ``wanted`` must all stay symbolic.
    """
    kept = list(scene.parameters if wanted is None else wanted)
    while True:
        try:
            return tuple(kept), compile_scene(scene, list(scene.points), kept)
        except UsageError as err:
            if wanted is not None or err.argument != "params" or err.value not in kept:
                raise
            kept.remove(err.value)


def _every_point(prepared: Prepared) -> Compiled:
    """The prepared scene's compiled system, which must hold every point's coordinates."""
    missing = [p for p in prepared.scene.points if p not in prepared.compiled.coordinates]
    if missing:
        raise UsageError("scene", prepared.scene.name, f"prepared without {', '.join(missing)}: a motion draws every "
                         "point (prepare it with outputs=list(scene.points))")
    return prepared.compiled


class Motion:
    """Closed forms of every point of ``scene`` on every branch, dimensions symbolic.

    ``scene`` may be a ``Prepared`` one (``algkin.prepare``) with every point among its outputs:
    its branches are taken as they are. Given a scene, the motion compiles it itself, with no
    check that it assembles (a drawing shows where it does not)."""

    def __init__(self, scene: SceneLike | Prepared, params: Sequence[str] | None = None) -> None:
        params = validation.names("params", params)  # a lone string would split into letters
        if isinstance(scene, Prepared):
            given(scene, params=params)
            self.scene, self.compiled, self.branches = scene.scene, _every_point(scene), list(scene.branches)
            self.params = self.compiled.system.parameters
        else:
            self.scene = scene if isinstance(scene, Scene) else load_scene(scene)
            self.params, self.compiled = symbolic_parameters(self.scene, params)
            self.branches = closed_forms(self.compiled)
        self.inputs = {n: self.scene.inputs[n] for n in self.compiled.system.inputs}
        if not self.inputs:  # a scene of dimensions alone (a length swept as a parameter): nothing to sweep
            raise UsageError("scene", self.scene.name, "has no input: nothing moves to draw (a length that "
                                                      "moves is an input with unit = \"length\")")
        self.defaults = {n: float(v) for n, v in self.compiled.parameter_values.items()}
        self.points = self._point_forms()

    def _point_forms(self) -> list[dict[str, tuple[sympy.Expr, sympy.Expr]]]:
        """Per branch: point -> (x, y) sympy expressions in c_*, s_* and the symbolic dimensions."""
        forms = []
        for branch in self.branches:
            substitution = {symbol(u): v for u, v in branch.values.items()}
            forms.append({p: tuple(v.xreplace(substitution) for v in xy)
                          for p, xy in self.compiled.coordinates.items()})
        return forms

    @property
    def selected(self) -> int:
        """Index of the branch the scene file asks for."""
        return next(k for k, b in enumerate(self.branches) if b.selected)

    def branch_index(self, label: str | None = None) -> int:
        """Index of the branch called ``label`` (the scene's own when ``None``)."""
        if label is None:
            return self.selected
        for k, branch in enumerate(self.branches):
            if branch.label == label:
                return k
        known = ", ".join(b.label for b in self.branches)
        raise UsageError("branch", label, f"not a branch of {self.scene.name} (branches: {known})")

    @property
    def bars(self) -> list[tuple[str, str]]:
        """Pairs of points joined by a rigid link, in construction order."""
        bars: list[tuple[str, str]] = []
        for name, c in self.scene.points.items():
            if isinstance(c, Crank):
                bars.append((c.center, name))
            elif isinstance(c, (Dyad, Frame)):
                bars += [(c.bases[0], name), (c.bases[1], name)]
            elif isinstance(c, Slider):
                bars.append((c.to, name))
                if c.toward is not None:  # a moving line: the slotted bar through its two points
                    bars.append((c.through, c.toward))
            elif isinstance(c, Meet):  # each line drawn out to where they meet
                bars += [(p, name) for p in c.references]
        return bars

    @property
    def ground(self) -> list[str]:
        """Fixed points: pivots, guides and anchors (the arm's B)."""
        return [n for n, c in self.scene.points.items() if isinstance(c, Fixed)]

    @property
    def guides(self) -> list[tuple[str, str, tuple[float, float]]]:
        """The fixed line of each slider point: (slider point, a point on the line, direction); a line
        through two points is drawn as their bar (``bars``)."""
        at = self._default_subs
        return [(n, c.through, (float(c.direction[0].xreplace(at)), float(c.direction[1].xreplace(at))))
                for n, c in self.scene.points.items() if isinstance(c, Slider) and c.direction is not None]

    @property
    def anchors(self) -> list[str]:
        """Fixed points that only place a slider's line (no bar or string ends there): drawn as
        the slider's rail, not as a ground pivot.

        >>> Motion("slider-crank").anchors, Motion("slider-crank").ground
        (['L'], ['O', 'L'])
        """
        ends = {p for pair in self.bars + self.strings for p in pair}
        through = {t for _, t, _ in self.guides}
        return [n for n in self.ground if n in through and n not in ends]

    @property
    def _default_subs(self) -> dict[sympy.Symbol, sympy.Expr]:
        return {symbol(n): v for n, v in self.compiled.parameter_values.items()}

    @property
    def strings(self) -> list[tuple[str, ...]]:
        """Distances the scene outputs (the arm's string AB): drawn as thin lines."""
        return [o.points for o in self.scene.outputs.values() if o.kind == "dist"]

    @property
    def traced(self) -> list[str]:
        """Moving points named by the scene's outputs: the ones whose trajectory is drawn.

        A point moves when its closed form involves an input on some branch: a frame point on
        two pivots is no fixed construction, but its trajectory is a single point.
        """
        angles = {symbol(n) for pair in self.compiled.system.inputs.values() for n in pair}
        moving = [n for n in self.scene.points
                  if any(sympy.sympify(v).free_symbols & angles for form in self.points for v in form[n])]
        named = [p for o in self.scene.outputs.values() for p in o.points]
        return [p for p in moving if p in named] or moving[-1:]

    def values(self, inputs: Mapping[str, ArrayLike] | None = None,
               parameters: Mapping[str, float] | None = None) -> dict[str, FloatArray]:
        """Variable name -> value for ``evaluate``: c_*, s_* of inputs in degrees (a length input
        as it is), dimensions."""
        inputs, parameters = self.complete(inputs, parameters)
        values: dict[str, FloatArray] = {}
        for name, variables in self.compiled.system.inputs.items():
            given = np.asarray(inputs[name], dtype=float)
            values.update(input_values(variables, np.radians(given) if self.inputs[name].is_angle else given))
        values.update({p: np.asarray(v, dtype=float) for p, v in parameters.items()})
        return values

    def complete(self, inputs: Mapping[str, _V] | None = None, parameters: Mapping[str, float] | None = None
                 ) -> tuple[dict[str, _V | float], dict[str, float]]:
        """Inputs (degrees) and symbolic dimensions, missing ones at the range start / defaults."""
        given: dict[str, _V | float] = dict(inputs or {})
        for name in given:
            if name not in self.inputs:
                raise UsageError("inputs", name, f"not an input of {self.scene.name}"
                                 + suggest.known(name, self.inputs, plural="inputs"))
        for name, spec in self.inputs.items():
            given.setdefault(name, spec.span[0])
        parameters = dict(parameters or {})
        for name in parameters:
            if name not in self.params:
                raise UsageError("parameters", name, f"not a symbolic dimension of {self.scene.name} "
                                                  f"(symbolic: {', '.join(self.params) or 'none'})")
        return given, {p: parameters.get(p, self.defaults[p]) for p in self.params}

    def evaluate(self, branch: int, values: Mapping[str, FloatArray]) -> tuple[Trajectories, Blocked]:
        """Point -> (x, y) arrays, nan where the branch cannot assemble; and the blocked mask per point."""
        form = self.branches[branch]
        # beyond where the branch assembles a later discriminant holds an earlier one's sqrt (nan),
        # a mirror point the span of its coincident bases (a pole): neither is worth a warning
        with np.errstate(all="ignore"):
            blocked = {p: ~(np.asarray(evaluate(d, values, NUMPY)) >= 0) for p, d in form.discriminants.items()}
            floats = lambda v: np.asarray(evaluate(v, values, NUMPY), dtype=float)  # noqa: E731
            points = {p: (floats(x), floats(y)) for p, (x, y) in self.points[branch].items()}
        return points, blocked

    def at(self, inputs: Mapping[str, float] | None = None, parameters: Mapping[str, float] | None = None,
           branch: str | None = None) -> Pose:
        """The configuration at ``inputs`` (degrees) and ``parameters`` on branch ``branch``."""
        inputs, parameters = self.complete(inputs, parameters)
        k = self.branch_index(branch)
        points, blocked = self.evaluate(k, self.values(inputs, parameters))
        failing = tuple(p for p, mask in blocked.items() if np.any(mask))
        shown = {p: None if failing else (float(x), float(y)) for p, (x, y) in points.items()}
        return Pose(inputs, parameters, self.branches[k].label, shown, failing)

    def sweep(self, parameters: Mapping[str, float] | None = None, branch: str | None = None, samples: int = 721,
              inputs: Mapping[str, float] | None = None) -> tuple[FloatArray, Trajectories]:
        """Angles swept over the first input's range (others fixed) and every point's arrays
        (nan where the branch cannot assemble)."""
        angles, points, _, _, _ = self._sweep(parameters, branch, samples, inputs)
        return angles, points

    def _sweep(self, parameters: Mapping[str, float] | None, branch: str | None, samples: int,
               inputs: Mapping[str, float] | None, endpoint: bool = True
               ) -> tuple[FloatArray, Trajectories, Blocked, dict[str, float], dict[str, float]]:
        inputs, parameters = self.complete(inputs, parameters)
        name, spec = next(iter(self.inputs.items()))
        angles = np.linspace(*spec.span, samples, endpoint=endpoint)
        points, blocked = self.evaluate(self.branch_index(branch), self.values({**inputs, name: angles}, parameters))
        blocked = {p: np.broadcast_to(m, angles.shape) for p, m in blocked.items()}
        mask = np.any(list(blocked.values()), axis=0) if blocked else np.zeros(angles.shape, bool)
        cut = lambda v: np.where(mask, np.nan, np.broadcast_to(v, mask.shape))  # noqa: E731
        return angles, {p: (cut(x), cut(y)) for p, (x, y) in points.items()}, blocked, inputs, parameters

    def start(self, parameters: Mapping[str, float] | None = None, branch: str | None = None) -> dict[str, float]:
        """Input angles a picture starts from: the first input near 7/20 of its range (the
        seed's 63 deg of a turn), moved to the nearest angle where the branch assembles."""
        name, spec = next(iter(self.inputs.items()))
        lo, hi = spec.span
        angles, points = self.sweep(parameters, branch, samples=361)
        alive = np.isfinite(next(iter(points.values()))[0])
        order = np.argsort(np.abs(angles - (lo + 0.175 * (hi - lo))))
        chosen = next((angles[k] for k in order if alive[k]), lo + 0.175 * (hi - lo))
        return {name: float(chosen), **{n: s.span[0] for n, s in list(self.inputs.items())[1:]}}

    def poses(self, parameters: Mapping[str, float] | None = None, branch: str | None = None, samples: int = 72,
              inputs: Mapping[str, float] | None = None) -> list[Pose]:
        """``samples`` configurations turning the first input through its range, evaluated at once.

        A full turn leaves out its last angle (the first one again), so an animation loops.
        """
        spec = next(iter(self.inputs.values()))
        lo, hi = spec.span
        angles, points, blocked, inputs, parameters = self._sweep(parameters, branch, samples, inputs,
                                                                  endpoint=not spec.is_angle or hi - lo < 360)
        label = self.branches[self.branch_index(branch)].label
        name = next(iter(self.inputs))
        result = []
        for k, angle in enumerate(angles):
            failing = tuple(p for p, m in blocked.items() if m[k])
            shown = {p: None if failing else (float(x[k]), float(y[k])) for p, (x, y) in points.items()}
            result.append(Pose({**inputs, name: float(angle)}, parameters, label, shown, failing))
        return result
