"""A slider's branch algebra (``SliderSpec``: the point on the line through P with direction d at
distance l from Q, ahead or behind).

The direction is fixed (``direction = [dx, dy]``) or moves (``toward = R``: ``d = R - P``, in
system variables when P or R moves); every formula below holds for either.

Closed form. ``X = P + (dot(d, w) + sigma*sqrt(disc)) / |d|**2 * d`` with ``w = Q - P`` and
``disc = l**2*|d|**2 - cross(d, w)**2``. Since ``dot(d, X - Q) = sigma*sqrt(disc)``,
``sigma = +1`` is the point ahead of the foot of the perpendicular from Q, along d.

Toggles: *tangent* where the circle about Q touches the line, ``cross(d, w)**2 = l**2 |d|**2``.

Stable floats: the root of the quadratic that cannot cancel, the other from their product,
``(|w|**2 - l**2) / |d|**2``. A fixed direction enters as float constants, a moving one
(``d = R - P`` taken exactly, symbolically, before any rounding) is compiled with P and Q.

>>> from sympy import Integer, symbols
>>> from algkin.scene.implicit import SliderSpec
>>> c, s = symbols("c s", real=True)
>>> O = (Integer(0), Integer(0))
>>> spec = SliderSpec("B", ("B_x", "B_y"), "ahead", through=O, direction=(2*c, 2*s), center=O, length=Integer(3))
>>> SliderAlgebra(spec).closed_form({}, sigma=1, inputs=[(c, s)])[0]  # toward the crank tip (2c, 2s), 3 from O
(3*c, 3*s)
"""

from collections.abc import Sequence

import attrs
import numpy as np
import sympy

from ...evaluate.program import numpy_function
from ...scene.implicit import SliderSpec
from ...scene.implicit.algebra import Circles
from ...scene.implicit.base import FloatArray, Point
from ..algebra import reducer, tidy_product, tidy_sqrt
from .base import BranchAlgebra, Fix, HalfAngle, Mode, StableEvaluator, Substitution

__all__ = ["SliderAlgebra"]


@attrs.frozen
class SliderAlgebra(BranchAlgebra):
    """A compiled slider's closed form, toggles and stable floats."""

    spec: SliderSpec

    def modes(self, substitution: Substitution, *, inputs: Circles) -> Mode:
        reduce = reducer(substitution, inputs)
        px, py = (reduce(v) for v in self.spec.through)
        qx, qy = (reduce(v) for v in self.spec.center)
        dx, dy = (reduce(v) for v in self.spec.direction)  # a moving direction in earlier points' closed forms
        wx, wy = reduce(qx - px), reduce(qy - py)
        norm2 = reduce(dx**2 + dy**2)
        dot, cross = reduce(dx * wx + dy * wy), reduce(dx * wy - dy * wx)
        norm = sympy.sqrt(norm2)
        # a fixed direction, or one toward a crank tip from its centre: |d| = r, and the
        # discriminant a difference of squares, (l|d| - cross)(l|d| + cross)
        if norm.is_rational:
            disc = tidy_product(reduce(self.spec.length * norm - cross), reduce(self.spec.length * norm + cross))
        else:
            disc = tidy_product(reduce(self.spec.length**2 * norm2 - cross**2))
        root = tidy_sqrt(disc)

        def mode(sigma: int) -> tuple[Point, sympy.Expr]:
            along = (dot + sigma * root) / norm2
            return (px + along * dx, py + along * dy), disc
        return mode

    def toggle_conditions(self) -> dict[str, sympy.Expr]:
        (px, py), (qx, qy), (dx, dy) = self.spec.through, self.spec.center, self.spec.direction
        cross = dx * (qy - py) - dy * (qx - px)
        return {"tangent": cross**2 - self.spec.length**2 * (dx**2 + dy**2)}

    def stable_evaluator(self, *, fix: Fix, arguments: Sequence[sympy.Symbol], half_angles: Circles,
                         sigma: float) -> StableEvaluator:
        return _Stable(self.spec, fix=fix, arguments=arguments, sigma=sigma)


class _Stable:
    """One slider's evaluator: the root of its quadratic that cannot cancel, the other from their product.

    On the line ``X = P + a d`` at distance l from Q (``w = Q - P``):
    ``a |d|**2 = dot(d, w) + sigma sqrt(disc)``, ``disc = l**2 |d|**2 - cross(d, w)**2``;
    the two roots multiply to ``(|w|**2 - l**2) / |d|**2``.
    ``|d|`` (``reach = l |d|``) is exact when ``|d|**2`` is a constant, even for a moving
    direction (toward a crank tip from its centre); otherwise it is taken from the floats.
    """

    def __init__(self, slider: SliderSpec, *, fix: Fix, arguments: Sequence[sympy.Symbol], sigma: float) -> None:
        (px, py), (qx, qy) = slider.through, slider.center
        dx, dy = (fix(v) for v in slider.direction)
        self.fixed = dx.is_number and dy.is_number
        base = [fix(e) for e in (px, py, qx - px, qy - py)] + ([] if self.fixed else [dx, dy])
        self.unknowns = slider.unknowns
        self.base = numpy_function(arguments, base)
        length, norm2 = fix(slider.length), fix(dx**2 + dy**2)
        self.sigma, self.length, self.length2 = sigma, float(length), float(length**2)
        self.dx, self.dy = (float(dx), float(dy)) if self.fixed else (0.0, 0.0)
        self.norm2 = float(norm2) if norm2.is_number else None
        self.reach = float(length * sympy.sqrt(norm2)) if norm2.is_number else None

    def __call__(self, values: Sequence[FloatArray], half: Sequence[HalfAngle]) -> tuple[FloatArray, FloatArray]:
        if self.fixed:
            px, py, wx, wy = self.base(*values)
            dx, dy = self.dx, self.dy
        else:
            px, py, wx, wy, dx, dy = self.base(*values)
        norm2 = dx * dx + dy * dy if self.norm2 is None else self.norm2
        reach = self.length * np.sqrt(norm2) if self.reach is None else self.reach
        dot, cross = dx * wx + dy * wy, dx * wy - dy * wx
        with np.errstate(invalid="ignore"):
            root = np.sqrt((reach - cross) * (reach + cross))
        larger = dot + np.copysign(root, dot)  # no cancellation: both terms of one sign
        with np.errstate(divide="ignore", invalid="ignore"):
            along = np.where(np.copysign(1.0, dot) == self.sigma, larger / norm2,
                             (wx * wx + wy * wy - self.length2) / larger)
        return px + along * dx, py + along * dy
