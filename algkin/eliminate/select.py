"""Keep the factors the true motion satisfies, decided by ball arithmetic at witnesses.

A *witness* is a configuration of the mechanism (every variable's value as a python-flint
``arb`` ball); witnesses come in groups, one group per branch. A factor is kept when its
ball contains zero at every witness of some group, and dropped when that fails: at some
witness of every group its ball excludes zero, which proves it non-zero there.

Each factor is evaluated at the witnesses' own precision plus its coefficients' bits and
its degree times the witnesses' magnitude, not at python-flint's default of 53 bits: at 53
bits a degree-30 factor with 160-bit coefficients gives a ball of width 1e38 around every
value, and would be kept for "containing" zero.
"""

import functools
import math

import flint

from ..errors import ComputationError

__all__ = ["evaluate_terms", "select_factors"]

MARGIN_BITS = 64


def evaluate_terms(terms, names, point, degrees):
    """Ball value of the polynomial with ``terms`` (its ``degrees`` per variable) at ``point``
    (name -> arb); each variable's powers are taken once."""
    values = [point[n] for n in names]
    powers = [_powers(v, int(d)) for v, d in zip(values, degrees)]
    total = flint.arb(0)
    for exponents, numerator, denominator in terms:
        term = flint.arb(numerator) / denominator
        for table, e in zip(powers, exponents):
            if e:
                term *= table[e]
        total += term
    return total


def _powers(value, degree):
    table = [flint.arb(1)]
    for _ in range(degree):
        table.append(table[-1] * value)
    return table


def select_factors(backend, factors, witness_groups):
    """Split ``factors`` into (kept, dropped) by the witnesses; keep all without witnesses."""
    groups = [g for g in witness_groups if g]
    if not groups:
        return list(factors), []
    values = [v for group in groups for point in group for v in point.values()]
    witness_bits = max(_bits(v) for v in values)
    magnitude_bits = max(1, math.ceil(math.log2(1 + max(float(abs(v).mid()) for v in values))))
    # enough for the factor's own coefficients and powers on top of the witnesses' precision
    bits = [MARGIN_BITS + witness_bits + backend.coefficient_bits(f) + backend.total_degree(f) * magnitude_bits
            for f in factors]
    return _select(backend, factors, groups, bits)


def _bits(ball):
    """Bits of the ball's midpoint mantissa: the precision it was computed at."""
    return int(ball.mid().man_exp()[0]).bit_length() if ball.mid() != 0 else 0


def _select(backend, factors, groups, bits):
    tests = [backend.vanishes(f) for f in factors]

    @functools.cache
    def vanishes(i, g, w):
        with flint.ctx.workprec(bits[i]):
            return tests[i](groups[g][w])

    kept, dropped = [], []
    for i, factor in enumerate(factors):
        if any(all(vanishes(i, g, w) for w in range(len(group))) for g, group in enumerate(groups)):
            kept.append(i)
        else:
            dropped.append(factor)
    for g, group in enumerate(groups):
        for w in range(len(group)):
            if not any(vanishes(i, g, w) for i in kept):
                raise ComputationError("no kept factor vanishes at a witness configuration: "
                                       "the eliminant does not describe the motion")
    return [factors[i] for i in kept], dropped
