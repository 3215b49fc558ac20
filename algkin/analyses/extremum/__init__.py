"""Stationary points of an output over its input, by elimination and certified roots.

>>> result = extremum("arm-string", "AB", (0, 180))
>>> round(result.minimum.value, 9), round(result.minimum.input_deg, 6)
(57.921561087, 78.690068)

With a dimension symbolic, the minimum and its input come as closed forms in it:

>>> extremum("arm-string", "AB", (0, 180), params=["b"]).closed_form.value
sqrt(b**2 + 160000) - 350
"""

from dataclasses import dataclass

import sympy

from ...derivation.pipeline import derive
from ...errors import UsageError
from ...scene.model import range_problem
from ...system import symbol
from .closed import ClosedForm, closed_form
from .critical import CriticalPoint, Problem, critical_points, extreme, points_at, stationary_factors

__all__ = ["extremum", "extremum_of", "problem_for", "Extremum", "ClosedForm", "CriticalPoint",
           "critical_points", "points_at", "extreme"]


@dataclass
class Extremum:
    """Critical points of an output in a range, its minimum and maximum, and closed forms."""

    scene: str
    output: str
    input: str
    range: tuple
    parameters: dict  # the dimensions the numbers are for (symbolic ones at their defaults)
    critical_points: list  # CriticalPoint, stationary ones then the two range ends
    minimum: CriticalPoint
    maximum: CriticalPoint
    closed_form: ClosedForm = None
    problem: Problem = None
    stationary: list = None  # stationary factors in t and the symbolic dimensions

    def to_json(self):
        document = {"scene": self.scene, "of": self.output, "input": self.input, "range": list(self.range),
                    "parameters": {n: str(v) for n, v in self.parameters.items()},
                    "critical_points": [p.to_json() for p in self.critical_points if p.kind != "endpoint"],
                    "endpoints": [p.to_json() for p in self.critical_points if p.kind == "endpoint"],
                    "minimum": self.minimum.to_json(), "maximum": self.maximum.to_json()}
        if self.closed_form is not None:
            document["closed_form"] = self.closed_form.to_json()
        return document


def problem_for(derived, output):
    """The extremum problem of ``output`` (a scalar) in a derivation of it."""
    compiled = derived.compiled
    if len(compiled.system.inputs) != 1:
        raise UsageError("scene", compiled.scene.name, "an extremum needs exactly one input")
    (name, (c_name, s_name)), = compiled.system.inputs.items()
    (unknowns,) = compiled.outputs.values()
    if len(unknowns) != 1:
        raise UsageError("--of", output, "name a scalar output (a distance or a coordinate), not a point")
    chosen = next(b for b in derived.branches if b.selected)
    return Problem(derived.eliminations[unknowns[0]].polynomial, chosen.values[unknowns[0]],
                   symbol(unknowns[0]), symbol(c_name), symbol(s_name), symbol(f"t_{name}"),
                   tuple(symbol(p) for p in compiled.system.parameters))


def _range_degrees(spec, angle_range):
    lo, hi = angle_range if angle_range is not None else (spec.lo, spec.hi)
    to_degrees = lambda v: sympy.Rational(str(v)) * (1 if spec.unit == "deg" else 180 / sympy.pi)  # noqa: E731
    try:
        lo, hi = to_degrees(lo), to_degrees(hi)
    except (TypeError, ValueError, sympy.SympifyError):
        raise UsageError("--range", angle_range, "expected two finite numbers (lo, hi)") from None
    problem = range_problem(float(lo), float(hi)) if lo.is_finite and hi.is_finite else "must be finite"
    if problem:
        raise UsageError("--range", f"{float(lo):g}:{float(hi):g}", problem)
    return lo, hi


def extremum(scene, output, angle_range=None, params=(), largest=False, method="resultant", backend="flint",
             set=None):  # noqa: A002 - the public API's name, as in derive
    """Critical points, minimum and maximum of ``output`` over the scene's one input.

    ``angle_range`` is in the input's unit (default: its declared range). With ``params``
    symbolic, ``closed_form`` gives the minimum (the maximum with ``largest``) and its
    input in those parameters, with where that holds. ``set`` gives dimensions exact values.
    """
    derived = derive(scene, [output], method, backend, params=params, samples=0, set=set)
    return extremum_of(derived, output, angle_range, largest, backend)


def extremum_of(derived, output, angle_range=None, largest=False, backend="flint"):
    """``extremum`` of an output of an existing derivation (with that output alone)."""
    problem = problem_for(derived, output)
    (name,) = derived.compiled.system.inputs
    lo, hi = _range_degrees(derived.compiled.scene.inputs[name], angle_range)
    defaults = {p: sympy.Rational(str(derived.compiled.parameter_values[p.name])) for p in problem.parameters}
    stationary = stationary_factors(problem, backend)
    points = points_at(problem, stationary, defaults, lo, hi)
    closed = closed_form(problem, stationary, defaults, lo, hi, largest) if problem.parameters else None
    return Extremum(derived.compiled.scene.name, output, name, (float(lo), float(hi)),
                    {p.name: v for p, v in defaults.items()}, points, extreme(points), extreme(points, True),
                    closed, problem, stationary)
