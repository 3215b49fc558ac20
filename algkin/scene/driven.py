"""Inputs geared to others: cos and sin of ``k*t`` as polynomials in those of ``t``.

A driven input ``t2 = { driven_by = "t1", ratio = "k" }`` has no variables of its own: for an
integer ``k``, ``cos(k t) = T_k(cos t)`` and ``sin(k t) = sin t * U_{k-1}(cos t)`` (Chebyshev's
polynomials of the first and second kind), and a negative ``k`` turns the other way
(``sin(-k t) = -sin(k t)``): the system stays polynomial, in the root input's ``c_t1, s_t1``,
and each form is already reduced on its unit circle (no ``s**2``).

>>> c, s = sympy.symbols("c s")
>>> multiple_angle(2, c, s)
(2*c**2 - 1, 2*c*s)
>>> multiple_angle(-3, c, s)
(4*c**3 - 3*c, -s*(4*c**2 - 1))
"""

from collections.abc import Mapping

import sympy

from .model import Scene

__all__ = ["multiple_angle", "root_of", "driven_angles"]

Pair = tuple[sympy.Expr, sympy.Expr]


def multiple_angle(k: int, c: sympy.Expr, s: sympy.Expr) -> Pair:
    """``(cos(k t), sin(k t))`` as polynomials in ``c = cos t``, ``s = sin t``, for an integer ``k`` (not 0)."""
    n = abs(k)
    cos = sympy.chebyshevt_poly(n, c)
    sin = s * sympy.chebyshevu_poly(n - 1, c)
    return cos, sin if k > 0 else -sin


def root_of(scene: Scene, name: str) -> tuple[str, int]:
    """``(input, ratio)``: the input at the root of ``name``'s chain of drivers, and ``name`` as a
    multiple of it (an input that no gear drives is its own root, ratio 1)."""
    ratio = 1
    while name in scene.driven:
        ratio *= int(scene.driven[name].ratio)
        name = scene.driven[name].driver
    return name, ratio


def driven_angles(scene: Scene, pairs: Mapping[str, Pair]) -> dict[str, Pair]:
    """Every driven input whose root is in ``pairs`` (input -> its cos and sin) -> its own cos and sin."""
    angles: dict[str, Pair] = {}
    for name in scene.driven:
        root, ratio = root_of(scene, name)
        if root in pairs:
            angles[name] = multiple_angle(ratio, *pairs[root])
    return angles
