"""Stationary points of an output over its input, by elimination and certified roots.

>>> result = extremum("arm-string", "AB", (0, 180))
>>> round(result.minimum.value, 9), round(result.minimum.input_deg, 6)
(57.921561087, 78.690068)

With a dimension symbolic, the minimum and its input come as closed forms in it:

>>> extremum("arm-string", "AB", (0, 180), params=["b"]).closed_form.value
sqrt(b**2 + 160000) - 350
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any, Union

import attrs
import mpmath
import sympy

from ...derivation.pipeline import derive
from ...derivation.prepared import Prepared, given, prepare, require_outputs
from ...derivation.witnesses import Groups
from ...errors import UsageError, renamed
from ...runtime import validation
from ...runtime.budget import Budget, Deadline, started
from ...runtime.frozen import FrozenDict, frozen
from ...runtime.exclusive import one_at_a_time
from ...scene.load import SceneLike, Values
from ...scene.compile import Span, lengths_in, spans_lengths_positive
from ...scene.model import Input, Scene, length_range_problem, range_problem
from ...system import symbol
from ..toggles import single_input
from .angles import AngleScale, direction_problem
from .closed import ClosedForm, Region, closed_form, describe, value_factors
from .critical import (DIGITS, CriticalPoint, Number, Problem, constant_value, critical_points, extreme,
                       meeting_factors, points_at, stationary_factors, stretches_of)

if TYPE_CHECKING:
    from ...derivation.pipeline import Derivation
    from ...scene.compile import Compiled

Exact = tuple[Union[sympy.Expr, None], Union[sympy.Expr, None]]  # an angle's extreme in degrees, its via's value

__all__ = ["extremum", "extremum_of", "problem_for", "Extremum", "ClosedForm", "CriticalPoint",
           "critical_points", "points_at", "extreme", "extreme_at", "AngleScale"]


def _points(points: Any) -> tuple[CriticalPoint, ...]:
    return tuple(points)


def _maybe_tuple(items: Any) -> tuple[sympy.Expr, ...] | None:
    return None if items is None else tuple(items)


def _maybe_frozen(items: Any) -> FrozenDict[str, Exact] | None:
    return None if items is None else frozen(items)


@attrs.frozen
class Extremum:
    """Critical points of an output in a range, its minimum and maximum, and closed forms."""

    scene: str
    output: str
    input: str
    range: tuple[float, float]
    # the dimensions the numbers are for (symbolic ones at their defaults)
    parameters: FrozenDict[str, sympy.Expr] = attrs.field(converter=frozen)
    critical_points: tuple[CriticalPoint, ...] = attrs.field(converter=_points)  # stationary ones, the range ends
    minimum: CriticalPoint
    maximum: CriticalPoint
    closed_form: ClosedForm | None = None
    # how it was found, not what: its parametrisation compares by identity
    problem: Problem | None = attrs.field(default=None, eq=False)
    # stationary factors in t and the symbolic dimensions
    stationary: tuple[sympy.Expr, ...] | None = attrs.field(default=None, converter=_maybe_tuple)
    # an angle output: 'minimum'/'maximum' -> (degrees, via), or Nones
    exact: FrozenDict[str, Exact] | None = attrs.field(default=None, converter=_maybe_frozen)

    def to_json(self) -> dict[str, object]:
        angle = self.problem is None or self.problem.line.is_angle
        point = lambda p: p.to_json() if angle else _in_lengths(p.to_json())  # noqa: E731
        document: dict[str, Any] = {"scene": self.scene, "of": self.output, "input": self.input, "unit": "deg" if angle else "length",
                    "range": list(self.range), "parameters": {n: str(v) for n, v in self.parameters.items()},
                    "critical_points": [point(p) for p in self.critical_points if p.kind != "endpoint"],
                    "endpoints": [point(p) for p in self.critical_points if p.kind == "endpoint"],
                    "minimum": point(self.minimum), "maximum": point(self.maximum)}
        scale = self.problem.scale if self.problem is not None else None
        if scale is not None:
            document["angle"] = scale.to_json()
            for key, (degrees, via) in (self.exact or {}).items():
                document[key].update(exact=_text(degrees), exact_via=_text(via))
        if self.closed_form is not None:
            document["closed_form"] = self.closed_form.to_json()
        return document


def _in_lengths(point: Mapping[str, object]) -> dict[str, object]:
    """A critical point's JSON for a length input: ``input_length``, ``enclosure_length``."""
    return {key.replace("_deg", "_length"): value for key, value in point.items()}


def _text(expr: sympy.Expr | None) -> str | None:
    return None if expr is None else str(expr)


def problem_for(derived: Derivation, output: str, degrees: tuple[sympy.Expr, sympy.Expr] | None = None, *,
                witnesses: Groups | None = None, deadline: Deadline | None = None) -> Problem:
    """The extremum problem of ``output`` (a scalar or an angle) in a derivation of it; a
    direction's reference is chosen for its motion over ``degrees`` (lo, hi), by default the
    input's range. ``witnesses``: the derivation's (its ``Prepared``'s), drawn again if not given;
    its eliminations keep to ``deadline``, if any."""
    compiled = derived.compiled
    _one_input(compiled, output)
    name, line = single_input(compiled, "extrema")
    ((output_name, unknowns),) = compiled.outputs.items()
    parameters = tuple(symbol(p) for p in compiled.system.parameters)
    angle = compiled.angles.get(output_name)
    if angle is not None and angle.direction:
        lo, hi = degrees if degrees is not None else compiled.scene.inputs[name].span
        return direction_problem(derived, angle, line, parameters, lo, hi, output, witnesses=witnesses,
                                 deadline=deadline)
    if len(unknowns) != 1:
        raise UsageError("output", output, "name a scalar output (a distance, a coordinate or an angle), not a point")
    chosen = next(b for b in derived.branches if b.selected)
    scale = AngleScale(angle.cos, None) if angle is not None else None
    return Problem(derived.eliminations[unknowns[0]].polynomial, chosen.values[unknowns[0]],
                   symbol(unknowns[0]), line, parameters, scale, tuple(chosen.discriminants.values()),
                   stretches_of(derived, chosen, lambda b: b.values[unknowns[0]], output))


def input_span(spec: Input, angle_range: tuple[float | str, float | str] | None) -> tuple[sympy.Expr, sympy.Expr]:
    """The range ``extremum`` searches, exactly, in degrees (a length input's own unit):
    ``angle_range`` in the input's unit, else its declared range; refused in one line if not finite."""
    if angle_range is not None and (isinstance(angle_range, str) or not isinstance(angle_range, Sequence)
                                    or len(angle_range) != 2):  # a string of two digits would unpack too
        raise UsageError("angle_range", angle_range, "expected two finite numbers (lo, hi)")
    lo, hi = angle_range if angle_range is not None else (spec.lo, spec.hi)
    # read within algkin's sizes: sympy.Rational("1e999999999") is minutes of work on 10**999999999
    to_degrees = lambda v: sympy.Rational(validation.rational(str(v))) * (1 if spec.unit != "rad" else 180 / sympy.pi)  # noqa: E731
    try:
        lo, hi = to_degrees(lo), to_degrees(hi)
    except validation.NumberTooLarge as err:
        raise UsageError("angle_range", angle_range, str(err)) from None
    except (TypeError, ValueError):
        raise UsageError("angle_range", angle_range, "expected two finite numbers (lo, hi)") from None
    problem: str | None = None
    if not (lo.is_finite and hi.is_finite):
        problem = "must be finite"
    else:
        problem = range_problem(float(lo), float(hi)) if spec.is_angle else length_range_problem(lo, hi)
    if problem:
        raise UsageError("angle_range", f"{float(lo):g}:{float(hi):g}", problem)
    return lo, hi


def _one_input(compiled: Compiled, output: str) -> str:
    """The one input ``output`` moves with; a UsageError if none (it is made of fixed points only) or several."""
    if not compiled.system.inputs:
        raise UsageError("output", output, "the output does not depend on the input")
    if len(compiled.system.inputs) != 1:
        raise UsageError("scene", compiled.scene.name, "an extremum needs exactly one input")
    (name,) = compiled.system.inputs
    return name


@one_at_a_time
def extremum(scene: SceneLike | Prepared, output: str, angle_range: tuple[float | str, float | str] | None = None,
             params: Sequence[str] = (), largest: bool = False, method: str = "resultant", backend: str = "flint",
             set: Values | None = None,  # noqa: A002 - the public API's name, as in derive
             budget: Budget | Deadline | None = None) -> Extremum:
    """Critical points, minimum and maximum of ``output`` over the scene's one input.

    ``angle_range`` is in the input's unit (default: its declared range). With ``params``
    symbolic, ``closed_form`` gives the minimum (the maximum with ``largest``) and its
    input in those parameters, with where that holds. ``set`` gives dimensions exact values.
    ``scene`` may be a ``Prepared`` one (``prepare``) for ``output`` alone. A ``Budget`` (or the
    ``Deadline`` of one running) bounds the time and the eliminants' terms.
    """
    deadline = started(budget)
    largest = validation.flag("largest", largest)
    given(scene, params=params, set=set)
    with renamed("outputs", to="output"):
        prepared = scene if isinstance(scene, Prepared) else prepare(scene, outputs=[output], params=params, set=set,
                                                                     deadline=deadline)
    require_outputs(prepared, "output", [output])
    derived = derive(prepared, method=method, backend=backend, samples=0, budget=deadline)
    return extremum_of(derived, output, angle_range, largest, backend, witnesses=prepared.witnesses,
                       deadline=deadline)


def extremum_of(derived: Derivation, output: str, angle_range: tuple[float | str, float | str] | None = None,
                largest: bool = False, backend: str = "flint", *, witnesses: Groups | None = None,
                deadline: Deadline | None = None) -> Extremum:
    """``extremum`` of an output of an existing derivation (with that output alone).

    An angle output's values are in degrees (see ``angles``): its extrema are the via's,
    mapped, and the least and greatest exchanged where the angle falls as its via grows. Its
    eliminations keep to ``deadline``, if any.
    """
    name = _one_input(derived.compiled, output)
    lo, hi = input_span(derived.compiled.scene.inputs[name], angle_range)
    problem = problem_for(derived, output, (lo, hi), witnesses=witnesses, deadline=deadline)
    scale = problem.scale
    flip = scale is not None and scale.decreasing
    defaults = {p: sympy.Rational(str(derived.compiled.parameter_values[p.name])) for p in problem.parameters}
    constant = constant_value(problem, defaults, lo, hi)
    if constant is not None:
        raise UsageError("output", output, f"the output does not depend on the input: it is {constant} throughout")
    stationary = stationary_factors(problem, backend, deadline=deadline)
    points = points_at(problem, stationary, defaults, lo, hi)
    closed = closed_form(problem, stationary, defaults, lo, hi, largest != flip, deadline=deadline,
                         domain=_domain(derived.compiled.scene, problem.parameters),
                         lengths=lengths_in(derived.compiled.scene, [p.name for p in problem.parameters])) \
        if problem.parameters else None
    exact = None
    if scale is not None:
        exact = {key: _exact(problem, stationary, defaults, extreme(points, largest=(key == "maximum") != flip),
                             deadline)
                 for key in ("minimum", "maximum")}
        points = [in_degrees(p, scale) for p in points]
        closed = closed if closed is None else closed_in_degrees(closed, scale)
    return Extremum(derived.compiled.scene.name, output, name, (float(lo), float(hi)),
                    {p.name: v for p, v in defaults.items()}, points, extreme(points), extreme(points, True),
                    closed, problem, stationary, exact)


def _domain(scene: Scene, parameters: Sequence[sympy.Symbol]) -> tuple[Span, ...] | None:
    """Where one symbolic dimension makes a mechanism: where the lengths it is stay positive (None:
    every real value, a coordinate's; regions are not drawn in more than one dimension)."""
    return spans_lengths_positive(scene, parameters[0].name) if len(parameters) == 1 else None


def _exact(problem: Problem, stationary: Sequence[sympy.Expr], defaults: Mapping[sympy.Symbol, sympy.Expr],
           best: CriticalPoint, deadline: Deadline | None) -> Exact:
    """``(degrees, via)`` of an angle's extremum ``best`` at the dimensions ``defaults``, as exact
    expressions (radicals); ``(None, None)`` where the via's root has none of degree <= 4."""
    assert problem.scale is not None, "an angle output's"
    fixed = problem.at(defaults)
    factors = [sympy.expand(f.xreplace(defaults)) for f in stationary]
    with mpmath.workdps(DIGITS):
        found = describe(fixed, factors, value_factors(fixed, deadline=deadline), {}, best,
                         meeting_factors(fixed, deadline=deadline))
        return exact_pair(problem.scale, found.value, best)


def exact_pair(scale: AngleScale, value: sympy.Expr | None, best: CriticalPoint) -> Exact:
    """``(degrees, via)`` of an angle's extremum ``best`` from its via's exact ``value``;
    ``(None, None)`` where there is none or it is not ``best``'s (to 1e-12)."""
    if value is None or not _equal(value, best.value):
        return None, None
    return scale.expr(value), value


def _equal(expr: sympy.Expr, value: mpmath.mpf) -> bool:
    # a rational's float directly (most extremes of a design are at a turn's end: rational)
    number = complex(float(expr)) if expr.is_Rational else complex(sympy.N(expr, DIGITS))
    return abs(number.imag) < 1e-20 and abs(number.real - float(value)) <= 1e-12 * (1 + abs(float(value)))


def in_degrees(point: CriticalPoint, scale: AngleScale) -> CriticalPoint:
    """A critical point of an angle's via as one of the angle: its value in degrees, and its
    kind turned round where the angle falls as the via grows."""
    kind = {"minimum": "maximum", "maximum": "minimum"}.get(point.kind, point.kind) if scale.decreasing \
        else point.kind
    return CriticalPoint(point.input_deg, scale.degrees(point.value), kind, point.enclosure, point.value)


def closed_in_degrees(form: ClosedForm, scale: AngleScale) -> ClosedForm:
    """The closed form of an angle's via's extremum as the angle's, in degrees."""
    values = [None if v is None else scale.expr(v) for v in form.region_values]
    regions: list[Region] = []
    k = 0
    for original in form.regions:
        region: Region = dict(original)  # type: ignore[assignment]  # a frozen Region, thawed to change
        if region["at"] != "nowhere":
            region["value"] = _text(values[k])
            if "sample_value" in region:
                region["sample_value"] = float(scale.degrees(region["sample_value"]))
        k += 1
        regions.append(region)
    return attrs.evolve(form, value=scale.expr(form.value), regions=regions, region_values=values, via_value=form.value)


def extreme_at(problem: Problem, stationary: Sequence[sympy.Expr], values: Mapping[sympy.Symbol, sympy.Expr],
               lo: Number, hi: Number, largest: bool = False) -> CriticalPoint:
    """The certified minimum (maximum with ``largest``) of ``problem``'s output at the dimensions
    ``values``, over ``[lo, hi]`` degrees: an angle's in degrees."""
    scale = problem.scale
    flip = scale is not None and scale.decreasing
    best = extreme(points_at(problem, stationary, values, lo, hi), largest != flip)
    return best if scale is None else in_degrees(best, scale)
