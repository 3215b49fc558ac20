"""``algkin accuracy`` on a scene with points solved together: speed against error per strategy.

At each sample of the input every strategy gives every real configuration it finds; each is
compared with the reference's configuration nearest to it, point by point. Strategies:

- ``eliminant-roots``: each group's eliminant at the input in floats, its roots by
  ``numpy.roots`` (a root counted real where its imaginary part is below ``REAL`` of its
  size), every other unknown from its lift in floats;
- ``newton``: float Newton on the groups' own equations, each mode continued from its value at
  the previous sample (at its first, from the reference's): what a user's solver would do; a
  sample where it does not converge is ``unsolved`` (counted, left out of the errors);
- ``certified``: ``algkin.solve`` (the eliminant's roots isolated exactly, lifted in balls) at
  17 digits.

The reference is ``algkin.solve`` at ``DIGITS`` digits: certified, from the original
equations; errors are exact differences from its decimals. Cases: ``uniform`` inputs over the
range, ``near-toggle`` inputs within 1e-12 to 1e-6 (relative) of each certified toggle of the
groups (where two modes meet: the eliminant's roots come together and lose half their
digits in floats), and the scene translated ``FAR`` away.

>>> result = group_accuracy("3rpr", samples=10)
>>> sorted({(r["strategy"], r["case"]) for r in result.rows})[:3]
[('certified', 'far-1e3'), ('certified', 'near-toggle'), ('certified', 'uniform')]
"""

from __future__ import annotations

import itertools
import statistics
import time
from collections.abc import Callable, Sequence
from fractions import Fraction
from typing import Any, TypeVar

import numpy as np
import sympy

from ..analyses.groups.scene import GroupScene, prepare_groups
from ..analyses.groups.toggles import toggles_groups
from ..analyses.solve import solve
from ..errors import UsageError
from ..scene import Scene
from ..scene.load import SceneLike, as_scene

__all__ = ["group_accuracy", "GroupAccuracy", "STRATEGIES", "DIGITS", "MAX_SAMPLES"]

STRATEGIES = ("eliminant-roots", "newton", "certified")
DIGITS = 40
"""The reference's digits."""
CERTIFIED_DIGITS = 17
MAX_SAMPLES = 100
"""Samples per case at most: the reference solves exactly at each one."""
REAL = 1e-6
"""A float root's imaginary part, relative to its size, under which it is taken as real."""
NEWTON_STEPS = 40
SOLVED = 2.0**-26
"""Newton's last step, relative to the unknowns' size, when it counts as converged."""
FAR = 10**3
NEAR = (-12.0, -6.0)
"""Exponents of the relative distances to a toggle sampled in the near-toggle case."""

_T = TypeVar("_T")
Configuration = dict[str, Fraction]  # every moving point's coordinate ("P1.x") -> its value
Found = list[tuple[str, Configuration]]  # (label or "", configuration) at one input


class GroupAccuracy:
    """Rows of one accuracy run on a group scene, as ``accuracy``'s (``to_json``)."""

    def __init__(self, scene: str, points: Sequence[str], rows: list[dict[str, Any]], note: str = "") -> None:
        self.scene, self.points, self.rows, self.note = scene, tuple(points), rows, note

    @property
    def point(self) -> str:
        """What is measured, as ``Accuracy.point`` says it: every moving point."""
        return ", ".join(self.points)

    def to_json(self) -> dict[str, object]:
        reference = f"algkin solve at {DIGITS} digits (certified, from the original equations)"
        document: dict[str, object] = {"scene": self.scene, "point": self.point, "rows": self.rows,
                                       "reference": reference, "eps": 2.0**-53, "solved_together": True}
        if self.note:
            document["note"] = self.note
        return document


class _Floats:
    """A group scene's equations, Jacobian, eliminants and lifts as numpy functions of the input."""

    def __init__(self, prepared: GroupScene) -> None:
        compiled = prepared.compiled
        self.unknowns = tuple(u for g in compiled.groups for u in g.unknowns)
        self.variables = prepared.variables
        unknowns = sympy.symbols(self.unknowns)
        variables = sympy.symbols(self.variables)
        equations = sympy.Matrix([e for g in compiled.groups for e in g.equations])
        self.residual = sympy.lambdify((unknowns, variables), equations, "numpy")
        self.jacobian = sympy.lambdify((unknowns, variables), equations.jacobian(unknowns), "numpy")
        self.eliminants = [self._eliminant(s) for s in prepared.solutions]

    def _eliminant(self, solution: Any) -> tuple[Callable[..., Any], list[tuple[str, Callable[..., Any]]], str]:
        variable = sympy.Symbol(solution.variable)
        parameters = sympy.symbols(self.variables)
        coefficients = sympy.Poly(sympy.sympify(str(solution.eliminant)), variable).all_coeffs()
        lifts = [(lift.unknown, sympy.lambdify((variable, parameters), sympy.sympify(str(lift.numerator))
                                               / sympy.sympify(str(lift.denominator)), "numpy"))
                 for lift in solution.lifts]
        return sympy.lambdify((parameters,), coefficients, "numpy"), lifts, solution.variable

    def roots(self, at: list[float]) -> list[dict[str, float]]:
        """Every group's real solutions from ``numpy.roots`` and the lifts, combined."""
        per_group = []
        for coefficients, lifts, variable in self.eliminants:
            found = []
            for root in np.roots(np.array(coefficients(at), dtype=float)):
                if abs(root.imag) <= REAL * (1 + abs(root.real)):
                    x = float(root.real)
                    found.append({variable: x, **{u: float(f(x, at)) for u, f in lifts}})
            per_group.append(found)
        return [{k: v for part in combination for k, v in part.items()} for combination in itertools.product(*per_group)]

    def newton(self, guess: Sequence[float] | np.ndarray, at: list[float]) -> np.ndarray | None:
        """Float Newton from ``guess``; None where it does not converge."""
        x = np.array(guess, dtype=float)
        for _ in range(NEWTON_STEPS):
            jacobian = np.asarray(self.jacobian(list(x), at), dtype=float)
            residual = np.asarray(self.residual(list(x), at), dtype=float).ravel()
            step = np.linalg.lstsq(jacobian, -residual, rcond=None)[0]
            x = x + step
            if not np.all(np.isfinite(x)):
                return None
            if np.max(np.abs(step)) <= SOLVED * (1 + np.max(np.abs(x))):
                return x
        return None


def _solved(scene: Scene, name: str, value: Fraction, digits: int) -> Found:
    found = solve(scene, {name: value}, digits=digits).configurations
    return [(c.mode, {f"{p}.{a}": Fraction(v) for p, xy in c.points.items() for a, v in zip("xy", xy)})
            for c in found]


def _at(coordinate: Any, values: dict[str, sympy.Rational]) -> Fraction:
    """A coordinate's exact value at rational unknowns and inputs (a float's value exactly)."""
    expr = sympy.sympify(coordinate)
    return Fraction(str(expr.xreplace({s: values[s.name] for s in expr.free_symbols})))


def _distance(a: Configuration, b: Configuration) -> Fraction:
    return max(abs(a[k] - b[k]) for k in a)


def _row(strategy: str, case: str, samples: int, times: list[float], errors: list[tuple[Fraction, Fraction]], *,
         compared: int, missed: int, unsolved: int = 0, note: str = "") -> dict[str, Any]:
    """One strategy's figures on one case: ``times`` of the evaluations (their median), ``errors``
    as (distance, the configuration's size) pairs."""
    worst = max((float(e) for e, _ in errors), default=float("nan"))
    relative = max((float(e / s) if s else float(e) for e, s in errors), default=float("nan"))
    row: dict[str, Any] = {"strategy": strategy, "case": case, "samples": samples,
                           "ns_per_sample": statistics.median(times) * 1e9 if times else float("nan"), "max_abs_error": worst,
                           "max_rel_error": relative, "compared": compared, "missed": missed}
    if unsolved:
        row["unsolved"] = unsolved
    if note:
        row["note"] = note
    return row


class _Case:
    """One case's samples of one scene: the reference at each, then each strategy measured."""

    def __init__(self, scene: Scene, name: str, values: Sequence[Fraction], *, clock: Callable[[], float]) -> None:
        self.scene, self.name, self.clock = scene, name, clock
        self.prepared = prepare_groups(scene, command="accuracy")
        self.floats = _Floats(self.prepared)
        self.input = self.prepared.input.name  # type: ignore[union-attr]
        self.values = sorted(values)
        self.reference = [_solved(scene, self.input, v, DIGITS) for v in self.values]

    def _compare(self, found: list[Configuration], k: int, errors: list[tuple[Fraction, Fraction]]) -> tuple[int, int]:
        """Each reference configuration at sample ``k`` against the nearest found: (compared, missed)."""
        compared = missed = 0
        for _, truth in self.reference[k]:
            if not found:
                missed += 1
                continue
            size = max(abs(v) for v in truth.values())
            errors.append((min(_distance(truth, f) for f in found), size))
            compared += 1
        return compared, missed

    def _placed(self, unknowns: dict[str, float], k: int) -> Configuration:
        """The moving points' coordinates from the unknowns' floats (the reference's other points are the input's)."""
        values = {u: Fraction(v) for u, v in unknowns.items()}
        values.update({v: self.values[k] for v in self.floats.variables})
        exact = {n: sympy.Rational(v.numerator, v.denominator) for n, v in values.items()}
        return {f"{p}.{a}": _at(c, exact) for p, xy in self.prepared.compiled.coordinates.items() for a, c in zip("xy", xy)}

    def _timed(self, work: Callable[[], _T]) -> tuple[_T, float]:
        start = self.clock()
        result = work()
        return result, self.clock() - start

    def rows(self) -> list[dict[str, Any]]:
        return [self._roots(), self._newton(), self._certified()]

    def _roots(self) -> dict[str, Any]:
        errors: list[tuple[Fraction, Fraction]] = []
        times, compared, missed = [], 0, 0
        for k, value in enumerate(self.values):
            found, spent = self._timed(lambda: self.floats.roots([float(value)]))
            times.append(spent)
            c, m = self._compare([self._placed(f, k) for f in found], k, errors)
            compared, missed = compared + c, missed + m
        return _row("eliminant-roots", self.name, len(self.values), times, errors, compared=compared, missed=missed)

    def _newton(self) -> dict[str, Any]:
        errors: list[tuple[Fraction, Fraction]] = []
        times, compared, missed, unsolved = [], 0, 0, 0
        previous: dict[str, np.ndarray] = {}
        for k, value in enumerate(self.values):
            starts = {label: previous.get(label, self._unknowns(truth)) for label, truth in self.reference[k]}
            if not starts:  # no mode to continue here: nothing to time either
                continue
            found, spent = self._timed(lambda: {label: self.floats.newton(x, [float(value)]) for label, x in starts.items()})
            times.append(spent)
            for label, truth in self.reference[k]:
                x = found[label]
                if x is None:
                    unsolved += 1
                    continue
                previous[label] = x
                size = max(abs(v) for v in truth.values())
                errors.append((_distance(truth, self._placed(dict(zip(self.floats.unknowns, map(float, x))), k)), size))
                compared += 1
        note = ("each mode started from the reference at its first sample, then from its previous value; "
                "near a toggle it can cross onto the other mode (its error then the modes' distance)")
        return _row("newton", self.name, len(self.values), times, errors, compared=compared, missed=missed, unsolved=unsolved, note=note)

    def _unknowns(self, truth: Configuration) -> np.ndarray:
        """The unknowns' floats in a reference configuration (each unknown is a point's coordinate)."""
        where = {str(c): f"{p}.{a}" for p, xy in self.prepared.compiled.coordinates.items() for a, c in zip("xy", xy)}
        return np.array([float(truth[where[u]]) for u in self.floats.unknowns])

    def _certified(self) -> dict[str, Any]:
        errors: list[tuple[Fraction, Fraction]] = []
        times, compared, missed = [], 0, 0
        for k, value in enumerate(self.values):
            found, spent = self._timed(lambda: _solved(self.scene, self.input, value, CERTIFIED_DIGITS))
            times.append(spent)
            c, m = self._compare([f for _, f in found], k, errors)
            compared, missed = compared + c, missed + m
        return _row("certified", self.name, len(self.values), times, errors, compared=compared, missed=missed)


def _inputs(prepared: GroupScene, samples: int, rng: np.random.Generator) -> dict[str, list[Fraction]]:
    """Each case's inputs (exact: the floats drawn, as rationals) in the input's range."""
    spec = prepared.input
    assert spec is not None
    lo, hi = (float(v) for v in spec.span)
    cases = {"uniform": [Fraction(float(v)) for v in rng.uniform(lo, hi, samples)]}
    toggles = [t.value for t in toggles_groups(prepared.scene).toggles if t.certified]
    if toggles:
        at = np.array(toggles)[rng.integers(0, len(toggles), samples)]
        offsets = np.sign(rng.uniform(-1, 1, samples)) * 10 ** rng.uniform(*NEAR, samples)
        near = [Fraction(float(v)) for v in at * (1 + offsets) if lo <= v <= hi]
        cases["near-toggle"] = near
    return cases


def group_accuracy(scene: SceneLike, samples: int = 40, seed: int = 0, *,
                   clock: Callable[[], float] = time.perf_counter) -> GroupAccuracy:
    """Rows of speed and error per strategy and case on a scene with points solved together
    (one length input, groups solved apart: a UsageError otherwise); ``clock`` times each evaluation."""
    scene = as_scene(scene)
    prepared = prepare_groups(scene, command="accuracy")
    if prepared.input is None or prepared.input.is_angle:
        raise UsageError("scene", scene.name, "accuracy on points solved together is measured over a length input, for now")
    if prepared.later():
        raise UsageError("scene", scene.name, "accuracy on points solved together takes groups solved apart, for now")
    count = min(samples, MAX_SAMPLES)
    rng = np.random.default_rng(seed)
    rows: list[dict[str, Any]] = []
    for case, values in _inputs(prepared, count, rng).items():
        rows += _Case(scene, case, values, clock=clock).rows()
    far = scene.translated(FAR)
    far_inputs = _inputs(prepare_groups(far, command="accuracy"), count, rng)["uniform"]
    rows += _Case(far, f"far-{FAR:.0e}".replace("+0", "").replace("+", ""), far_inputs, clock=clock).rows()
    moving = [p for g in prepared.compiled.groups for p in g.points]
    note = f"{count} samples per case (at most {MAX_SAMPLES}: the reference solves exactly at each)" if count < samples else ""
    return GroupAccuracy(scene.name, moving, rows, note)
