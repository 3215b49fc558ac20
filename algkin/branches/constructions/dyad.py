"""A dyad's branch algebra (``DyadSpec``: the point at distance l1 from P and l2 from Q, left or right of P -> Q).

Closed form. ``X = P + a*d + sigma*h*rot90(d)`` with ``d = Q - P``,
``a = (l1**2 - l2**2 + |d|**2) / (2|d|**2)`` and ``h = sqrt(disc) / (2|d|**2)``, where
``disc = ((l1+l2)**2 - |d|**2) * (|d|**2 - (l1-l2)**2)``. Since
``cross(d, X - P) = sigma*h*|d|**2``, ``sigma = +1`` is the point left of P -> Q: the
label is the geometry, not the sign in a quadratic formula. Both coordinates come from
the one expression, so they are paired by construction.

Toggles: *extended* where ``|PQ| = l1 + l2`` (both bars in line, pointing apart),
*folded* where ``|PQ| = |l1 - l2|`` (in line, one over the other).

Stable floats. ``X = M + a*d + sigma*h*rot90(d)`` with the midpoint ``M = (P + Q)/2`` and
``d = Q - P`` taken *exactly, symbolically* (a mechanism far from the origin loses
nothing: the offset cancels before any rounding), ``a = (l1**2 - l2**2) / (2|d|**2)`` and
``h = sqrt(F+ * F-) / (2|d|**2)`` with ``F+ = (l1 + l2)**2 - |d|**2`` (zero when the dyad
is extended) and ``F- = |d|**2 - (l1 - l2)**2`` (zero when folded). Where the triangle
cannot close the result is nan. When ``|d|**2 = K + beta*c + gamma*s`` (a dyad on a crank
and a ground pivot) each factor is ``q(t) * w`` with ``q`` a quadratic in the half-angle
``t`` whose coefficients are exact rationals (``stable_quadratic``): near a dead centre of a
near-change-point four-bar, ``(l1 + l2)**2 - |d|**2`` is then a sum of positive terms
instead of the difference of two large ones. Other dyads use Kahan's sorted-Heron area,
accurate to a few ulps even for needle triangles.
"""

from collections.abc import Callable, Sequence

import attrs
import flint
import numpy as np
import sympy

from ...evaluate.program import numpy_function
from ...scene.implicit import DyadSpec
from ...scene.implicit.algebra import HALF, Circles, reduce_exact_on_circles
from ...system.convert import from_terms, to_flint
from ...scene.implicit.base import FloatArray, Point
from ..algebra import product, product_root, reducer, tidy_product, tidy_ratio, total, unsplit_root
from ..tower import Tower, Unsupported, roots_in
from .base import BranchAlgebra, Fix, HalfAngle, Mode, StableEvaluator, Substitution
from .floats import heron_area, stable_quadratic

__all__ = ["DyadAlgebra", "NestedModes"]

Factored = tuple[int, list[Callable[[FloatArray], FloatArray]]]  # an input, quadratics in its t


@attrs.frozen
class DyadAlgebra(BranchAlgebra):
    """A compiled dyad's closed form, toggles and stable floats."""

    spec: DyadSpec

    def modes(self, substitution: Substitution, *, inputs: Circles) -> Mode:
        base = [e.xreplace(substitution) for e in (*self.spec.base_p, *self.spec.base_q)]
        if roots_in(base):  # built on an earlier point's root: sympy's expansion reads (and costs) far worse
            try:
                return _nested_modes(base, self.spec.lengths, inputs)
            except Unsupported:
                pass
        l1, l2 = self.spec.lengths
        reduced = _reduced_in_flint(base, (l1, l2), inputs)
        if reduced is None:
            reduce = reducer(substitution, inputs)
            px, py = (reduce(v) for v in self.spec.base_p)
            qx, qy = (reduce(v) for v in self.spec.base_q)
            dx, dy = reduce(qx - px), reduce(qy - py)
            dist2 = reduce(dx**2 + dy**2)
            extended, folded = reduce((l1 + l2) ** 2 - dist2), reduce(dist2 - (l1 - l2) ** 2)
        else:
            px, py, qx, qy, dx, dy, dist2, extended, folded = reduced
        along = tidy_ratio((l1**2 - l2**2 + dist2) / (2 * dist2))
        disc = tidy_product(extended, folded)
        spread = tidy_product(dist2)
        # both modes'; ``product``: sympy's ``/ 2`` asks the root's assumptions again (a millisecond)
        half_root = product(HALF, product_root(disc))

        def mode(sigma: int) -> tuple[Point, sympy.Expr]:
            # sympy's products and sums, put together where that is all they do (``product``, ``total``)
            across = product(sigma, half_root, 1 / spread)
            return (total(px, product(along, dx), product(-1, across, dy)),
                    total(py, product(along, dy), product(across, dx))), disc
        return mode

    def toggle_conditions(self) -> dict[str, sympy.Expr]:
        (px, py), (qx, qy) = self.spec.base_p, self.spec.base_q
        span = (qx - px) ** 2 + (qy - py) ** 2
        l1, l2 = self.spec.lengths
        return {"extended": (l1 + l2) ** 2 - span, "folded": span - (l1 - l2) ** 2}

    def stable_evaluator(self, *, fix: Fix, arguments: Sequence[sympy.Symbol], half_angles: Circles,
                         sigma: float) -> StableEvaluator:
        return _Stable(self.spec, fix=fix, arguments=arguments, half_angles=half_angles, sigma=sigma)


def _reduced_in_flint(base: Sequence[sympy.Expr], lengths: tuple[sympy.Expr, sympy.Expr],
                      inputs: Circles) -> list[sympy.Expr] | None:
    """``modes``' polynomials, each reduced on the circles (``reduce_on_circles``, the same
    expressions), computed in one python-flint ring from the base's coordinates ``(px, py, qx,
    qy)``: ``px, py, qx, qy, dx, dy, |d|**2, (l1 + l2)**2 - |d|**2, |d|**2 - (l1 - l2)**2``. Each
    went to python-flint and back, a sympy expression of the last built between (most of the rest
    of a cold dyad's modes). None where they are not polynomials over the rationals (sympy's path)."""
    circles = [v for circle in inputs for v in circle]
    every = set().union(*(e.free_symbols for e in (*base, *lengths)), circles)
    symbols = sorted(every, key=lambda v: v.name)
    names = [v.name for v in symbols]
    if len(set(names)) != len(names):
        return None
    ring = flint.fmpq_mpoly_ctx.get(tuple(names), "lex")
    try:
        px, py, qx, qy, l1, l2 = (to_flint(e, ring) for e in (*base, *lengths))
    except TypeError:  # a root (a length's), a quotient: sympy's reduction
        return None
    def reduce(poly: flint.fmpq_mpoly) -> flint.fmpq_mpoly:
        reduced = reduce_exact_on_circles(poly, inputs)
        assert reduced is not None  # every input's cos and sin are in the ring
        return reduced
    px, py, qx, qy = (reduce(v) for v in (px, py, qx, qy))
    dx, dy = reduce(qx - px), reduce(qy - py)
    dist2 = reduce(dx * dx + dy * dy)
    polynomials = [px, py, qx, qy, dx, dy, dist2, reduce((l1 + l2) ** 2 - dist2), reduce(dist2 - (l1 - l2) ** 2)]
    return [from_terms(p.to_dict(), symbols) for p in polynomials]


class NestedModes:
    """A dyad's ``Mode`` over a base that holds square roots, with the ``Tower`` it is built in (a point
    defined on it is built there too, from the values it remembers)."""

    def __init__(self, tower: Tower, mode: Mode) -> None:
        self.tower, self._mode = tower, mode

    def __call__(self, sigma: int) -> tuple[Point, sympy.Expr]:
        return self._mode(sigma)


def _nested_modes(base: list[sympy.Expr], lengths: tuple[sympy.Expr, sympy.Expr], inputs: Circles) -> NestedModes:
    """``modes`` over a base that holds square roots, in a ``Tower``. With the base over one
    denominator ``E`` (``P = p/E``, ``Q = q/E``, ``a = q - p``, ``G = |a|**2``: ``|PQ|**2 = G/E**2``),
    the closed form of the module's first paragraph is
    ``X = (G (p + q) + (l1**2 - l2**2) E**2 a + sigma r rot90(a)) / (2 G E)`` with ``r = sqrt(H+ H-)``,
    ``H+ = (l1 + l2)**2 E**2 - G`` (zero extended), ``H- = G - (l1 - l2)**2 E**2`` (zero folded):
    ``r = E**2 sqrt(F+ F-)``, the discriminant ``H+ H-`` without the positive ``E**4``."""
    tower = Tower([*base, *lengths], inputs, new_roots=1)
    (px, py, qx, qy), common = tower.over_common([tower.value(e) for e in base])
    l1, l2 = (tower.value(v) for v in lengths)
    ax, ay, square = qx - px, qy - py, common * common
    spread = ax * ax + ay * ay
    extended, folded = (l1 + l2) * (l1 + l2) * square - spread, spread - (l1 - l2) * (l1 - l2) * square
    (ke, he), (kf, hf) = tower.primitive(extended), tower.primitive(folded)
    n, d = (ke * kf).as_numer_denom()  # sqrt(k he hf) = sqrt(n d he hf) / d
    root = tower.new_root(extended * folded * int(d) ** 2, unsplit_root(sympy.Mul(n * d, he, hf))) / int(d)
    along = (l1 * l1 - l2 * l2) * square
    below = 2 * spread * common
    discriminant = sympy.Mul(he, hf)  # its sign (the contents are positive)

    def mode(sigma: int) -> tuple[Point, sympy.Expr]:
        x = (spread * (px + qx) + along * ax - sigma * root * ay) / below
        y = (spread * (py + qy) + along * ay + sigma * root * ax) / below
        return (tower.expr(x, remember=True), tower.expr(y, remember=True)), discriminant
    return NestedModes(tower, mode)


class _Stable:
    """One dyad's evaluator: its compiled base, its lengths, and the factored span if it has one."""

    def __init__(self, dyad: DyadSpec, *, fix: Fix, arguments: Sequence[sympy.Symbol], half_angles: Circles,
                 sigma: float) -> None:
        (px, py), (qx, qy) = dyad.base_p, dyad.base_q
        base = [fix(e) for e in ((px + qx) / 2, (py + qy) / 2, qx - px, qy - py)]  # midpoint, exactly
        self.unknowns = dyad.unknowns
        self.base = numpy_function(arguments, base)
        l1, l2 = (fix(v) for v in dyad.lengths)
        self.sigma = sigma
        # a length input (an actuator, a string) moves a length: evaluated per sample then
        self.moving = None if l1.is_number and l2.is_number else \
            numpy_function(arguments, [l1, l2, l1**2 - l2**2])
        self.l1, self.l2, self.lengths_term = (float(v) if v.is_number else 0.0 for v in (l1, l2, l1**2 - l2**2))
        self.factored = _factored_span(fix(base[2] ** 2 + base[3] ** 2), l1, l2, half_angles) \
            if self.moving is None else None

    def __call__(self, values: Sequence[FloatArray], half: Sequence[HalfAngle]) -> tuple[FloatArray, FloatArray]:
        mx, my, dx, dy = self.base(*values)
        l1, l2, lengths_term = (self.l1, self.l2, self.lengths_term) if self.moving is None \
            else self.moving(*values)
        if self.factored is None:
            span = np.hypot(dx, dy)
            span2 = span * span
            height = 2 * heron_area(l1, l2, span) / span2
        else:
            index, factors = self.factored
            t, w = half[index]
            extended, folded, span2 = (q(t) for q in factors)
            with np.errstate(invalid="ignore"):  # w cancels from the height: two roundings fewer
                height = np.sqrt(extended * folded) / (2 * span2)
            span2 = span2 * w
        # both scaled by 1/|d|: no square root of |d|**2 is taken and undone
        across = self.sigma * height
        if self.moving is None and not lengths_term:  # equal lengths: straight across from the midpoint
            return mx - across * dy, my + across * dx
        along = lengths_term / (2 * span2)
        return mx + (along * dx - across * dy), my + (along * dy + across * dx)


def _factored_span(span2: sympy.Expr, l1: sympy.Expr, l2: sympy.Expr,
                   half_angles: Circles) -> Factored | None:
    """``(input index, [F+, F-, |d|**2] as quadratics in t)`` if ``|d|**2 = K + beta c + gamma s``."""
    for index, (c, s) in enumerate(half_angles):
        if not span2.free_symbols <= {c, s}:
            continue
        poly = sympy.Poly(span2, c, s)
        if poly.total_degree() > 1:
            return None
        k, beta, gamma = (poly.coeff_monomial(m) for m in (1, c, s))
        return index, [_in_half_angle((l1 + l2) ** 2 - k, -beta, -gamma),
                       _in_half_angle(k - (l1 - l2) ** 2, beta, gamma), _in_half_angle(k, beta, gamma)]
    return None


def _in_half_angle(k: sympy.Expr, beta: sympy.Expr, gamma: sympy.Expr) -> Callable[[FloatArray], FloatArray]:
    """``k + beta c + gamma s`` times ``1 + t**2``: ``(k - beta) t**2 + 2 gamma t + (k + beta)``, stably."""
    return stable_quadratic(k - beta, 2 * gamma, k + beta)
