"""Angles as algebra: the tangent half-angle ``t = tan(theta/2)`` and back.

On the circle ``c**2 + s**2 = 1`` every point but ``theta = 180 deg`` is
``c = (1 - t**2)/(1 + t**2)``, ``s = 2t/(1 + t**2)``, so a polynomial condition in ``c, s``
becomes one in ``t`` alone; ``theta = 180 deg`` is ``t`` at infinity, checked apart.

>>> import sympy
>>> c, s, t = sympy.symbols("c s t")
>>> half_angle_numerator(c - s, c, s, t)
-t**2 - 2*t + 1
>>> import flint
>>> tangent_to_degrees(flint.arb(1)).contains(90)
True
"""

from __future__ import annotations

import math
from collections.abc import Callable

import flint
import mpmath
import sympy

from .convert import flint_context, from_terms, to_flint, univariate
from .roots import real_roots

__all__ = ["half_angle_numerator", "half_angle_poly", "off_the_circle", "tangent_to_degrees", "vanishes_at_half_turn", "Parametrisation"]


def half_angle_numerator(expr: sympy.Expr, c: sympy.Symbol, s: sympy.Symbol, t: sympy.Symbol) -> sympy.Expr:
    """The numerator, in ``t``, of ``expr`` with ``c``, ``s`` in the half-angle form: ``expr``
    times ``(1 + t**2)**k`` (``k`` its degree in ``c, s``) and its denominators' lcm, in
    python-flint (a sympy substitution took minutes on an eliminant of thousands of terms in
    a symbolic dimension: ``extremum --param``)."""
    gens = [c, s, *sorted(sympy.sympify(expr).free_symbols - {c, s, t}, key=str), t]
    ring = flint_context(map(str, gens))
    poly = to_flint(expr, ring)
    terms = poly.to_dict()
    degree = max((m[0] + m[1] for m in terms), default=0)
    cosines, sines, ones = ([base**k for k in range(degree + 1)] for base in (_COSINE, _SINE, _ONE))
    grouped: dict[tuple[int, ...], flint.fmpq_poly] = {}  # the other variables' exponents -> a polynomial in t
    for monomial, coefficient in terms.items():
        i, j, rest = monomial[0], monomial[1], tuple(monomial[2:])
        grouped[rest] = grouped.get(rest, flint.fmpq_poly([])) + coefficient * cosines[i] * sines[j] * ones[degree - i - j]
    numerator: dict[tuple[int, ...], flint.fmpq] = {}
    for rest, in_t in grouped.items():
        for k, coefficient in enumerate(in_t.coeffs()):
            if coefficient != 0:
                numerator[(0, 0) + rest[:-1] + (rest[-1] + k,)] = flint.fmpq(coefficient)
    if not numerator:
        return sympy.Integer(0)
    lcm = math.lcm(*(int(v.q) for v in numerator.values()))
    return from_terms({m: v * lcm for m, v in numerator.items()}, gens)


_COSINE, _SINE, _ONE = flint.fmpq_poly([1, 0, -1]), flint.fmpq_poly([0, 2]), flint.fmpq_poly([1, 0, 1])


def off_the_circle(numerator: sympy.Expr, t: sympy.Symbol) -> sympy.Expr:
    """``numerator`` divided by ``1 + t**2`` as often as it divides exactly (in python-flint)."""
    gens = sorted(sympy.sympify(numerator).free_symbols | {t}, key=str)
    ring = flint_context(map(str, gens))
    poly = to_flint(numerator, ring)
    circle = 1 + ring.gens()[gens.index(t)] ** 2
    divided = False
    while not poly.is_zero():
        quotient, remainder = divmod(poly, circle)
        if not remainder.is_zero():
            break
        poly, divided = quotient, True
    return from_terms(poly.to_dict(), gens) if divided else numerator


def half_angle_poly(expr: sympy.Expr, c: sympy.Symbol, s: sympy.Symbol) -> flint.fmpz_poly:
    """The numerator, in ``t = tan(theta/2)``, of ``expr(c, s)`` (numbers alone besides ``c, s``):
    ``c = (1 - t^2)/(1 + t^2)``, ``s = 2t/(1 + t^2)``, times ``(1 + t^2)**degree``, in python-flint
    (a sympy substitution takes minutes on thousands of terms).

    >>> c, s = sympy.symbols("c s")
    >>> half_angle_poly(c**2 + s**2, c, s)  # (1 + t**2)**2 / (1 + t**2)**2: no root
    x^4 + 2*x^2 + 1
    """
    terms = to_flint(expr, flint_context([str(c), str(s)])).to_dict()
    degree = max((i + j for i, j in terms), default=0)
    cosine, sine, one = flint.fmpq_poly([1, 0, -1]), flint.fmpq_poly([0, 2]), flint.fmpq_poly([1, 0, 1])
    total = flint.fmpq_poly([])
    for (i, j), coefficient in terms.items():
        total += coefficient * cosine**i * sine**j * one ** (degree - i - j)
    if total.degree() < 0:
        return flint.fmpz_poly([])
    denominator = math.lcm(*(int(flint.fmpq(a).q) for a in total.coeffs()))
    return flint.fmpz_poly([int(flint.fmpq(a) * denominator) for a in total.coeffs()])


def vanishes_at_half_turn(expr: sympy.Expr, c: sympy.Symbol, s: sympy.Symbol) -> bool:
    """Whether the condition holds at ``theta = 180 deg`` (``t`` at infinity)."""
    return bool(sympy.expand(expr.xreplace({c: -1, s: 0})) == 0)


def tangent_to_degrees(t: flint.arb) -> flint.arb:
    """``2 atan(t)`` in degrees, for an arb ball ``t``: in (-180, 180)."""
    return 2 * t.atan() * 180 / flint.arb.pi()


class Parametrisation:
    """An input's variables as polynomials (after clearing denominators) in one variable ``t``.

    An angle's ``(c, s)`` takes the half-angle form, ``t = tan(theta/2)``, its values shown in
    degrees, with ``theta = 180`` at ``t`` infinite and the motion repeating every turn; a
    length's one variable is ``t`` itself, shown as it is.

    >>> c, s, t = sympy.symbols("c s t")
    >>> angle = Parametrisation((c, s), t)
    >>> angle.numerator(c - s), angle.derivative(c * s)
    (-t**2 - 2*t + 1, c**2 - s**2)
    >>> length = Parametrisation((t,), t)
    >>> length.numerator(t**2 - 2), length.derivative(t**2 - 2), length.turns
    (t**2 - 2, 2*t, (0,))
    """

    def __init__(self, variables: tuple[sympy.Symbol, ...], t: sympy.Symbol) -> None:
        self.variables, self.t = variables, t
        self.is_angle = len(variables) == 2
        self.turns: tuple[int, ...] = (-360, 0, 360) if self.is_angle else (0,)

    def numerator(self, expr: sympy.Expr) -> sympy.Expr:
        """``expr`` as a polynomial in ``t`` (the numerator of its half-angle form for an angle)."""
        if self.is_angle:
            c, s = self.variables
            return half_angle_numerator(expr, c, s, self.t)
        return sympy.expand(expr.xreplace({self.variables[0]: self.t}))

    def derivative(self, expr: sympy.Expr) -> sympy.Expr:
        """``d expr / d input``: ``-s*d/dc + c*d/ds`` along an angle, ``d/dt`` along a length."""
        gens = sorted(sympy.sympify(expr).free_symbols | set(self.variables), key=str)
        ring = flint_context(map(str, gens))  # in python-flint: sympy takes seconds on thousands of terms
        poly = to_flint(expr, ring)
        if self.is_angle:
            c, s = self.variables
            along = -ring.gens()[gens.index(s)] * poly.derivative(str(c)) \
                + ring.gens()[gens.index(c)] * poly.derivative(str(s))
        else:
            along = poly.derivative(str(self.variables[0]))
        return from_terms(along.to_dict(), gens)

    def shown(self, root: flint.arb) -> flint.arb:
        """A root in ``t`` as the input users read: degrees for an angle, the length itself."""
        return tangent_to_degrees(root) if self.is_angle else root

    def at_infinity(self, expr: sympy.Expr) -> list[flint.arb]:
        """Where ``expr`` vanishes that no root in ``t`` shows: an angle's half turn."""
        return [flint.arb(180)] if self.is_angle and vanishes_at_half_turn(expr, *self.variables[:2]) else []

    def roots(self, expr: sympy.Expr) -> list[flint.arb]:
        """Certified enclosures of the inputs (as users read them) where ``expr`` vanishes, at
        ``flint.ctx``'s working precision: the roots in ``t`` shown, then ``at_infinity``.

        >>> c, s, t = sympy.symbols("c s t")
        >>> [float(r.mid()) for r in Parametrisation((c, s), t).roots(s)]
        [0.0, 180.0]
        >>> [round(float(r.mid()), 12) for r in Parametrisation((t,), t).roots(t**2 - 2)]
        [-1.414213562373, 1.414213562373]
        """
        found = real_roots(univariate(self.numerator(expr), self.t))
        return [self.shown(r.ball) for r in found] + self.at_infinity(expr)

    def exact_shown(self, t: sympy.Expr) -> sympy.Expr:
        """An exact value of ``t`` as the input users read (degrees: ``360 atan(t) / pi``)."""
        return 360 * sympy.atan(t) / sympy.pi if self.is_angle else t

    def exact_at(self, shown: sympy.Expr) -> dict[sympy.Symbol, sympy.Expr]:
        """The input's variables at an exact value as users read it (degrees for an angle)."""
        if not self.is_angle:
            return {self.variables[0]: shown}
        angle = sympy.pi * shown / 180
        return dict(zip(self.variables, (sympy.cos(angle), sympy.sin(angle))))

    def exact_in_t(self, t: sympy.Expr) -> dict[sympy.Symbol, sympy.Expr]:
        """The input's variables at an exact ``t`` (an angle's half-angle tangent)."""
        if not self.is_angle:
            return {self.variables[0]: t}
        return dict(zip(self.variables, ((1 - t**2) / (1 + t**2), 2 * t / (1 + t**2))))

    def t_of(self, shown: mpmath.mpf) -> mpmath.mpf:
        """``t`` at a value as users read it, in mpmath (``tan(theta/2)`` from degrees)."""
        return mpmath.tan(mpmath.radians(shown) / 2) if self.is_angle else shown

    def numbers_at(self, shown: mpmath.mpf) -> dict[str, mpmath.mpf]:
        """Variable name -> mpmath value at a value as users read it."""
        if not self.is_angle:
            return {self.variables[0].name: shown}
        angle = mpmath.radians(shown)
        return {self.variables[0].name: mpmath.cos(angle), self.variables[1].name: mpmath.sin(angle)}

    def at_end(self, end: sympy.Rational) -> Callable[[sympy.Expr], sympy.Expr]:
        """A polynomial in ``t`` -> one without it that vanishes where it vanishes at ``end``.

        For an angle, 180 degrees is ``t`` at infinity: the leading coefficient; otherwise the
        resultant with the minimal polynomial of ``tan(end/2)`` (linear at multiples of 90 degrees).
        """
        t = self.t
        if not self.is_angle:
            return lambda poly: sympy.expand(poly.xreplace({t: end}))
        half_turns = sympy.Rational(end) / 360
        if half_turns.q == 2:
            return lambda poly: sympy.Poly(poly, t).LC()
        minimal = sympy.minimal_polynomial(sympy.tan(sympy.pi * half_turns), t)
        return lambda poly: sympy.resultant(poly, minimal, t)
