import math
from fractions import Fraction

import pytest
from hypothesis import given, strategies as st

from algkin.system.between import simplest_between

# Any finite float, tiny to huge, of either sign
FLOATS = st.floats(allow_nan=False, allow_infinity=False)
DENOMINATORS = 300  # the brute force's reach


# Simple fractions as floats: ends near the small denominators the brute force reaches
SIMPLE = st.fractions(min_value=-100, max_value=100, max_denominator=40).map(float)


@st.composite
def intervals(draw):
    """(lo, hi), lo < hi, an end None at times; hi at times a few floats past lo (the tightest gaps)."""
    ends = draw(st.sampled_from([FLOATS, SIMPLE]))
    lo = draw(ends)
    if draw(st.booleans()):
        hi = lo
        for _ in range(draw(st.integers(1, 4))):
            hi = math.nextafter(hi, math.inf)
    else:
        hi = draw(ends)
    lo, hi = sorted((lo, hi))
    if lo == hi or math.isinf(hi):
        hi = None
    return (None if draw(st.integers(0, 5)) == 0 else lo), (None if draw(st.integers(0, 5)) == 0 else hi)


def _inside(q, lo, hi):
    return (lo is None or Fraction(lo) < q) and (hi is None or q < Fraction(hi))


def _nonzero_of_denominator(q, lo, hi):
    """The nonzero fractions p/q in (lo, hi) nearest 0 on each side, by counting numerators."""
    first_positive = 1 if lo is None else max(1, math.floor(Fraction(lo) * q) + 1)
    first_negative = -1 if hi is None else min(-1, math.ceil(Fraction(hi) * q) - 1)
    return [f for f in (Fraction(first_positive, q), Fraction(first_negative, q)) if _inside(f, lo, hi)]


def _brute_force(lo, hi):
    """The nonzero fraction of smallest denominator up to ``DENOMINATORS`` in (lo, hi), then of
    smallest magnitude, the positive first; None if no denominator that small has one."""
    for q in range(1, DENOMINATORS + 1):
        found = _nonzero_of_denominator(q, lo, hi)
        if found:
            return min(found, key=lambda f: (abs(f), f < 0))
    return None


@given(intervals())
def test_strictly_inside_and_the_simplest_nonzero_by_brute_force(interval):
    lo, hi = interval
    result = simplest_between(lo, hi)
    assert isinstance(result, Fraction) and result != 0 and _inside(result, lo, hi)
    expected = _brute_force(lo, hi)
    if expected is None:
        assert result.denominator > DENOMINATORS
    else:
        assert result == expected


@pytest.mark.parametrize(("lo", "hi"), [
    (0.5, 0.500000001),  # cuts 1e-9 apart: extremum's sample was 1/2, on the lower end
    (0.1, 0.1 + 1e-7),  # its sample 1/10, below the float 0.1: outside
    (1e-7, 2e-7),  # its sample 0: outside
    (2.0, 2.0000001),  # its sample 2: on the end
    (1e308, None),  # an unbounded region past a huge cut: an overflow to infinity, an internal error
    (None, -1e308),
    (-1.7976931348623157e308, 1.7976931348623157e308),
])
def test_close_or_huge_cuts_give_a_sample_strictly_inside(lo, hi):
    assert _inside(simplest_between(lo, hi), lo, hi)


def test_simple_values_by_hand():
    # the floats 0.1 and 0.2 are a little above 1/10 and 1/5
    assert simplest_between(0.1, 0.2) == Fraction(1, 5)
    assert simplest_between(0.25, 0.3) == Fraction(2, 7)  # 1/4 on the end; 2/7 = 0.2857...
    assert simplest_between(3.0, None) == 4 and simplest_between(None, -2.5) == -3
    assert simplest_between(None, None) == 1  # not 0: the positive side on a tie
    assert simplest_between(-2.0, 0.4) == -1  # -1 beats the positive side's 1/3


def test_an_empty_interval_is_refused():
    with pytest.raises(ValueError, match="empty"):
        simplest_between(1.0, 1.0)
