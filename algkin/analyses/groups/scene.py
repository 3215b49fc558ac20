"""A scene with points solved together, ready for derive, curve, toggles and verify.

Each group's equations are solved once (``solve_group``: an eliminant in one unknown with the
inputs' variables as parameters, the other unknowns rational in it); the inputs are sampled at
exact values: a length as a rational, an angle as a rational point of the unit circle
(``c = (1 - t**2)/(1 + t**2)``, ``s = 2t/(1 + t**2)`` for a rational ``t``, the tangent of half
the angle), so every mode at a sample is isolated over QQ and certified.

>>> prepared = prepare_groups("3rpr")
>>> [(s.variable, s.complex_count) for s in prepared.solutions], prepared.input.name
([('P1_x', 6)], 'r1')
>>> sample = prepared.sample(6)
>>> {n: str(v) for n, v in sample.values.items()}, sample.shown
({'r1': '6'}, '6')
>>> len(prepared.modes(sample)[0])
2
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from fractions import Fraction

import attrs
import flint
import sympy

from ...eliminate.group import GroupSolution, Mode, modes, modes_in_sequence, solve_group
from ...eliminate.group.algebra import pseudo_remainder
from ...errors import ComputationError, UsageError
from ...scene import Input, Scene
from ...scene.groups import Groups, compile_groups
from ...scene.load import as_scene
from ...system.convert import flint_context, to_flint

__all__ = ["GroupScene", "Sample", "prepare_groups", "solve_in_order", "on_circle", "REFERENCE_CANDIDATES"]

REFERENCE_CANDIDATES = 8
"""Evenly spaced inputs (and an angle's multiples of 90 degrees) tried for the reference sample."""


@attrs.frozen
class Sample:
    """An input at an exact value: its variables' ``values`` (an angle's cos and sin, rational),
    ``degrees`` (an angle's, a float) or the length, and how it reads (``shown``)."""

    values: Mapping[str, Fraction | int]
    value: float
    shown: str

    def exact(self) -> dict[str, flint.fmpq]:
        return {n: flint.fmpq(Fraction(v).numerator, Fraction(v).denominator) for n, v in self.values.items()}

    def balls(self, bits: int = 192) -> dict[str, flint.arb]:
        """The values as balls, rounded at ``bits`` (exact where they fit)."""
        with flint.ctx.workprec(bits):
            return {n: flint.arb(v) for n, v in self.exact().items()}


@attrs.frozen
class GroupScene:
    """A scene's groups (``compiled``), each solved (``solutions``, in the same order), and the
    one input they move with (``input``; None for a structure)."""

    scene: Scene
    compiled: Groups
    solutions: tuple[GroupSolution, ...]
    input: Input | None

    @property
    def variables(self) -> tuple[str, ...]:
        """The input's variables: an angle's (cos, sin) or a length."""
        return self.compiled.inputs[self.input.name] if self.input is not None else ()

    def sample(self, value: Fraction | int | str) -> Sample:
        """The input at ``value`` (degrees for an angle, taken at the nearest rational point of
        the circle whose half-angle tangent has a denominator below 10**6; a half turn exactly)."""
        assert self.input is not None
        exact = Fraction(str(value))
        if not self.input.is_angle:
            return Sample({self.variables[0]: exact}, float(exact), f"{float(exact):g}")
        c, s = self.variables
        if exact % 360 == 180:
            return Sample({c: -1, s: 0}, float(exact), f"{float(exact):g}°")
        t = Fraction(math.tan(math.radians(float(exact)) / 2)).limit_denominator(10**6)
        if exact % 90 == 0:  # exactly: the tangent's float is off by an ulp
            t = Fraction((0, 1, None, -1)[int(exact // 90) % 4] or 0)
        half = math.degrees(2 * math.atan(t))
        degrees = half + round((float(exact) - half) / 360) * 360
        return Sample({c: (1 - t * t) / (1 + t * t), s: 2 * t / (1 + t * t)}, degrees, f"{degrees:.6g}°")

    def modes(self, sample: Sample, *, bits: int = 128) -> list[tuple[Mode, ...]]:
        """Each group's real modes at ``sample``, certified (a ComputationError where the
        sample is not generic: two modes meet there); a group solved after another (its
        equations hold an earlier group's points): its modes under each real configuration of
        the earlier ones, in turn."""
        exact = sample.exact()
        later = self.later()
        combinations = self.configurations(sample, bits=bits) if later else []
        found = []
        for k, solution in enumerate(self.solutions):
            if k not in later:
                found.append(modes(solution, {p: exact[p] for p in solution.parameters}, bits=bits))
                continue
            seen = {id(c[k]): c[k] for c in combinations}
            found.append(tuple(seen.values()))
        return found

    def configurations(self, sample: Sample, *, bits: int = 128) -> list[tuple[Mode, ...]]:
        """Every real configuration at ``sample``: one mode per group, a later group's found at
        each configuration of the groups before it (``modes_in_sequence``), certified."""
        return modes_in_sequence(self.solutions, sample.exact(), bits=bits)

    def chain(self, index: int) -> list[int]:
        """Group ``index`` and every group it is solved after (whose unknowns its equations hold,
        and theirs), in order."""
        held = {index}
        for k in range(index, -1, -1):
            if k in held:
                parameters = set(self.solutions[k].parameters)
                held |= {j for j in range(k) if parameters & set(self.solutions[j].unknowns)}
        return sorted(held)

    def later(self) -> set[int]:
        """The groups solved after another: their equations hold an earlier group's unknowns."""
        earlier = {u for s in self.solutions for u in s.unknowns}
        return {k for k, s in enumerate(self.solutions) if set(s.parameters) & earlier}

    def reference(self) -> Sample:
        """The sample with the most real modes among evenly spaced inputs (an angle's multiples
        of 90 degrees first): where the modes are counted and named."""
        assert self.input is not None
        lo, hi = _span_exact(self.input)
        candidates = [lo + (hi - lo) * k / REFERENCE_CANDIDATES for k in range(REFERENCE_CANDIDATES + 1)]
        if self.input.is_angle:
            candidates = [Fraction(90 * k) for k in range(-8, 9) if lo <= 90 * k <= hi] + candidates
        best, count = None, -1
        for value in dict.fromkeys(candidates):
            sample = self.sample(value)
            try:
                # groups in sequence: the configurations (a later group's modes vary with the earlier's)
                found = len(self.configurations(sample)) if self.later() else sum(len(m) for m in self.modes(sample))
            except ComputationError:  # modes meet there
                continue
            if found > count:
                best, count = sample, found
        if best is None:
            raise ComputationError(f"{self.scene.name}: no input tried is generic for its groups")
        return best


def _span_exact(spec: Input) -> tuple[Fraction, Fraction]:
    """The input's range in users' units, as rationals."""
    lo, hi = spec.span
    return Fraction(lo).limit_denominator(10**6), Fraction(hi).limit_denominator(10**6)


def prepare_groups(scene: Scene | str, *, command: str = "this command") -> GroupScene:
    """``scene`` (a Scene, a catalog name or a path) with its groups solved, in order (a later
    group's parameters hold the earlier groups' unknowns); a UsageError where the points move
    with more than one input (``command`` named)."""
    scene = as_scene(scene)
    compiled = compile_groups(scene)
    solutions = tuple(_solution(compiled, k) for k in range(len(compiled.groups)))
    held = {str(v) for s in solutions for v in s.parameters}
    held |= {str(v) for xy in compiled.coordinates.values() for c in xy for v in sympy.sympify(c).free_symbols}
    used = [n for n, names in compiled.inputs.items() if set(names) & held]
    if len(used) > 1:
        raise UsageError("scene", scene.name, f"moves with {len(used)} inputs ({', '.join(used)}): {command} takes "
                         "points solved together that move with one input, for now")
    return GroupScene(scene, compiled, solutions, scene.inputs[used[0]] if used else None)


def _solution(compiled: Groups, index: int) -> GroupSolution:
    """The group's rational univariate representation; its parameters are the inputs' variables
    and the unknowns of the earlier groups its equations hold."""
    return solve_in_order(compiled, index)


def solve_in_order(compiled: Groups, index: int) -> GroupSolution:
    """The rational univariate representation of group ``index``, every other name its equations
    hold (an input's variable, an earlier group's unknown) a parameter."""
    group = compiled.groups[index]
    names = sorted({str(v) for e in group.equations for v in e.free_symbols} - set(group.unknowns))
    ctx = flint_context(group.unknowns + tuple(names))
    return solve_group([to_flint(e, ctx) for e in group.equations], group.unknowns)


def on_circle(poly: flint.fmpq_mpoly, variables: Sequence[str]) -> flint.fmpq_mpoly:
    """``poly`` reduced modulo ``c**2 + s**2 - 1`` (its degree in ``s`` below 2), for an angle's
    ``variables = (c, s)``: the same values on the circle, often far fewer terms; as it is for a
    length's one variable.

    >>> ctx = flint.fmpq_mpoly_ctx.get(("x", "c", "s"), "lex")
    >>> x, c, s = ctx.gens()
    >>> on_circle(x * s**2 + s**3, ("c", "s"))
    -x*c^2 + x - c^2*s + s
    """
    if len(variables) != 2 or poly.is_zero():
        return poly
    ctx = poly.context()
    names = [str(n) for n in ctx.names()]
    if variables[1] not in names or variables[0] not in names:
        return poly
    c, s = (ctx.gens()[names.index(v)] for v in variables)
    return pseudo_remainder(poly, s * s + c * c - 1, variables[1])
