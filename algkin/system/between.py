"""The simplest rational strictly inside an open interval, exact.

>>> simplest_between(0.1, 0.2)  # the float 0.2 is a little above 1/5
Fraction(1, 5)
>>> simplest_between(0.1, 0.125)
Fraction(1, 9)
>>> simplest_between(None, -2.5)
Fraction(-3, 1)
>>> simplest_between(-1.0, 3.0)  # never 0
Fraction(1, 1)
>>> simplest_between(-1.0, 0.4)
Fraction(-1, 2)
"""

from __future__ import annotations

import math
from fractions import Fraction

__all__ = ["simplest_between"]

End = float | Fraction | None
"""An interval's end, a float read as its exact binary value; None: unbounded."""


def simplest_between(lo: End, hi: End) -> Fraction:
    """The rational of smallest denominator, then of smallest magnitude, strictly between ``lo``
    and ``hi`` (``lo < hi``; None: infinity). Never 0, where a dimension degenerates (a crank of
    length 0 moves nothing): around 0, the simpler of the simplest on each side, the positive on a tie."""
    low, high = _exact(lo), _exact(hi)
    if low is not None and high is not None and not low < high:
        raise ValueError(f"an empty interval ({lo}, {hi})")
    if (low is None or low < 0) and (high is None or high > 0):
        sides = (_simplest_above(Fraction(0), high), -_simplest_above(Fraction(0), _negated(low)))
        return min(sides, key=lambda q: (q.denominator, abs(q), q < 0))
    if high is not None and high <= 0:
        return -_simplest_above(-high, _negated(low))
    assert low is not None  # 0 <= low here
    return _simplest_above(low, high)


def _exact(end: End) -> Fraction | None:
    if end is None:
        return None
    if isinstance(end, float) and not math.isfinite(end):
        raise ValueError(f"an interval's end is not finite: {end}")
    return Fraction(end)


def _negated(end: Fraction | None) -> Fraction | None:
    return None if end is None else -end


def _simplest_above(low: Fraction, high: Fraction | None) -> Fraction:
    """The simplest rational in (low, high), 0 <= low < high (None: infinity), by continued fractions:
    the smallest integer past ``low`` if one is inside, else its integer part plus the reciprocal of
    the simplest in the reciprocal interval. A loop: two floats' shared terms can outnumber the
    recursion limit."""
    terms: list[int] = []
    while True:
        whole = math.floor(low)
        if high is None or whole + 1 < high:
            terms.append(whole + 1)
            break
        terms.append(whole)
        rest = low - whole
        low, high = 1 / (high - whole), (None if rest == 0 else 1 / rest)
    value = Fraction(terms.pop())
    for term in reversed(terms):
        value = term + 1 / value
    return value
