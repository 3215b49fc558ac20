"""A branch evaluated fast and without cancellation, from the input angles.

Each dyad point is ``X = M + a*d + sigma*h*rot90(d)`` with the midpoint ``M = (P + Q)/2``
and ``d = Q - P`` taken *exactly, symbolically* (a mechanism far from the origin loses
nothing: the offset cancels before any rounding), ``a = (l1**2 - l2**2) / (2|d|**2)`` and
``h = sqrt(F+ * F-) / (2|d|**2)``
with ``F+ = (l1 + l2)**2 - |d|**2`` (zero when the dyad is extended) and
``F- = |d|**2 - (l1 - l2)**2`` (zero when folded). Where the triangle cannot close the
result is nan.

Every input enters through one transcendental, ``t = tan(theta/2)`` (numpy's is
vectorised and correctly rounded to within an ulp), with ``c = (1 - t**2) w``,
``s = 2 t w``, ``w = 1 / (1 + t**2)``. When ``|d|**2 = K + beta*c + gamma*s`` (a dyad on a
crank and a ground pivot) each factor is ``q(t) * w`` with ``q`` a quadratic in ``t``
whose coefficients are exact rationals, evaluated in the form that cannot cancel: as
``a2 (t - r1)(t - r2)`` through its real roots (the toggles, each rounded once), or as
``a2 ((t - m)**2 + e)`` when it has none. Near a dead centre of a near-change-point
four-bar, ``(l1 + l2)**2 - |d|**2`` is then a sum of positive terms instead of the
difference of two large ones. Other dyads use Kahan's sorted-Heron area, accurate to a
few ulps even for needle triangles.

The base coordinates are compiled once (``sympy.lambdify`` with common subexpressions
shared) and the samples are run in cache-sized chunks.

>>> import numpy as np
>>> from algkin.scene import load_scene, compile_scene
>>> from algkin.branches import closed_forms
>>> compiled = compile_scene(load_scene("chebyshev-lambda"), ["B"])
>>> stable = StableBranch(compiled, closed_forms(compiled)[0])
>>> point = stable(np.array([0.0]))   # crank at 0 deg: A = (1, 0), D = (2, 0)
>>> round(float(point["B_x"][0]), 12), round(float(point["B_y"][0]), 12)
(1.5, 2.449489742783)
"""

import numpy as np
import sympy

from ..scene.compile import SliderSpec
from ..system import symbol
from .closed_form import reduce_on_circles

__all__ = ["StableBranch", "heron_area", "stable_quadratic"]

CHUNK = 4096  # samples per pass: temporaries stay in cache and below malloc's mmap threshold


def heron_area(a, b, c):
    """Area of the triangle with sides a, b, c (arrays), Kahan's ordering; nan if it cannot close."""
    low, high = np.minimum(a, b), np.maximum(a, b)
    big, small = np.maximum(high, c), np.minimum(low, c)
    middle = np.maximum(low, np.minimum(high, c))  # the median, exactly (no arithmetic)
    product = (big + (middle + small)) * (small - (big - middle)) * (small + (big - middle)) \
        * (big + (middle - small))
    with np.errstate(invalid="ignore"):
        return 0.25 * np.sqrt(product)


def stable_quadratic(a2, a1, a0):
    """``t -> a2 t**2 + a1 t + a0`` (exact rational coefficients) in a form free of cancellation.

    >>> q = stable_quadratic(sympy.Rational(1, 10**4), 0, 16)   # no real roots: a sum
    >>> float(q(np.array([1e3]))[0])
    116.0
    >>> q = stable_quadratic(1, -3, 2)                             # (t - 1)(t - 2)
    >>> float(q(np.array([1 + 2**-40]))[0]) == -2**-40 * (1 - 2**-40)
    True
    """
    a2, a1, a0 = (sympy.Rational(v) for v in (a2, a1, a0))
    if a2 == 0:
        if a1 == 0:
            return lambda t: np.full_like(t, float(a0))
        root = float(-a0 / a1)
        return lambda t: float(a1) * (t - root)
    disc = a1**2 - 4 * a2 * a0
    if disc < 0:
        middle, rise = float(-a1 / (2 * a2)), float(-disc / (4 * a2**2))
        return lambda t: float(a2) * ((t - middle) ** 2 + rise)
    (h1, l1), (h2, l2) = (_split((-a1 + sign * sympy.sqrt(disc)) / (2 * a2)) for sign in (1, -1))
    # t - r as (t - high) - low: t - high is exact near the root (Sterbenz), so the root's own
    # rounding no longer limits the distance to a toggle
    return lambda t: float(a2) * (((t - h1) - l1) * ((t - h2) - l2))


def _split(value):
    """An exact real as two floats, ``high + low``, good to about 106 bits."""
    precise = sympy.N(value, 40)
    high = float(precise)
    return high, float(sympy.N(precise - sympy.Float(high, 40), 20))


class _Dyad:
    """One dyad's evaluator: its compiled base, its lengths, and the factored span if it has one."""

    def __init__(self, dyad, fix, arguments, half_angles, sigma):
        (px, py), (qx, qy) = dyad.base_p, dyad.base_q
        base = [fix(e) for e in ((px + qx) / 2, (py + qy) / 2, qx - px, qy - py)]  # midpoint, exactly
        self.unknowns = dyad.unknowns
        self.base = sympy.lambdify(arguments, base, "numpy", cse=True)
        l1, l2 = (fix(v) for v in dyad.lengths)
        self.l1, self.l2, self.sigma = float(l1), float(l2), sigma
        self.lengths_term = float(l1**2 - l2**2)
        self.input, self.factors = _factored_span(fix(base[2] ** 2 + base[3] ** 2), l1, l2, half_angles)

    def __call__(self, values, half):
        mx, my, dx, dy = self.base(*values)
        if self.factors is None:
            span = np.hypot(dx, dy)
            span2 = span * span
            height = 2 * heron_area(self.l1, self.l2, span) / span2
        else:
            t, w = half[self.input]
            extended, folded, span2 = (q(t) for q in self.factors)
            with np.errstate(invalid="ignore"):  # w cancels from the height: two roundings fewer
                height = np.sqrt(extended * folded) / (2 * span2)
            span2 = span2 * w
        # both scaled by 1/|d|: no square root of |d|**2 is taken and undone
        across = self.sigma * height
        if not self.lengths_term:  # equal lengths: the point is straight across from the midpoint
            return mx - across * dy, my + across * dx
        along = self.lengths_term / (2 * span2)
        return mx + (along * dx - across * dy), my + (along * dy + across * dx)


def _factored_span(span2, l1, l2, half_angles):
    """``(input index, [F+, F-, |d|**2] as quadratics in t)`` if ``|d|**2 = K + beta c + gamma s``."""
    for index, (c, s) in enumerate(half_angles):
        if not span2.free_symbols <= {c, s}:
            continue
        poly = sympy.Poly(span2, c, s)
        if poly.total_degree() > 1:
            return None, None
        k, beta, gamma = (poly.coeff_monomial(m) for m in (1, c, s))
        # k + beta c + gamma s, times 1 + t**2:  (k - beta) t**2 + 2 gamma t + (k + beta)
        quadratic = lambda k, beta, gamma: stable_quadratic(k - beta, 2 * gamma, k + beta)  # noqa: E731
        return index, [quadratic((l1 + l2) ** 2 - k, -beta, -gamma),
                       quadratic(k - (l1 - l2) ** 2, beta, gamma), quadratic(k, beta, gamma)]
    return None, None


class _Slider:
    """One slider's evaluator: the root of its quadratic that cannot cancel, the other from their product.

    On the line ``X = P + a d`` at distance l from Q (``w = Q - P``):
    ``a |d|**2 = dot(d, w) + sigma sqrt(disc)``, ``disc = l**2 |d|**2 - cross(d, w)**2``;
    the two roots multiply to ``(|w|**2 - l**2) / |d|**2``.
    """

    def __init__(self, slider, fix, arguments, sigma):
        (px, py), (qx, qy) = slider.through, slider.center
        base = [fix(e) for e in (px, py, qx - px, qy - py)]
        self.unknowns = slider.unknowns
        self.base = sympy.lambdify(arguments, base, "numpy", cse=True)
        dx, dy = (fix(v) for v in slider.direction)
        length, norm = fix(slider.length), sympy.sqrt(dx**2 + dy**2)
        self.dx, self.dy, self.norm2, self.sigma = float(dx), float(dy), float(dx**2 + dy**2), sigma
        self.reach, self.length2 = float(length * norm), float(length**2)

    def __call__(self, values, half):
        px, py, wx, wy = self.base(*values)
        dot, cross = self.dx * wx + self.dy * wy, self.dx * wy - self.dy * wx
        with np.errstate(invalid="ignore"):
            root = np.sqrt((self.reach - cross) * (self.reach + cross))
        larger = dot + np.copysign(root, dot)  # no cancellation: both terms of one sign
        with np.errstate(divide="ignore", invalid="ignore"):
            along = np.where(np.copysign(1.0, dot) == self.sigma, larger / self.norm2,
                             (wx * wx + wy * wy - self.length2) / larger)
        return px + along * self.dx, py + along * self.dy


class StableBranch:
    """Vectorised float64 evaluation of every dyad and slider point of ``branch`` (dimensions at defaults)."""

    def __init__(self, compiled, branch):
        defaults = {symbol(n): sympy.Rational(str(v)) for n, v in compiled.parameter_values.items()}
        self.half_angles = [tuple(symbol(v) for v in pair) for pair in compiled.system.inputs.values()]
        fix = lambda e: reduce_on_circles(sympy.sympify(e).xreplace(defaults), self.half_angles)  # noqa: E731
        arguments = [v for pair in self.half_angles for v in pair]
        self.dyads = []
        for spec in compiled.implicit or compiled.dyads:
            sigma = 1.0 if branch.labels[spec.point] == spec.labels[0] else -1.0
            if isinstance(spec, SliderSpec):
                self.dyads.append(_Slider(spec, fix, list(arguments), sigma))
            else:
                self.dyads.append(_Dyad(spec, fix, list(arguments), self.half_angles, sigma))
            arguments += [symbol(u) for u in spec.unknowns]

    def __call__(self, *angles):
        """Dyad coordinates (unknown -> array) from each input's angles in radians."""
        angles = np.broadcast_arrays(*(np.asarray(a, dtype=float) for a in angles))
        flat = [a.ravel() for a in angles]
        out = {u: np.empty(flat[0].size) for d in self.dyads for u in d.unknowns}
        for start in range(0, flat[0].size, CHUNK):
            part = slice(start, start + CHUNK)
            for unknown, value in self._chunk([a[part] for a in flat]).items():
                out[unknown][part] = value
        return {u: v.reshape(angles[0].shape) for u, v in out.items()}

    def _chunk(self, angles):
        values, half = [], []
        for theta in angles:
            t = np.tan(0.5 * theta)
            w = 1 / (1 + t * t)
            values += [(1 - t) * (1 + t) * w, 2 * t * w]
            half.append((t, w))
        result = {}
        for dyad in self.dyads:
            x, y = dyad(values, half)
            values += [x, y]
            result.update(zip(dyad.unknowns, (x, y)))
        return result
