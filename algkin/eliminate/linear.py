"""Linear algebra before resultants: radical axes and linear substitution.

Mechanism equations are mostly circles (``|X - C|**2 = r**2``) and frames (points linear
in other points). Two circles in the same unknowns share their quadratic part up to a
factor, so a combination of them is *linear* (the radical axis); an unknown that appears
linearly, with a coefficient free of the other unknowns, is substituted out
(``v = -rest/a``, each equation multiplied through by ``a**k``). Only what neither step
removes goes to a resultant chain. Extraneous factors brought in by the multipliers are
removed by factoring and selection at the witnesses, as for resultants.

>>> import sympy
>>> from algkin.eliminate import eliminate
>>> ax, ay, bx, by, px, py = sympy.symbols("ax ay bx by px py")
>>> bars = [ax**2 + ay**2 - 1, (bx - 2)**2 + by**2 - 1, (bx - ax)**2 + (by - ay)**2 - 4,
...         2*px - ax - bx, 2*py - ay - by]          # the midpoint P of a bar AB on two cranks
>>> result = eliminate(bars, ["ax", "ay", "bx", "by"], ["px", "py"], method="linear")
>>> [step for step, _ in result.log]
['substituted', 'substituted', 'radical-axis', 'substituted', 'radical-axis', 'substituted']
>>> sympy.factor(result.polynomial)  # with no witnesses given, the multiplier py is kept
py*(px**2 - 2*px + py**2)*(px**4 - 4*px**3 + 2*px**2*py**2 + 5*px**2 - 4*px*py**2 - 2*px + py**4 + 5*py**2)
"""

from collections.abc import Sequence
from typing import Generic

import attrs

from .methods import cheapest, resultant_chain, resultant_step
from .protocol import Backend, P
from .request import EliminationRequest, LogEntry, MethodOutcome

__all__ = ["linear_elimination"]


def linear_elimination(backend: Backend[P], polys: list[P], request: EliminationRequest) -> MethodOutcome[P]:
    """Substitute linear unknowns and reduce circles to radical axes; resultants for the rest.

    A multiplier may hold numbers and the request's ``parameters`` (kept variables: the
    dimensions, and a derivation's inputs); it may hold the other kept variables (a curve's
    coordinates) only for the last two unknowns (the closing Cramer step): earlier, it would
    raise the degree of everything still to be eliminated, and resultants do better
    (``benchmarks/bench_ideas.py``: the Stephenson III curve is ten times slower otherwise).
    Every multiplier holding a variable is in the outcome's ``multipliers``: the eliminant's
    extraneous factors can only be theirs.
    """
    outcome = MethodOutcome(polys)
    original = polys
    remaining = list(request.eliminate)
    closing = False  # whether a multiplier held a kept variable
    ahead: tuple[list[P], list[str], _Linear[P]] | None = None  # what the axes' check found, for the next turn
    while True:
        present: set[str] = set().union(*(backend.variables(p) for p in outcome.left))
        remaining = [v for v in remaining if v in present]  # substituted away already (prepare)
        if not remaining:
            if closing and all(backend.is_zero(p) for p in outcome.left):
                # the multiplier was the eliminant itself, every equation divided by it (an inversor's
                # straight line, where a spurious component hides it): resultants from the start,
                # whose factors the witnesses choose step by step
                return MethodOutcome(original, log=[("linear-left-nothing", "")]).then(
                    resultant_chain(backend, original, request))
            return outcome
        allowed = set(request.parameters) if len(remaining) > 2 else set(backend.names) - set(remaining)
        polys = [p for p in outcome.left if not backend.is_zero(p)]
        found = ahead[2] if ahead is not None and _same(ahead[0], polys) and ahead[1] == remaining else \
            _linear_unknown(backend, polys, remaining, allowed)
        if found is not None:
            closing = closing or not backend.variables(found.coefficient) <= set(request.parameters)
            # after the last unknown, the multiplier's factors are left for factoring to divide out
            outcome = outcome.then(_substitution(backend, polys, found, strip=len(remaining) > 1, request=request))
            remaining.remove(found.var)
            continue
        # after a multiplier held a kept variable, the axis' closing Cramer step brings in only
        # its factors, which trial division removes, where a resultant brings mismatched roots
        reduced = None if not closing and _one_resultant_left(backend, polys, remaining) else \
            _radical_axes(backend, polys, remaining, allowed)
        after = _linear_unknown(backend, reduced.left, remaining, allowed) if reduced is not None else None
        if reduced is not None and after is not None:
            outcome, ahead = outcome.then(reduced), (reduced.left, list(remaining), after)
            continue
        # an axis no unknown can be substituted from only reshuffles the resultants
        step, done = _by_resultants(backend, polys, remaining, request)
        outcome = outcome.then(step)
        remaining = [v for v in remaining if v not in done]


def _same(these: Sequence[P], those: Sequence[P]) -> bool:
    """Whether two lists hold the same polynomials (the same objects), in the same order."""
    return len(these) == len(those) and all(a is b for a, b in zip(these, those))


def _one_resultant_left(backend: Backend[P], polys: Sequence[P], remaining: Sequence[str]) -> bool:
    """Whether one unknown is left, held by two equations: their resultant, one call, is the
    eliminant the axis and its substitution would build in several (the seed's two circles)."""
    return len(remaining) == 1 and sum(1 for p in polys if backend.degree(p, remaining[0])) == 2


def _by_resultants(backend: Backend[P], polys: list[P], remaining: Sequence[str], request: EliminationRequest
                   ) -> tuple[MethodOutcome[P], list[str]]:
    """One resultant, on the cheapest unknown: with fewer unknowns left, a linear step may
    apply again (on the six-bars, the closing Cramer step, which brings in no mismatched
    roots the way a second resultant does). The step, and the unknowns it eliminated."""
    var = cheapest(backend, polys, remaining)
    return resultant_step(backend, polys, var, request=request, last=len(remaining) == 1), [var]


@attrs.frozen
class _Linear(Generic[P]):
    """An equation ``pivot = coefficient * var + rest`` linear in the unknown ``var``."""

    pivot: P
    var: str
    coefficient: P


def _linear_unknown(backend: Backend[P], polys: Sequence[P], remaining: Sequence[str], allowed: set[str]
                    ) -> _Linear[P] | None:
    """The simplest equation linear in an unknown whose coefficient holds only ``allowed``
    variables, or None."""
    best: tuple[tuple[bool, int, int], P, str, P] | None = None
    for var in remaining:
        for poly in polys:
            if backend.degree(poly, var) != 1:
                continue
            coefficient = backend.derivative(poly, var)
            held = backend.variables(coefficient)
            if not held <= allowed:
                continue
            # a number first (no extraneous factor), then the smallest coefficient
            key = (bool(held), backend.nterms(coefficient), backend.nterms(poly))
            if best is None or key < best[0]:
                best = (key, poly, var, coefficient)
    if best is None:
        return None
    _, poly, var, coefficient = best
    return _Linear(poly, var, coefficient)


def _substitution(backend: Backend[P], polys: list[P], found: _Linear[P], *, strip: bool,
                  request: EliminationRequest) -> MethodOutcome[P]:
    """The step substituting the unknown of ``found`` (``_linear_unknown``) out of ``polys``;
    its coefficient is a multiplier if it holds a variable."""
    var, coefficient = found.var, found.coefficient
    polys, stripped = _substitute(backend, polys, found, strip=strip)
    request.deadline.check_terms(max(map(backend.nterms, polys), default=0), f"an equation after substituting {var}")
    multipliers = [] if backend.is_constant(coefficient) else [coefficient]
    # a stripped equation is no longer in the ideal (only in its saturation by the multiplier)
    log: list[LogEntry] = [("substituted", var)]
    if stripped:
        log.append(("stripped", var))
    return MethodOutcome(polys, log=log, multipliers=multipliers)


def _substitute(backend: Backend[P], polys: Sequence[P], found: _Linear[P], *, strip: bool) -> tuple[list[P], bool]:
    """``a**k f(-rest/a)`` for every other equation ``f`` of degree ``k`` in ``var`` (``found``'s
    unknown, ``a`` its coefficient), with the factors it shares with ``a`` stripped (if ``strip``);
    and whether any was.

    ``a**k f(-rest/a)`` is the resultant in ``var`` of the pivot ``a*var + rest`` and ``f`` (the
    pivot's leading coefficient to the power ``k``, times ``f`` at its one root): one call in C,
    where splitting ``f`` by powers of ``var`` and summing took a dozen."""
    pivot, var, coefficient = found.pivot, found.var, found.coefficient
    pieces = backend.factors(coefficient) if strip and not backend.is_constant(coefficient) else []
    out: list[P] = []
    stripped = False
    for poly in polys:
        if poly is pivot:
            continue
        if not backend.degree(poly, var):
            out.append(poly)
            continue
        total = backend.resultant(pivot, poly, var)
        out.append(_strip(backend, total, pieces))
        stripped = stripped or out[-1] is not total
    return out, stripped


def _strip(backend: Backend[P], poly: P, pieces: Sequence[P]) -> P:
    """``poly`` without the irreducible factors ``pieces`` of the multiplier, by trial division."""
    for piece in pieces:
        quotient = backend.quotient(poly, piece) if not backend.is_zero(poly) else None
        while quotient is not None:
            poly, quotient = quotient, backend.quotient(quotient, piece)
    return poly


def _radical_axes(backend: Backend[P], polys: Sequence[P], remaining: Sequence[str], allowed: set[str]
                  ) -> MethodOutcome[P] | None:
    """Fraction-free row reduction on the quadratic monomials in the unknowns: the step (how many
    equations became linear, and the multipliers of the rows), or None if none became linear."""
    shared = _shared_quadratic_part(backend, polys, remaining)
    if shared is not None:
        return shared
    rows: list[dict[tuple[int, ...], P]] = []
    others: list[P] = []
    for poly in polys:
        # only a quadratic in the unknowns can become an axis: one of higher degree in any
        # unknown is passed over without splitting it
        parts = backend.split(poly, remaining) if all(backend.degree(poly, v) <= 2 for v in remaining) else None
        if parts is not None and max(sum(e) for e in parts) == 2:
            rows.append(parts)
        else:
            others.append(poly)
    if len(rows) < 2:
        return None
    columns = sorted({e for parts in rows for e in parts if sum(e) == 2}, reverse=True)
    pivots: set[int] = set()
    used: list[P] = []
    for column in columns:
        candidates = [i for i, parts in enumerate(rows) if i not in pivots and column in parts
                      and backend.variables(parts[column]) <= allowed]
        if not candidates:
            continue
        p = min(candidates, key=lambda i: (not backend.is_constant(rows[i][column]), backend.nterms(rows[i][column])))
        pivots.add(p)
        for i in candidates:
            if i != p:
                rows[i], multiplier = _combine(backend, rows[p], rows[i], column)
                if not backend.is_constant(multiplier):
                    used.append(multiplier)
    linear = [i for i, parts in enumerate(rows) if i not in pivots and parts
              and max(sum(e) for e in parts) == 1]
    if not linear:
        return None
    return MethodOutcome(others + [backend.join(parts, remaining) for parts in rows if parts],
                         log=[("radical-axis", len(linear))], multipliers=used)


def _combine(backend: Backend[P], pivot: dict[tuple[int, ...], P], row: dict[tuple[int, ...], P],
             column: tuple[int, ...]) -> tuple[dict[tuple[int, ...], P], P]:
    """``a*row - b*pivot`` with the ``column`` coefficient cancelled (``a``, ``b`` over their gcd),
    and ``a``, the row's multiplier."""
    a, b = pivot[column], row[column]
    common = backend.gcd(a, b)
    a, b = backend.divide(a, common), backend.divide(b, common)
    out: dict[tuple[int, ...], P] = {}
    for exponent in set(pivot) | set(row):
        value = a * row.get(exponent, backend.zero()) - b * pivot.get(exponent, backend.zero())
        if not backend.is_zero(value):
            out[exponent] = value
    return out, a


def _shared_quadratic_part(backend: Backend[P], polys: Sequence[P], remaining: Sequence[str]
                           ) -> MethodOutcome[P] | None:
    """The row reduction's answer at the cost of subtractions, when the quadratics share their
    quadratic part exactly (circles as a scene writes them, ``|X - C|**2 - r**2``, all do):
    each less the first is linear in the unknowns, its axis, with no multiplier. None when
    no difference is linear."""
    unknowns = set(remaining)
    quadratics = [p for p in polys if max(backend.degree(p, v) for v in remaining) == 2]
    axes = {}
    for poly in quadratics[1:]:
        difference = poly - quadratics[0]
        held = [v for v in remaining if backend.degree(difference, v)] if not backend.is_zero(difference) else []
        if held and all(backend.degree(difference, v) == 1 and
                        not backend.variables(backend.derivative(difference, v)) & unknowns for v in held):
            axes[id(poly)] = difference
    if not axes:
        return None
    return MethodOutcome([axes.get(id(p), p) for p in polys], log=[("radical-axis", len(axes))])
