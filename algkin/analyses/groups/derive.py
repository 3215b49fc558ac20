"""``derive`` on a scene with points solved together: per group, its eliminant and closed forms per mode.

Per group (``solve_group``): the eliminant in the separating unknown, with the input's variables
(and the dimensions, at their values) as parameters, factored; every other unknown rational in
it (an angle's ``c``, ``s`` reduced with ``c**2 + s**2 = 1``). At a reference input the real
roots are isolated and certified: each is a mode, labelled as ``algkin solve`` labels it, and
its closed form is "root k of this factor" (the k-th real root, ascending, at the reference),
in radicals where the factor is of degree 1 or 2.

>>> found = derive_groups("3rpr", samples=0)
>>> group, = found.groups
>>> group.variable, group.degree, len(group.modes), found.reference.shown
('P1_x', 6, 2, '5')
>>> [m.label for m in group.modes]
['---', '+++']
"""

from __future__ import annotations

import time
from collections.abc import Mapping, Sequence
from typing import Any

import attrs
import flint
import sympy

from ...eliminate.group import GroupSolution, Mode
from ...eliminate.group.records import Values
from ...eliminate.group.algebra import coefficients, univariate
from ...errors import AlgkinError
from ...scene import Scene
from ...runtime.frozen import FrozenDict, frozen
from ...system import inputs_json
from ...system.roots import real_roots
from ..solve import solve
from .scene import GroupScene, Sample, on_circle, prepare_groups

__all__ = ["derive_groups", "GroupDerivation", "GroupForms", "ModeForm"]


@attrs.frozen
class ModeForm:
    """One mode at the reference input: its ``label``, the ``factor`` of the eliminant (by
    position, from 1) whose ``rank``-th real root (ascending, from 1) it is, that root's value there
    (``value``, a decimal), and each unknown's closed form (``values``: the variable's in
    radicals where the factor's degree allows, else ``root k of F``; the others rational in it)."""

    label: str
    factor: int
    rank: int
    value: str
    values: FrozenDict[str, str] = attrs.field(converter=frozen)

    def to_json(self) -> dict[str, Any]:
        return {"label": self.label, "factor": self.factor, "root": self.rank, "value": self.value,
                "values": dict(self.values)}


@attrs.frozen
class GroupForms:
    """A group solved: its points and constraints, the separating ``variable``, the eliminant
    and its ``factors`` (text), the ``lifts`` (unknown -> rational function of the variable),
    the factors ``dropped``, and its ``modes`` at the reference input."""

    points: tuple[str, ...]
    constraints: tuple[str, ...]
    unknowns: tuple[str, ...]
    variable: str
    form: FrozenDict[str, int] = attrs.field(converter=frozen)
    eliminant: str = ""
    factors: tuple[str, ...] = ()
    degree: int = 0
    lifts: FrozenDict[str, str] = attrs.field(converter=frozen, factory=FrozenDict)
    dropped: tuple[str, ...] = ()
    modes: tuple[ModeForm, ...] = ()

    def to_json(self) -> dict[str, Any]:
        return {"points": list(self.points), "constraints": list(self.constraints), "unknowns": list(self.unknowns),
                "variable": self.variable, "form": dict(self.form), "eliminant": self.eliminant,
                "factors": list(self.factors), "degree": self.degree, "complex_count": self.degree,
                "lifts": dict(self.lifts), "dropped_factors": list(self.dropped),
                "real_modes": len(self.modes), "modes": [m.to_json() for m in self.modes]}


@attrs.frozen
class GroupDerivation:
    """``derive`` on a scene with points solved together: its ``groups``, the ``reference``
    input where the modes are counted, the independent ``verification`` (a JSON document,
    ``algkin.analyses.groups.verify``; skipped with no samples) and the ``timings``."""

    scene: Scene
    prepared: GroupScene = attrs.field(eq=False)
    groups: tuple[GroupForms, ...]
    reference: Sample | None
    verification: FrozenDict[str, Any] = attrs.field(converter=frozen)
    timings: FrozenDict[str, float] = attrs.field(converter=frozen)

    @property
    def passed(self) -> bool:
        return self.verification["status"] in ("passed", "skipped")

    def to_json(self) -> dict[str, Any]:
        compiled = self.prepared.compiled
        unknowns = [u for g in compiled.groups for u in g.unknowns]
        parameters = list(self.prepared.variables)
        reference = None
        if self.reference is not None and self.prepared.input is not None:
            reference = {"input": self.prepared.input.name, "value": self.reference.value, "shown": self.reference.shown,
                         "values": {n: str(v) for n, v in self.reference.values.items()}}
        branches = [{"label": " ".join(m.label for m in combination),
                     "values": {u: v for m in combination for u, v in m.values.items()},
                     "valid_when": [f"the mode exists (its root is real) at {self.reference.shown}"
                                    if self.reference else "always"]}
                    for combination in _combinations([g.modes for g in self.groups])]
        return {"scene": self.scene.name, "method": "group", "backend": "flint",
                "inputs": inputs_json({n: v for n, v in compiled.inputs.items()
                                       if self.prepared.input is not None and n == self.prepared.input.name}),
                "system": {"unknowns": unknowns, "parameters": parameters,
                           "equations": [str(e) for g in compiled.groups for e in g.equations]},
                "eliminants": {g.variable: g.eliminant for g in self.groups},
                "branches": branches, "groups": [g.to_json() for g in self.groups], "reference": reference,
                "verification": dict(self.verification), "timings": dict(self.timings)}


def _combinations(modes: Sequence[Sequence[ModeForm]]) -> list[tuple[ModeForm, ...]]:
    combinations: list[tuple[ModeForm, ...]] = [()]
    for group in modes:
        combinations = [c + (m,) for c in combinations for m in group]
    return combinations


def derive_groups(scene: Scene | str, *, samples: int = 40, seed: int = 0) -> GroupDerivation:
    """Per group of ``scene``'s points solved together: its eliminant, lifts and closed forms
    per mode at a reference input; with ``samples`` > 0 checked against independent numeric
    solutions (``verify_groups``)."""
    start = time.perf_counter()
    timings: dict[str, float] = {}
    prepared = prepare_groups(scene, command="derive")
    timings["eliminate"] = time.perf_counter() - start
    reference = prepared.reference() if prepared.input is not None else None
    found = prepared.modes(reference) if reference is not None else [() for _ in prepared.solutions]
    labels = _labels(prepared, reference, found)
    groups = tuple(_forms(prepared, k, found[k], labels[k], reference=reference) for k in range(len(prepared.solutions)))
    timings["forms"] = time.perf_counter() - start - timings["eliminate"]
    verification: dict[str, Any] = {"status": "skipped", "passed": True, "samples": 0}
    if samples:
        from .verify import verify_groups  # the check is a command of its own too

        mark = time.perf_counter()
        verification = verify_groups(prepared, samples=samples, seed=seed).to_json()["verification"]
        timings["verify"] = time.perf_counter() - mark
    timings["total"] = time.perf_counter() - start
    return GroupDerivation(prepared.scene, prepared, groups, reference, verification, timings)


def _labels(prepared: GroupScene, reference: Sample | None, found: Sequence[Sequence[Mode]]) -> list[list[str]]:
    """Each mode's label as ``algkin solve`` gives it at the reference (its index, from 1, where
    ``solve`` cannot take that input: an angle off the multiples of 90 degrees)."""
    fallback = [[str(m.index + 1) for m in group] for group in found]
    if reference is None or prepared.input is None or len(prepared.solutions) != 1:
        return fallback
    value = reference.value if prepared.input.is_angle else reference.values[prepared.variables[0]]
    try:
        solution = solve(prepared.scene, {prepared.input.name: value}, digits=10)
    except AlgkinError:
        return fallback
    labels = [c.mode for c in solution.configurations]
    return [labels] if len(labels) == len(found[0]) else fallback


def _forms(prepared: GroupScene, index: int, found: Sequence[Mode], labels: Sequence[str], *,
           reference: Sample | None) -> GroupForms:
    solution = prepared.solutions[index]
    group = prepared.compiled.groups[index]
    circle = prepared.variables
    eliminant = solution.eliminant.to_flint()
    factors = [f for f, _ in eliminant.factor()[1] if f.degrees()[0] > 0]
    lifts = {lift.unknown: _ratio(on_circle(lift.numerator.to_flint(), circle),
                                  on_circle(lift.denominator.to_flint(), circle)) for lift in solution.lifts}
    forms = tuple(_mode_form(solution, factors, mode, label, lifts=lifts, at=_point(reference, solution))
                  for mode, label in zip(found, labels))
    return GroupForms(group.points, group.constraints, solution.unknowns, solution.variable, solution.form,
                      _text(on_circle(eliminant, circle)), tuple(_text(on_circle(f, circle)) for f in factors),
                      solution.complex_count, lifts, tuple(str(d) for d in solution.dropped), forms)


def _point(reference: Sample | None, solution: GroupSolution) -> dict[str, flint.fmpq]:
    """The reference input's exact values, for the parameters ``solution`` holds."""
    exact = reference.exact() if reference is not None else {}
    return {p: exact[p] for p in solution.parameters}


def _mode_form(solution: GroupSolution, factors: Sequence[flint.fmpq_mpoly], mode: Mode, label: str, *,
               lifts: Mapping[str, str], at: Mapping[str, flint.fmpq]) -> ModeForm:
    """Which factor's root the mode is (by its exact root at the reference), and its closed forms."""
    variable = solution.variable
    for position, factor in enumerate(factors):
        point: Values = {name: value for name, value in at.items()}
        roots = list(real_roots(univariate(factor.subs(point), variable)))
        if mode.root in roots:
            rank = roots.index(mode.root)
            value = _radical(factor, variable, rank=rank, count=len(roots), at=at) or \
                f"root {rank + 1} of factor {position + 1}"
            values = {variable: value, **lifts}
            return ModeForm(label, position + 1, rank + 1, mode.values[variable].str(15, radius=False), values)
    raise AssertionError("a mode's root is a root of one factor of the eliminant")  # squarefree, kept factors


def _radical(factor: flint.fmpq_mpoly, variable: str, *, rank: int, count: int,
             at: Mapping[str, flint.fmpq]) -> str | None:
    """The factor's root in radicals (sympy's syntax) when it is of degree 1 or 2 in ``variable``:
    for a quadratic, the sign of the square root that gives the ``rank``-th real root at ``at``."""
    parts = [sympy.sympify(_text(c)) for c in coefficients(factor, variable)]
    if len(parts) == 2:
        return str(sympy.simplify(-parts[0] / parts[1]))
    if len(parts) != 3 or count != 2:
        return None
    c, b, a = parts
    lead = a.subs({sympy.Symbol(n, real=True): sympy.Rational(int(v.p), int(v.q)) for n, v in at.items()})
    lead = lead.subs({sympy.Symbol(n): sympy.Rational(int(v.p), int(v.q)) for n, v in at.items()})
    sign = 1 if (rank == 1) == bool(lead > 0) else -1
    return str((-b + sign * sympy.sqrt(b**2 - 4 * a * c)) / (2 * a))


def _ratio(numerator: flint.fmpq_mpoly, denominator: flint.fmpq_mpoly) -> str:
    return _text(numerator) if denominator.is_one() else f"({_text(numerator)})/({_text(denominator)})"


def _text(poly: flint.fmpq_mpoly) -> str:
    return str(poly).replace("^", "**")
