"""Elimination methods: chains of resultants, and lex Gröbner bases.

Both run on any backend of ``backends.BACKENDS`` and share the same preparation
(substituting variables defined linearly, dropping equations that alone hold a variable
to eliminate) and the same factor selection at witnesses.
"""

from ..errors import ComputationError
from ..runtime.budget import current
from .select import select_factors

__all__ = ["prepare", "cheapest", "resultant_step", "resultant_chain", "groebner_basis"]


def _linear_definition(backend, poly, var):
    """``value`` with ``var = value`` if ``poly`` is ``k*var + rest`` (k a number), else None."""
    if backend.degree(poly, var) != 1:
        return None
    slope = backend.derivative(poly, var)
    if not backend.is_constant(slope):
        return None
    (_, numerator, denominator), = backend.terms(slope)
    return backend.scale(backend.substitute(poly, var, backend.zero()), -denominator, numerator)


def prepare(backend, polys, eliminate, log):
    """Substitute linearly defined variables; drop equations alone in holding a variable."""
    polys = [p for p in polys if not backend.is_zero(p)]
    changed = True
    while changed:
        changed = False
        for var in eliminate:
            holders = [p for p in polys if backend.degree(p, var)]
            if len(holders) == 1:
                polys.remove(holders[0])
                log.append(("dropped-alone", var))
                changed = True
                continue
            for poly in holders:
                value = _linear_definition(backend, poly, var)
                if value is not None:
                    polys = [backend.substitute(p, var, value) for p in polys if p is not poly]
                    log.append(("substituted", var))
                    changed = True
                    break
    return polys


def _squarefree_kept(backend, poly, witnesses, dropped):
    factors = backend.factors(poly)
    if len(factors) == 1:  # nothing to choose; the final eliminant's check answers for it
        return factors[0]
    kept, lost = select_factors(backend, factors, witnesses, check=False)
    dropped.extend(lost)
    if not kept:
        raise ComputationError("every factor of an intermediate resultant was dropped")
    product = kept[0]
    for factor in kept[1:]:
        product = product * factor
    return product


def cheapest(backend, polys, remaining):
    """The unknown held by the fewest equations, then of the least degree in them."""
    def cost(var):
        holders = [p for p in polys if backend.degree(p, var)]
        return (len(holders), min((backend.degree(p, var) for p in holders), default=0))

    return min(remaining, key=cost)


def resultant_step(backend, polys, var, witnesses, dropped, log, budget=None):
    """``polys`` with ``var`` eliminated: resultants of its holders against the one of least
    degree in it, each factored and cut to the factors the witnesses satisfy."""
    holders = [p for p in polys if backend.degree(p, var)]
    others = [p for p in polys if not backend.degree(p, var)]
    if len(holders) <= 1:
        return others
    pivot = min(holders, key=lambda p: (backend.degree(p, var), backend.nterms(p)))
    for poly in holders:
        if poly is pivot:
            continue
        result = backend.resultant(pivot, poly, var)
        if backend.is_zero(result):
            raise ComputationError(f"resultant in {var} vanished: the equations share a factor")
        if backend.is_constant(result):
            raise ComputationError(f"resultant in {var} is a non-zero constant: the system is inconsistent")
        (budget or current()).check_terms(backend.nterms(result), f"the resultant in {var}")
        others.append(_squarefree_kept(backend, result, witnesses, dropped))
    log.append(("resultant", var))
    return others


def resultant_chain(backend, polys, eliminate, witnesses, dropped, log, parameters=(), budget=None, multipliers=None):
    """Eliminate one variable at a time by Sylvester resultants against a pivot."""
    remaining = list(eliminate)
    while remaining:
        var = cheapest(backend, polys, remaining)
        remaining.remove(var)
        polys = resultant_step(backend, polys, var, witnesses, dropped, log, budget)
    return polys


def groebner_basis(backend, polys, eliminate, witnesses, dropped, log, parameters=(), budget=None, multipliers=None):
    """The elimination ideal's generators from a lex basis, eliminated variables first."""
    keep = [n for n in backend.names if n not in eliminate]
    order = [n for n in eliminate] + keep
    basis = backend.groebner_lex(polys, order)
    log.append(("groebner", len(basis)))
    for element in basis:  # the basis is one call: its size is checked once it is there
        (budget or current()).check_terms(backend.nterms(element), "an element of the Gröbner basis")
    return [g for g in basis if not (backend.variables(g) & set(eliminate))]

