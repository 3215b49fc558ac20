"""``curve`` on a scene with points solved together: a point's path while the input moves.

The input's variables (an angle's ``c``, ``s`` with ``c**2 + s**2 = 1``) and every group's
unknowns are eliminated from the groups' equations and the point's definition; the eliminant is
factored and a factor kept only where it vanishes at a real mode's configuration at some
sample input (certified modes, ``GroupScene.modes``): extraneous factors are dropped. The check:
at other seeded samples, the point at every real mode lies on the curve (in balls).

>>> found = curve_groups("stephenson-iii-triad", "P", samples=4)
>>> found.degree, found.circularity, found.verification["passed"]
(6, 3, True)
"""

from __future__ import annotations

import random
import time
from collections.abc import Sequence
from fractions import Fraction
from typing import Any

import attrs
import flint
import sympy

from ...derivation.curves import curve_figures
from ...eliminate import eliminate
from ...eliminate.select import Witness
from ...errors import ComputationError, UsageError
from ...evaluate import ARB, evaluate
from ...runtime import suggest
from ...runtime.frozen import FrozenDict, frozen
from ...scene import Scene
from ...system import symbol
from .scene import GroupScene, Sample, prepare_groups

__all__ = ["curve_groups", "GroupCurve", "WITNESS_SAMPLES", "configurations", "assembling"]

WITNESS_SAMPLES = 6
"""Sample inputs whose real modes choose the curve's factors."""


@attrs.frozen
class GroupCurve:
    """The implicit curve of ``point`` (in ``variables``), its ``factors`` kept and ``dropped``,
    its degree and circularity, the check and the timings."""

    scene: Scene
    point: str
    variables: tuple[str, str]
    curve: str
    factors: tuple[str, ...]
    dropped: tuple[str, ...]
    degree: int
    circularity: int
    verification: FrozenDict[str, Any] = attrs.field(converter=frozen)
    timings: FrozenDict[str, float] = attrs.field(converter=frozen)
    exact: flint.fmpq_mpoly = attrs.field(eq=False, repr=False, default=None)

    @property
    def passed(self) -> bool:
        return bool(self.verification["passed"])

    def to_json(self) -> dict[str, Any]:
        return {"scene": self.scene.name, "point": self.point, "variables": list(self.variables),
                "curve": self.curve, "degree": self.degree, "circularity": self.circularity,
                "factors": list(self.factors), "dropped_factors": list(self.dropped),
                "verification": dict(self.verification), "timings": dict(self.timings)}


def curve_groups(scene: Scene | str, point: str, *, samples: int = 40, seed: int = 0) -> GroupCurve:
    """The curve traced by ``point`` of ``scene`` (with points solved together) while its one
    input moves; checked at ``samples`` seeded inputs (0: not checked)."""
    start = time.perf_counter()
    prepared = prepare_groups(scene, command="curve")
    scene = prepared.scene
    if not isinstance(point, str) or point not in scene.points:
        raise UsageError("point", point, f"not a point of {scene.name}" + suggest.known(point, scene.points, plural="points"))
    x, y = (sympy.sympify(v) for v in prepared.compiled.coordinates[point])
    unknowns = [u for g in prepared.compiled.groups for u in g.unknowns]
    moving = set(unknowns) | set(prepared.variables)
    if prepared.input is None or not {str(v) for v in (x.free_symbols | y.free_symbols)} & moving:
        raise UsageError("point", point, f"is fixed at ({x}, {y}): its trajectory is a point, not a curve")
    variables = (f"{point}_x", f"{point}_y")
    equations = [e for g in prepared.compiled.groups for e in g.equations]
    if (x, y) == tuple(symbol(v) for v in variables):  # a point solved for: its unknowns are the curve's variables
        unknowns = [u for u in unknowns if u not in variables]
    else:
        equations += [symbol(variables[0]) - x, symbol(variables[1]) - y]
    if len(prepared.variables) == 2:
        c, s = (symbol(v) for v in prepared.variables)
        equations.append(c**2 + s**2 - 1)
    rng = random.Random(seed)
    witnesses = [[Witness(c, exact=sample.exact())] for sample in _samples(prepared, WITNESS_SAMPLES, rng)
                 for c in configurations(prepared, sample, {point: variables})]
    timings = {"witnesses": time.perf_counter() - start}
    result = eliminate(equations, unknowns + list(prepared.variables), list(variables), witnesses=witnesses)
    curve, kept = result.exact
    timings["eliminate"] = time.perf_counter() - start - timings["witnesses"]
    degree, circularity = curve_figures(curve, variables)
    mark = time.perf_counter()
    verification = _check(prepared, curve, point=point, variables=variables, samples=samples, rng=rng)
    timings["verify"] = time.perf_counter() - mark
    timings["total"] = time.perf_counter() - start
    return GroupCurve(scene, point, variables, result.text, tuple(str(sympy.sympify(str(f).replace("^", "**")))
                                                                        for f in kept),
                      tuple(str(d) for d in result.dropped), degree, circularity, verification, timings, curve)


def _samples(prepared: GroupScene, count: int, rng: random.Random) -> list[Sample]:
    """The reference input and ``count - 1`` seeded ones in the input's range."""
    assert prepared.input is not None
    lo, hi = prepared.input.span
    found = [prepared.reference()]
    while len(found) < count:
        value = Fraction(rng.uniform(lo, hi)).limit_denominator(1000)
        found.append(prepared.sample(value))
    return found


def assembling(prepared: GroupScene, count: int, rng: random.Random, *, tries: int = 10) -> list[Sample]:
    """Up to ``count`` seeded inputs in range where every group has a real mode (of ``tries`` times
    as many drawn: a group may assemble over a small part of the range only)."""
    found: list[Sample] = []
    for sample in _samples(prepared, count * tries + 1, rng)[1:]:
        try:
            if prepared.configurations(sample) if prepared.later() else all(prepared.modes(sample)):
                found.append(sample)
        except ComputationError:  # modes meet exactly there: not a sample to compare at
            continue
        if len(found) == count:
            break
    return found


def configurations(prepared: GroupScene, sample: Sample, points: dict[str, tuple[str, str]] | None = None,
                   *, bits: int = 128) -> list[dict[str, flint.arb]]:
    """Every real configuration at ``sample`` (one mode per group), each variable in a ball: the
    input's, the groups' unknowns and, for each ``points`` entry, the point's coordinates under
    the names given; none where the sample is not generic (modes meet there)."""
    try:
        found = prepared.configurations(sample, bits=bits)
    except ComputationError:
        return []
    unknowns = {u for g in prepared.compiled.groups for u in g.unknowns}  # not a linear form's variable
    combos = [dict(sample.balls(bits), **{u: v for m in c for u, v in m.values.items() if u in unknowns})
              for c in found]
    with flint.ctx.workprec(bits):
        for values in combos:
            for name, (vx, vy) in (points or {}).items():
                xy = prepared.compiled.coordinates[name]
                values[vx], values[vy] = (evaluate(sympy.sympify(v), values, ARB) for v in xy)
    return combos


def _check(prepared: GroupScene, curve: flint.fmpq_mpoly, *, point: str, variables: Sequence[str], samples: int,
           rng: random.Random) -> dict[str, Any]:
    """The point at every real mode of ``samples`` seeded inputs, on the curve (its ball holding 0)."""
    if not samples:
        return {"status": "skipped", "passed": True, "samples": 0}
    names = [str(n) for n in curve.context().names()]
    compared, worst, failures = 0, 0.0, []
    for sample in assembling(prepared, samples, rng):
        for values in configurations(prepared, sample, {point: (variables[0], variables[1])}, bits=256):
            with flint.ctx.workprec(256):
                residual = _value(curve, names, values)
            compared += 1
            worst = max(worst, float(abs(residual).upper()))
            if not residual.contains(0):
                failures.append(f"{point} at {sample.shown}: the curve is {residual.str(5)} there, not 0")
    passed = compared > 0 and not failures
    status = "passed" if passed else "failed"
    if not compared:
        failures.append("no sample input assembles: nothing compared")
    return {"status": status, "passed": passed, "samples": samples, "compared": compared,
            "max_abs_error": worst, "failures": failures,
            "method": "the point at every real mode of each sample (the group's eliminant, certified in balls) "
                      "put into the curve"}


def _value(poly: flint.fmpq_mpoly, names: Sequence[str], values: dict[str, flint.arb]) -> flint.arb:
    total = flint.arb(0)
    for monomial, coefficient in zip(poly.monoms(), poly.coeffs()):
        term = flint.arb(coefficient)
        for name, exponent in zip(names, monomial):
            if exponent:
                term *= values[name] ** int(exponent)
        total += term
    return total
