"""Real roots: every expected value from an independent source (roots known by hand, Chebyshev
nodes ``cos((2k - 1) pi / 2n)``, square roots by arb's ``sqrt``), never from the module's output."""

from fractions import Fraction
from math import prod

import attrs
import flint
import pytest
from hypothesis import given, settings, strategies as st

from algkin.errors import ComputationError, UsageError
from algkin.system.roots import RealRoot, isolates, quadratic_roots, real_roots, refined_together

X = flint.fmpz_poly([0, 1])


def linear(value: Fraction) -> flint.fmpz_poly:
    """``q x - p`` for ``value = p/q``: the root ``value`` exactly."""
    return flint.fmpz_poly([-value.numerator, value.denominator])


def fmpq(value: Fraction) -> flint.fmpq:
    return flint.fmpq(value.numerator, value.denominator)


def chebyshev(n: int) -> flint.fmpz_poly:
    """``T_n`` by its recurrence ``T_{n+1} = 2x T_n - T_{n-1}``."""
    previous, current = flint.fmpz_poly([1]), X
    for _ in range(n - 1):
        previous, current = current, 2 * X * current - previous
    return current


def test_square_root_of_two_both_signs_in_exact_brackets():
    minus, plus = real_roots(X**2 - 2)
    assert plus.ball.overlaps(flint.arb(2).sqrt()) and minus.ball.overlaps(-flint.arb(2).sqrt())
    lo, hi = plus.interval()
    assert 0 < lo and lo * lo < 2 < hi * hi  # exact rationals around sqrt(2)
    assert (minus.index, plus.index, plus.multiplicity, plus.degree) == (0, 1, 1, 2)
    assert plus.factor == X**2 - 2 and plus.exact() is None


@pytest.mark.parametrize("n", [1, 2, 7, 12, 25])
def test_chebyshev_roots_are_its_nodes(n):
    roots = real_roots(chebyshev(n), bits=100)
    with flint.ctx.workprec(200):
        nodes = sorted((((2 * k - 1) * flint.arb.pi() / (2 * n)).cos() for k in range(1, n + 1)),
                       key=lambda b: float(b.mid()))
    assert len(roots) == n
    assert all(r.ball.overlaps(node) for r, node in zip(roots, nodes))
    assert all(r.ball.rad() < 1e-25 for r in roots)


def test_wilkinson_roots_are_the_integers_exactly():
    roots = real_roots(prod((X - k for k in range(1, 21)), start=flint.fmpz_poly([1])))
    assert [r.exact() for r in roots] == list(range(1, 21))
    assert all(r.multiplicity == 1 and r.degree == 1 for r in roots)


def test_roots_1e_minus_40_apart_are_separated_in_order():
    # sqrt(2) and sqrt(2 + 1e-40): 3.5e-41 apart, far below the 53 bits the balls start at
    near = flint.fmpz_poly([-(2 * 10**40 + 1), 0, 10**40])
    roots = real_roots((X**2 - 2) * near)
    assert len(roots) == 4
    assert [r.factor for r in roots[2:]] == [X**2 - 2, near]
    assert roots[2].interval()[1] < roots[3].interval()[0]  # disjoint, ascending, exactly
    assert all(not a.ball.overlaps(b.ball) for a, b in zip(roots, roots[1:]))


def test_rational_roots_1e_minus_30_apart_are_told_apart():
    big = 10**30
    one, next_one = real_roots((X - 1) * flint.fmpz_poly([-(big + 1), big]))
    assert one.exact() == 1 and next_one.exact() == flint.fmpq(big + 1, big)


def test_a_double_and_a_triple_root_carry_their_multiplicity():
    roots = real_roots((X - 1)**2 * (X + 2) * (X**2 - 2)**3)
    with flint.ctx.workprec(100):
        root2 = flint.arb(2).sqrt()
    assert [(r.multiplicity, r.degree) for r in roots] == [(1, 1), (3, 2), (2, 1), (3, 2)]
    assert roots[0].exact() == -2 and roots[2].exact() == 1
    assert roots[1].ball.overlaps(-root2) and roots[3].ball.overlaps(root2)


def test_huge_coefficients():
    roots = real_roots(flint.fmpz_poly([-3, 10**50]) * (X - 10**40))
    assert [r.exact() for r in roots] == [flint.fmpq(3, 10**50), 10**40]
    minus, plus = real_roots(X**2 - 10**101)
    with flint.ctx.workprec(200):
        expected = flint.arb(10)**50 * flint.arb(10).sqrt()
    assert plus.ball.overlaps(expected) and minus.ball.overlaps(-expected)


def test_rational_coefficients_same_roots_as_cleared():
    half = flint.fmpq_poly([flint.fmpq(-1, 4), 0, 1])  # x**2 - 1/4
    assert [r.exact() for r in real_roots(half)] == [flint.fmpq(-1, 2), flint.fmpq(1, 2)]


def test_no_real_root_and_constants():
    assert real_roots(X**2 + 1) == () and real_roots(X**4 + X + 1) == ()
    assert real_roots(flint.fmpz_poly([7])) == ()


def test_zero_polynomial_and_a_reversed_interval_are_refused():
    with pytest.raises(UsageError, match="poly"):
        real_roots(flint.fmpz_poly([]))
    with pytest.raises(UsageError, match="within"):
        real_roots(X - 1, within=(2, 1))


def test_roots_exactly_at_the_interval_ends_are_inside():
    cubic = (X - 1) * (X - 2) * (X - 3)
    assert [r.exact() for r in real_roots(cubic, within=(1, 2))] == [1, 2]
    assert [r.exact() for r in real_roots(cubic, within=(2, 2))] == [2]
    assert [r.exact() for r in real_roots(cubic, within=(flint.fmpq(3, 2), flint.fmpq(5, 2)))] == [2]


def test_an_end_closer_to_an_irrational_root_than_its_first_ball():
    # sqrt(2) = 1.41421356237309504880...: the ends differ from it by 5e-17, under 53 bits' reach
    below, above = flint.fmpq(1414213562373095, 10**15), flint.fmpq(1414213562373096, 10**15)
    assert real_roots(X**2 - 2, within=(0, below)) == ()
    assert len(real_roots(X**2 - 2, within=(0, above))) == 1
    assert len(real_roots(X**2 - 2, within=(below, above))) == 1


def test_isolates_is_a_count_of_exactly_one():
    cubic = X**3 - X  # -1, 0, 1
    assert isolates(cubic, flint.fmpq(-1, 2), flint.fmpq(1, 2)) and isolates(cubic, flint.fmpq(1, 2), 2)
    assert not isolates(cubic, 0, 1) and not isolates(cubic, 2, 3)


def test_sign_at_a_root_exact_zero_and_refined():
    plus = real_roots(X**2 - 2)[1]
    assert plus.sign(X - 1) == 1 and plus.sign(X**3 - 3) == -1  # 2 sqrt(2) < 3
    assert plus.sign(X**4 - 4) == 0 and plus.sign(flint.fmpq_poly([flint.fmpq(-1, 2), 0, flint.fmpq(1, 4)])) == 0
    # sqrt(2) - 1.414213562373095048 = 8.0e-20: undecided at 53 bits, decided refined
    close = flint.fmpq_poly([-flint.fmpq(1414213562373095048, 10**18), 1])
    assert plus.sign(close) == 1
    with pytest.raises(ComputationError, match="undecided"):
        plus.sign(close, max_bits=64)


def test_refined_narrows_and_keeps_the_root():
    plus = real_roots(X**2 - 2)[1]
    fine = plus.refined(300)
    with flint.ctx.workprec(400):
        assert fine.ball.overlaps(flint.arb(2).sqrt())
    assert fine.ball.rad() < 2.0**-290 and fine.bits == 300
    assert fine.refined(100) is fine
    assert fine.value(X**2, bits=300).overlaps(flint.arb(2)) and fine.value(X**2).rad() < 1e-80


def test_roots_are_frozen_values_equal_whatever_their_balls():
    plus = real_roots(X**2 - 2)[1]
    assert plus == plus.refined(200) and len({plus, plus.refined(200), real_roots(X**2 - 2)[0]}) == 2
    with pytest.raises(attrs.exceptions.FrozenInstanceError):
        plus.index = 0  # type: ignore[misc]
    assert isinstance(plus, RealRoot)


def test_quadratic_roots_in_balls():
    one, two = sorted(quadratic_roots(flint.arb(1), flint.arb(-3), flint.arb(2)), key=lambda b: float(b.mid()))
    assert one.overlaps(flint.arb(1)) and two.overlaps(flint.arb(2))
    assert quadratic_roots(flint.arb(1), flint.arb(-2), flint.arb(1)) is None  # a double root
    assert quadratic_roots(flint.arb(1), flint.arb(0), flint.arb(1)) is None  # no real root
    assert quadratic_roots(flint.arb(0, 1e-3), flint.arb(1), flint.arb(-1)) is None  # a may be zero
    assert quadratic_roots(flint.arb(1), flint.arb(0), flint.arb(0, 1e-3)) is None  # disc may be zero


def test_quadratic_roots_without_cancellation():
    # t**2 - 1e8 t + 1: the small root ~1e-8 loses half its digits in the schoolbook formula
    small, big = sorted(quadratic_roots(flint.arb(1), flint.arb(-10**8), flint.arb(1)), key=lambda b: float(b.mid()))
    assert (small * big).overlaps(flint.arb(1)) and (small + big).overlaps(flint.arb(10**8))
    assert float(small.rad() / small.mid()) < 1e-13


fractions = st.fractions(min_value=-100, max_value=100, max_denominator=1000)


@settings(max_examples=60, deadline=None)
@given(st.lists(fractions, min_size=1, max_size=8), st.integers(0, 2))
def test_a_product_of_linear_factors_gives_back_exactly_those_roots(values, unreal):
    poly = prod((linear(v) for v in values), start=flint.fmpz_poly([1])) * (X**2 + 1)**unreal
    roots = real_roots(poly)
    assert [Fraction(int(r.exact().p), int(r.exact().q)) for r in roots] == sorted(set(values))
    assert [r.multiplicity for r in roots] == [values.count(v) for v in sorted(set(values))]


@settings(max_examples=60, deadline=None)
@given(st.lists(fractions, min_size=1, max_size=6, unique=True), fractions, fractions)
def test_within_keeps_exactly_the_roots_in_the_closed_interval(values, a, b):
    lo, hi = min(a, b), max(a, b)
    poly = prod((linear(v) for v in values), start=flint.fmpz_poly([1]))
    found = real_roots(poly, within=(fmpq(lo), fmpq(hi)))
    assert [r.exact() for r in found] == [fmpq(v) for v in sorted(values) if lo <= v <= hi]


@settings(max_examples=30, deadline=None)
@given(st.sets(st.integers(2, 10**6).filter(lambda n: int(n**0.5)**2 != n and (int(n**0.5) + 1)**2 != n),
               min_size=1, max_size=5))
def test_square_roots_of_non_squares(numbers):
    roots = real_roots(prod((X**2 - n for n in numbers), start=flint.fmpz_poly([1])), bits=80)
    expected = sorted([s * flint.arb(n).sqrt() for n in numbers for s in (-1, 1)], key=lambda b: float(b.mid()))
    assert len(roots) == len(expected)
    assert all(r.ball.overlaps(e) for r, e in zip(roots, expected))


@settings(max_examples=30, deadline=None)
@given(st.lists(st.lists(st.integers(-30, 30), min_size=2, max_size=7), min_size=1, max_size=3),
       st.sampled_from([128, 300, 1000]))
def test_refined_together_gives_each_roots_own_refinement(factors, bits):
    """Roots of several factors refined together: the very balls each root's own ``refined`` gives,
    each holding the root arb's ``complex_roots`` finds at four times the precision."""
    poly = prod((flint.fmpz_poly(c) for c in factors if any(c[1:])), start=flint.fmpz_poly([1]))
    roots = real_roots(poly, bits=64)
    together = refined_together(roots, bits)
    for root, mine in zip(roots, together):
        alone = root.refined(bits)
        assert (mine.ball.mid(), mine.ball.rad(), mine.bits) == (alone.ball.mid(), alone.ball.rad(), alone.bits)
        with flint.ctx.workprec(4 * bits):
            fine = [r.real for r, _ in root.factor.complex_roots() if r.imag.is_zero()]
        assert mine.ball.contains(sorted(fine, key=lambda b: b.mid())[root.index])
