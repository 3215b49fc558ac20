"""The real roots of a condition in the input's ``c, s`` as angles: isolated in
``t = tan(theta/2)`` by ``system.roots``, each with its irreducible factor and exact angle.

>>> import sympy
>>> c, s, t = sympy.symbols("c s t")
>>> with flint.ctx.workprec(ROOT_BITS):
...     found = angle_roots([s * (2 * c - 1)], c, s, t)       # sin = 0 or cos = 1/2
>>> [(r.exact_deg, str(r.factor)) for r in found]
[(180, 'None'), (0, 't'), (-60, '3*t**2 - 1'), (60, '3*t**2 - 1')]
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import flint
import sympy

from ...system.angles import half_angle_poly, tangent_to_degrees, vanishes_at_half_turn
from ...system.roots import RealRoot, real_roots

__all__ = ["ROOT_BITS", "Root", "angle_roots"]

ROOT_BITS = 128  # root isolation: enclosures about 1e-36 deg wide


@dataclass(frozen=True)
class Root:
    """A real root of an eliminant: its enclosure in degrees, the factor in t and its exact angle."""

    degrees: flint.arb
    factor: sympy.Expr | None  # None at 180 deg (t at infinity)
    exact_deg: sympy.Expr
    t_value: sympy.Expr | None  # the root in radicals (factor of degree <= 2), None otherwise or at 180


def angle_roots(polys: Sequence[sympy.Expr], c: sympy.Symbol, s: sympy.Symbol, t: sympy.Symbol) -> list[Root]:
    """Every real root (as an angle) of every polynomial in ``c, s``, each with its factor, at
    ``flint.ctx``'s working precision; per polynomial, 180 deg first, then factor by factor."""
    found: list[Root] = []
    for poly in polys:
        numerator = half_angle_poly(poly, c, s)
        if vanishes_at_half_turn(poly, c, s):
            found.append(Root(flint.arb(180), None, sympy.Integer(180), None))
        if numerator.degree() < 1:
            continue
        factors: dict[tuple[int, ...], tuple[sympy.Expr, list[sympy.Expr]]] = {}
        for root in _by_factor(numerator):
            if root.coefficients not in factors:
                expr = sympy.Add(*[sympy.Integer(a) * t**k for k, a in enumerate(root.coefficients)])
                factors[root.coefficients] = expr, _radical_roots(expr, t) if root.degree <= 2 else []
            found.append(_angle(root, *factors[root.coefficients]))
    return found


def _by_factor(poly: flint.fmpz_poly) -> list[RealRoot]:
    """The real roots of ``poly`` factor by factor (in the order python-flint factors it, so the
    dropped roots are listed as they always were), ascending within each."""
    order = {tuple(int(a) for a in f.coeffs()): k for k, (f, _) in enumerate(poly.factor()[1])}
    return sorted(real_roots(poly), key=lambda root: order[root.coefficients])


def _angle(root: RealRoot, factor: sympy.Expr, radicals: Sequence[sympy.Expr]) -> Root:
    """``root`` (in ``t``) as an angle: exactly in radicals where its factor has them, else a CRootOf."""
    value = next((r for r in radicals if root.ball.overlaps(flint.arb(str(sympy.N(r, 60))))), None)
    exact = sympy.CRootOf(factor, root.index) if value is None else value
    return Root(tangent_to_degrees(root.ball), factor, 360 * sympy.atan(exact) / sympy.pi, value)


def _radical_roots(expr: sympy.Expr, t: sympy.Symbol) -> list[sympy.Expr]:
    return [sympy.radsimp(r) for r in sympy.roots(sympy.Poly(expr, t)) if r.is_real]
