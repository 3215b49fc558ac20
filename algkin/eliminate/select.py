"""Keep the factors the true motion satisfies, decided by ball arithmetic at witnesses.

A *witness* is a configuration of the mechanism (every variable's value as a python-flint
``arb`` ball); witnesses come in groups, one group per branch. A factor is kept when its
ball contains zero at every witness of some group, and dropped when that fails: at some
witness of every group its ball excludes zero, which proves it non-zero there.
"""

import flint

from ..errors import ComputationError

__all__ = ["evaluate_terms", "select_factors"]


def evaluate_terms(terms, names, point):
    """Ball value of the polynomial with ``terms`` at ``point`` (name -> arb)."""
    values = [point[n] for n in names]
    total = flint.arb(0)
    for exponents, numerator, denominator in terms:
        term = flint.arb(numerator) / denominator
        for value, e in zip(values, exponents):
            if e:
                term *= value**e
        total += term
    return total


def _vanishes(backend, poly, point):
    return evaluate_terms(backend.terms(poly), backend.names, point).contains(0)


def select_factors(backend, factors, witness_groups):
    """Split ``factors`` into (kept, dropped) by the witnesses; keep all without witnesses."""
    groups = [g for g in witness_groups if g]
    if not groups:
        return list(factors), []
    kept, dropped = [], []
    for factor in factors:
        if any(all(_vanishes(backend, factor, w) for w in group) for group in groups):
            kept.append(factor)
        else:
            dropped.append(factor)
    for group in groups:
        for witness in group:
            if not any(_vanishes(backend, f, witness) for f in kept):
                raise ComputationError("no kept factor vanishes at a witness configuration: "
                                       "the eliminant does not describe the motion")
    return kept, dropped
