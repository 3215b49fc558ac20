"""Elimination methods: chains of resultants, and lex Gröbner bases.

Both run on any backend of ``backends.BACKENDS`` and share the same preparation
(substituting variables defined linearly, dropping equations that alone hold a variable
to eliminate) and the same factor selection at witnesses.
"""

from collections.abc import Sequence

import flint

from ..errors import ComputationError
from .protocol import Backend, P
from .request import EliminationRequest, LogEntry, MethodOutcome
from .select import WitnessGroups, select_factors

__all__ = ["prepare", "cheapest", "resultant_step", "resultant_chain", "groebner_basis"]


def _linear_definition(backend: Backend[P], poly: P, var: str) -> P | None:
    """``value`` with ``var = value`` if ``poly`` is ``k*var + rest`` (k a number), else None."""
    if backend.degree(poly, var) != 1:
        return None
    slope = backend.derivative(poly, var)
    if not backend.is_constant(slope):
        return None
    # divided by the number k in C, not scaled by its numerator and denominator read off its terms
    return -backend.divide(backend.specialize(poly, {var: flint.fmpq(0)}), slope)


def prepare(backend: Backend[P], polys: list[P], eliminate: Sequence[str]) -> MethodOutcome[P]:
    """Substitute linearly defined variables; drop equations alone in holding a variable."""
    polys = [p for p in polys if not backend.is_zero(p)]
    log: list[LogEntry] = []
    held = [backend.variables(p) for p in polys]  # read once per change: a degree is a call each
    changed = True
    while changed:
        changed = False
        for var in eliminate:
            holders = [k for k, names in enumerate(held) if var in names]
            if len(holders) == 1:
                del polys[holders[0]], held[holders[0]]
                log.append(("dropped-alone", var))
                changed = True
                continue
            for k in holders:
                value = _linear_definition(backend, polys[k], var)
                if value is not None:
                    polys = [backend.substitute(p, var, value) if var in names else p
                             for j, (p, names) in enumerate(zip(polys, held)) if j != k]
                    held = [backend.variables(p) for p in polys]
                    log.append(("substituted", var))
                    changed = True
                    break
    return MethodOutcome(polys, log=log)


def _squarefree_kept(backend: Backend[P], poly: P, witnesses: WitnessGroups) -> tuple[P, list[P]]:
    """The product of the factors of ``poly`` the witnesses keep, and the factors dropped."""
    factors = [poly] if backend.irreducibility(poly) else backend.factors(poly)
    if len(factors) == 1:  # nothing to choose; the final eliminant's check answers for it
        return factors[0], []
    kept, lost = select_factors(backend, factors, witnesses, check=False)
    if not kept:
        raise ComputationError("every factor of an intermediate resultant was dropped")
    product = kept[0]
    for factor in kept[1:]:
        product = product * factor
    return product, lost


def cheapest(backend: Backend[P], polys: Sequence[P], remaining: Sequence[str]) -> str:
    """The unknown held by the fewest equations, then of the least degree in them."""
    if len(remaining) == 1:
        return remaining[0]

    def cost(var: str) -> tuple[int, int]:
        holders = [p for p in polys if backend.degree(p, var)]
        return (len(holders), min((backend.degree(p, var) for p in holders), default=0))

    return min(remaining, key=cost)


def resultant_step(backend: Backend[P], polys: list[P], var: str, *, request: EliminationRequest,
                   last: bool = False) -> MethodOutcome[P]:
    """``polys`` with ``var`` eliminated: resultants of its holders against the one of least
    degree in it, each factored and cut to the factors the witnesses satisfy, unless it is the
    ``last`` step: the eliminant is factored and cut once, at the end, not twice."""
    degrees = [backend.degree(p, var) for p in polys]
    holders = [p for p, degree in zip(polys, degrees) if degree]
    others = [p for p, degree in zip(polys, degrees) if not degree]
    if len(holders) <= 1:
        return MethodOutcome(others)
    # the least degree, then the fewest terms, then the first
    pivot = polys[min((d, backend.nterms(p), k) for k, (p, d) in enumerate(zip(polys, degrees)) if d)[2]]
    dropped: list[P] = []
    for poly in holders:
        if poly is pivot:
            continue
        result = backend.resultant(pivot, poly, var)
        if backend.is_zero(result):
            raise ComputationError(f"resultant in {var} vanished: the equations share a factor")
        if backend.is_constant(result):
            raise ComputationError(f"resultant in {var} is a non-zero constant: the system is inconsistent")
        request.deadline.check_terms(backend.nterms(result), f"the resultant in {var}")
        if last:
            others.append(result)
            continue
        kept, lost = _squarefree_kept(backend, result, request.witnesses)
        others.append(kept)
        dropped.extend(lost)
    return MethodOutcome(others, dropped, [("resultant", var)])


def resultant_chain(backend: Backend[P], polys: list[P], request: EliminationRequest) -> MethodOutcome[P]:
    """Eliminate one variable at a time by Sylvester resultants against a pivot."""
    outcome = MethodOutcome(polys)
    remaining = list(request.eliminate)
    while remaining:
        var = cheapest(backend, outcome.left, remaining)
        remaining.remove(var)
        outcome = outcome.then(resultant_step(backend, outcome.left, var, request=request, last=not remaining))
    return outcome


def groebner_basis(backend: Backend[P], polys: list[P], request: EliminationRequest) -> MethodOutcome[P]:
    """The elimination ideal's generators from a lex basis, eliminated variables first."""
    keep = [n for n in backend.names if n not in request.eliminate]
    order = list(request.eliminate) + keep
    basis = backend.groebner_lex(polys, order)
    for element in basis:  # the basis is one call: its size is checked once it is there
        request.deadline.check_terms(backend.nterms(element), "an element of the Gröbner basis")
    left = [g for g in basis if not (backend.variables(g) & set(request.eliminate))]
    return MethodOutcome(left, log=[("groebner", len(basis))])
