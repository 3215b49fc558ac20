"""A singular point's coordinates told exactly: minimal polynomials, sympy roots, enclosures.

A coordinate ``c(t)`` in ``Q[t]/(p)`` has as minimal polynomial the irreducible factor of
``res_t(p(t), z - c(t))`` (its characteristic polynomial, a power of the minimal one). Its
exact value is sympy's ``CRootOf`` of that polynomial at the index of the real root its ball
overlaps alone (a rational as itself, a quadratic's root in radicals).

>>> import flint
>>> from .numberfield import NumberField
>>> field = NumberField(flint.fmpz_poly([-2, 0, 1]))            # t = +-sqrt(2)
>>> root = field.real_roots()[1]
>>> half = field.mul(field.gen(), field.const(flint.fmpq(1, 2)))    # sqrt(2)/2
>>> minimal_polynomial(field, half)
2*x^2 + (-1)
>>> value, = coordinates(field, half, [root], "x")
>>> value.exact, value.minimal, round(value.value, 12)
(sqrt(2)/2, 2*x**2 - 1, 0.707106781187)
"""

from __future__ import annotations

import attrs
import flint
import sympy

from ...errors import ComputationError
from ...system.convert import fmpq_to_rational, to_sympy
from ...system.roots import MAX_BITS, RealRoot, real_roots
from .numberfield import START_BITS, Element, NumberField

__all__ = ["Coordinate", "coordinates", "minimal_polynomial", "polynomial_text", "ENCLOSURE_BITS"]

ENCLOSURE_BITS = 192


@attrs.frozen
class Coordinate:
    """One coordinate of a real singular point: float, certified ball, exact value, minimal polynomial."""

    value: float
    ball: flint.arb = attrs.field(eq=False)  # balls do not hash: the exact value says which point
    exact: sympy.Expr
    minimal: sympy.Expr


def coordinates(field: NumberField, element: Element, roots: list[RealRoot], name: str) -> list[Coordinate]:
    """``element`` at each of ``roots``: its ball at ``ENCLOSURE_BITS`` and exact forms (variable
    ``name``); the minimal polynomial, shared by the conjugates, found once."""
    if not roots:
        return []
    minimal = minimal_polynomial(field, element)
    text = polynomial_text(minimal, name)
    balls = [root.value(element, bits=ENCLOSURE_BITS) for root in roots]
    return [Coordinate(float(ball.mid()), ball, _exact(minimal, text, element, root), text)
            for ball, root in zip(balls, roots)]


def minimal_polynomial(field: NumberField, element: Element) -> flint.fmpz_poly:
    """The primitive irreducible integer polynomial with ``element`` (at any root) as a root."""
    if element.degree() < 1:
        value = flint.fmpq(element[0]) if not element.is_zero() else flint.fmpq(0)
        return flint.fmpz_poly([-value.p, value.q])
    ctx = flint.fmpz_mpoly_ctx.get(("t", "z"), "lex")
    t, z = ctx.gens()
    den = element.denom()
    numerator = sum((int(c) * t**k for k, c in enumerate(element.numer().coeffs())), ctx.from_dict({}))
    modulus = sum((int(c) * t**k for k, c in enumerate(field.minimal.coeffs())), ctx.from_dict({}))
    characteristic = modulus.resultant(den * z - numerator, 0)
    terms = {int(j): int(c) for (_, j), c in characteristic.to_dict().items()}
    factors = flint.fmpz_poly([terms.get(k, 0) for k in range(max(terms) + 1)]).factor()[1]
    (minimal, _), = factors  # a power of one irreducible polynomial
    return minimal if minimal.coeffs()[-1] > 0 else -minimal


def _exact(minimal: flint.fmpz_poly, text: sympy.Expr, element: Element, root: RealRoot) -> sympy.Expr:
    """The sympy value: the rational itself, or ``CRootOf(minimal, index)`` at the root the ball meets."""
    if minimal.degree() == 1:
        a, b = minimal.coeffs()
        return fmpq_to_rational(flint.fmpq(-a, b))
    bits = START_BITS
    while bits <= MAX_BITS:
        ball = root.value(element, bits=bits)
        meeting = [r.index for r in real_roots(minimal, bits=bits) if r.ball.overlaps(ball)]
        if len(meeting) == 1:
            return sympy.CRootOf(text, meeting[0], radicals=minimal.degree() == 2)
        bits *= 2
    raise ComputationError(f"a singular point's coordinate stayed unseparated among the roots of {minimal}")


def polynomial_text(poly: flint.fmpz_poly | flint.fmpq_poly, name: str) -> sympy.Expr:
    """A univariate python-flint polynomial as a sympy expression in ``name``."""
    ctx = flint.fmpq_mpoly_ctx.get((name,), "lex")
    return to_sympy(ctx.from_dict({(k,): c for k, c in enumerate(flint.fmpq_poly(poly).coeffs()) if c != 0}), ctx)
