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

from ...eliminate.group import GroupSolution, Mode, Polynomial, modes_in_balls
from ...eliminate.group.samples import ball_value
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
    after: tuple[str, ...] = ()
    """Solved after other groups: their points (whose unknowns are parameters here); its
    ``modes`` are then those under each configuration of them, in turn."""

    def to_json(self) -> dict[str, Any]:
        document = {"points": list(self.points), "constraints": list(self.constraints), "unknowns": list(self.unknowns),
                "variable": self.variable, "form": dict(self.form), "eliminant": self.eliminant,
                "factors": list(self.factors), "degree": self.degree, "complex_count": self.degree,
                "lifts": dict(self.lifts), "dropped_factors": list(self.dropped),
                "real_modes": len(self.modes), "modes": [m.to_json() for m in self.modes]}
        if self.after:  # a key of its own: a scene whose groups are independent gives the document it gave
            document["after"] = list(self.after)
        return document


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
    configurations: tuple[tuple[int, ...], ...] | None = None
    """Groups solved in turn: each real configuration at the reference, as each group's mode's
    position in its ``modes`` (None: every combination of the groups' modes)."""

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
                    for combination in self._combinations()]
        return {"scene": self.scene.name, "method": "group", "backend": "flint",
                "inputs": inputs_json({n: v for n, v in compiled.inputs.items()
                                       if self.prepared.input is not None and n == self.prepared.input.name}),
                "system": {"unknowns": unknowns, "parameters": parameters,
                           "equations": [str(e) for g in compiled.groups for e in g.equations]},
                "eliminants": {g.variable: g.eliminant for g in self.groups},
                "branches": branches, "groups": [g.to_json() for g in self.groups], "reference": reference,
                "verification": dict(self.verification), "timings": dict(self.timings)}


    def _combinations(self) -> list[tuple[ModeForm, ...]]:
        if self.configurations is not None:
            return [tuple(g.modes[k] for g, k in zip(self.groups, c)) for c in self.configurations]
        combinations: list[tuple[ModeForm, ...]] = [()]
        for group in self.groups:
            combinations = [c + (m,) for c in combinations for m in group.modes]
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
    found: list[tuple[Mode, ...]] = prepared.modes(reference) if reference is not None else \
        [() for _ in prepared.solutions]
    configurations: tuple[tuple[int, ...], ...] | None = None
    parents: dict[int, dict[str, flint.arb]] = {}
    if reference is not None and prepared.later():  # a later group's modes hang on the earlier ones'
        found, configurations, parents = _in_turn(prepared, reference, found)
    labels = _labels(prepared, reference, found)
    groups = tuple(_forms(prepared, k, found[k], labels[k], reference=reference, parents=parents)
                   for k in range(len(prepared.solutions)))
    timings["forms"] = time.perf_counter() - start - timings["eliminate"]
    verification: dict[str, Any] = {"status": "skipped", "passed": True, "samples": 0}
    if samples:
        from .verify import verify_groups  # the check is a command of its own too

        mark = time.perf_counter()
        verification = verify_groups(prepared, samples=samples, seed=seed).to_json()["verification"]
        timings["verify"] = time.perf_counter() - mark
    timings["total"] = time.perf_counter() - start
    return GroupDerivation(prepared.scene, prepared, groups, reference, verification, timings, configurations)


def _in_turn(prepared: GroupScene, reference: Sample, found: list[tuple[Mode, ...]]
             ) -> tuple[list[tuple[Mode, ...]], tuple[tuple[int, ...], ...], dict[int, dict[str, flint.arb]]]:
    """Groups solved in turn, at the reference: each group's modes (a later group's: under every
    configuration of the earlier ones, in turn), every configuration as positions in them, and
    each later mode's earlier unknowns' balls (by the mode's id)."""
    configurations = prepared.configurations(reference)
    later = prepared.later()
    modes = [group if k not in later else tuple({id(c[k]): c[k] for c in configurations}.values())
             for k, group in enumerate(found)]
    positions = tuple(tuple(next(i for i, m in enumerate(modes[k]) if (m is mode if k in later else m == mode))
                            for k, mode in enumerate(c)) for c in configurations)
    parents = {id(c[k]): {u: v for m in c[:k] for u, v in m.values.items()} for c in configurations for k in later}
    return modes, positions, parents


def _labels(prepared: GroupScene, reference: Sample | None, found: Sequence[Sequence[Mode]]) -> list[list[str]]:
    """Each mode's label as ``algkin solve`` gives it at the reference (its index, from 1, where
    ``solve`` cannot take that input: an angle off the multiples of 90 degrees)."""
    fallback = [[str(m.index + 1) for m in group] for group in found]
    if reference is None or prepared.input is None or (len(prepared.solutions) != 1 and not prepared.later()):
        return fallback
    value = reference.value if prepared.input.is_angle else reference.values[prepared.variables[0]]
    try:
        solution = solve(prepared.scene, {prepared.input.name: value}, digits=10)
    except AlgkinError:
        return fallback
    labels = [c.mode for c in solution.configurations]
    if len(prepared.solutions) == 1:
        return [labels] if len(labels) == len(found[0]) else fallback
    # groups in turn: solve lists the configurations in the same order, a label per group
    configurations = prepared.configurations(reference)
    if len(labels) != len(configurations):
        return fallback
    named = [{_key(c[k]): label.split(" ")[k] for c, label in zip(configurations, labels)} for k in range(len(found))]
    return [[named[k].get(_key(m), fallback[k][i]) for i, m in enumerate(group)] for k, group in enumerate(found)]


def _key(mode: Mode) -> tuple[Any, ...]:
    """A mode's identity across two enumerations: its exact root, or (a later group's) its balls' midpoints."""
    if mode.root is not None:
        return (mode.index, mode.root)
    return tuple(sorted((u, v.mid().str(10)) for u, v in mode.values.items()))


def _forms(prepared: GroupScene, index: int, found: Sequence[Mode], labels: Sequence[str], *,
           reference: Sample | None, parents: Mapping[int, Mapping[str, flint.arb]]) -> GroupForms:
    solution = prepared.solutions[index]
    group = prepared.compiled.groups[index]
    circle = prepared.variables
    eliminant = solution.eliminant.to_flint()
    factors = [f for f, _ in eliminant.factor()[1] if f.degrees()[0] > 0]
    lifts = {lift.unknown: _ratio(on_circle(lift.numerator.to_flint(), circle),
                                  on_circle(lift.denominator.to_flint(), circle)) for lift in solution.lifts}
    forms = tuple(_mode_form(solution, factors, mode, label, lifts=lifts, at=_point(reference, solution))
                  if mode.root is not None else _mode_form_in_balls(solution, factors, mode, label, lifts=lifts,
                                                                    at=_point(reference, solution),
                                                                    parents=parents[id(mode)])
                  for mode, label in zip(found, labels))
    after = tuple(p for g in prepared.compiled.groups[:index] if set(g.unknowns) & set(solution.parameters)
                  for p in g.points)
    return GroupForms(group.points, group.constraints, solution.unknowns, solution.variable, solution.form,
                      _text(on_circle(eliminant, circle)), tuple(_text(on_circle(f, circle)) for f in factors),
                      solution.complex_count, lifts, tuple(str(d) for d in solution.dropped), forms, after)


def _point(reference: Sample | None, solution: GroupSolution) -> dict[str, flint.fmpq]:
    """The reference input's exact values, for the parameters ``solution`` holds."""
    exact = reference.exact() if reference is not None else {}
    return {p: exact[p] for p in solution.parameters if p in exact}  # not an earlier group's unknown


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


def _mode_form_in_balls(solution: GroupSolution, factors: Sequence[flint.fmpq_mpoly], mode: Mode, label: str, *,
                        lifts: Mapping[str, str], at: Mapping[str, flint.fmpq],
                        parents: Mapping[str, flint.arb]) -> ModeForm:
    """A mode of a group solved after another (its parameters an earlier mode's balls): the factor
    whose value holds 0 at it (the others' certified nonzero) and its rank among that factor's real
    roots there (``modes_in_balls`` on the factor alone)."""
    variable = solution.variable
    parents = {p: v for p, v in parents.items() if p in solution.parameters}
    given = {**{n: flint.arb(v) for n, v in at.items()}, **parents, **mode.values}
    for position, factor in enumerate(factors):
        if not ball_value(factor, given).contains(0):
            continue
        alone = attrs.evolve(solution, eliminant=Polynomial.of(factor), lifts=())
        roots = [m.values[variable] for m in modes_in_balls(alone, at, parents)]
        rank = next(k for k, r in enumerate(roots) if r.overlaps(mode.values[variable]))
        lead = ball_value(coefficients(factor, variable)[-1], given)
        value = (_radical(factor, variable, rank=rank, count=len(roots), at=at, positive=lead > 0)
                 if not lead.contains(0) else None) or f"root {rank + 1} of factor {position + 1}"
        return ModeForm(label, position + 1, rank + 1, mode.values[variable].str(15, radius=False),
                        {variable: value, **lifts})
    raise AssertionError("a mode's root is a root of one factor of the eliminant")


def _radical(factor: flint.fmpq_mpoly, variable: str, *, rank: int, count: int,
             at: Mapping[str, flint.fmpq], positive: bool | None = None) -> str | None:
    """The factor's root in radicals (sympy's syntax) when it is of degree 1 or 2 in ``variable``:
    for a quadratic, the sign of the square root that gives the ``rank``-th real root at ``at``."""
    parts = [sympy.sympify(_text(c)) for c in coefficients(factor, variable)]
    if len(parts) == 2:
        return str(sympy.simplify(-parts[0] / parts[1]))
    if len(parts) != 3 or count != 2:
        return None
    c, b, a = parts
    if positive is None:  # the leading coefficient's sign at the reference, exactly
        lead = a.subs({sympy.Symbol(n, real=True): sympy.Rational(int(v.p), int(v.q)) for n, v in at.items()})
        lead = lead.subs({sympy.Symbol(n): sympy.Rational(int(v.p), int(v.q)) for n, v in at.items()})
        positive = bool(lead > 0)
    sign = 1 if (rank == 1) == positive else -1
    return str((-b + sign * sympy.sqrt(b**2 - 4 * a * c)) / (2 * a))


def _ratio(numerator: flint.fmpq_mpoly, denominator: flint.fmpq_mpoly) -> str:
    return _text(numerator) if denominator.is_one() else f"({_text(numerator)})/({_text(denominator)})"


def _text(poly: flint.fmpq_mpoly) -> str:
    return str(poly).replace("^", "**")
