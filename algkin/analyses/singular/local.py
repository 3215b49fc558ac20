"""What a singular point looks like: multiplicity, tangents, and for a double point its type.

The curve is expanded exactly about the point (its coordinates in ``Q[t]/(p)``):
``F(x0 + X, y0 + Y) = F_m + F_(m+1) + ...``, ``F_k`` the form of degree ``k``. The
multiplicity is ``m``; the tangents are the linear factors of ``F_m``, counted (distinct, and
real by Sturm's theorem at the point's embedding). A double point with ``F_2`` of nonzero
discriminant is a node, ``A_1``: a *crunode* when the Hessian determinant ``4ac - b**2``
(``F_2 = aX**2 + bXY + cY**2``) is negative (two real branches crossing), an *acnode* when
positive (an isolated real point). With ``F_2 = c*V**2`` a square the point is an ``A_k``,
``k >= 2``: by the splitting lemma ``F ~ c*V'**2 + g(W)``, where ``V = phi(W)`` solves
``F_V = 0`` as a power series and ``g(W) = F(W, phi(W)) = a*W**(k+1) + ...``. Even ``k``:
one real branch with a cusp (``A_2`` a cusp, ``A_4`` a ramphoid cusp); odd ``k``: two
branches tangent to each other, real when ``a`` and ``c`` differ in sign (``A_3`` a tacnode,
``A_5`` an oscnode), else an isolated point. An isolated singularity of a degree ``n`` curve has
Milnor number at most ``(n - 1)**2``, which bounds the series' length.

>>> import flint
>>> from .numberfield import NumberField
>>> q = NumberField(flint.fmpz_poly([0, 1]))                        # the rational point (0, 0)
>>> cusp = {(3, 0): -1, (0, 2): 1}                                   # y**2 - x**3
>>> describe(q, shift(q, cusp, q.zero(), q.zero()), 3, q.real_roots()[0])["kind"]
'cusp'
>>> tacnode = {(4, 0): -1, (0, 2): 1}                                # y**2 - x**4
>>> describe(q, shift(q, tacnode, q.zero(), q.zero()), 4, q.real_roots()[0])["a_k"]
3
"""

from __future__ import annotations

from collections.abc import Sequence
from math import comb
from typing import TypedDict

from ...system.roots import RealRoot
from .numberfield import Element, NumberField, poly_derivative, poly_gcd, real_root_count, trim

__all__ = ["shift", "multiplicity", "describe", "Local"]



class Tangents(TypedDict):
    distinct: int
    real: int


class Local(TypedDict, total=False):
    """A singular point's local type (a double point's type as found: some keys only)."""

    kind: str
    multiplicity: int
    a_k: int | None
    hessian_sign: int | None
    real_branches: int | None
    tangents: Tangents


Expansion = dict[tuple[int, int], Element]
_NAMES = {2: "cusp", 3: "tacnode", 4: "ramphoid cusp", 5: "oscnode"}
_MULTIPLE = {3: "triple point", 4: "quadruple point"}


def shift(field: NumberField, curve: dict[tuple[int, int], int], x0: Element, y0: Element) -> Expansion:
    """The coefficients of ``curve(x0 + X, y0 + Y)``, ``{(i, j): coefficient of X**i Y**j}``, nonzero ones."""
    degree = max(i + j for i, j in curve)
    xs, ys = _powers(field, x0, degree), _powers(field, y0, degree)
    out: dict[tuple[int, int], Element] = {}
    for (i, j), c in curve.items():
        for k in range(i + 1):
            for m in range(j + 1):
                term = field.mul(xs[i - k], ys[j - m]) * (c * comb(i, k) * comb(j, m))
                out[k, m] = out[k, m] + term if (k, m) in out else term
    return {key: value for key, value in ((key, field.reduce(v)) for key, v in out.items()) if not value.is_zero()}


def _powers(field: NumberField, value: Element, count: int) -> list[Element]:
    powers = [field.one()]
    for _ in range(count):
        powers.append(field.mul(powers[-1], value))
    return powers


def multiplicity(expansion: Expansion) -> int:
    """The degree of the lowest nonzero form (0 off the curve, 1 at a smooth point)."""
    return min(i + j for i, j in expansion)


def describe(field: NumberField, expansion: Expansion, degree: int, root: RealRoot) -> Local:
    """The point's local type (``root``: the real root of the field's polynomial it sits at)."""
    m = multiplicity(expansion)
    form = {i: c for (i, j), c in expansion.items() if i + j == m}  # X**i Y**(m - i)
    local: Local = {"multiplicity": m, "tangents": _tangents(field, form, m, root),
                    "kind": _MULTIPLE.get(m, f"point of multiplicity {m}"),
                    "a_k": None, "hessian_sign": None, "real_branches": None}
    if m == 2:  # its kind told apart
        local.update(_double(field, expansion, form, degree, root))
    return local


def _tangents(field: NumberField, form: dict[int, Element], m: int, root: RealRoot) -> Tangents:
    """Distinct and real tangent lines: roots of ``F_m(s, 1)``, and the line ``Y = 0`` where
    ``F_m(1, 0) = 0`` (the form's degree in ``s`` drops)."""
    f = trim(field, [form.get(i, field.zero()) for i in range(m + 1)])
    horizontal = 1 if len(f) - 1 < m else 0
    distinct = len(f) - len(poly_gcd(field, f, poly_derivative(field, f))) + horizontal
    return {"distinct": distinct, "real": real_root_count(field, f, root) + horizontal}


def _double(field: NumberField, expansion: Expansion, form: dict[int, Element], degree: int,
            root: RealRoot) -> Local:
    """Node (crunode, acnode) by the Hessian's sign; else the ``A_k`` and its real branches."""
    zero = field.zero()
    a, b, c = form.get(2, zero), form.get(1, zero), form.get(0, zero)
    hessian = field.sub(field.mul(a, c) * 4, field.mul(b, b))
    sign = root.sign(hessian)
    if sign:
        kind = "crunode" if sign < 0 else "acnode"
        return {"kind": kind, "a_k": 1, "hessian_sign": sign, "real_branches": 2 if sign < 0 else 0}
    found = _splitting(field, expansion, a, b, c, degree)
    if found is None:  # past the Milnor bound: cannot happen on a squarefree curve, said honestly if it does
        return {"kind": "higher double point", "hessian_sign": 0}
    k, lead, square = found
    if k % 2 == 0:
        return {"kind": _NAMES.get(k, f"A_{k} cusp"), "a_k": k, "hessian_sign": 0, "real_branches": 1}
    real = root.sign(lead) != root.sign(square)
    kind = _NAMES.get(k, f"A_{k} tacnode") if real else "isolated point"
    return {"kind": kind, "a_k": k, "hessian_sign": 0, "real_branches": 2 if real else 0}


def _splitting(field: NumberField, expansion: Expansion, a: Element, b: Element, c: Element,
               degree: int) -> tuple[int, Element, Element] | None:
    """``(k, a, c)`` of ``F ~ c*V**2 + a*W**(k+1)``, or None past the Milnor bound."""
    h = _tangent_frame(field, expansion, a, b, c)
    square = h.get((0, 2), field.zero())
    n = max(i + j for i, j in h)
    limit = (degree - 1) ** 2 + 2
    rows = [[h.get((i, j), field.zero()) for i in range(limit)] for j in range(n + 1)]  # rows[j]: V**j's series
    phi = [field.zero()] * limit
    inverse = field.inverse(square * 2)
    correct = 2  # phi = 0 is right to O(W**2): the tangent is V = 0
    while True:
        bound = min(2 * correct, limit)
        g = _horner(field, rows, phi, bound)
        lead = next((i for i, v in enumerate(g) if not v.is_zero()), None)
        if lead is not None:
            return lead - 1, g[lead], square
        if bound >= limit:
            return None
        slope = _horner(field, [[r[i] * j for i in range(limit)] for j, r in enumerate(rows)][1:], phi, correct + 1)
        phi = [field.sub(p, field.mul(s, inverse)) for p, s in zip(phi, slope + [field.zero()] * limit)]
        correct += 1


def _tangent_frame(field: NumberField, expansion: Expansion, a: Element, b: Element, c: Element) -> Expansion:
    """The expansion in ``(W, V)`` with the doubled tangent ``V = 0``: ``{(W power, V power): coefficient}``."""
    if c.is_zero():  # F_2 = a X**2: the tangent is X = 0
        return {(j, i): v for (i, j), v in expansion.items()}
    beta = field.div(b, c * 2)  # F_2 = c (Y + beta X)**2; V = Y + beta X, W = X
    out: Expansion = {}
    for (i, j), value in expansion.items():  # X**i (V - beta W)**j
        for k in range(j + 1):
            term = field.mul(value, _power(field, -beta, j - k)) * comb(j, k)
            key = (i + j - k, k)
            out[key] = field.add(out[key], term) if key in out else term
    return out


def _power(field: NumberField, value: Element, n: int) -> Element:
    result = field.one()
    for _ in range(n):
        result = field.mul(result, value)
    return result


def _horner(field: NumberField, rows: Sequence[Sequence[Element]], phi: Sequence[Element],
            bound: int) -> list[Element]:
    """``sum_j rows[j](W) * phi(W)**j`` to ``O(W**bound)``."""
    total = [field.zero()] * bound
    for row in reversed(rows):
        total = _series_mul(field, total, phi, bound)
        total = [field.add(t, r) for t, r in zip(total, row[:bound])]
    return [field.reduce(t) for t in total]


def _series_mul(field: NumberField, a: Sequence[Element], b: Sequence[Element], bound: int) -> list[Element]:
    out = [field.zero()] * bound
    for i, ai in enumerate(a[:bound]):
        if ai.is_zero():
            continue
        for j in range(bound - i):
            if not b[j].is_zero():
                out[i + j] = field.add(out[i + j], field.mul(ai, b[j]))
    return out
