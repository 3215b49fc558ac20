"""Where ``F = F_x = F_y = 0``: the singular points of a plane curve, exactly.

The candidates' coordinate ``t = x + shear*y`` is a root of
``gcd(res_y(G, G_y), res_y(G_t, G_y), res_y(G, G_t))``, with ``G(t, y) = F(t - shear*y, y)``
(python-flint resultants and gcd over the integers). For each irreducible factor ``p`` of that
gcd, the gcd of ``G, G_t, G_y`` over ``Q[t]/(p)`` (as polynomials in ``y``) decides it: a
constant means no singular point has that ``t`` (the resultants met by coincidence); a power
``(y - q(t))**k`` (``k > 1`` at a point of multiplicity ``k + 1``) gives one singular point per
root of ``p``, ``(t - shear*q(t), q(t))``, exactly (a rational univariate representation);
anything else means two singular points share ``t``, and a different shear separates them. The shear is also chosen so that ``y**n`` keeps a
nonzero coefficient in ``G`` (``n`` the degree): no singular point escapes the resultants
through a vanishing leading coefficient.

>>> ctx = flint.fmpz_mpoly_ctx.get(("x", "y"), "lex")
>>> x, y = ctx.gens()
>>> [(str(p.field.minimal), str(p.x), str(p.y)) for p in locate((x**2 + y**2)**2 - 2*(x**2 - y**2))]
[('x', '0', '0')]
>>> [(str(p.field.minimal), str(p.x), str(p.y)) for p in locate(y**2 - (x**2 - 2)**2 * (x - 3))]
[('x^2 + (-2)', 'x', '0')]
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
import attrs
import flint

from ...errors import ComputationError
from .numberfield import Element, NumberField, poly_gcd

__all__ = ["ExactPoint", "locate", "top_form"]

MAX_SHEARS = 40


@attrs.frozen
class ExactPoint:
    """A class of conjugate singular points: for each root ``t`` of ``field.minimal``, the
    point ``(x(t), y(t))``; ``t = x + shear*y``."""

    field: NumberField
    x: Element
    y: Element
    shear: int


def top_form(curve: flint.fmpz_mpoly) -> dict[tuple[int, int], int]:
    """The terms of highest total degree, ``{(i, j): coefficient}``."""
    terms = {(int(i), int(j)): int(c) for (i, j), c in curve.to_dict().items()}
    degree = max(i + j for i, j in terms)
    return {m: c for m, c in terms.items() if sum(m) == degree}


def locate(curve: flint.fmpz_mpoly) -> list[ExactPoint]:
    """The singular points of the squarefree curve ``curve(x, y) = 0`` (generators ``x, y``),
    one ``ExactPoint`` per conjugate class."""
    top = top_form(curve)
    for shear in _shears():
        if sum(c * (-shear) ** i for (i, _), c in top.items()) == 0:
            continue  # y**n would vanish from G: a leading coefficient in t, not a constant
        found = _with_shear(curve, shear)
        if found is not None:
            return found
    raise ComputationError(f"no shear among the first {MAX_SHEARS} separates the singular points of {curve}")


def _shears() -> Iterator[int]:
    yield 0
    for k in range(1, MAX_SHEARS // 2 + 1):
        yield k
        yield -k


def _with_shear(curve: flint.fmpz_mpoly, shear: int) -> list[ExactPoint] | None:
    """The points, or None when two singular points share ``t`` under this shear."""
    ctx = curve.context()
    t, y = ctx.gens()
    g = curve.compose(t - shear * y, y) if shear else curve
    gt, gy = g.derivative(0), g.derivative(1)
    candidates = g.resultant(gy, 1).gcd(gt.resultant(gy, 1)).gcd(g.resultant(gt, 1))
    points: list[ExactPoint] = []
    for factor, _ in _univariate(candidates).factor()[1]:
        if factor.degree() < 1:
            continue
        field = NumberField(factor)
        common = poly_gcd(field, *(_specialised(field, p) for p in (g, gt, gy)))
        if len(common) < 2:
            continue
        y_value = _single_root(field, common)
        if y_value is None:
            return None
        x_value = field.sub(field.gen(), field.mul(field.const(shear), y_value))
        points.append(ExactPoint(field, x_value, y_value, shear))
    return points


def _single_root(field: NumberField, monic: Sequence[Element]) -> Element | None:
    """``r`` if the monic ``monic`` is ``(y - r)**k`` (a point of multiplicity ``k + 1`` makes the
    gcd a power), else None: two singular points share ``t``."""
    k = len(monic) - 1
    root = field.mul(monic[k - 1], field.const(flint.fmpq(-1, k)))
    power = [field.one()]
    for _ in range(k):  # (y - root)**k, low to high
        power = [field.sub(a, field.mul(root, b)) for a, b in zip([field.zero()] + power, power + [field.zero()])]
    return root if all(field.reduce(a - b).is_zero() for a, b in zip(power, monic)) else None


def _univariate(poly: flint.fmpz_mpoly) -> flint.fmpz_poly:
    """A polynomial of the context's first generator alone, as an ``fmpz_poly``."""
    terms = {int(i): int(c) for (i, _), c in poly.to_dict().items()}
    return flint.fmpz_poly([terms.get(k, 0) for k in range(max(terms, default=0) + 1)])


def _specialised(field: NumberField, poly: flint.fmpz_mpoly) -> list[Element]:
    """``poly(t, y)`` at ``t`` the field's generator: a polynomial in ``y`` over the field."""
    by_power: dict[int, dict[int, int]] = {}
    for (i, j), c in poly.to_dict().items():
        by_power.setdefault(int(j), {})[int(i)] = int(c)
    size = max(by_power, default=-1) + 1
    return [field.reduce(flint.fmpq_poly([row.get(k, 0) for k in range(max(row) + 1)]))
            if (row := by_power.get(j)) else field.zero() for j in range(size)]
