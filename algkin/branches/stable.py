"""A branch evaluated without cancellation: local frame and the sorted-Heron half-chord.

Each dyad point is ``X = P + (a*d + sigma*h*rot90(d)) / |d|`` with ``d = Q - P`` taken as
the *exact symbolic difference* (a mechanism far from the origin loses nothing: the
offset cancels before any rounding), ``|d| = hypot(d)``, the along-distance
``a = (|d|**2 + (l1 - l2)*(l1 + l2)) / (2|d|)`` and the height ``h = 2*area/|d|`` of the
triangle (l1, l2, |d|), its area by Kahan's sorted Heron formula, accurate to a few ulps
even for needle triangles. Where the triangle cannot close the result is nan.

>>> import numpy as np
>>> from algkin.scene import load_scene, compile_scene
>>> from algkin.branches import closed_forms
>>> compiled = compile_scene(load_scene("chebyshev-lambda"), ["B"])
>>> stable = StableBranch(compiled, closed_forms(compiled)[0])
>>> point = stable(np.array([1.0]), np.array([0.0]))   # crank at 0 deg: A = (1, 0), D = (2, 0)
>>> round(float(point["B_x"][0]), 12), round(float(point["B_y"][0]), 12)
(1.5, 2.449489742783)
"""

import numpy as np
import sympy

from ..evaluate import NUMPY, evaluate
from ..system import symbol
from .closed_form import reduce_on_circles

__all__ = ["StableBranch", "heron_area"]


def heron_area(a, b, c):
    """Area of the triangle with sides a, b, c (arrays), Kahan's ordering; nan if it cannot close."""
    low, high = np.minimum(a, b), np.maximum(a, b)
    big, small = np.maximum(high, c), np.minimum(low, c)
    middle = np.maximum(low, np.minimum(high, c))  # the median, exactly (no arithmetic)
    product = (big + (middle + small)) * (small - (big - middle)) * (small + (big - middle)) \
        * (big + (middle - small))
    with np.errstate(invalid="ignore"):
        return 0.25 * np.sqrt(product)


class StableBranch:
    """Vectorised float64 evaluation of every dyad point of ``branch`` (dimensions at defaults)."""

    def __init__(self, compiled, branch):
        defaults = {symbol(n): sympy.Rational(str(v)) for n, v in compiled.parameter_values.items()}
        inputs = [tuple(symbol(v) for v in pair) for pair in compiled.system.inputs.values()]
        fix = lambda e: reduce_on_circles(sympy.sympify(e).xreplace(defaults), inputs)  # noqa: E731
        self.inputs = list(compiled.system.inputs.values())
        self.dyads = []
        for dyad in compiled.dyads:
            (px, py), (qx, qy) = dyad.base_p, dyad.base_q
            l1, l2 = (float(fix(v)) for v in dyad.lengths)
            sigma = 1.0 if branch.labels[dyad.point] == "left" else -1.0
            self.dyads.append((dyad.unknowns, fix(px), fix(py), fix(qx - px), fix(qy - py), l1, l2, sigma))

    def __call__(self, *cos_sin):
        """Dyad coordinates (unknown -> array) from each input's cos and sin arrays."""
        values = {}
        for (c, s), (cos, sin) in zip(self.inputs, zip(cos_sin[::2], cos_sin[1::2])):
            values[c], values[s] = cos, sin
        shape = np.shape(cos_sin[0])
        for (x, y), px, py, dx, dy, l1, l2, sigma in self.dyads:
            px, py, dx, dy = (np.broadcast_to(evaluate(e, values, NUMPY), shape) for e in (px, py, dx, dy))
            span = np.hypot(dx, dy)
            along = (span * span + (l1 - l2) * (l1 + l2)) / (2 * span)
            height = 2 * heron_area(l1, l2, span) / span
            values[x] = px + (along * dx - sigma * height * dy) / span
            values[y] = py + (along * dy + sigma * height * dx) / span
        return {u: values[u] for d in self.dyads for u in d[0]}
