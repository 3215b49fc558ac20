"""Critical points of an output over one input, at fixed dimensions, certified.

On the motion the output ``u`` satisfies its eliminant ``F(u, c, s) = 0``; it is
stationary where ``dF/dtheta = -s*F_c + c*F_s = 0`` (the ``F_u * du/dtheta`` term
vanishes there). With the half-angle ``t = tan(theta/2)`` both become polynomials in
``(u, t)``; their resultant in ``u`` is a polynomial in ``t`` whose real roots, isolated
by python-flint with certified enclosures, hold every stationary input. No calculus on
square roots, no numeric minimiser. A length input is ``t`` itself (``F_t = 0``), its
values shown as lengths where an angle's are in degrees (``input_deg`` holds either).

A value of ``u`` can run off to infinity only where the eliminant's leading coefficient in
``u`` vanishes (two lines of a meet turning parallel); there the branch's closed form is read
from each side: a pole makes the output unbounded (+-inf), a 0/0 has its limit.
"""

from __future__ import annotations

import functools
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
from ...system.angles import Parametrisation
from ...system.convert import flint_context, from_terms, integer_factors, to_flint, to_flint_integer, univariate
from ...system.roots import Polynomial, real_roots

if TYPE_CHECKING:
    from ...branches import Branch
    from ...derivation.modes import Piece
    from ...derivation.results import Derivation
    from ...runtime.budget import Deadline
    from .angles import AngleScale

__all__ = ["Problem", "Stretch", "CriticalPoint", "critical_points", "points_in", "points_at", "extreme",
           "stationary_factors", "meeting_factors", "pole_factors", "one_sided_limit", "constant_value",
           "resultant_factors", "along_input", "stretches_of", "ROOT_BITS", "SEAM"]

ROOT_BITS = 128
DIGITS = 40
# a closed form with integers of more digits than this is worked out with that many more (``Problem.guard_digits``):
# it loses up to as many to cancellation, and the slope's test (1e-9 from steps of 1e-12) needs 21 of the 40 kept
GUARD = DIGITS // 4

Number = Union[int, float, sympy.Rational, mpmath.mpf]  # a range end: exact, or an mpf


SEAM = 1e-9  # degrees: how far a stretch reaches past its (float) end into a neighbour that does not assemble

# Where the output's closed form may have a pole it is read at these distances from it (in the
# input's unit; the pole is known to ROOT_BITS, far closer), at twice the digits: a value running
# off grows by at least ``RUN_OFF`` from one to the next (by 1e8 like 1/x, by 1e4 like
# 1/sqrt(x)), a bounded one tends to its limit.
PROBES = (8, 16, 24)  # powers of ten
RUN_OFF = 100
SAME_INPUT = mpmath.mpf(10) ** (-DIGITS // 2)  # two inputs closer than this are one (a suspect's, a range end's)


@dataclass(frozen=True)
class Stretch:
    """Where a named mode (``derive``'s ``modes``) is another branch than the chosen one: on
    ``[lo, hi]`` (the input as users read it) the output's closed form is ``closed``, assembled
    where every one of ``valid`` is >= 0; ``closed`` None where the mode is absent."""

    lo: float
    hi: float
    closed: sympy.Expr | None
    valid: tuple[sympy.Expr, ...] = ()


def stretches_of(derived: Derivation, chosen: Branch, closed_of: Callable[[Branch], sympy.Expr], output: str
                 ) -> tuple[Stretch, ...]:
    """Where a named mode (``derived.modes``) is another branch than ``chosen`` (its label changed
    where it crossed the other mode: Hart's C), the output's closed form there, ``closed_of`` that
    branch; where the mode is absent, none. The modes are followed at the dimensions' values:
    refused with any symbolic."""
    found: list[Stretch] = []
    for followed in derived.modes:
        pieces = followed.pieces
        for k, piece in enumerate(pieces):
            branch = followed.branch_of(piece, derived.branches) if piece.status == "mode" else None
            if piece.status == "absent" or (branch is not None and branch is not chosen):
                # its ends are floats: widened where the other side does not assemble (a dead centre)
                lo, hi = (piece.lo - _seam(pieces, k - 1), piece.hi + _seam(pieces, k + 1))
                found.append(Stretch(lo, hi, None) if branch is None else
                             Stretch(lo, hi, closed_of(branch), tuple(branch.discriminants.values())))
    if found and derived.compiled.system.parameters:
        raise UsageError("params", ", ".join(derived.compiled.system.parameters),
                         f"{output} follows a named mode that changes branch along the motion, followed at fixed "
                         "dimensions only: give them values (--set) rather than leave them symbolic")
    return tuple(found)


def _seam(pieces: Sequence[Piece], k: int) -> float:
    """How far a stretch reaches into its neighbour ``pieces[k]``: ``SEAM`` where that does not
    assemble (or there is none), so that a dead centre rounded out of the stretch stays in it."""
    return SEAM if not 0 <= k < len(pieces) or pieces[k].status == "no-assembly" else 0.0


@dataclass(frozen=True)
class Problem:
    """An output ``u`` on the motion: its eliminant and the chosen branch's closed form (a
    named mode's, on its ``stretches``, at fixed dimensions)."""

    eliminant: sympy.Expr  # F(u, c, s; parameters), or F(u, t; parameters) for a length input t
    closed: sympy.Expr  # u(c, s; parameters) on the selected branch
    u: sympy.Symbol
    line: Parametrisation  # the input's variables in t = tan(theta / 2), or the length t
    parameters: tuple[sympy.Symbol, ...]  # symbols left symbolic
    scale: AngleScale | None = None  # an angle output: how its degrees follow from u (``angles``)
    valid: tuple[sympy.Expr, ...] = ()  # the chosen branch's discriminants: it assembles where all are >= 0
    stretches: tuple[Stretch, ...] = ()  # none with parameters symbolic

    def at(self, values: Mapping[sympy.Symbol, sympy.Expr]) -> Problem:
        """The problem with parameters fixed (``values``: symbol -> rational)."""
        if not values and not self.parameters:
            return self  # nothing to fix: the eliminant is not expanded again (a second, on thousands of terms)
        return replace(self, eliminant=sympy.expand(self.eliminant.xreplace(values)),
                       closed=self.closed.xreplace(values), parameters=(),
                       valid=tuple(d.xreplace(values) for d in self.valid))

    @property
    def t(self) -> sympy.Symbol:
        return self.line.t

    def half_angle(self) -> list[sympy.Expr]:
        """``F`` and ``dF/dtheta`` as polynomials in ``u``, ``t`` and the parameters: ``F`` the
        product of the eliminant's ``moving`` components in ``t``, each once. What else its
        numerator holds would share a factor with the derivative and make their resultant in ``u``
        vanish: a repeated factor (two factors in ``c, s`` equal on the circle), a factor free of
        ``t`` (a component on which the output keeps one value). Factors free of ``u`` (``1 + t**2``
        among them) would only add roots where no value is stationary.

        >>> c, s, t, u = sympy.symbols("c s t u")
        >>> Problem((c**2 + s**2) * (u - s)**2, s, u, Parametrisation((c, s), t), ()).half_angle()
        [t**2*u - 2*t + u, 2*t**2 - 2]
        """
        moving, _ = self.components()
        if not moving:
            raise UsageError("output", str(self.u), "the output does not depend on the input")
        symbols = sorted(set().union(*(f.free_symbols for f in moving)) | {self.t}, key=lambda v: v.name)
        ctx = flint_context([v.name for v in symbols])
        product = to_flint(sympy.Mul(*moving), ctx)
        return [from_terms(p.to_dict(), symbols) for p in (product, along_input(product, self.t.name,
                                                                               angle=self.line.is_angle))]

    def components(self) -> tuple[list[sympy.Expr], list[sympy.Expr]]:
        """The distinct irreducible factors of the eliminant's numerator in ``t`` that hold ``u``:
        those that hold ``t`` too (the output moves on them), then those free of it (it keeps one
        value on them).

        >>> c, s, t, u = sympy.symbols("c s t u")
        >>> Problem((2*u + 3)**2 * (u - c) * s, u, u, Parametrisation((c, s), t), ()).components()
        ([t**2*u + t**2 + u - 1], [2*u + 3])
        """
        factors = _factors(self.numerator_in_t(self.eliminant))
        moving = [f for f in factors if f.has(self.u) and f.has(self.t)]
        return moving, [f for f in factors if f.has(self.u) and not f.has(self.t)]

    def numerator_in_t(self, expr: sympy.Expr) -> sympy.Expr:
        return self.line.numerator(expr)

    def on(self, degrees: mpmath.mpf) -> Problem | None:
        """The problem whose closed form is the output's at ``degrees`` (a named mode's stretch
        there, turns apart), None where the mode is absent."""
        for stretch in self.stretches:
            if any(stretch.lo <= degrees + turn <= stretch.hi for turn in self.line.turns):
                return None if stretch.closed is None else \
                    replace(self, closed=stretch.closed, valid=stretch.valid, stretches=())
        return self

    def valid_anywhere(self) -> tuple[sympy.Expr, ...]:
        """The discriminants of every branch the output takes: the chosen one's and its stretches'."""
        found = list(self.valid)
        found += [d for s in self.stretches for d in s.valid if d not in found]
        return tuple(found)

    def value(self, degrees: mpmath.mpf) -> mpmath.mpf:
        """The closed form at ``degrees`` (a length input's value; mpmath), nan where it is not
        real or the branch does not assemble (a closed form may be real past that: a
        transmission angle's cosine)."""
        here = self.on(degrees)
        if here is not self:
            return mpmath.nan if here is None else here.value(degrees)
        at = self.line.numbers_at(degrees)
        result = self.closed_at(at)
        if not isinstance(result, mpmath.mpf) or not self.assembles(at):
            return mpmath.nan
        return result

    def closed_at(self, at: Mapping[str, mpmath.mpf]) -> mpmath.mpf | mpmath.mpc:
        """The closed form at the input's variables ``at`` (mpmath), complex where it is not
        real, nan where it divides by zero; worked out with ``guard_digits`` more than the
        working precision, and rounded to it."""
        if not self.guard_digits:
            return _evaluated(self.closed, at)
        with mpmath.workdps(mpmath.mp.dps + self.guard_digits):
            result = _evaluated(self.closed, at)
        return +result

    @functools.cached_property
    def guard_digits(self) -> int:
        """The digits the closed form may lose to cancellation, where that is more than ``GUARD``:
        its largest integer's (a numerator's, a denominator's). A family's closed form is a
        polynomial in ``c, s`` of degree 63 with 85-digit coefficients (the Stephenson III's
        ``dist(P, O)`` with ``u`` symbolic): at 40 digits its value had 11 right, no stationary
        point passed ``_is_stationary`` and the minimum was read at a range end. Below ``GUARD``
        the working precision keeps enough (and a 0/0's probes are read at it)."""
        integers = [abs(n) for r in self.closed.atoms(sympy.Rational) for n in (r.p, r.q)]
        digits = max((len(str(n)) for n in integers), default=0)
        return digits if digits > GUARD else 0

    def assembles(self, at: Mapping[str, mpmath.mpf]) -> bool:
        """Whether the chosen branch assembles at the input's variables ``at``: no discriminant negative."""
        return not any(evaluate(d, at, MPMATH) < 0 for d in self.valid)


def _evaluated(expr: sympy.Expr, values: Mapping[str, object]) -> mpmath.mpf | mpmath.mpc:
    """``expr`` in mpmath, nan where it divides by zero (a direction's via at its cut)."""
    try:
        return evaluate(expr, values, MPMATH)
    except ZeroDivisionError:
        return mpmath.nan


def _factors(poly: sympy.Expr) -> list[sympy.Expr]:
    """The distinct irreducible factors of a polynomial with rational coefficients, primitive
    over the integers (python-flint: sympy's factoring takes seconds on a few hundred terms)."""
    symbols = sorted(poly.free_symbols, key=lambda v: v.name)
    if not symbols:
        return []
    ctx = flint_context([v.name for v in symbols])
    integer = to_flint_integer(to_flint(poly, ctx), flint.fmpz_mpoly_ctx.get(ctx.names(), "lex"))
    return [from_terms(f.to_dict(), symbols) for f, _ in integer_factors(integer)]


def along_input(poly: flint.fmpq_mpoly, t: str, *, angle: bool) -> flint.fmpq_mpoly:
    """The derivative along the input of ``poly``, a polynomial in ``t``: a length's ``d/dt``; an
    angle's ``d/dtheta`` of the polynomial in ``c, s`` of degree ``m`` whose numerator ``poly`` is
    (``2 m`` its degree or one more), ``(1 + t**2) dF/dt - 2 m t F`` (twice its numerator), without
    the factors ``1 + t**2`` (none is a real root)."""
    derivative = poly.derivative(t)
    if not angle:
        return derivative
    index = list(poly.context().names()).index(t)
    tee = poly.context().gens()[index]
    circle = 1 + tee**2
    along = circle * derivative - 2 * ((poly.degrees()[index] + 1) // 2) * tee * poly
    while not along.is_zero():
        quotient, remainder = divmod(along, circle)
        if not remainder.is_zero():
            break
        along = quotient
    return along


@dataclass(frozen=True)
class CriticalPoint:
    """A stationary point or range end: input in degrees, the output there, its kind."""

    input_deg: mpmath.mpf
    value: mpmath.mpf
    kind: str  # minimum, maximum, inflection, dead centre, pole (value +-inf), endpoint
    # the input in degrees; None at a range end (balls do not hash: left out of eq and hash)
    enclosure: flint.arb | None = field(default=None, compare=False)
    via: mpmath.mpf | None = None  # an angle output: the value of the scalar standing for it (``angles``)
    side: int = 0  # a pole's: -1 where the output runs off as the input rises to it, +1 as it falls to it

    @property
    def unbounded(self) -> bool:
        """Whether the output runs off to infinity here (its value is +inf or -inf)."""
        return bool(mpmath.isinf(self.value))

    def to_json(self) -> dict[str, object]:
        point: dict[str, object] = {"input_deg": float(self.input_deg), "value": float(self.value), "kind": self.kind}
        if self.enclosure is not None:
            point["enclosure_deg"] = self.enclosure.str(20)
        if self.via is not None:
            point["via"] = float(self.via)
        if self.unbounded:  # strict JSON has no infinity: the value is null there, and this says which
            point["limit"] = "+inf" if self.value > 0 else "-inf"
        if self.side:
            point["side"] = "below" if self.side < 0 else "above"
        return point


def stationary_factors(problem: Problem, backend: str = "flint", *, deadline: Deadline | None = None
                       ) -> list[sympy.Expr]:
    """Factors, in ``t`` and the parameters, of the resultant in ``u`` of ``F`` and ``dF/dtheta``
    (``Problem.half_angle``; the elimination keeping to ``deadline``, if any)."""
    try:
        return resultant_factors(problem.half_angle(), problem.u, [problem.t, *problem.parameters],
                                  backend=backend, deadline=deadline)
    except ComputationError as err:
        raise ComputationError(f"no stationary condition for {problem.u}: {err}") from None


def resultant_factors(pair: list[sympy.Expr], variable: sympy.Symbol, keep: Sequence[sympy.Symbol], *,
                       backend: str, deadline: Deadline | None) -> list[sympy.Expr]:
    """Factors of the resultant in ``variable`` of ``F`` and its derivative ``pair``: none where
    the derivative is a number (the output strictly monotone; a resultant with a number is one)."""
    if not pair[1].free_symbols:
        return []
    halved = in_square(pair, variable)
    # both even in it (a distance's eliminant is one in its square): Res(G(v**2), K(v**2)) is a constant times
    # Res(G, K)**2, the same factors from a resultant of half the degree (on the Stephenson III family's
    # distance, 0.1 s instead of 17 s)
    return eliminate(halved or pair, [variable.name], [v.name for v in keep], method="resultant", backend=backend,
                     budget=deadline).factors


def in_square(polys: Sequence[sympy.Expr], variable: sympy.Symbol) -> list[sympy.Expr] | None:
    """``polys`` with ``variable**2`` written ``variable`` where each holds it in even powers only; None
    where one holds an odd power (or none holds it).

    >>> u, t = sympy.symbols("u t")
    >>> in_square([u**4 - t*u**2 + 1, 3*u**2 - t], u), in_square([u**2 - t, u], u)
    ([-t*u + u**2 + 1, -t + 3*u], None)
    """
    symbols = sorted(set().union(*(p.free_symbols for p in polys)) | {variable}, key=lambda v: v.name)
    ctx = flint_context([v.name for v in symbols])
    index = symbols.index(variable)
    terms = [to_flint(p, ctx).to_dict() for p in polys]
    powers = {m[index] for t in terms for m in t}
    if max(powers, default=0) == 0 or any(e % 2 for e in powers):
        return None
    halve = lambda m: m[:index] + (m[index] // 2,) + m[index + 1:]  # noqa: E731
    return [from_terms({halve(m): c for m, c in t.items()}, symbols) for t in terms]


def constant_value(problem: Problem, values: Mapping[sympy.Symbol, sympy.Expr], lo: Number, hi: Number
                   ) -> sympy.Expr | None:
    """The output's one value where the chosen branch lies on a component of the eliminant free
    of the input (``Problem.components``): in the parameters where that component is linear in
    ``u``, a number at ``values`` otherwise; None where the output moves. The branch is read at
    ``values`` at inputs across ``[lo, hi]`` degrees; on no component at two of them, it moves."""
    _, still = problem.components()
    if not still:
        return None
    fixed = problem.at(values)
    with mpmath.workdps(DIGITS):
        lo, hi = _mp(lo), _mp(hi)
        samples = [fixed.value(lo + (hi - lo) * (k + mpmath.mpf(0.382)) / 8) for k in range(8)]
        real = [v for v in samples if v == v]
        for factor in still:
            coefficients = [_mp(c) for c in reversed(sympy.Poly(factor.xreplace(values), problem.u).all_coeffs())]
            if len(real) >= 2 and all(_root_of(coefficients, v) for v in real):
                linear = sympy.Poly(factor, problem.u)
                if linear.degree() == 1:
                    return sympy.factor(-linear.coeff_monomial(1) / linear.coeff_monomial(problem.u))
                return sympy.Float(mpmath.nstr(real[0], 15), 15)
    return None


def _root_of(coefficients: Sequence[mpmath.mpf], value: mpmath.mpf) -> bool:
    """Whether ``value`` is a root of the polynomial of ``coefficients`` (lowest first), to rounding."""
    scale = sum(abs(c) * abs(value) ** k for k, c in enumerate(coefficients))
    residual = abs(mpmath.fsum(c * value**k for k, c in enumerate(coefficients)))
    return residual <= mpmath.mpf(10) ** (-DIGITS // 2) * scale


def meeting_factors(problem: Problem, *, deadline: Deadline | None = None) -> list[sympy.Expr]:
    """Factors, in ``t`` and the parameters, of ``F``'s discriminant in ``u``: where two values
    of the output meet (dead centres among them); none where ``u`` is polynomial in the input.
    With them, the factors of the branch's own discriminants (``Problem.valid``): where it
    stops assembling even though the output's values do not meet (both modes give a
    transmission angle the same cosine). The elimination keeps to ``deadline``, if any."""
    moving, _ = problem.half_angle()  # a repeated factor would make the discriminant vanish
    found: list[sympy.Expr] = []
    if sympy.degree(moving, problem.u) >= 2:
        try:
            found = _discriminant_factors(moving, problem.u, [problem.t, *problem.parameters], deadline=deadline)
        except ComputationError:
            pass  # the discriminant is a constant: the values never meet
    for discriminant in problem.valid_anywhere():  # one on a dyad built on another's root: its conjugates' zeros too
        for factor, _ in sympy.factor_list(problem.numerator_in_t(root_free(discriminant)))[1]:
            factor = sympy.expand(factor)
            if factor.has(problem.t) and not any(sympy.expand(factor - f) == 0 or sympy.expand(factor + f) == 0
                                                 for f in found):
                found.append(factor)
    return found


def _discriminant_factors(poly: sympy.Expr, variable: sympy.Symbol, keep: Sequence[sympy.Symbol], *,
                          deadline: Deadline | None) -> list[sympy.Expr]:
    """Factors of the resultant in ``variable`` of ``poly`` and its derivative in it. Where ``poly`` is
    ``G(v**2)`` that resultant is a constant times ``G(0) * Res(G, G')**2`` (``v * G'(v**2)`` the
    derivative, halved): the factors of ``G``'s discriminant in ``v**2``, then ``G(0)``'s (two values
    meeting at 0), from resultants of half the degree."""
    halved = in_square([poly], variable)
    if halved is None:
        return resultant_factors([poly, sympy.diff(poly, variable)], variable, keep, backend="flint",
                                 deadline=deadline)
    (square,) = halved
    try:
        found = resultant_factors([square, sympy.diff(square, variable)], variable, keep, backend="flint",
                                  deadline=deadline)
    except ComputationError:
        found = []  # G's discriminant is a constant: only G(0)'s factors are left
    at_zero = square.xreplace({variable: sympy.Integer(0)})
    found += [f for f in _factors(at_zero) if not any(sympy.expand(f - g) == 0 or sympy.expand(f + g) == 0
                                                       for g in found)]
    if not found:
        raise ComputationError("the discriminant is a constant")
    return found


def pole_factors(problem: Problem) -> list[sympy.Expr]:
    """Factors, in ``t`` and the parameters, of the leading coefficients in ``u`` of the
    eliminant's moving components (``Problem.components``): the only finite inputs where a
    value of the output can run off to infinity (two lines of a meet turning parallel).

    >>> c, s, t, u = sympy.symbols("c s t u")
    >>> pole_factors(Problem(c * u - s, u, u, Parametrisation((c, s), t), ()))
    [t - 1, t + 1]
    """
    moving, _ = problem.components()
    found: list[sympy.Expr] = []
    for component in moving:
        for factor in _factors(_leading_coefficient(component, problem.u)):
            if factor.has(problem.t) and not any(sympy.expand(factor + f) == 0 for f in found) \
                    and factor not in found:
                found.append(factor)
    return found


def _leading_coefficient(poly: sympy.Expr, variable: sympy.Symbol) -> sympy.Expr:
    """The coefficient of ``poly``'s highest power of ``variable`` (python-flint: no sympy Poly of thousands of terms)."""
    symbols = sorted(poly.free_symbols, key=lambda v: v.name)
    index = symbols.index(variable)
    terms = to_flint(poly, flint_context([v.name for v in symbols])).to_dict()
    top = max(m[index] for m in terms)
    leading = from_terms({m: c for m, c in terms.items() if m[index] == top}, symbols)
    return leading.xreplace({variable: sympy.Integer(1)})  # xreplace gives back a rule's value as it is


def critical_points(problem: Problem, factors: Sequence[sympy.Expr] | None, lo: Number, hi: Number,
                    meeting: Sequence[sympy.Expr] | None = None, poles: Sequence[sympy.Expr] | None = None
                    ) -> list[CriticalPoint]:
    """Stationary points of ``problem`` (fixed dimensions) in ``[lo, hi]`` degrees, its dead
    centres and poles, then the two ends.

    ``factors`` are ``stationary_factors``, ``meeting`` ``meeting_factors`` and ``poles``
    ``pole_factors`` (each computed here if not given) with the parameters fixed as in
    ``problem``; either of the first two is recomputed if fixing the parameters made one of
    its factors vanish identically.
    """
    t = problem.t
    polys = [univariate(p, t) for p in _fixed_or_anew(factors, stationary_factors, problem) if p.has(t)]
    meeting = [univariate(f, t) for f in _fixed_or_anew(meeting, meeting_factors, problem) if f.has(t)]
    leading = pole_factors(problem) if poles is None else poles
    return points_in(problem, polys, meeting, lo, hi, [univariate(f, t) for f in leading if f.has(t)])


def points_in(problem: Problem, stationary: Sequence[Polynomial], meeting: Sequence[Polynomial], lo: Number,
              hi: Number, poles: Sequence[Polynomial] = ()) -> list[CriticalPoint]:
    """``critical_points`` from the ``stationary``, ``meeting`` and ``poles`` factors at fixed
    dimensions, as univariate polynomials in ``t`` (python-flint): no sympy on the way."""
    found: list[CriticalPoint] = []
    with flint.ctx.workprec(ROOT_BITS), mpmath.workdps(DIGITS):
        lo, hi = _mp(lo), _mp(hi)
        suspects = _pole_suspects(problem, poles, lo, hi)
        balls = [problem.line.shown(r.ball) for p in stationary if p.degree() >= 1 for r in real_roots(p)]
        if problem.line.is_angle:
            balls.append(flint.arb(180))  # t = infinity
        for ball in balls:
            middle = mpmath.mpf(ball.mid().str(DIGITS, radius=False))
            for turn in problem.line.turns:
                degrees = middle + turn
                if not lo <= degrees <= hi or _seen(found, degrees):
                    continue
                here = _value_at(problem, degrees, suspects)
                if _is_stationary(problem, degrees, here):
                    found.append(CriticalPoint(degrees, here, _kind(problem, degrees, here), ball + turn))
        found += _dead_centres(problem, meeting, lo, hi, found)
        found += _poles(problem, suspects, lo, hi, found)
        ends = [CriticalPoint(x, _end_value(problem, x, inward, suspects, found), "endpoint")
                for x, inward in ((lo, 1), (hi, -1))]
    return sorted(found, key=lambda p: (p.input_deg, p.side)) + ends


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


Suspect = tuple[mpmath.mpf, flint.arb]  # where the output may run off: the input, its enclosure


def _pole_suspects(problem: Problem, poles: Sequence[Polynomial], lo: mpmath.mpf, hi: mpmath.mpf) -> list[Suspect]:
    """The inputs in the range (to rounding) where a value of the output can run off to infinity
    or its closed form be 0/0: the real roots of the leading coefficients in ``u``
    (``pole_factors``), and an angle's half turn, where its degree in ``t`` may drop."""
    balls = [problem.line.shown(r.ball) for p in poles if p.degree() >= 1 for r in real_roots(p)]
    if problem.line.is_angle:
        balls.append(flint.arb(180))  # t = infinity
    suspects: list[Suspect] = []
    for ball in balls:
        middle = mpmath.mpf(ball.mid().str(DIGITS, radius=False))
        suspects += [(middle + turn, ball + turn) for turn in problem.line.turns if _sides_within(middle + turn, lo, hi)]
    return suspects


def _poles(problem: Problem, suspects: Sequence[Suspect], lo: mpmath.mpf, hi: mpmath.mpf,
           found: list[CriticalPoint]) -> list[CriticalPoint]:
    """Where the output runs off to infinity inside the range (a "pole" on each side it does so
    from: -inf on one and +inf on the other like 1/x), and where its closed form is 0/0 but
    bounded and the output stationary (the limit there is a critical value).

    Only at the ``suspects`` (``_pole_suspects``) can a value of ``u`` be unbounded; whether the
    branch's is, is read from each side (``one_sided_limit``). An angle's via is not looked at:
    its value is bounded, and a direction's via runs off only where the direction passes its
    reference's opposite.
    """
    points: list[CriticalPoint] = []
    for degrees, ball in suspects:
        if _seen(found, degrees):
            continue  # a stationary point, its value finite (``_value_at``): no pole
        limits = {side: one_sided_limit(problem, degrees, side) for side in _sides_within(degrees, lo, hi)}
        points += [CriticalPoint(degrees, limit, "pole", ball, side=side)
                   for side, limit in limits.items() if mpmath.isinf(limit) and problem.scale is None]
        if len(limits) == 2 and all(mpmath.isfinite(v) for v in limits.values()) and not _seen(points, degrees):
            here = _value_at(problem, degrees, suspects)
            if _is_stationary(problem, degrees, here):
                points.append(CriticalPoint(degrees, here, _kind(problem, degrees, here), ball))
    return points


def _sides_within(degrees: mpmath.mpf, lo: mpmath.mpf, hi: mpmath.mpf) -> list[int]:
    """The sides (-1 below, +1 above) from which the range reaches ``degrees``: none outside it,
    one at its ends (to rounding)."""
    return [side for side, inside in ((-1, lo + SAME_INPUT < degrees <= hi + SAME_INPUT),
                                      (1, lo - SAME_INPUT <= degrees < hi - SAME_INPUT)) if inside]


def one_sided_limit(problem: Problem, degrees: mpmath.mpf, side: int) -> mpmath.mpf:
    """The output's limit as the input tends to ``degrees`` from below (``side`` -1) or above
    (+1): +inf or -inf where it runs off, nan where the branch does not assemble just there.

    Read at ``PROBES`` from ``degrees`` at twice the digits: nearer and nearer, a value that
    runs off grows by ``RUN_OFF`` or more at each step (like ``x**(-1/k)``, ``k`` up to 4),
    a bounded one does not.
    """
    with mpmath.workdps(2 * DIGITS):
        probes = [problem.value(degrees + side * mpmath.mpf(10) ** -k) for k in PROBES]
        if any(v != v for v in probes):
            return mpmath.nan
        if all(abs(far) * RUN_OFF < abs(near) for far, near in zip(probes, probes[1:])):
            return mpmath.inf if probes[-1] > 0 else -mpmath.inf
    return +probes[-1]  # rounded to the working digits


def _value_at(problem: Problem, degrees: mpmath.mpf, suspects: Sequence[Suspect]) -> mpmath.mpf:
    """The output at ``degrees`` (a dead centre's to rounding); at a suspect (``_pole_suspects``),
    its limit (from below, or above where it does not assemble below) where the closed form
    there reads otherwise (0/0: a cancellation, not a value), nan where it runs off."""
    value = problem.value(degrees)
    if value != value:  # a discriminant touching zero here reads a rounding below it
        value = _value_at_meeting(problem, degrees)
    if not _near(suspects, degrees):
        return value
    limit = one_sided_limit(problem, degrees, -1)
    if limit != limit:  # the branch does not assemble below
        limit = one_sided_limit(problem, degrees, 1)
    if mpmath.isinf(limit):
        return mpmath.nan
    return value if limit != limit or _agrees(value, limit) else limit


def _end_value(problem: Problem, degrees: mpmath.mpf, inward: int, suspects: Sequence[Suspect],
               found: Sequence[CriticalPoint]) -> mpmath.mpf:
    """The output at a range end: a point's of ``found`` there (a dead centre's: the one value,
    that point the extreme where they tie); where its closed form is not real there or the end
    is a suspect (``_pole_suspects``), its limit from inside the range (+-inf where it runs
    off), the value there where that agrees with it (to rounding); nan where the branch does
    not assemble just inside it either."""
    there = [p for p in found if _seen([p], degrees) and (not p.side or p.side == inward)]
    if there:
        return there[0].value
    value = problem.value(degrees)
    if value == value and not _near(suspects, degrees):
        return value
    limit = one_sided_limit(problem, degrees, inward)
    if mpmath.isinf(limit):
        return limit if problem.scale is None else mpmath.nan  # an angle's via runs off at no pole of the angle
    if limit != limit:
        return value
    if value != value:
        value = _value_at_meeting(problem, degrees)  # a dead centre's value to rounding, not the probe's
    return value if _agrees(value, limit) else limit


def _near(suspects: Sequence[Suspect], degrees: mpmath.mpf) -> bool:
    return any(abs(degrees - at) < SAME_INPUT for at, _ in suspects)


def _agrees(value: mpmath.mpf, limit: mpmath.mpf) -> bool:
    """Whether a value read at a point is its limit there, to the probes' accuracy (a 0/0 read
    where the closed form cancels is off by far more)."""
    return value == value and abs(value - limit) <= mpmath.mpf(10) ** -9 * (1 + abs(limit))


def _ends_here(problem: Problem, degrees: mpmath.mpf) -> bool:
    """Whether the branch is real just on one side of ``degrees``."""
    step = mpmath.mpf(10) ** -12
    left, right = (problem.value(degrees + d) for d in (-step, step))
    return (left == left) != (right == right)


def _value_at_meeting(problem: Problem, degrees: mpmath.mpf) -> mpmath.mpf:
    """The branch's value where its square root's argument is zero up to rounding (the
    imaginary part then tiny), nan where the branch is not real."""
    here = problem.on(degrees)
    if here is None:
        return mpmath.nan
    result = here.closed_at(problem.line.numbers_at(degrees))
    if isinstance(result, mpmath.mpc):
        tiny = mpmath.mpf(10) ** (-DIGITS // 3) * (1 + abs(result))
        return result.real if abs(result.imag) <= tiny else mpmath.nan
    return result


def points_at(problem: Problem, stationary: Sequence[sympy.Expr], values: Mapping[sympy.Symbol, sympy.Expr],
              lo: Number, hi: Number, meeting: Sequence[sympy.Expr] | None = None,
              poles: Sequence[sympy.Expr] | None = None) -> list[CriticalPoint]:
    """``critical_points`` with the dimensions fixed at ``values`` (symbol -> rational); the
    ``stationary``, ``meeting`` and ``poles`` factors, found once with the dimensions symbolic,
    are specialised rather than eliminated again."""
    factors = [sympy.expand(f.xreplace(values)) for f in stationary]
    fixed_meeting = None if meeting is None else [sympy.expand(f.xreplace(values)) for f in meeting]
    fixed_poles = None if poles is None else [sympy.expand(f.xreplace(values)) for f in poles]
    with mpmath.workdps(DIGITS):
        return critical_points(problem.at(values), factors, lo, hi, fixed_meeting, fixed_poles)


def _mp(number: Number) -> mpmath.mpf:
    """A rational (sympy, int), an exact real (a radians range end in degrees, ``540/pi``) or an
    mpf as an mpf at the working precision."""
    if isinstance(number, (mpmath.mpf, float)):
        return mpmath.mpf(number)  # a float's own value (sympy evaluates 0.0 to an exact zero)
    exact = sympy.sympify(number)
    if exact.is_Rational:
        return mpmath.mpf(int(exact.p)) / int(exact.q)
    return mpmath.mpf(exact.evalf(mpmath.mp.dps + 5)._mpf_)


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
