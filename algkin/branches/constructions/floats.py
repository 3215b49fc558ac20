"""Float kernels free of cancellation, for the implicit points' stable evaluators."""

from collections.abc import Callable

import numpy as np
import sympy

from ...scene.implicit.base import FloatArray

__all__ = ["heron_area", "stable_quadratic"]


def heron_area(a: FloatArray | float, b: FloatArray | float, c: FloatArray | float) -> FloatArray:
    """Area of the triangle with sides a, b, c (arrays), Kahan's ordering; nan if it cannot close."""
    low, high = np.minimum(a, b), np.maximum(a, b)
    big, small = np.maximum(high, c), np.minimum(low, c)
    middle = np.maximum(low, np.minimum(high, c))  # the median, exactly (no arithmetic)
    product: FloatArray = (big + (middle + small)) * (small - (big - middle)) * (small + (big - middle)) \
        * (big + (middle - small))
    with np.errstate(invalid="ignore"):
        return 0.25 * np.sqrt(product)


def stable_quadratic(a2: sympy.Expr | int, a1: sympy.Expr | int,
                     a0: sympy.Expr | int) -> Callable[[FloatArray], FloatArray]:
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


def _split(value: sympy.Expr) -> tuple[float, float]:
    """An exact real as two floats, ``high + low``, good to about 106 bits."""
    precise = sympy.N(value, 40)
    high = float(precise)
    return high, float(sympy.N(precise - sympy.Float(high, 40), 20))
