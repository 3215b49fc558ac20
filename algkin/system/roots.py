"""Real roots of a univariate polynomial with rational coefficients: isolated, refined and
certified in arb balls, by python-flint's own isolation (``complex_roots``, Arb's).

A root is told exactly by the irreducible factor it is a root of and its rank among that
factor's real roots, ascending (sympy's ``CRootOf(factor, index)``); its ball, computed at
some working precision, holds it and no other real root of the polynomial it was found in.
Every computation scopes its own precision (``flint.ctx.workprec``); none is set globally.

>>> x = flint.fmpz_poly([0, 1])
>>> minus, plus = real_roots(x**2 - 2)                 # -sqrt(2), +sqrt(2)
>>> plus.factor, plus.index, plus.ball.overlaps(flint.arb(2).sqrt())
(x^2 + (-2), 1, True)
>>> plus.sign(x**3 - 3), plus.sign(x**4 - 4)           # 2**(3/2) < 3; 4 - 4 exactly
(-1, 0)
>>> plus.refined(200).ball.rad() < 1e-58 < plus.ball.rad()
True
>>> [(r.exact(), r.multiplicity) for r in real_roots((x - 1)**2 * (x - 3), within=(1, 2))]
[(1, 2)]
>>> isolates(x**2 - 2, 1, 2), isolates(x**2 - 2, -2, 2)
(True, False)
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Union, cast

import attrs
import flint

from ..errors import ComputationError, UsageError

__all__ = ["RealRoot", "real_roots", "refined_together", "isolates", "quadratic_roots", "Polynomial", "Rational", "MAX_BITS"]

Polynomial = Union[flint.fmpz_poly, flint.fmpq_poly]
Rational = Union[int, flint.fmpz, flint.fmpq]

MAX_BITS = 1 << 16  # refining past this: two numbers this close are taken as unseparable


@attrs.frozen
class RealRoot:
    """One real root: exactly, the irreducible ``factor`` (coefficients low to high, primitive,
    leading one positive) and its ``index`` among that factor's real roots, ascending; with the
    factor's ``multiplicity`` in the polynomial it was found in, and an isolating ``ball``
    computed at ``bits`` of working precision (not part of its identity: equal roots compare
    equal whatever their balls).

    >>> root, = real_roots(flint.fmpz_poly([-1, 0, 0, 1]))          # the real cube root of 1
    >>> root.exact(), root == root.refined(300), hash(root) == hash(root.refined(300))
    (1, True, True)
    """

    coefficients: tuple[int, ...]
    index: int
    multiplicity: int
    ball: flint.arb = attrs.field(eq=False, repr=lambda ball: ball.str(10))
    bits: int = attrs.field(eq=False)

    @property
    def factor(self) -> flint.fmpz_poly:
        """The irreducible polynomial the root is a simple root of."""
        return flint.fmpz_poly(list(self.coefficients))

    @property
    def degree(self) -> int:
        """The degree of the root as an algebraic number (1: rational)."""
        return len(self.coefficients) - 1

    def exact(self) -> flint.fmpq | None:
        """The root as a rational number, if it is one (its factor is linear), else None."""
        if self.degree != 1:
            return None
        constant, leading = self.coefficients
        return flint.fmpq(-constant, leading)

    def interval(self) -> tuple[flint.fmpq, flint.fmpq]:
        """The ball's ends as exact rationals: an interval holding this root and no other.

        >>> lo, hi = real_roots(flint.fmpz_poly([-2, 0, 1]))[1].interval()
        >>> lo * lo < 2 < hi * hi
        True
        """
        middle, radius = _rational(self.ball.mid()), _rational(self.ball.rad())  # exact, unlike lower()
        return middle - radius, middle + radius

    def refined(self, bits: int) -> RealRoot:
        """The same root, its ball computed again at ``bits`` of working precision (met with the
        ball it had, so it still isolates the root); itself where its ball is that fine already."""
        if bits <= self.bits:
            return self
        return self._at(_real_balls(self.factor, bits)[self.index], bits)

    def _at(self, ball: flint.arb, bits: int) -> RealRoot:
        """The root with ``ball``, its factor's root of its rank computed at ``bits``."""
        if not self.ball.contains(ball):
            with flint.ctx.workprec(bits):
                ball = ball.intersection(self.ball)
        return attrs.evolve(self, ball=ball, bits=bits)

    def value(self, poly: Polynomial, *, bits: int | None = None) -> flint.arb:
        """``poly`` at the root, in ball arithmetic at ``bits`` (default: the root's own).

        >>> root = real_roots(flint.fmpz_poly([-2, 0, 1]))[1]
        >>> root.value(flint.fmpq_poly([0, flint.fmpq(1, 2)]), bits=100).overlaps(1 / flint.arb(2).sqrt())
        True
        """
        root = self.refined(bits or self.bits)
        with flint.ctx.workprec(root.bits):
            return flint.arb_poly(list(poly.coeffs()))(root.ball)

    def sign(self, poly: Polynomial, *, max_bits: int = MAX_BITS) -> int:
        """-1, 0 or 1, the sign of ``poly`` at the root: 0 exactly (the factor divides ``poly``),
        otherwise decided in balls, refining the root (a ComputationError past ``max_bits``)."""
        if (flint.fmpq_poly(poly) % flint.fmpq_poly(self.factor)).is_zero():
            return 0
        root = self
        while True:
            value = root.value(poly)
            if value > 0 or value < 0:
                return 1 if value > 0 else -1
            if root.bits * 2 > max_bits:
                raise ComputationError(f"the sign of {poly} at a root of {self.factor} stayed undecided "
                                       f"at {root.bits} bits")
            root = root.refined(root.bits * 2)


def real_roots(poly: Polynomial, *, within: tuple[Rational, Rational] | None = None,
               bits: int | None = None) -> tuple[RealRoot, ...]:
    """The distinct real roots of ``poly``, ascending, their balls pairwise disjoint; only those
    in the closed interval ``within`` (exact rational ends) if given. Balls are computed at
    ``bits`` of working precision (default: ``flint.ctx``'s), finer where two need separating.

    >>> x = flint.fmpz_poly([0, 1])
    >>> [str(r.exact()) for r in real_roots((3 * x - 1) * (x + 2) * (x**2 + 1))]
    ['-2', '1/3']
    >>> [r.ball.str(12, radius=False) for r in real_roots(flint.fmpq_poly([-1, 0, 2]), bits=100)]
    ['-0.707106781187', '0.707106781187']
    """
    integer = _integer(poly)
    if integer.is_zero():
        raise UsageError("poly", poly, "is zero: every number is a root")
    bits = bits or flint.ctx.prec
    found = [RealRoot(tuple(int(c) for c in factor.coeffs()), index, multiplicity, ball, bits)
             for factor, multiplicity in integer.factor()[1]
             for index, ball in enumerate(_real_balls(factor, bits))]
    roots = _separated(found)
    if within is not None:
        lo, hi = (flint.fmpq(end) for end in within)
        if lo > hi:
            raise UsageError("within", within, "is no interval: its lower end is above its upper end")
        roots = [r for r in roots if _inside(r, lo, hi)]
    return tuple(roots)


def refined_together(roots: Sequence[RealRoot], bits: int) -> list[RealRoot]:
    """``[root.refined(bits) for root in roots]``, the same balls, each factor's roots computed
    once (a factor's roots are found all at once: refining its real roots one by one would find
    them all again for each).

    >>> roots = real_roots(flint.fmpz_poly([-1, 0, 0, 0, 0, 3]) * flint.fmpz_poly([2, -7, 0, 1]))
    >>> together, alone = refined_together(roots, 300), [r.refined(300) for r in roots]
    >>> [(a.ball.mid() == b.ball.mid(), a.ball.rad() == b.ball.rad(), a.bits) for a, b in zip(together, alone)][0]
    (True, True, 300)
    >>> all(a.ball.mid() == b.ball.mid() and a.ball.rad() == b.ball.rad() for a, b in zip(together, alone))
    True
    """
    found: dict[tuple[int, ...], list[flint.arb]] = {}
    refined = []
    for root in roots:
        if bits <= root.bits:
            refined.append(root)
            continue
        if root.coefficients not in found:
            found[root.coefficients] = _real_balls(root.factor, bits)
        refined.append(root._at(found[root.coefficients][root.index], bits))
    return refined


def isolates(poly: Polynomial, lo: Rational, hi: Rational) -> bool:
    """Whether the closed interval ``[lo, hi]`` holds exactly one distinct real root of ``poly``:
    a certificate (exact ends, certified isolation).

    >>> isolates(flint.fmpz_poly([0, -1, 0, 1]), 0, 1)     # x**3 - x: 0 and 1 both inside
    False
    """
    return len(real_roots(poly, within=(lo, hi))) == 1


def quadratic_roots(a: flint.arb, b: flint.arb, c: flint.arb) -> tuple[flint.arb, flint.arb] | None:
    """The two roots of ``a t**2 + b t + c`` for every value of the balls ``a, b, c``, or None
    unless they are proved real and distinct (``a`` nonzero, discriminant > 0) and enclosed in
    finite balls; computed without cancellation (``q = -(b + sign(b) sqrt(disc)) / 2``, roots
    ``q / a`` and ``c / q``), at ``flint.ctx``'s working precision.

    >>> one, two = quadratic_roots(flint.arb(1), flint.arb(-3), flint.arb(2))   # (t - 1)(t - 2)
    >>> two.overlaps(flint.arb(1)), one.overlaps(flint.arb(2)), quadratic_roots(*map(flint.arb, (1, 2, 1)))
    (True, True, None)
    """
    disc = b * b - 4 * a * c
    if not (disc > 0 and (a > 0 or a < 0)):
        return None
    root = disc.sqrt()
    q = -(b + root) / 2 if b.mid() >= 0 else -(b - root) / 2
    first, second = q / a, c / q
    return (first, second) if first.is_finite() and second.is_finite() else None


def _integer(poly: Polynomial) -> flint.fmpz_poly:
    """``poly`` with its denominators cleared (same roots)."""
    return poly.numer() if isinstance(poly, flint.fmpq_poly) else flint.fmpz_poly(poly)


def _real_balls(factor: flint.fmpz_poly, bits: int) -> list[flint.arb]:
    """The real roots of ``factor`` in disjoint balls, ascending: Arb gives real roots an
    imaginary part of exactly zero."""
    with flint.ctx.workprec(bits):
        # (root, multiplicity) pairs: python-flint 0.9's stub says bare roots
        pairs = cast("list[tuple[flint.acb, int]]", factor.complex_roots())
    return sorted((r.real for r, _ in pairs if r.imag.is_zero()), key=_middle)


def _middle(ball: flint.arb) -> flint.fmpq:
    return _rational(ball.mid())


def _separated(roots: Sequence[RealRoot]) -> list[RealRoot]:
    """``roots`` ascending, refined until no two balls overlap (roots of distinct factors are
    distinct; those of one factor are isolated already)."""
    ordered = sorted(roots, key=lambda r: _middle(r.ball))
    while True:
        clash = next((k for k in range(len(ordered) - 1) if ordered[k].ball.overlaps(ordered[k + 1].ball)), None)
        if clash is None:
            return ordered
        bits = 2 * max(ordered[clash].bits, ordered[clash + 1].bits)
        if bits > MAX_BITS:
            raise ComputationError(f"two real roots stayed unseparated at {MAX_BITS} bits")
        ordered[clash:clash + 2] = [r.refined(bits) for r in ordered[clash:clash + 2]]
        ordered.sort(key=lambda r: _middle(r.ball))


def _inside(root: RealRoot, lo: flint.fmpq, hi: flint.fmpq) -> bool:
    """Whether ``lo <= root <= hi``: an end that is the root is found exactly (a linear factor),
    any other is told from the root by refining its ball."""
    if root.exact() is not None:
        return lo <= cast(flint.fmpq, root.exact()) <= hi
    while True:
        lower, upper = root.interval()
        if hi < lower or upper < lo:
            return False
        if lo < lower and upper < hi:
            return True
        if root.bits * 2 > MAX_BITS:  # an irrational root is no rational end: unreachable but for memory
            raise ComputationError(f"a root of {root.factor} stayed unseparated from {lo} or {hi}")
        root = root.refined(root.bits * 2)


def _rational(point: flint.arb) -> flint.fmpq:
    """An exact ball (a point: a midpoint, an end) as a rational."""
    mantissa, exponent = (int(v) for v in point.man_exp())
    return flint.fmpq(mantissa << exponent) if exponent >= 0 else flint.fmpq(mantissa, 1 << -exponent)
