"""scene -> system -> elimination -> closed-form branches -> verification.

>>> result = curve("chebyshev-lambda", "P")
>>> result.degree, result.circularity, result.irreducible, result.verification.passed
(6, 3, True, True)
"""

from __future__ import annotations

import contextlib
import functools
import math
import time
from collections.abc import Iterable, Iterator, Mapping, Sequence
from fractions import Fraction
from typing import Any

import attrs
import flint
import sympy

from ..branches import check_assembly, closed_forms
from ..branches import Branch
from ..eliminate import DEFAULT_METHOD, Elimination, Witness
from ..errors import UsageError
from ..evaluate import ARB, evaluate
from ..runtime import validation
from ..runtime.budget import Budget, Deadline, started
from ..runtime.cache import BoundedCache
from ..runtime.frozen import FrozenDict, frozen
from ..scene import Compiled, compile_scene
from ..scene.load import SceneLike, Values, as_scene
from ..scene.settings import with_values
from ..system import inputs_json, symbol
from ..verify import CheckSetup, Verification, verify_branches
from .assembles import certify_labels, where_assembled
from .tasks import curve_task, eliminant_tasks

__all__ = ["derive", "curve", "family_method", "Derivation", "CurveResult", "witnesses", "certify_labels", "compile_and_branch",
           "check_setup"]

WITNESS_BITS = 256
WITNESSES_PER_BRANCH = 3
FAMILY_UNKNOWNS = 4  # eliminated unknowns up to which a family stays with the linear method
PREPARED_SCENES = 32  # compiled scenes (with their branches) kept for the next call
# What a derivation or a curve builds of a scene before eliminating, kept by the values it is
# built from (a scene, its outputs and symbolic dimensions; a compiled scene and its branches):
# an equal question later in the process starts at the elimination. ``clear()`` them for a cold start.
PREPARED: BoundedCache[_Prepared] = BoundedCache(PREPARED_SCENES)
CHECKED: BoundedCache[tuple[Any, ...]] = BoundedCache(PREPARED_SCENES)


def _branches(branches: Iterable[Branch]) -> tuple[Branch, ...]:
    return tuple(branches)


def _intervals(certified: Iterable[Iterable[Mapping[str, Any]] | None]) -> tuple[Any, ...]:
    """Per branch, its certified intervals as frozen mappings (None where labels were not certified)."""
    return tuple(None if c is None else tuple(frozen(i) for i in c) for c in certified)


@attrs.frozen
class Derivation:
    """What ``derive`` found for a scene: system, eliminants, branches, verification (an
    immutable, hashable value; its timings are not part of what it equals)."""

    compiled: Compiled
    method: str
    backend: str
    eliminations: FrozenDict[str, Elimination[Any]] = attrs.field(converter=frozen)  # unknown -> its eliminant
    branches: tuple[Branch, ...] = attrs.field(converter=_branches)
    verification: Verification
    timings: FrozenDict[str, float] = attrs.field(converter=frozen, eq=False)
    # per branch: ({from_deg, to_deg, status}, ...), one-input scenes
    certified: tuple[Any, ...] = attrs.field(default=(), converter=_intervals)

    def to_json(self) -> dict[str, Any]:
        system = self.compiled.system
        return {
            "scene": self.compiled.scene.name,
            "method": self.method,
            "backend": self.backend,
            "inputs": inputs_json(system.inputs),
            "system": system.to_json(),
            "outputs": {n: list(v) for n, v in self.compiled.outputs.items()},
            "eliminants": {u: str(e.polynomial) for u, e in self.eliminations.items()},
            "eliminant_figures": {u: _figures(e) for u, e in self.eliminations.items()},
            "branches": [dict(b.to_json(), certified=None if c is None else [dict(i) for i in c])
                         for b, c in zip(self.branches, self.certified)],
            "verification": self.verification.to_json(),
            "timings": dict(self.timings),
        }


@attrs.frozen
class CurveResult:
    """The implicit curve of a point: polynomial, figures, dropped factors, verification (an
    immutable, hashable value; its timings are not part of what it equals)."""

    compiled: Compiled
    point: str
    variables: tuple[str, ...]
    elimination: Elimination[Any]
    degree: int
    circularity: int
    irreducible: bool
    verification: Verification
    timings: FrozenDict[str, float] = attrs.field(converter=frozen, eq=False)

    def to_json(self) -> dict[str, Any]:
        return {
            "scene": self.compiled.scene.name,
            "point": self.point,
            "variables": list(self.variables),
            "parameters": list(self.compiled.system.parameters),
            "method": self.elimination.method,
            "backend": self.elimination.backend,
            "curve": self.elimination.text,
            "degree": self.degree,
            "circularity": self.circularity,
            "irreducible": self.irreducible,
            # why the curve needed no choice of factors at the witnesses, when it needed none
            "irreducibility": str(self.elimination.proof) if self.elimination.proof else None,
            "terms": self.elimination.terms,
            "coefficient_bits": self.elimination.bits,
            "dropped_factors": [str(f) for f in self.elimination.dropped],
            "verification": self.verification.to_json(),
            "timings": dict(self.timings),
        }


def _figures(elimination):
    return {
        "degree": elimination.degree,
        "terms": elimination.terms,
        "coefficient_bits": elimination.bits,
        "dropped_factors": [str(f) for f in elimination.dropped],
    }


def _arguments(outputs, params, samples, seed, budget):
    """The public arguments checked, with the deadline to run under (``budget`` started, if not already)."""
    validation.count("samples", samples, validation.MAX_VERIFY_SAMPLES)
    validation.seed(seed)
    return (validation.names("outputs", outputs), validation.names("params", params) or (),
            started(validation.budget(budget)))


def _exact_samples(spec, count, pieces=None):
    """``4 * count`` exact rational inputs spread over the input's range (or over ``pieces`` of it, in
    radians or lengths: where something assembles), the same number for every input: an angle's as an
    exact point ``(cos, sin)`` on the unit circle, a length's as ``(length,)``.

    >>> from algkin.scene.model import Input
    >>> points = _exact_samples(Input("t", 179, 181, "deg"), 2)
    >>> len(points), all(c * c + s * s == 1 and c < 0 for c, s in points)
    (8, True)
    """
    pieces = pieces or [(float(spec.to_radians(spec.lo)), float(spec.to_radians(spec.hi)))]
    values = []
    for k in range(4 * count):
        value = _along(pieces, (k + 0.5) / (4 * count))
        values.append(_on_circle(value) if spec.is_angle else (Fraction(value).limit_denominator(97),))
    # Interleave so that the first few samples already spread over the range.
    return values[::4] + values[1::4] + values[2::4] + values[3::4]


def _along(pieces, share):
    """The point ``share`` (0 to 1) of the way along the intervals ``pieces`` put end to end."""
    left = share * sum(hi - lo for lo, hi in pieces)
    for lo, hi in pieces:
        if left <= hi - lo:
            return lo + left
        left -= hi - lo
    return pieces[-1][1]


def _on_circle(angle):
    """An exact rational point ``(cos, sin)`` on the unit circle near ``angle`` (radians), from the
    rational half-angle tangent ``t`` (or, near a half turn where ``t`` is unbounded, its cotangent ``u``).

    >>> _on_circle(0.0), _on_circle(math.pi)
    ((Fraction(1, 1), Fraction(0, 1)), (Fraction(-1, 1), Fraction(0, 1)))
    """
    if abs(math.cos(angle / 2)) >= abs(math.sin(angle / 2)):
        t = Fraction(math.tan(angle / 2)).limit_denominator(97)
        return (1 - t * t) / (1 + t * t), 2 * t / (1 + t * t)
    u = Fraction(1 / math.tan(angle / 2)).limit_denominator(97)
    return (u * u - 1) / (u * u + 1), 2 * u / (u * u + 1)


def witnesses(compiled, branches):
    """Per branch, configurations in ball arithmetic at exact rational inputs."""
    where = where_assembled(compiled, branches) or {}
    spread = {n: _exact_samples(compiled.scene.inputs[n], WITNESSES_PER_BRANCH * 3, where.get(n))
              for n in compiled.system.inputs}
    groups = []
    with flint.ctx.workprec(WITNESS_BITS):
        for branch in branches:
            group = []
            for k in range(len(next(iter(spread.values()), [None]))):
                point = _witness(compiled, branch, spread, k)
                if point is not None:
                    group.append(point)
                if len(group) == WITNESSES_PER_BRANCH:
                    break
            groups.append(group)
    return groups


def _witness(compiled, branch, spread, k):
    exact = {}  # the inputs' cos and sin (or lengths) and the dimensions are rational: kept exactly too
    for name, variables in compiled.system.inputs.items():
        exact.update(zip(variables, spread[name][k]))
    for n in compiled.system.parameters:
        default = Fraction(str(compiled.parameter_values[n]))
        exact[n] = default * (1 + Fraction(k + 1, 211)) if default else Fraction(k + 1, 211)
    values = {n: ARB.number(v.numerator, v.denominator) for n, v in exact.items()}
    for disc in branch.discriminants.values():
        if not evaluate(disc, values, ARB) > 0:
            return None
    for unknown, expr in branch.values.items():
        values[unknown] = evaluate(expr, values, ARB)
        if not values[unknown].is_finite():
            return None
    return Witness(values, {n: flint.fmpq(v.numerator, v.denominator) for n, v in exact.items()})


def _verify(compiled, branches, samples, seed, polynomials, factors=None):
    """Independent check, with symbolic parameters at their defaults; ``factors`` (name ->
    the kept factors of ``polynomials[name]``) lets it catch a leftover extraneous factor."""
    if not samples:
        return Verification.skipped()
    fixed, indicators, fixed_branches, inputs = _checked(compiled, branches)
    setup = CheckSetup(system=fixed, indicators=indicators, branches=fixed_branches, inputs=inputs,
                       parameters=compiled.parameter_values)
    return verify_branches(setup, samples=samples, seed=seed, polynomials=polynomials, factors=factors,
                           where=where_assembled(compiled, branches))


def _checked(compiled, branches):
    """What the check needs of a compiled scene, with the dimensions at their defaults (once per scene)."""
    branches = tuple(branches)
    return CHECKED.get((compiled, branches), lambda: _check_setup(compiled, branches))


def _check_setup(compiled, branches):
    system = compiled.system
    defaults = {symbol(n): compiled.parameter_values[n] for n in system.parameters}
    fixed = type(system)(system.unknowns, (), system.inputs,
                         tuple(sympy.expand(e.xreplace(defaults)) for e in system.equations),
                         system.nonnegative)
    inputs = {n: (float(i.to_radians(i.lo)), float(i.to_radians(i.hi)))
              for n, i in compiled.scene.inputs.items() if n in system.inputs}
    return (
        fixed,
        tuple((i.point, i.expr.xreplace(defaults), i.positive, i.negative) for i in compiled.indicators),
        tuple((b.labels, frozen({u: v.xreplace(defaults) for u, v in b.values.items()}),
               frozen({p: d.xreplace(defaults) for p, d in b.discriminants.items()})) for b in branches),
        frozen(inputs))


def check_setup(compiled, branches):
    """What an independent check of ``branches`` starts from, the dimensions at their defaults:
    ``(system, indicators, [(labels, values, discriminants)], {input: (lo, hi) radians})``."""
    return _checked(compiled, branches)


def compile_and_branch(scene, outputs, params):
    """The stages derive and curve share: compile, closed forms, assembly check, witnesses.

    Built once per scene, outputs and parameters, and reused: a second derivation of the same
    scene in one process starts at the elimination."""
    timings = {}
    prepared = _prepared(scene, outputs, params, timings)
    return prepared.compiled, *prepared.branch(timings), timings


class _Prepared:
    """A compiled scene and what is built from it once: its branches and their witnesses."""

    def __init__(self, compiled):
        self.compiled = compiled
        self.built = None
        self.places = {}  # point -> where it stays on each branch (None where it moves)

    def branch(self, timings):
        """``(branches, witnesses)``, found on the first call."""
        if self.built is None:
            with _timed(timings, "branches"):
                branches = tuple(closed_forms(self.compiled))
                check_assembly(self.compiled, branches)
                where_assembled(self.compiled, branches)  # a structure refused before its witnesses
                self.built = branches, tuple(witnesses(self.compiled, branches))
        timings.setdefault("branches", 0.0)
        return self.built


def _prepared(scene, outputs, params, timings):
    """The compiled scene, kept from before when the same scene was compiled for the same
    outputs and symbolic dimensions (its file too: the errors found later name it)."""
    key = (scene, scene.source, tuple(outputs or ()), tuple(params))
    with _timed(timings, "compile"):
        return PREPARED.get(key, lambda: _Prepared(compile_scene(scene, outputs, params)))


@contextlib.contextmanager
def _timed(timings: dict[str, float], stage: str) -> Iterator[None]:
    """``timings[stage]``: the seconds the block took."""
    mark = time.perf_counter()
    try:
        yield
    finally:
        timings[stage] = time.perf_counter() - mark


def derive(scene: SceneLike, outputs: Sequence[str] | None = None, method: str = DEFAULT_METHOD,
           backend: str = "flint", params: Sequence[str] = (), samples: int = 40, seed: int = 0,
           certify: bool = True, budget: Budget | Deadline | None = None,
           set: Values | None = None) -> Derivation:  # noqa: A002 - ``set=`` is the public name (the command line's --set)
    """Eliminants, closed-form branches and their verification for ``outputs`` of ``scene``.

    ``certify`` also certifies each branch's label per input interval (the slowest stage);
    a ``Budget`` bounds the time of the whole derivation, loading and compiling the scene
    included, and the size of its eliminants (the ``Deadline`` of one already running: the
    derivation counts against it). ``set`` gives dimensions exact values
    (``{"a": "3/2"}``) in place of their defaults.
    """
    outputs, params, budget = _arguments(outputs, params, samples, seed, budget)
    values = set
    start = time.perf_counter()
    return budget.run(functools.partial(_derive, scene, values, outputs, params, start, method, backend, samples,
                                        seed, certify, budget))


def _derive(scene, values, outputs, params, start, method, backend, samples, seed, certify, budget):
    scene = _load(scene, values, params, budget)
    budget.note(f"compiling {scene.name} and finding its branches")
    compiled, branches, groups, timings = compile_and_branch(scene, outputs, params)
    with _timed(timings, "eliminate"):
        eliminations = {u: task.run(method, backend, budget) for u, task in eliminant_tasks(compiled, groups).items()}
    budget.note(f"verifying the branches of {compiled.scene.name}")
    with _timed(timings, "verify"):
        verification = _verify(compiled, branches, samples, seed,
                               {u: e.exact[0] for u, e in eliminations.items()},
                               {u: e.exact[1] for u, e in eliminations.items()})
    budget.note(f"certifying the branch labels of {compiled.scene.name}")
    with _timed(timings, "certify"):
        certified = certify_labels(compiled, branches) if certify else [None] * len(branches)
    timings["total"] = time.perf_counter() - start
    return Derivation(compiled, method, backend, eliminations, branches, verification, timings, certified)


def _load(scene, values, params, budget):
    """The scene, loaded (or a given one checked) inside the budget, its expressions can be costly;
    with the dimensions in ``values`` set."""
    budget.note(f"loading {getattr(scene, 'name', scene)}")
    return with_values(as_scene(scene), values, params)


def _curve_figures(result, variables):
    """Degree in the point's coordinates, and circularity: how many times ``x**2 + y**2``
    divides the top-degree form (in python-flint, on the exact eliminant, no conversion)."""
    poly = result.exact[0]
    ctx = poly.context()
    names = [str(n) for n in ctx.names()]
    ix, iy = (names.index(v) for v in variables)
    terms = poly.to_dict()
    degree = max(int(m[ix]) + int(m[iy]) for m in terms)
    top = ctx.from_dict({m: c for m, c in terms.items() if int(m[ix]) + int(m[iy]) == degree})
    x, y = ctx.gens()[ix], ctx.gens()[iy]
    circle, count = x * x + y * y, 0
    while 2 * (count + 1) <= degree:
        top, remainder = divmod(top, circle)
        if not remainder.is_zero():
            break
        count += 1
    return degree, count


def still_at(compiled, branch, point):
    """Where ``point`` stays on ``branch`` if its closed form involves no input, else ``None``.

    A fixed point, or one built only from fixed points (a frame on two pivots), does not move:
    its "trajectory" is a point, and eliminating towards a curve would find no polynomial.
    """
    substitution = {symbol(u): v for u, v in branch.values.items()}
    xy = tuple(sympy.sympify(v).xreplace(substitution) for v in compiled.coordinates[point])
    angles = {symbol(n) for pair in compiled.system.inputs.values() for n in pair}
    return None if any(v.free_symbols & angles for v in xy) else xy


def _refuse_still(prepared, branches, point):
    """A usage error naming where ``point`` stays, if it stays put on every branch (the
    substitution is costly on big closed forms: its answer is kept with the scene)."""
    compiled = prepared.compiled
    if point not in prepared.places:
        prepared.places[point] = [still_at(compiled, b, point) for b in branches]
    places = prepared.places[point]
    if all(p is not None for p in places):
        x, y = places[next(k for k, b in enumerate(branches) if b.selected)]
        raise UsageError("point", point, f"is fixed at ({x}, {y}): its trajectory is a point, not a curve")


def family_method(task, method):
    """``interpolate`` for the default method when the curve's parameters enter only the
    traced point's own equations (a symbolic tracing point: every specialisation is a fixed
    curve, cheap to eliminate, while the linear method would carry them through every
    resultant), and more than a four-bar's four unknowns are eliminated (a four-bar's
    family takes the linear method milliseconds); ``method`` otherwise."""
    coordinates = {symbol(v) for v in task.keep[:2]}
    held = [e for e in task.equations if e.free_symbols & {symbol(p) for p in task.parameters}]
    if method != DEFAULT_METHOD or len(task.eliminate) <= FAMILY_UNKNOWNS or not held \
            or any(not e.free_symbols & coordinates for e in held):
        return method
    return "interpolate"


def curve(scene: SceneLike, point: str, method: str = DEFAULT_METHOD, backend: str = "flint",
          params: Sequence[str] = (), samples: int = 40, seed: int = 0, budget: Budget | Deadline | None = None,
          set: Values | None = None) -> CurveResult:  # noqa: A002 - as in derive
    """The implicit curve ``F(point_x, point_y) = 0`` traced by ``point`` (a one-input motion).

    A ``Budget`` bounds the time of the whole computation, loading and compiling the scene
    included, and the size of its eliminants (or the ``Deadline`` of one running, as in
    ``derive``). ``set`` gives dimensions exact values.
    """
    _, params, budget = _arguments(None, params, samples, seed, budget)
    values = set
    start = time.perf_counter()
    return budget.run(functools.partial(_curve, scene, values, point, params, start, method, backend, samples,
                                        seed, budget))


def _curve(scene, values, point, params, start, method, backend, samples, seed, budget):
    scene = _load(scene, values, params, budget)
    if not isinstance(point, str) or point not in scene.points:
        raise UsageError("point", point, f"not a point of {scene.name} (points: {', '.join(scene.points)})")
    budget.note(f"compiling {scene.name}")
    timings = {}
    prepared = _prepared(scene, [point], params, timings)
    compiled = prepared.compiled
    if len(compiled.system.inputs) > 1:
        raise UsageError("point", point, f"moves with {len(compiled.system.inputs)} inputs "
                         f"({', '.join(compiled.system.inputs)}) in {scene.name}: its trajectory is a region, "
                         "not a curve")
    budget.note(f"finding the branches of {compiled.scene.name}")
    branches, groups = prepared.branch(timings)
    _refuse_still(prepared, branches, point)
    with _timed(timings, "eliminate"):
        task = curve_task(compiled, groups, point)
        result = task.run(family_method(task, method), backend, budget)
    variables = task.keep[:2]
    figures = _curve_figures(result, variables)
    budget.note(f"verifying the curve of {point} in {compiled.scene.name}")
    with _timed(timings, "verify"):
        verification = _verify(compiled, branches, samples, seed, {"curve": result.exact[0]},
                               {"curve": result.exact[1]})
    timings["total"] = time.perf_counter() - start
    return CurveResult(compiled, point, variables, result, figures[0], figures[1],
                       len(result.raw_factors) == 1, verification, timings)
