"""Critical points of an output over one input, at fixed dimensions, certified.

On the motion the output ``u`` satisfies its eliminant ``F(u, c, s) = 0``; it is
stationary where ``dF/dtheta = -s*F_c + c*F_s = 0`` (the ``F_u * du/dtheta`` term
vanishes there). With the half-angle ``t = tan(theta/2)`` both become polynomials in
``(u, t)``; their resultant in ``u`` is a polynomial in ``t`` whose real roots, isolated
by python-flint with certified enclosures, hold every stationary input. No calculus on
square roots, no numeric minimiser. A length input is ``t`` itself (``F_t = 0``), its
values shown as lengths where an angle's are in degrees (``input_deg`` holds either).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING, Union

import flint
import mpmath
import sympy

from ...branches.tower import root_free
from ...eliminate import eliminate
from ...errors import ComputationError, UsageError
from ...evaluate import MPMATH, evaluate
from ...system.angles import Parametrisation, off_the_circle
from ...system.convert import univariate
from ...system.roots import Polynomial, real_roots

if TYPE_CHECKING:
    from ...runtime.budget import Deadline
    from .angles import AngleScale

__all__ = ["Problem", "CriticalPoint", "critical_points", "points_in", "points_at", "extreme",
           "stationary_factors", "meeting_factors", "ROOT_BITS"]

ROOT_BITS = 128
DIGITS = 40

Number = Union[int, float, sympy.Rational, mpmath.mpf]  # a range end: exact, or an mpf


@dataclass(frozen=True)
class Problem:
    """An output ``u`` on the motion: its eliminant and the chosen branch's closed form."""

    eliminant: sympy.Expr  # F(u, c, s; parameters), or F(u, t; parameters) for a length input t
    closed: sympy.Expr  # u(c, s; parameters) on the selected branch
    u: sympy.Symbol
    line: Parametrisation  # the input's variables in t = tan(theta / 2), or the length t
    parameters: tuple[sympy.Symbol, ...]  # symbols left symbolic
    scale: AngleScale | None = None  # an angle output: how its degrees follow from u (``angles``)
    valid: tuple[sympy.Expr, ...] = ()  # the chosen branch's discriminants: it assembles where all are >= 0

    def at(self, values: Mapping[sympy.Symbol, sympy.Expr]) -> Problem:
        """The problem with parameters fixed (``values``: symbol -> rational)."""
        return replace(self, eliminant=sympy.expand(self.eliminant.xreplace(values)),
                       closed=self.closed.xreplace(values), parameters=(),
                       valid=tuple(d.xreplace(values) for d in self.valid))

    @property
    def t(self) -> sympy.Symbol:
        return self.line.t

    def half_angle(self) -> list[sympy.Expr]:
        """``F`` and ``dF/dtheta`` as polynomials in ``u``, ``t`` and the parameters, an angle's
        without the factors ``1 + t**2`` (an eliminant whose highest terms hold ``c**2 + s**2`` gives
        them to both, and a shared factor makes their resultant in ``t`` vanish; they have no real root).

        >>> c, s, t, u = sympy.symbols("c s t u")
        >>> Problem((c**2 + s**2) * (u - s), s, u, Parametrisation((c, s), t), ()).half_angle()
        [t**2*u - 2*t + u, t**2 - 1]
        """
        along = self.line.derivative(self.eliminant)
        if along == 0:
            raise UsageError("output", str(self.u), "the output does not depend on the input")
        return [self._off_the_circle(self.numerator_in_t(e)) for e in (self.eliminant, along)]

    def _off_the_circle(self, numerator: sympy.Expr) -> sympy.Expr:
        return off_the_circle(numerator, self.t) if self.line.is_angle else numerator

    def numerator_in_t(self, expr: sympy.Expr) -> sympy.Expr:
        return self.line.numerator(expr)

    def value(self, degrees: mpmath.mpf) -> mpmath.mpf:
        """The closed form at ``degrees`` (a length input's value; mpmath), nan where it is not
        real or the branch does not assemble (a closed form may be real past that: a
        transmission angle's cosine)."""
        at = self.line.numbers_at(degrees)
        result = self.closed_at(at)
        if not isinstance(result, mpmath.mpf) or not self.assembles(at):
            return mpmath.nan
        return result

    def closed_at(self, at: Mapping[str, mpmath.mpf]) -> mpmath.mpf | mpmath.mpc:
        """The closed form at the input's variables ``at`` (mpmath), complex where it is not
        real, nan where it divides by zero."""
        return _evaluated(self.closed, at)

    def assembles(self, at: Mapping[str, mpmath.mpf]) -> bool:
        """Whether the chosen branch assembles at the input's variables ``at``: no discriminant negative."""
        return not any(evaluate(d, at, MPMATH) < 0 for d in self.valid)


def _evaluated(expr: sympy.Expr, values: Mapping[str, object]) -> mpmath.mpf | mpmath.mpc:
    """``expr`` in mpmath, nan where it divides by zero (a direction's via at its cut)."""
    try:
        return evaluate(expr, values, MPMATH)
    except ZeroDivisionError:
        return mpmath.nan


@dataclass(frozen=True)
class CriticalPoint:
    """A stationary point or range end: input in degrees, the output there, its kind."""

    input_deg: mpmath.mpf
    value: mpmath.mpf
    kind: str  # minimum, maximum, inflection, dead centre, endpoint
    # the input in degrees; None at a range end (balls do not hash: left out of eq and hash)
    enclosure: flint.arb | None = field(default=None, compare=False)
    via: mpmath.mpf | None = None  # an angle output: the value of the scalar standing for it (``angles``)

    def to_json(self) -> dict[str, object]:
        point: dict[str, object] = {"input_deg": float(self.input_deg), "value": float(self.value), "kind": self.kind}
        if self.enclosure is not None:
            point["enclosure_deg"] = self.enclosure.str(20)
        if self.via is not None:
            point["via"] = float(self.via)
        return point


def stationary_factors(problem: Problem, backend: str = "flint", *, deadline: Deadline | None = None
                       ) -> list[sympy.Expr]:
    """Factors, in ``t`` and the parameters, of the resultant in ``u`` of ``F`` and ``dF/dtheta``
    (the elimination keeping to ``deadline``, if any)."""
    names = [p.name for p in problem.parameters]
    try:
        return eliminate(problem.half_angle(), [problem.u.name], [problem.t.name] + names,
                         method="resultant", backend=backend, budget=deadline).factors
    except ComputationError as err:
        raise ComputationError(f"no stationary condition for {problem.u}: {err}") from None


def meeting_factors(problem: Problem, *, deadline: Deadline | None = None) -> list[sympy.Expr]:
    """Factors, in ``t`` and the parameters, of ``F``'s discriminant in ``u``: where two values
    of the output meet (dead centres among them); none where ``u`` is polynomial in the input.
    With them, the factors of the branch's own discriminants (``Problem.valid``): where it
    stops assembling even though the output's values do not meet (both modes give a
    transmission angle the same cosine). The elimination keeps to ``deadline``, if any."""
    eliminant = problem.numerator_in_t(problem.eliminant)
    found: list[sympy.Expr] = []
    if sympy.degree(eliminant, problem.u) >= 2:
        names = [p.name for p in problem.parameters]
        try:
            found = eliminate([eliminant, sympy.diff(eliminant, problem.u)], [problem.u.name],
                              [problem.t.name] + names, method="resultant", budget=deadline).factors
        except ComputationError:
            pass  # the discriminant is a constant: the values never meet
    for discriminant in problem.valid:  # one on a dyad built on another's root: its conjugates' zeros too
        for factor, _ in sympy.factor_list(problem.numerator_in_t(root_free(discriminant)))[1]:
            factor = sympy.expand(factor)
            if factor.has(problem.t) and not any(sympy.expand(factor - f) == 0 or sympy.expand(factor + f) == 0
                                                 for f in found):
                found.append(factor)
    return found


def critical_points(problem: Problem, factors: Sequence[sympy.Expr] | None, lo: Number, hi: Number,
                    meeting: Sequence[sympy.Expr] | None = None) -> list[CriticalPoint]:
    """Stationary points of ``problem`` (fixed dimensions) in ``[lo, hi]`` degrees, its dead
    centres, then the two ends.

    ``factors`` are ``stationary_factors`` and ``meeting`` (computed here if not given)
    ``meeting_factors`` with the parameters fixed as in ``problem``; either is recomputed
    if fixing the parameters made one of its factors vanish identically.
    """
    t = problem.t
    polys = [univariate(p, t) for p in _fixed_or_anew(factors, stationary_factors, problem) if p.has(t)]
    meeting = [univariate(f, t) for f in _fixed_or_anew(meeting, meeting_factors, problem) if f.has(t)]
    return points_in(problem, polys, meeting, lo, hi)


def points_in(problem: Problem, stationary: Sequence[Polynomial], meeting: Sequence[Polynomial], lo: Number,
              hi: Number) -> list[CriticalPoint]:
    """``critical_points`` from the ``stationary`` and ``meeting`` factors at fixed dimensions,
    as univariate polynomials in ``t`` (python-flint): no sympy on the way."""
    found: list[CriticalPoint] = []
    with flint.ctx.workprec(ROOT_BITS), mpmath.workdps(DIGITS):
        lo, hi = _mp(lo), _mp(hi)
        balls = [problem.line.shown(r.ball) for p in stationary if p.degree() >= 1 for r in real_roots(p)]
        if problem.line.is_angle:
            balls.append(flint.arb(180))  # t = infinity
        for ball in balls:
            middle = mpmath.mpf(ball.mid().str(DIGITS, radius=False))
            for turn in problem.line.turns:
                degrees = middle + turn
                if not lo <= degrees <= hi or _seen(found, degrees):
                    continue
                here = problem.value(degrees)
                if here != here:  # a discriminant touching zero here reads a rounding below it
                    here = _value_at_meeting(problem, degrees)
                if _is_stationary(problem, degrees, here):
                    found.append(CriticalPoint(degrees, here, _kind(problem, degrees, here), ball + turn))
        found += _dead_centres(problem, meeting, lo, hi, found)
        ends = [CriticalPoint(mpmath.mpf(x), problem.value(mpmath.mpf(x)), "endpoint") for x in (lo, hi)]
    return sorted(found, key=lambda p: p.input_deg) + ends


def _fixed_or_anew(factors: Sequence[sympy.Expr] | None, compute: Callable[[Problem], list[sympy.Expr]],
                   problem: Problem) -> list[sympy.Expr]:
    """``factors`` with the parameters fixed, or ``compute(problem)`` where fixing them made
    one vanish identically (or none were given)."""
    if factors is None or any(f == 0 for f in factors):
        return compute(problem)
    return list(factors)


def _dead_centres(problem: Problem, meeting: Sequence[Polynomial], lo: mpmath.mpf, hi: mpmath.mpf,
                  found: list[CriticalPoint]) -> list[CriticalPoint]:
    """Where the branch stops being real, inside the range: the ends of its real intervals.

    There ``du/dtheta`` is infinite, not zero, so no stationary condition holds, yet the
    branch's extreme over the inputs where it assembles may lie there. They are among the
    real roots in ``t`` of ``F``'s discriminant in ``u`` (two values of ``u`` meet), those
    where the branch is real on one side only; at the others two branches merely share a value.
    """
    points: list[CriticalPoint] = []
    for ball in (problem.line.shown(r.ball) for f in meeting if f.degree() >= 1 for r in real_roots(f)):
        middle = mpmath.mpf(ball.mid().str(DIGITS, radius=False))
        for degrees in (middle + turn for turn in problem.line.turns):
            value = _value_at_meeting(problem, degrees)
            if lo <= degrees <= hi and value == value and _ends_here(problem, degrees) \
                    and not _seen(found + points, degrees):
                points.append(CriticalPoint(degrees, value, "dead centre", ball + (degrees - middle)))
    return points


def _ends_here(problem: Problem, degrees: mpmath.mpf) -> bool:
    """Whether the branch is real just on one side of ``degrees``."""
    step = mpmath.mpf(10) ** -12
    left, right = (problem.value(degrees + d) for d in (-step, step))
    return (left == left) != (right == right)


def _value_at_meeting(problem: Problem, degrees: mpmath.mpf) -> mpmath.mpf:
    """The branch's value where its square root's argument is zero up to rounding (the
    imaginary part then tiny), nan where the branch is not real."""
    result = problem.closed_at(problem.line.numbers_at(degrees))
    if isinstance(result, mpmath.mpc):
        tiny = mpmath.mpf(10) ** (-DIGITS // 3) * (1 + abs(result))
        return result.real if abs(result.imag) <= tiny else mpmath.nan
    return result


def points_at(problem: Problem, stationary: Sequence[sympy.Expr], values: Mapping[sympy.Symbol, sympy.Expr],
              lo: Number, hi: Number, meeting: Sequence[sympy.Expr] | None = None) -> list[CriticalPoint]:
    """``critical_points`` with the dimensions fixed at ``values`` (symbol -> rational); the
    ``stationary`` and ``meeting`` factors, found once with the dimensions symbolic, are
    specialised rather than eliminated again."""
    factors = [sympy.expand(f.xreplace(values)) for f in stationary]
    fixed_meeting = None if meeting is None else [sympy.expand(f.xreplace(values)) for f in meeting]
    with mpmath.workdps(DIGITS):
        return critical_points(problem.at(values), factors, lo, hi, fixed_meeting)


def _mp(number: Number) -> mpmath.mpf:
    """A rational (sympy, int) or mpf as an mpf at the working precision."""
    number = sympy.Rational(number) if not isinstance(number, mpmath.mpf) else number
    return number if isinstance(number, mpmath.mpf) else mpmath.mpf(int(number.p)) / int(number.q)


def _seen(found: Sequence[CriticalPoint], degrees: mpmath.mpf) -> bool:
    return any(abs(p.input_deg - degrees) < mpmath.mpf(10) ** (-DIGITS // 2) for p in found)


def _is_stationary(problem: Problem, degrees: mpmath.mpf, here: mpmath.mpf) -> bool:
    """Whether the output's slope at ``degrees`` (its value there ``here``) is zero to rounding."""
    step = mpmath.mpf(10) ** -12
    slope = (problem.value(degrees + step) - problem.value(degrees - step)) / (2 * step)
    return abs(slope) <= mpmath.mpf(10) ** -9 * (1 + abs(here))


def _kind(problem: Problem, degrees: mpmath.mpf, here: mpmath.mpf) -> str:
    step = mpmath.mpf(10) ** -4
    left, right = (problem.value(degrees + d) for d in (-step, step))
    if left > here and right > here:
        return "minimum"
    if left < here and right < here:
        return "maximum"
    return "inflection"


def extreme(points: Sequence[CriticalPoint], largest: bool = False) -> CriticalPoint:
    """The lowest (or highest) real-valued point of ``points``."""
    real = [p for p in points if p.value == p.value]
    if not real:
        raise ComputationError("the output is not real anywhere on the range")
    return (max if largest else min)(real, key=lambda p: p.value)
