"""One output's extremum for a family of designs: the scene derived once with its dimensions
symbolic, each design's ``Extremum`` instantiated from it in about a millisecond.

``extremum`` prepares, derives and eliminates with sympy on every call: tens of milliseconds a
design, most of them spent on sympy forms of polynomials with a handful of terms. A family
does that once, with the dimensions ``params`` symbolic: the output's eliminant, its closed form
and its branch's discriminants, as python-flint polynomials, the closed form compiled for
mpmath. A design (``ExtremumFamily.at``) then only specialises them: the half-angle numerators
of the eliminant and of its derivative along the input are built in python-flint and
eliminated there (the stationary and meeting factors, the value factors only where an extreme
lies inside the range), the roots are isolated as ``extremum`` isolates them, and the closed
form is evaluated by the compiled program. The answer is the one ``extremum`` gives on the
scene with those values (``with_values``): the same points and kinds, their numbers equal up
to rounding in the last of the 40 digits, the same ``exact`` forms.

>>> family = extremum_family("fourbar", "angle(A, B, D)", ["a", "d", "l", "m"])
>>> design = family.at({"a": 1, "d": 4, "l": 3, "m": "7/2"})
>>> [(float(p.input_deg), p.kind) for p in design.critical_points if p.kind != "endpoint"]
[(0.0, 'minimum'), (180.0, 'maximum'), (360.0, 'minimum')]
>>> {key: str(degrees) for key, (degrees, via) in design.exact.items()}
{'minimum': '180*acos(7/12)/pi', 'maximum': '180*acos(-5/28)/pi'}

Where the generic forms are not the design's, the design is computed as ``extremum`` computes
it (``fell_back`` counts those designs): the eliminant loses its degree in the output or
factors, a discriminant or the closed form's denominator vanishes identically, the output
stops depending on the input, or no point of the range is real (a design that does not
assemble: ``extremum`` then raises as it does). An output that is a direction (its reference
is chosen from the design's motion) and a length input always take that way.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any, Union

import flint
import mpmath
import sympy

from ...derivation.pipeline import derive
from ...derivation.prepared import given, prepare, require_outputs
from ...eliminate import Elimination, eliminate
from ...errors import ComputationError, UsageError, renamed
from ...evaluate.program import MPMATH, CompiledProgram, compile_program
from ...runtime.budget import Budget, Deadline, started
from ...scene.load import SceneLike, as_scene
from ...scene.model import Scene
from ...scene.settings import with_values
from ...system import symbol
from ...system.angles import half_angle_terms
from ...system.convert import flint_context, to_flint, to_sympy
from . import Extremum, exact_pair, extremum, in_degrees, input_span, problem_for
from .closed import describe, end_degrees, value_at_angle
from .critical import DIGITS, CriticalPoint, Problem, along_input, extreme, points_in

__all__ = ["extremum_family", "ExtremumFamily"]

Value = Union[Fraction, int, str, sympy.Rational]  # a dimension's exact value


def extremum_family(scene: SceneLike, output: str, params: Sequence[str], *,
                    angle_range: tuple[float | str, float | str] | None = None, backend: str = "flint",
                    budget: Budget | Deadline | None = None) -> ExtremumFamily:
    """The extremum of ``output`` over the scene's one input, for every value of the dimensions
    ``params``: derived once with them symbolic (``budget`` bounds that), each design given by
    ``ExtremumFamily.at``. ``angle_range`` and ``backend`` are ``extremum``'s."""
    deadline = started(budget)
    loaded = as_scene(scene)
    given(loaded, params=params)
    with renamed("outputs", to="output"):
        prepared = prepare(loaded, outputs=[output], params=params, deadline=deadline)
    require_outputs(prepared, "output", [output])
    derived = derive(prepared, backend=backend, samples=0, certify=False, budget=deadline)
    inputs = derived.compiled.system.inputs
    if len(inputs) != 1:
        raise UsageError("scene", loaded.name, "an extremum needs exactly one input")
    (name,) = inputs
    lo, hi = input_span(derived.compiled.scene.inputs[name], angle_range)
    problem = problem_for(derived, output, (lo, hi), witnesses=prepared.witnesses, deadline=deadline)
    defaults = {p.name: sympy.Rational(str(derived.compiled.parameter_values[p.name])) for p in problem.parameters}
    return ExtremumFamily(loaded, output, name, (lo, hi), problem, defaults, angle_range, backend, budget)


class ExtremumFamily:
    """A scene's output derived once with some dimensions symbolic: ``at`` gives a design's ``Extremum``."""

    def __init__(self, scene: Scene, output: str, input_name: str, span: tuple[sympy.Expr, sympy.Expr],
                 problem: Problem, defaults: Mapping[str, sympy.Rational],
                 angle_range: tuple[float | str, float | str] | None, backend: str,
                 budget: Budget | Deadline | None) -> None:
        self.scene, self.output, self.input, self.span, self.problem = scene, output, input_name, span, problem
        self.defaults = dict(defaults)
        self._settings: dict[str, Any] = {"angle_range": angle_range, "backend": backend, "budget": budget}
        self.fell_back = 0  # designs computed by ``extremum`` itself
        line = problem.line
        direction = problem.scale is not None and problem.scale.quarter_turns is not None
        # the direction's reference depends on the design's motion; a length input takes no half angle
        self.generic = line.is_angle and not direction and not problem.stretches  # a named mode: ``extremum``'s
        if not self.generic:
            return
        self._names = [v.name for v in line.variables] + [problem.u.name] + list(self.defaults)
        self._ring = flint_context(self._names)
        self._eliminant = to_flint(problem.eliminant, self._ring)
        self._valid = [to_flint(d, self._ring) for d in problem.valid]
        self._denominator = _polynomial_or_none(sympy.denom(sympy.together(problem.closed)), self._ring)
        self._closed: CompiledProgram[mpmath.mpf] = compile_program(
            [problem.closed], [v.name for v in line.variables] + list(self.defaults), MPMATH)
        self._ratio = _ratio(problem.closed, self._ring)
        self._u_degree = self._eliminant.degrees()[2]

    def at(self, values: Mapping[str, Value]) -> Extremum:
        """The ``Extremum`` of the design with the dimensions ``values`` (name -> exact number;
        those not given keep the scene's values): ``extremum(with_values(scene, values), output)``'s,
        from the family's forms where they are the design's, else from ``extremum`` itself."""
        exact = self._exact_values(values)
        found = self._instantiated(exact) if self.generic else None
        if found is None:
            self.fell_back += 1
            return self._computed(values)
        return found

    def _computed(self, values: Mapping[str, Value]) -> Extremum:
        """The design as ``extremum`` computes it, from the scene with ``values``."""
        scene = with_values(self.scene, dict(values))
        return extremum(scene, self.output, self._settings["angle_range"], backend=self._settings["backend"],
                        budget=self._settings["budget"])

    def _exact_values(self, values: Mapping[str, Value]) -> dict[str, flint.fmpq]:
        exact = {name: flint.fmpq(int(v.p), int(v.q)) for name, v in self.defaults.items()}
        for name, value in values.items():
            if name not in self.defaults:
                raise UsageError("values", name, "not a symbolic dimension of the family (those: "
                                 f"{', '.join(self.defaults) or 'none'})")
            exact[name] = _fmpq(name, value)
        return exact

    def _instantiated(self, values: Mapping[str, flint.fmpq]) -> Extremum | None:
        """The design's ``Extremum`` from the family's forms, None where they are not its own."""
        design = self._design(values)
        if design is None:
            return None
        points = points_in(design.problem, design.stationary_polys, design.meeting_polys, *self.span,
                           design.pole_polys)
        if not any(p.value == p.value for p in points):
            return None  # it assembles nowhere on the range: ``extremum`` says how it fails
        scale = self.problem.scale
        exact = None
        if scale is not None:
            flip = scale.decreasing
            exact = {key: design.exact(extreme(points, largest=(key == "maximum") != flip))
                     for key in ("minimum", "maximum")}
            points = [in_degrees(p, scale) for p in points]
        lo, hi = self.span
        return Extremum(self.scene.name, self.output, self.input, (float(lo), float(hi)), {}, points,
                        extreme(points), extreme(points, True), None, design.problem, design.stationary, exact)

    def _design(self, values: Mapping[str, flint.fmpq]) -> _Design | None:
        """The design's problem and factors, None where specialising is not valid."""
        specialised: dict[str | int, int | flint.fmpz | flint.fmpq] = {name: values[name] for name in self.defaults}
        eliminant = self._eliminant.subs(specialised)
        valid = [d.subs(specialised) for d in self._valid]
        if eliminant.degrees()[2] != self._u_degree or any(d.is_zero() for d in valid) or \
                (self._denominator is not None and self._denominator.subs(specialised).is_zero()) or \
                [e for _, e in eliminant.factor()[1]] != [1]:
            return None
        problem = self.problem
        names = (problem.u.name, problem.t.name)
        numerator = _moving(_half_angle(eliminant, names))
        if numerator is None:
            return None  # ``extremum`` says what the output keeps to
        with mpmath.workdps(DIGITS):
            numbers = tuple(mpmath.mpf(int(values[n].p)) / int(values[n].q) for n in self.defaults)
        fixed = _DesignProblem(to_sympy(eliminant, self._ring), problem.closed.xreplace(
            {p: sympy.Rational(int(values[p.name].p), int(values[p.name].q)) for p in problem.parameters}),
            problem.u, problem.line, (), problem.scale,
            tuple(to_sympy(d, self._ring) for d in valid), program=self._closed, numbers=numbers, exact_valid=valid,
            terms=self._terms(specialised))
        derivative = along_input(numerator, names[1], angle=True)
        try:
            stationary = eliminate([numerator, derivative], [names[0]], [names[1]], method="resultant",
                                   backend=self._settings["backend"])
        except ComputationError:
            return None  # ``extremum`` says why
        return _Design(fixed, stationary, numerator, derivative, valid, names)

    def _terms(self, values: Mapping[str | int, int | flint.fmpz | flint.fmpq]
               ) -> tuple[tuple[int, int, mpmath.mpf], ...] | None:
        """The closed form's terms in the input's variables at the design, where it is a polynomial in them."""
        if self._ratio is None:
            return None
        numerator, denominator = (p.subs(values) for p in self._ratio)
        scale = 1 / flint.fmpq(denominator.leading_coefficient())
        with mpmath.workdps(DIGITS):
            return tuple((int(m[0]), int(m[1]), mpmath.mpf(int((c * scale).p)) / int((c * scale).q))
                         for m, c in numerator.to_dict().items())


def _ratio(closed: sympy.Expr, ring: flint.fmpq_mpoly_ctx) -> tuple[flint.fmpq_mpoly, flint.fmpq_mpoly] | None:
    """A closed form polynomial in the input's variables over the dimensions' fractions, as its
    numerator and its denominator (in the dimensions alone); None otherwise (a square root)."""
    numerator, denominator = sympy.fraction(sympy.together(closed))
    pair = _polynomial_or_none(numerator, ring), _polynomial_or_none(denominator, ring)
    if pair[0] is None or pair[1] is None or any(d for d in pair[1].degrees()[:3]):
        return None
    return pair[0], pair[1]


@dataclass(frozen=True)
class _DesignProblem(Problem):
    """A design's ``Problem``: its closed form evaluated by the family's compiled program, its
    discriminants' signs exactly (python-flint, at the rational the input's numbers are)."""

    program: CompiledProgram[mpmath.mpf] | None = field(default=None, compare=False)
    numbers: tuple[mpmath.mpf, ...] = ()  # the dimensions, in the program's order
    exact_valid: Sequence[flint.fmpq_mpoly] = field(default=(), compare=False)
    # a closed form polynomial in the input's variables: its terms (c, s exponents -> coefficient)
    terms: tuple[tuple[int, int, mpmath.mpf], ...] | None = None

    def closed_at(self, at: Mapping[str, mpmath.mpf]) -> mpmath.mpf | mpmath.mpc:
        assert self.program is not None, "a design's problem is compiled"
        c, s = (at[v.name] for v in self.line.variables)
        if self.terms is not None:
            return mpmath.fsum(coefficient * c**i * s**j for i, j, coefficient in self.terms)
        try:
            (result,) = self.program(c, s, *self.numbers)
        except ZeroDivisionError:
            return mpmath.nan
        return result

    def assembles(self, at: Mapping[str, mpmath.mpf]) -> bool:
        c, s = (_rational(at[v.name]) for v in self.line.variables)
        rest = [flint.fmpq(0)] * (len(self.numbers) + 1)
        return not any(d(c, s, *rest) < 0 for d in self.exact_valid)


class _Design:
    """One design's problem and factors, in python-flint and (as ``extremum`` gives them) sympy."""

    def __init__(self, problem: _DesignProblem, stationary: Elimination[Any], numerator: flint.fmpq_mpoly,
                 derivative: flint.fmpq_mpoly, valid: Sequence[flint.fmpq_mpoly], names: tuple[str, str]) -> None:
        self.problem, self._numerator, self._derivative, self._names = problem, numerator, derivative, names
        self.stationary: tuple[sympy.Expr, ...] = tuple(stationary.factors)
        self.stationary_polys = [_univariate(f, names[1]) for f in stationary.exact[1]]
        self._meeting = _meeting(numerator, valid, names)
        self.meeting_polys = [p for p, _ in self._meeting]
        self.pole_polys = [_leading_in_u(numerator, names)]  # ``pole_factors``, unfactored: the same roots

    def exact(self, best: CriticalPoint) -> tuple[sympy.Expr | None, sympy.Expr | None]:
        """``(degrees, via)`` of the angle's extreme ``best`` (its via's point), as ``extremum``'s ``exact``."""
        problem = self.problem
        assert problem.scale is not None, "an angle output's"
        degrees = end_degrees(problem, best)
        with mpmath.workdps(DIGITS):
            at_zero = value_at_angle(problem, sympy.Integer(0), {}) if degrees is None and _exactly_zero(best) \
                else None
            if degrees is not None:
                value = value_at_angle(problem, degrees, {})
            elif at_zero is not None and at_zero.is_Rational:
                # a stationary input at exactly 0 degrees with a rational value: that rational is the
                # root of the linear value factor ``describe`` would find it by
                value = at_zero
            else:
                meeting = [m for _, m in self._meeting]
                value = describe(problem, self.stationary, self._value_factors(), {}, best, meeting).value
            return exact_pair(problem.scale, value, best)


    def _value_factors(self) -> list[sympy.Expr]:
        """``value_factors`` at the design, eliminated in python-flint."""
        u, t = self._names
        factors = eliminate([self._numerator, self._derivative], [t], [u], method="resultant").factors
        return [f for f in factors if f.has(self.problem.u)]


def _exactly_zero(point: CriticalPoint) -> bool:
    """Whether ``point``'s input is exactly a whole turn (its enclosure a point, from the root ``t = 0``)."""
    if point.enclosure is None:
        return False
    ball = flint.arb(point.enclosure)
    whole = ball.unique_fmpz() if ball.rad() == 0 else None
    return whole is not None and int(whole) % 360 == 0


def _meeting(numerator: flint.fmpq_mpoly, valid: Sequence[flint.fmpq_mpoly], names: tuple[str, str]
             ) -> list[tuple[flint.fmpq_poly, sympy.Expr]]:
    """``meeting_factors`` at the design, each as a polynomial in ``t`` and as sympy: the
    discriminant's factors in the output, then the new factors of the branch's discriminants."""
    u, t = names
    found: list[tuple[flint.fmpq_poly, sympy.Expr]] = []
    if numerator.degrees()[0] >= 2:
        try:
            met = eliminate([numerator, numerator.derivative(u)], [u], [t], method="resultant")
            found = [(_univariate(f, t), e) for f, e in zip(met.exact[1], met.factors)]
        except ComputationError:
            pass  # the discriminant is a constant: the values never meet
    variable = symbol(t)
    for discriminant in valid:
        for factor, _ in _half_angle_cs(discriminant).factor()[1]:
            poly = flint.fmpq_poly(factor)
            if poly.degree() >= 1 and not any(poly == p or poly == -p for p, _ in found):
                found.append((poly, sympy.Add(*[sympy.Integer(int(c)) * variable**k
                                                for k, c in enumerate(factor.coeffs()) if c != 0])))
    return found


def _leading_in_u(numerator: flint.fmpq_mpoly, names: tuple[str, str]) -> flint.fmpq_poly:
    """The coefficient in ``t`` of the highest power of ``u`` in ``numerator`` (in ``u, t``)."""
    top = numerator.degrees()[0]
    return _univariate(numerator.context().from_dict({m: c for m, c in numerator.to_dict().items() if m[0] == top}),
                       names[1])


def _moving(numerator: flint.fmpq_mpoly) -> flint.fmpq_mpoly | None:
    """``Problem.half_angle``'s ``F`` from the eliminant's numerator in ``u, t``: its distinct factors
    in both; None where a factor holds ``u`` alone (the output may keep one value) or none moves."""
    moving = numerator.context().from_dict({(0, 0): 1})
    for factor, _ in numerator.factor()[1]:
        in_u, in_t = factor.degrees()
        if in_u and not in_t:
            return None
        if in_u:
            moving *= factor
    return moving if moving.degrees()[0] else None


def _half_angle(poly: flint.fmpq_mpoly, names: tuple[str, str]) -> flint.fmpq_mpoly:
    """``poly`` in ``c, s, u`` (and dimensions already set) as its half-angle numerator in ``u, t``."""
    ring = flint_context(names)
    terms: dict[tuple[int, ...], int | flint.fmpz | flint.fmpq] = {}
    for rest, in_t in half_angle_terms(poly).items():
        for k, coefficient in enumerate(in_t.coeffs()):
            if coefficient != 0:
                terms[(rest[0], k)] = coefficient
    return ring.from_dict(terms)


def _half_angle_cs(poly: flint.fmpq_mpoly) -> flint.fmpz_poly:
    """``poly`` in ``c, s`` alone as its half-angle numerator, denominators cleared."""
    in_t = sum(half_angle_terms(poly).values(), flint.fmpq_poly([]))
    return flint.fmpz_poly([int(c * in_t.denom()) for c in in_t.coeffs()]) if in_t.degree() >= 0 else flint.fmpz_poly([])


def _univariate(poly: flint.fmpq_mpoly, name: str) -> flint.fmpq_poly:
    """An ``fmpq_mpoly`` in ``name`` alone as an ``fmpq_poly``."""
    index = [str(n) for n in poly.context().names()].index(name)
    coefficients: dict[int, flint.fmpq] = {m[index]: c for m, c in poly.to_dict().items()}
    return flint.fmpq_poly([coefficients.get(k, 0) for k in range(max(coefficients, default=-1) + 1)])


def _polynomial_or_none(expr: sympy.Expr, ring: flint.fmpq_mpoly_ctx) -> flint.fmpq_mpoly | None:
    """``expr`` in ``ring``, or None where it is not a polynomial there (a square root)."""
    try:
        return to_flint(expr, ring)
    except (TypeError, KeyError):
        return None


def _rational(number: mpmath.mpf) -> flint.fmpq:
    """An mpf as the rational it is exactly."""
    sign, mantissa, exponent, _ = number._mpf_
    mantissa = -int(mantissa) if sign else int(mantissa)
    return flint.fmpq(mantissa << exponent) if exponent >= 0 else flint.fmpq(mantissa, 1 << -exponent)


def _fmpq(name: str, value: Value) -> flint.fmpq:
    """A dimension's value as an exact rational: an integer, a fraction or its text (``"7/2"``, ``"0.1"``)."""
    try:
        if isinstance(value, bool):
            raise TypeError
        number = sympy.Rational(str(value)) if isinstance(value, str) else sympy.Rational(value)
    except (TypeError, ValueError, sympy.SympifyError):
        raise UsageError("values", f"{name}={value}", "expected an exact number (an integer, a fraction, '7/2')") from None
    return flint.fmpq(int(number.p), int(number.q))

