"""Keep the factors the true motion satisfies, decided by ball arithmetic at witnesses.

A *witness* is a configuration of the mechanism (every variable's value as a python-flint
``arb`` ball); witnesses come in groups, one group per branch. A factor is kept when its
ball contains zero at every witness of some group, and dropped when that fails: at some
witness of every group its ball excludes zero, which proves it non-zero there.

Each factor is evaluated at the witnesses' own precision plus its coefficients' bits and
its degree times the witnesses' magnitude, not at python-flint's default of 53 bits: at 53
bits a degree-30 factor with 160-bit coefficients gives a ball of width 1e38 around every
value, and would be kept for "containing" zero.

>>> import flint
>>> point = {"x": flint.arb(2).sqrt(), "y": flint.arb(3)}
>>> evaluator = Evaluator([((2, 0), 1, 1), ((0, 0), -2, 1)], ("x", "y"), 128)  # x**2 - 2
>>> evaluator.bits  # 128, + 3 for the coefficient -2/1 (2 + 1 bits), + 2 for degree 2 times 1 bit
133
>>> evaluator(point).contains(0), Evaluator([((0, 1), 1, 1)], ("x", "y"), 128)(point).contains(0)
(True, False)
"""

import math

import flint

from ..errors import ComputationError

__all__ = ["Evaluator", "select_factors"]

MARGIN_BITS = 64


class Evaluator:
    """The ball value of one polynomial, given by its ``terms`` (exponents, numerator,
    denominator) over ``names``, at ``base_bits`` of precision plus its coefficients' bits
    plus its degree times ``magnitude_bits`` (the witnesses' size).

    Coefficients are made balls once, and each term keeps only its non-zero exponents:
    mechanism polynomials are sparse, and most of a dense loop would multiply by one.
    """

    def __init__(self, terms, names, base_bits, magnitude_bits=1):
        self.names = names
        self.sparse = [[(i, e) for i, e in enumerate(exponents) if e] for exponents, _, _ in terms]
        degree = max((sum(e for _, e in exponents) for exponents in self.sparse), default=0)
        coefficient_bits = max((p.bit_length() + q.bit_length() for _, p, q in terms), default=0)
        self.bits = base_bits + coefficient_bits + degree * magnitude_bits
        highest = {}
        for exponents in self.sparse:
            for i, e in exponents:
                highest[i] = max(e, highest.get(i, 0))
        self.used = sorted(highest.items())
        with flint.ctx.workprec(self.bits):
            self.coefficients = [flint.arb(p) / q if q != 1 else flint.arb(p) for _, p, q in terms]

    def __call__(self, point):
        with flint.ctx.workprec(self.bits):
            powers = {}
            for i, degree in self.used:
                value, table = point[self.names[i]], [flint.arb(1)]
                for _ in range(degree):
                    table.append(table[-1] * value)
                powers[i] = table
            total = flint.arb(0)
            for coefficient, exponents in zip(self.coefficients, self.sparse):
                for i, e in exponents:
                    coefficient = coefficient * powers[i][e]
                total += coefficient
            return total


def select_factors(backend, factors, witness_groups, check=True):
    """Split ``factors`` into (kept, dropped) by the witnesses; keep all without witnesses.

    With ``check``, every witness must also have a kept factor vanishing there (else a
    ComputationError: the eliminant does not describe the motion). Intermediate eliminants
    skip it; the final one answers for them.
    """
    groups = [g for g in witness_groups if g]
    if not groups:
        return list(factors), []
    values = [v for group in groups for point in group for v in point.values()]
    witness_bits = max(_bits(v) for v in values)
    magnitude_bits = max(1, math.ceil(math.log2(1 + max(float(abs(v).mid()) for v in values))))
    # enough for the factor's own coefficients and powers on top of the witnesses' precision
    evaluators = [Evaluator(backend.terms(f), backend.names, MARGIN_BITS + witness_bits, magnitude_bits)
                  for f in factors]
    return _select(factors, groups, evaluators, check)


def _bits(ball):
    """Bits of the ball's midpoint mantissa: the precision it was computed at."""
    return int(ball.mid().man_exp()[0]).bit_length() if ball.mid() != 0 else 0


def _select(factors, groups, evaluators, check):
    known = {}

    def vanishes(i, g, w):
        if (i, g, w) not in known:
            known[i, g, w] = evaluators[i](groups[g][w]).contains(0)
        return known[i, g, w]

    kept, dropped = [], []
    for i, factor in enumerate(factors):
        if any(all(vanishes(i, g, w) for w in range(len(group))) for g, group in enumerate(groups)):
            kept.append(i)
        else:
            dropped.append(factor)
    for g, group in enumerate(groups) if check else ():
        for w in range(len(group)):
            if not any(vanishes(i, g, w) for i in kept):
                raise ComputationError("no kept factor vanishes at a witness configuration: "
                                       "the eliminant does not describe the motion")
    return [factors[i] for i in kept], dropped
