"""The minimum (or maximum) as a closed form in symbolic dimensions, and where it holds.

At a parameter point the certified critical points give the minimiser. The factor of
the stationary polynomial that vanishes there is solved in radicals for
``t = tan(theta/2)``, and the factor of the *value polynomial* (the resultant in ``t``)
for the value; of their roots, the one equal to the certified minimiser is kept, its
square roots denested.

What the minimum is can only change where an *event polynomial* in the parameters
vanishes: a critical point crosses a range end, appears or leaves the reals
(discriminants, leading coefficients), or two candidate values meet (resultants of their
value polynomials, range ends included). With one parameter their certified real roots
cut the line into intervals; each interval is described at a rational point inside it,
so the answer says where the minimiser leaves the range and what the minimum is there.
With more parameters the answer holds where every event polynomial keeps its sign at
the defaults (in the cell of the defaults).
"""

from __future__ import annotations

import itertools
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any, Optional, TypeAlias, TypedDict

import attrs
import flint
import mpmath
import sympy

from ...errors import ComputationError, UsageError
from ...runtime.budget import Deadline
from ...runtime.frozen import FrozenDict
from ...scene.compile import Span
from ...system.angles import half_angle_degree
from ...system.between import simplest_between
from ...system.convert import univariate
from ...system.roots import real_roots
from ..frozen import frozen_rows, thawed
from .critical import (DIGITS, ROOT_BITS, CriticalPoint, Number, Problem, extreme, meeting_factors, points_at,
                       pole_factors, resultant_factors)

__all__ = ["ClosedForm", "closed_form", "value_factors", "Region", "describe", "end_degrees", "value_at_angle"]

Values = Mapping[sympy.Symbol, sympy.Expr]  # the dimensions at a point: symbol -> rational
Found = tuple[CriticalPoint, "Description"]  # the certified extremum at a point, and its closed form


# ``from`` is a keyword: the functional form
_Interval = TypedDict("_Interval", {"from": Optional[float], "to": Optional[float], "sample": float, "at": str,
                                    "input": Optional[str], "value": Optional[str]})


class Region(_Interval, total=False):
    """An interval of the one symbolic dimension (None: unbounded) and what the extremum is
    there, described at ``sample``: its ``at``, its input and value as text (None where it does
    not assemble), and where it assembles the extremum at the sample."""

    sample_input_deg: float
    sample_value: float

MATCH = mpmath.mpf(10) ** -20


def _tuple(items: Any) -> tuple[Any, ...]:
    return tuple(items)


@attrs.frozen
class ClosedForm:
    """The extremum in the parameters: value and input (degrees), and where that holds."""

    value: sympy.Expr
    input: sympy.Expr | None  # degrees; None when the root has no expression in radicals
    at: str  # 'stationary', 'dead centre' or 'endpoint'
    input_polynomial: sympy.Expr | None  # in t = tan(input/2); None at an endpoint
    # where it holds: sympy relations (``true``: at every real value); ``valid_when_text`` says them
    # in words, as the JSON does ('every real b', '0.5 < b < 2')
    valid_when: tuple[sympy.Basic, ...] = attrs.field(converter=_tuple)
    # one parameter: [{from, to, at, input, value, ...}] (Regions, frozen), else []
    regions: tuple[FrozenDict[str, Any], ...] = attrs.field(converter=frozen_rows)
    region_values: tuple[sympy.Expr | None, ...] = attrs.field(converter=_tuple)  # each region's value as sympy: drawn without parsing the text back
    via_value: sympy.Expr | None = None  # an angle output: the value of the scalar standing for it
    valid_when_text: tuple[str, ...] = attrs.field(default=(), converter=_tuple)

    def to_json(self) -> dict[str, object]:
        document: dict[str, object] = {"value": _text(self.value), "input": _text(self.input), "at": self.at,
                    "input_polynomial": _text(self.input_polynomial), "valid_when": list(self.valid_when_text),
                    "regions": thawed(self.regions)}
        if self.via_value is not None:
            document["via_value"] = _text(self.via_value)
        return document


def _text(expr: sympy.Expr | None) -> str | None:
    return None if expr is None else str(expr)


def value_factors(problem: Problem, backend: str = "flint", *, deadline: Deadline | None = None) -> list[sympy.Expr]:
    """Factors, in ``u`` and the parameters, of the resultant in ``t`` of ``F`` and ``dF/dtheta``
    (the elimination keeping to ``deadline``, if any)."""
    factors = resultant_factors(problem.half_angle(), problem.t, [problem.u, *problem.parameters], backend=backend,
                                deadline=deadline)
    return [f for f in factors if f.has(problem.u)]


def _numeric(expr: sympy.Expr, values: Values) -> mpmath.mpc:
    """``expr`` at rational parameter ``values``, as an mpmath complex (40 digits)."""
    number = sympy.N(expr.xreplace(values), DIGITS)
    if not number.is_finite:
        return mpmath.mpc(mpmath.nan)
    real, imag = number.as_real_imag()
    return mpmath.mpc(mpmath.mpf(str(real)), mpmath.mpf(str(imag)))


def _matching_factor(factors: Iterable[sympy.Expr], variable: sympy.Symbol, target: mpmath.mpf,
                     values: Values) -> sympy.Expr | None:
    """The factor (in ``variable``) that vanishes at the number ``target`` for ``values``."""
    best = None
    for factor in factors:
        if not factor.has(variable):
            continue
        poly = sympy.Poly(factor.xreplace(values), variable)
        scale = sum(abs(mpmath.mpf(sympy.N(c, DIGITS))) * abs(target) ** k
                    for k, c in enumerate(reversed(poly.all_coeffs()))) or 1  # at 0, a root there is exact
        residual = abs(mpmath.polyval([mpmath.mpf(sympy.N(c, DIGITS)) for c in poly.all_coeffs()], target))
        if scale and residual <= MATCH * scale and (best is None or residual / scale < best[0]):
            best = (residual / scale, factor)
    return None if best is None else best[1]


def _root_matching(factor: sympy.Expr | None, variable: sympy.Symbol, target: mpmath.mpf,
                   values: Values) -> sympy.Expr | None:
    """The root of ``factor`` in radicals equal to ``target`` at ``values``, denested; None past a
    quadratic whose coefficients hold dimensions (Ferrari's formulas on the four-bar's ``dist(P, O)``
    with ``a`` symbolic: 6.5 s for roots of 124,000 characters, then minutes denesting them, for a
    form no reader could use: its factor says the input)."""
    if factor is None:
        return None
    degree = sympy.degree(factor, variable)
    if degree > 4 or (degree > 2 and factor.free_symbols - {variable}):
        return None
    candidates = []
    for root in sympy.roots(sympy.Poly(factor, variable)):
        for form in dict.fromkeys([root, sympy.sqrtdenest(root), sympy.radsimp(root)]):
            if abs(_numeric(form, values) - target) <= MATCH * (1 + abs(target)):
                candidates.append(form)
    # ties broken by the text: the same form in every process (a set's order follows the hash seed)
    return min(candidates, key=lambda form: (sympy.count_ops(form), str(form)), default=None)


def _exact_degrees(value: mpmath.mpf) -> sympy.Rational:
    return sympy.Rational(mpmath.nstr(value, 15))


def end_degrees(problem: Problem, best: CriticalPoint) -> sympy.Rational | None:
    """The exact input of ``best`` where it is a range end or an angle's ``t`` at infinity (a
    half turn), where its closed form is the closed form's at that input; None elsewhere."""
    line = problem.line
    turn = 360 * mpmath.floor((best.input_deg + 180) / 360) if line.is_angle else 0
    if best.kind == "endpoint" or (line.is_angle and abs(best.input_deg - turn + 180) < MATCH):
        return _exact_degrees(best.input_deg)
    return None


def value_at_angle(problem: Problem, degrees: sympy.Rational, values: Values) -> sympy.Expr | None:
    """The closed form at an exact angle, tidied (denested when that is shorter and equal); None
    where it has no value there (0/0: the output's value there is its limit)."""
    raw = _closed_at(problem, degrees).xreplace(problem.line.exact_at(degrees))
    if raw.is_Rational:
        return raw  # every tidier form of a rational is itself
    target = _numeric(raw, values)
    forms = [f for f in (raw, sympy.sqrtdenest(raw), sympy.radsimp(raw), sympy.factor(raw))
             if abs(_numeric(f, values) - target) <= MATCH * (1 + abs(target))]
    return min(forms, key=sympy.count_ops, default=None)


def _closed_at(problem: Problem, degrees: sympy.Rational | mpmath.mpf) -> sympy.Expr:
    """The closed form the output has at ``degrees``: a named mode's there (``Problem.on``)."""
    here = problem.on(mpmath.mpf(float(degrees)))
    return (here or problem).closed


@dataclass(frozen=True)
class Description:
    """What the extremum is at one parameter point, and the polynomials that pin it down."""

    at: str  # 'stationary', 'dead centre', 'endpoint', or 'unbounded' (a pole in the range: no extreme)
    input: sympy.Expr | None  # degrees, None without radicals
    value: sympy.Expr | None
    input_factor: sympy.Expr | None  # the stationary factor in t it is a root of; None at an end
    value_factor: sympy.Expr | None  # the polynomial in u its value is a root of


def describe(problem: Problem, stationary: Sequence[sympy.Expr], values_factors: Sequence[sympy.Expr], values: Values,
             best: CriticalPoint, meeting: Sequence[sympy.Expr] = ()) -> Description:
    """The closed form, in the parameters, of the certified extremum ``best`` at ``values``;
    at a dead centre its input is a root of one of the ``meeting`` factors, not a stationary one."""
    line = problem.line
    turn = 360 * mpmath.floor((best.input_deg + 180) / 360) if line.is_angle else 0
    degrees = end_degrees(problem, best)
    if degrees is not None:
        end_value = line.at_end(degrees)(problem.numerator_in_t(problem.eliminant)) \
            if _exact_end(problem, degrees) else None
        return Description("endpoint" if best.kind == "endpoint" else "stationary", degrees,
                           value_at_angle(problem, degrees, values), None, end_value)
    t_star = line.t_of(best.input_deg)
    at = "dead centre" if best.kind == "dead centre" else "stationary"
    factor = _matching_factor(meeting if at == "dead centre" else stationary, problem.t, t_star, values)
    root = _root_matching(factor, problem.t, t_star, values)
    degrees = None if root is None else line.exact_shown(root) + int(turn)
    u_factor = _matching_factor(values_factors, problem.u, best.value, values)
    value = _root_matching(u_factor, problem.u, best.value, values)
    if value is None and root is not None and at == "dead centre":
        value = _double_root(problem, root)
    if value is None and root is not None:
        value = _denested(_closed_at(problem, best.input_deg).xreplace(line.exact_in_t(root)))
    return Description(at, degrees, None if value is None else tidied(value), factor, u_factor)


# The largest degree of an angle's tan(end/2) at which an end's conditions are eliminated (the resultant
# with its minimal polynomial): 12 takes every multiple of 5 degrees (arm-string's b over 0:5 took 40 s, the
# degree 12; 91 degrees, of degree 48, ran past ten minutes)
END_DEGREE = 12


def _exact_end(problem: Problem, degrees: sympy.Expr) -> bool:
    """Whether the input at the end ``degrees`` is exact and small enough to eliminate (``END_DEGREE``)."""
    return not problem.line.is_angle or half_angle_degree(degrees, limit=END_DEGREE) is not None


def _check_ends(problem: Problem, lo: Number, hi: Number) -> None:
    """A UsageError unless both ends of the range are exact enough for the closed form's conditions."""
    for end in (lo, hi):
        if not _exact_end(problem, sympy.sympify(end)):
            raise UsageError("angle_range", f"{float(lo):g}:{float(hi):g}",
                             f"with dimensions kept symbolic, each end must be an angle whose tan(end/2) is "
                             f"algebraic of degree at most {END_DEGREE} (any multiple of 5 degrees; in radians, "
                             f"0), for the conditions on the dimensions: {float(end):.12g} deg's is not")


# Past this many operations a form is left as it is: sympy's denesting of the four-bar's dist(P, O) at a
# stationary input with ``a`` symbolic (6,080 operations) ran for minutes
DENEST_OPS = 400


def _denested(expr: sympy.Expr) -> sympy.Expr:
    """``expr`` denested (``sympy.sqrtdenest``) where it is small enough to try (``DENEST_OPS``)."""
    return sympy.sqrtdenest(expr) if sympy.count_ops(expr) <= DENEST_OPS else expr


# Where a tidied form is compared with the form it replaces, each dimension at one of these in turn:
# rationals that no dimension's special value (a pole, a radicand's root, a range end's) is likely at
PROBES = tuple(sympy.Rational(p, q) for p, q in ((37, 11), (-53, 17), (101, 29), (7, 13), (-211, 37)))
PROBE_DIGITS = 50


def tidied(expr: sympy.Expr) -> sympy.Expr:
    """``expr`` with each square root's radicand made one fraction, factored, and the terms over each
    root collected, their coefficient factored: a dead centre's value, one root thrice over a sum of
    fractions, as one root times one product. Kept as it is where that is no shorter, where the two
    differ at ``PROBES``, where it holds no dimension or is past ``DENEST_OPS`` (sympy's cost)."""
    size = sympy.count_ops(expr)
    if not expr.free_symbols or size > DENEST_OPS:
        return expr
    roots = {p: sympy.sqrt(sympy.factor(sympy.together(p.base))) for p in expr.atoms(sympy.Pow)
             if p.exp == sympy.S.Half}
    if not roots:
        return expr
    tidy = sympy.collect(expr.xreplace(roots), list(roots.values()), sympy.factor)
    return tidy if sympy.count_ops(tidy) < size and _equal_at_probes(tidy, expr) else expr


def _equal_at_probes(one: sympy.Expr, other: sympy.Expr) -> bool:
    """Whether two expressions agree to ``PROBE_DIGITS`` at each of ``PROBES`` where both are finite
    (each symbol at a different one), and at three at least."""
    symbols = sorted(one.free_symbols | other.free_symbols, key=str)
    agreeing = 0
    for k in range(len(PROBES)):
        at = {s: PROBES[(k + i) % len(PROBES)] for i, s in enumerate(symbols)}
        x, y = (sympy.N(e.xreplace(at), PROBE_DIGITS) for e in (one, other))
        if not (x.is_finite and y.is_finite):
            continue
        if abs(complex(x - y)) > 10.0 ** (10 - PROBE_DIGITS) * (1 + abs(complex(y))):
            return False
        agreeing += 1
    return agreeing >= 3


def _double_root(problem: Problem, root: sympy.Expr) -> sympy.Expr | None:
    """Where the two values of a quadratic eliminant meet (a dead centre at ``t = root``):
    ``-b / 2a``, far shorter than the closed form's square root of zero; None otherwise."""
    eliminant = sympy.Poly(problem.numerator_in_t(problem.eliminant), problem.u)
    if eliminant.degree() != 2:
        return None
    a, b, _ = (c.xreplace({problem.t: root}) for c in eliminant.all_coeffs())
    return sympy.cancel(sympy.radsimp(sympy.cancel(-b / (2 * a))))


def event_polynomials(problem: Problem, stationary: Sequence[sympy.Expr], values_factors: Sequence[sympy.Expr],
                      ends: Sequence[Number], own: Description | None = None) -> list[sympy.Expr]:
    """Polynomials in the parameters whose zeros are the only places the extremum can change.

    With ``own`` (a ``Description``), only the events of that extremum: its critical point
    crossing a range end or leaving the reals, its value meeting another candidate's.
    """
    t, u = problem.t, problem.u
    eliminant = problem.numerator_in_t(problem.eliminant)
    end_values = [problem.line.at_end(end)(eliminant) for end in ends]
    moving = stationary if own is None else [f for f in (own.input_factor,) if f is not None]
    events = [problem.line.at_end(end)(f) for end in ends for f in moving if f.has(t)]
    for factor in moving:
        if sympy.degree(factor, t) >= 1:
            events += [sympy.discriminant(factor, t), sympy.Poly(factor, t).LC()]
    candidates = [v for v in [*values_factors, *end_values] if v.has(u)]
    valued = candidates if own is None else [f for f in (own.value_factor,) if f is not None]
    for factor in valued:
        events += [sympy.discriminant(factor, u), sympy.Poly(factor, u).LC()]
    events += [sympy.resultant(f, g, u) for f, g in itertools.combinations(candidates, 2)
               if own is None or own.value_factor in (f, g)]
    return _event_factors(events, problem.parameters)


def _event_factors(events: Iterable[sympy.Expr], parameters: Sequence[sympy.Symbol]) -> list[sympy.Expr]:
    """Distinct irreducible factors, in the parameters, of the events, minus the sign-definite ones."""
    found: list[sympy.Expr] = []
    for event in events:
        event = sympy.expand(event)
        if event == 0 or not event.free_symbols & set(parameters):
            continue
        for factor, _ in sympy.factor_list(event)[1]:
            factor = sympy.expand(factor)
            if factor.free_symbols and not _sign_definite(factor, parameters):
                if not any(sympy.expand(factor - g) == 0 or sympy.expand(factor + g) == 0 for g in found):
                    found.append(factor)
    return found


def _sign_definite(poly: sympy.Expr, parameters: Sequence[sympy.Symbol]) -> bool:
    """Even powers only, coefficients of one sign: it cannot change sign (zero on a set of no extent)."""
    terms = sympy.Poly(poly, *parameters).terms()
    sign = 1 if terms[0][1] > 0 else -1
    return all(all(e % 2 == 0 for e in monomial) and sign * c > 0 for monomial, c in terms)


def closed_form(problem: Problem, stationary: list[sympy.Expr], defaults: Values, lo: Number, hi: Number,
                largest: bool = False, *, domain: Sequence[Span] | None = None, lengths: Sequence[sympy.Expr] = (),
                deadline: Deadline | None = None) -> ClosedForm:
    """The extremum of ``problem`` (parameters symbolic) over ``[lo, hi]`` degrees as a closed form
    (its eliminations keeping to ``deadline``, if any). With one parameter, its regions cover
    ``domain`` alone (the spans where a length it is stays positive; None: every real value); with
    more, where it holds says each of ``lengths`` (the scene's, in the parameters) is positive."""
    _check_ends(problem, lo, hi)
    values_factors = value_factors(problem, deadline=deadline)
    meeting = meeting_factors(problem, deadline=deadline)
    poles = pole_factors(problem)

    def extremum_at(values: Values) -> Found | None:
        """The certified extremum at ``values`` and its description; ``None`` where the output
        is real nowhere on the range (the mechanism does not assemble at those dimensions)."""
        points = points_at(problem, stationary, values, lo, hi, meeting, poles)
        if not any(p.value == p.value for p in points):
            return None
        best = extreme(points, largest)
        if best.unbounded:
            return best, Description("unbounded", None, None, None, None)
        return best, describe(problem, stationary, values_factors, values, best, meeting)

    if deadline is not None:
        deadline.note("writing the extremum in the dimensions, region by region")
    with mpmath.workdps(DIGITS):
        found = extremum_at(defaults)
        if found is None:  # real nowhere at the defaults: refused, as ``extreme`` refuses
            raise ComputationError("the output is not real anywhere on the range")
        best, here = found
        if best.unbounded:
            raise UsageError("params", ", ".join(p.name for p in problem.parameters),
                             f"the output is unbounded near {float(best.input_deg):.12g} deg (a pole) at the "
                             "dimensions' values: it has no extreme to give as a closed form")
        # a pole entering the range is an event too: where a leading coefficient's root crosses an end
        moving = stationary + meeting + poles
        if len(problem.parameters) == 1:
            events = event_polynomials(problem, moving, values_factors, (lo, hi))
            regions, values = _regions(problem, events, extremum_at, defaults, domain or [(None, None)])
            conditions = _interval_conditions(problem.parameters[0], regions, defaults)
        else:
            regions, values = [], []  # no regions in more than one dimension
            own = event_polynomials(problem, moving, values_factors, (lo, hi), here)
            conditions = _sign_conditions(own, defaults)
            conditions += _positive(lengths, already=[c for c, _ in conditions])
    return ClosedForm(here.value, here.input, here.at, here.input_factor, [c for c, _ in conditions], regions, values,
                      valid_when_text=[text for _, text in conditions])


Condition: TypeAlias = tuple[sympy.Basic, str]
"""A condition on the parameters as a sympy relation, and in words."""


def _sign_conditions(events: Iterable[sympy.Expr], defaults: Values) -> list[Condition]:
    conditions: list[Condition] = []
    for event in events:
        sign = mpmath.sign(_numeric(event, defaults).real)
        positive = event if sign > 0 else -event
        conditions.append((positive > 0, f"{positive} > 0") if sign else (sympy.Eq(event, 0), f"{event} = 0"))
    return conditions


def _positive(lengths: Iterable[sympy.Expr], *, already: Sequence[sympy.Basic]) -> list[Condition]:
    """``length > 0`` for each of ``lengths`` not already said: the events' signs at the defaults may
    not exclude a negative length (a non-Grashof four-bar's rocker ``m`` with its crank ``a``)."""
    return [(length > 0, f"{length} > 0") for length in dict.fromkeys(lengths) if (length > 0) not in already]


def _interval_conditions(name: sympy.Symbol, regions: Sequence[Region], defaults: Values) -> list[Condition]:
    home = next(r for r in regions if _contains(r, defaults[name]))
    return [(_interval(name, r["from"], r["to"]), _interval_text(name, r["from"], r["to"])) for r in regions
            if (r["at"], r["input"], r["value"]) == (home["at"], home["input"], home["value"])]


def _interval(name: sympy.Symbol, lo: float | None, hi: float | None) -> sympy.Basic:
    """``lo < name < hi`` (an end None: unbounded) as a sympy relation; ``true`` when both are."""
    above = sympy.true if lo is None else name > sympy.Float(lo, 15)
    below = sympy.true if hi is None else name < sympy.Float(hi, 15)
    return sympy.And(above, below)


def _contains(region: Region, value: float) -> bool:
    return (region["from"] is None or region["from"] <= value) and (region["to"] is None or value <= region["to"])


def _interval_text(name: sympy.Symbol, lo: float | None, hi: float | None) -> str:
    if lo is None and hi is None:
        return f"every real {name}"
    if lo is None:
        return f"{name} < {hi:.15g}"
    if hi is None:
        return f"{name} > {lo:.15g}"
    return f"{lo:.15g} < {name} < {hi:.15g}"


def _regions(problem: Problem, events: Sequence[sympy.Expr], extremum_at: Callable[[Values], Found | None],
             defaults: Values, domain: Sequence[Span]) -> tuple[list[Region], list[sympy.Expr | None]]:
    """Per interval between the events' real roots within ``domain``: where the extremum is and
    its closed form; and each region's value as a sympy expression."""
    (name,) = problem.parameters
    with flint.ctx.workprec(ROOT_BITS):
        cuts = sorted({float(r.ball.mid()) for e in events for r in real_roots(univariate(e, name))})
    intervals = [interval for span in domain for interval in _cut(span, cuts)]
    regions: list[Region] = []
    values: list[sympy.Expr | None] = []
    for lo, hi in intervals:
        sample = defaults[name] if len(intervals) == 1 else sympy.Rational(simplest_between(lo, hi))
        region, value = _region(lo, hi, sample, extremum_at({name: sample}))
        if regions and regions[-1]["to"] == lo and _same(regions[-1], region):
            regions[-1]["to"] = hi
        else:
            regions.append(region)
            values.append(value)
    return regions, values


def _cut(span: Span, cuts: Sequence[float]) -> list[Span]:
    """The open interval ``span`` cut at those of ``cuts`` inside it."""
    lo, hi = span
    inside = [c for c in cuts if (lo is None or lo < c) and (hi is None or c < hi)]
    bounds = [lo, *inside, hi]
    return list(zip(bounds, bounds[1:]))


def _same(one: Region, other: Region) -> bool:
    return (one["at"], one["input"], one["value"]) == (other["at"], other["input"], other["value"])


def _region(lo: float | None, hi: float | None, sample: sympy.Rational, found: Found | None
            ) -> tuple[Region, sympy.Expr | None]:
    """One interval of the parameter, described at ``sample`` by ``found`` (``extremum_at``):
    where the mechanism does not assemble on the range, ``at`` is 'nowhere' and there is no value."""
    if found is None:
        return Region({"from": lo, "to": hi, "sample": float(sample), "at": "nowhere", "input": None,
                       "value": None}), None
    best, described = found
    region = Region({"from": lo, "to": hi, "sample": float(sample), "at": described.at,
                     "input": _text(described.input), "value": _text(described.value)})
    # where it assembles, the extremum at the sample too (a figure draws it)
    region["sample_input_deg"], region["sample_value"] = float(best.input_deg), float(best.value)
    return region, described.value

