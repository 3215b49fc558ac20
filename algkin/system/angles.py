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

__all__ = ["half_angle_degree", "half_angle_numerator", "half_angle_poly", "half_angle_terms", "tangent_to_degrees", "vanishes_at_half_turn", "Parametrisation"]


def half_angle_numerator(expr: sympy.Expr, c: sympy.Symbol, s: sympy.Symbol, t: sympy.Symbol) -> sympy.Expr:
    """The numerator, in ``t`` (and ``expr``'s other symbols), of ``expr`` with ``c``, ``s`` in the
    half-angle form: a polynomial's in python-flint (``half_angle_terms``), a quotient's (a
    discriminant's norm) through sympy.

    >>> a, c, s, t = sympy.symbols("a c s t")
    >>> half_angle_numerator(a * c + s, c, s, t), half_angle_numerator(s / (c + 1), c, s, t)
    (-a*t**2 + a + 2*t, t**3 + t)
    """
    names = [c.name, s.name, *sorted({v.name for v in expr.free_symbols} - {c.name, s.name})]
    if len(set(names)) == len(names) and t.name not in names[2:]:
        try:
            poly = to_flint(expr, flint_context(names))
        except TypeError:  # a quotient, a root
            poly = None
        if poly is not None:
            others = sorted(expr.free_symbols - {c, s}, key=lambda v: v.name)
            return from_terms(_cleared(half_angle_terms(poly)), [t, *others])
    half = {c: (1 - t**2) / (1 + t**2), s: 2 * t / (1 + t**2)}
    return sympy.expand(sympy.numer(sympy.together(sympy.expand(expr).xreplace(half))))


_COSINE, _SINE, _ONE = flint.fmpq_poly([1, 0, -1]), flint.fmpq_poly([0, 2]), flint.fmpq_poly([1, 0, 1])


def half_angle_terms(poly: flint.fmpq_mpoly) -> dict[tuple[int, ...], flint.fmpq_poly]:
    """``poly``'s terms in ``c, s`` (its first two variables) in ``t`` (``c = (1 - t^2)/(1 + t^2)``,
    ``s = 2t/(1 + t^2)``) times ``(1 + t^2)**k``, ``k`` its degree in them, grouped by the
    exponents of its other variables."""
    terms = poly.to_dict()
    degree = max((m[0] + m[1] for m in terms), default=0)
    grouped: dict[tuple[int, ...], flint.fmpq_poly] = {}
    for monomial, coefficient in terms.items():
        i, j, rest = monomial[0], monomial[1], tuple(monomial[2:])
        grouped[rest] = grouped.get(rest, flint.fmpq_poly([])) + \
            coefficient * _COSINE**i * _SINE**j * _ONE**(degree - i - j)
    return grouped


def _cleared(grouped: dict[tuple[int, ...], flint.fmpq_poly]) -> dict[tuple[int, ...], int]:
    """``half_angle_terms`` as integer terms ``{(power of t, *other exponents): coefficient}``, the
    denominators cleared."""
    denominator = math.lcm(1, *(int(p.denom()) for p in grouped.values()))
    return {(k, *rest): int(a * denominator) for rest, in_t in grouped.items()
            for k, a in enumerate(in_t.coeffs()) if a != 0}


def half_angle_poly(expr: sympy.Expr, c: sympy.Symbol, s: sympy.Symbol) -> flint.fmpz_poly:
    """The numerator, in ``t = tan(theta/2)``, of ``expr(c, s)`` (numbers alone besides ``c, s``):
    ``c = (1 - t^2)/(1 + t^2)``, ``s = 2t/(1 + t^2)``, times ``(1 + t^2)**degree``, in python-flint
    (a sympy substitution takes minutes on thousands of terms).

    >>> c, s = sympy.symbols("c s")
    >>> half_angle_poly(c**2 + s**2, c, s)  # (1 + t**2)**2 / (1 + t**2)**2: no root
    x^4 + 2*x^2 + 1
    """
    terms = _cleared(half_angle_terms(to_flint(expr, flint_context([str(c), str(s)]))))
    return flint.fmpz_poly([terms.get((k,), 0) for k in range(max((m[0] + 1 for m in terms), default=0))])


def vanishes_at_half_turn(expr: sympy.Expr, c: sympy.Symbol, s: sympy.Symbol) -> bool:
    """Whether the condition holds at ``theta = 180 deg`` (``t`` at infinity)."""
    return bool(sympy.expand(expr.xreplace({c: -1, s: 0})) == 0)


def half_angle_degree(degrees: sympy.Expr | int, *, limit: int) -> int | None:
    """The degree over the rationals of ``tan(degrees/2)`` (``degrees`` an angle in degrees) where
    it is at most ``limit``; None where it is more, or where the tangent is not algebraic (an angle
    that is no rational number of degrees, such as 1 radian).

    ``tan(2 pi k/n)`` (``k/n`` in lowest terms) is of degree ``phi(n)``, halved where 4 divides
    ``n`` and quartered where 8 does; so the degree grows with the denominator of the angle.

    >>> half_angle_degree(90, limit=12), half_angle_degree(120, limit=12), half_angle_degree(5, limit=12)
    (1, 2, 12)
    >>> half_angle_degree(91, limit=12), half_angle_degree(sympy.Rational(9000000000001, 10**11), limit=12)
    (None, None)
    >>> half_angle_degree(180 / sympy.pi, limit=12) is None
    True
    """
    value = sympy.sympify(degrees)
    if not value.is_Rational:
        return None
    n = int((value / 720).q)
    if n > 2 * (4 * limit) ** 2:  # phi(n) >= sqrt(n/2): the degree, at least phi(n)/4, is past the limit
        return None
    degree = int(sympy.totient(n)) // {8: 4, 4: 2}.get(math.gcd(n, 8), 1)
    return degree if degree <= limit else None


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
    >>> angle.numerator(c - s)
    -t**2 - 2*t + 1
    >>> length = Parametrisation((t,), t)
    >>> length.numerator(t**2 - 2), length.turns
    (t**2 - 2, (0,))
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
