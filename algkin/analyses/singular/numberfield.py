"""Exact arithmetic in a number field ``Q(alpha) = Q[t]/(p)``, polynomials over it, and signs at
one real root of ``p`` (a ``system.roots.RealRoot``).

A singular point of a curve with rational coefficients has algebraic coordinates; all its
conjugates share one irreducible polynomial ``p``. Computing in ``Q[t]/(p)`` treats them at
once and exactly: an element is zero at one root of ``p`` exactly when it is zero as a
polynomial mod ``p`` (``p`` is irreducible), so every zero test is exact and every nonzero
element has a sign at a real root that ball arithmetic decides by refining the root.

>>> field = NumberField(flint.fmpz_poly([-2, 0, 1]))      # Q(sqrt(2))
>>> root = field.real_roots()[1]                           # +sqrt(2)
>>> half = field.inverse(field.gen())                      # 1/sqrt(2) = sqrt(2)/2
>>> half, root.sign(field.sub(half, field.const(flint.fmpq(7, 10))))
(1/2*x, 1)
>>> real_root_count(field, [field.const(-2), field.zero(), field.one()], root)   # y**2 - 2
2
"""

from __future__ import annotations

from collections.abc import Sequence

import flint

from ...system.roots import RealRoot, real_roots

__all__ = ["NumberField", "Element", "poly_gcd", "poly_rem", "poly_derivative", "real_root_count",
           "trim"]

Element = flint.fmpq_poly  # an element of the field: a polynomial in t of degree < deg p
START_BITS = 64  # the roots' first balls; signs refine them as far as they need


class NumberField:
    """``Q[t]/(p)`` for an irreducible integer polynomial ``p``."""

    def __init__(self, minimal: flint.fmpz_poly) -> None:
        self.minimal = minimal
        self.modulus = flint.fmpq_poly(minimal)
        self.degree = minimal.degree()

    def reduce(self, value: Element) -> Element:
        return value % self.modulus

    def const(self, value: flint.fmpq | int) -> Element:
        return flint.fmpq_poly([value])

    def zero(self) -> Element:
        return flint.fmpq_poly([])

    def one(self) -> Element:
        return flint.fmpq_poly([1])

    def gen(self) -> Element:
        """``t`` itself (reduced: in ``Q``, ``t`` is the rational root)."""
        return self.reduce(flint.fmpq_poly([0, 1]))

    def add(self, a: Element, b: Element) -> Element:
        return a + b

    def sub(self, a: Element, b: Element) -> Element:
        return a - b

    def mul(self, a: Element, b: Element) -> Element:
        return (a * b) % self.modulus

    def inverse(self, a: Element) -> Element:
        if a.is_zero():
            raise ZeroDivisionError("zero has no inverse in a number field")
        g, s, _ = a.xgcd(self.modulus)
        return s / g[0]  # g is a nonzero constant: p is irreducible and a is not a multiple

    def div(self, a: Element, b: Element) -> Element:
        return self.mul(a, self.inverse(b))

    def real_roots(self) -> list[RealRoot]:
        """The real roots of ``p``, ascending, each a ``RealRoot`` (balls at ``START_BITS``)."""
        return list(real_roots(self.minimal, bits=START_BITS))


def trim(field: NumberField, poly: Sequence[Element]) -> list[Element]:
    """A polynomial over the field (coefficients low to high), reduced, without leading zeros."""
    out = [field.reduce(c) for c in poly]
    while out and out[-1].is_zero():
        out.pop()
    return out


def poly_rem(field: NumberField, a: Sequence[Element], b: Sequence[Element]) -> list[Element]:
    """The remainder of ``a`` by ``b`` (``b`` trimmed, nonzero)."""
    rem = list(a)
    inverse = field.inverse(b[-1])
    while len(rem) >= len(b):
        factor = field.mul(rem[-1], inverse)
        shift = len(rem) - len(b)
        for k, c in enumerate(b):
            rem[shift + k] = field.sub(rem[shift + k], field.mul(factor, c))
        rem = trim(field, rem)
    return rem


def poly_gcd(field: NumberField, *polys: Sequence[Element]) -> list[Element]:
    """The monic gcd of polynomials over the field (``[]`` when all are zero)."""
    result: list[Element] = []
    for poly in polys:
        a, b = trim(field, result), trim(field, poly)
        while b:
            a, b = b, poly_rem(field, a, b)
        result = a
    if not result:
        return []
    inverse = field.inverse(result[-1])
    return [field.mul(c, inverse) for c in result]


def poly_derivative(field: NumberField, poly: Sequence[Element]) -> list[Element]:
    return trim(field, [c * k for k, c in enumerate(poly)][1:])


def real_root_count(field: NumberField, poly: Sequence[Element], root: RealRoot) -> int:
    """How many distinct real roots ``poly`` (over the field, read at the real ``root``) has: Sturm's
    theorem, the sequence computed exactly and its leading signs decided in balls."""
    poly = trim(field, poly)
    if len(poly) <= 1:
        return 0
    sequence = [poly]
    derivative = poly_derivative(field, poly)
    while derivative:
        sequence.append(derivative)
        derivative = trim(field, [-c for c in poly_rem(field, sequence[-2], sequence[-1])])
    leading = [root.sign(p[-1]) for p in sequence]
    at_plus = leading
    at_minus = [s if (len(p) - 1) % 2 == 0 else -s for s, p in zip(leading, sequence)]
    return _changes(at_minus) - _changes(at_plus)


def _changes(signs: Sequence[int]) -> int:
    signs = [s for s in signs if s]
    return sum(1 for a, b in zip(signs, signs[1:]) if a != b)
