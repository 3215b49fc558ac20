"""A meet's branch algebra (``MeetSpec``: where the line through A and B meets the line through C and D).

Closed form, by Cramer's rule: ``X = A + cross(v, C - A) / cross(v, u) * u`` with ``u = B - A``,
``v = D - C``; rational, one point, no mode. Its "discriminant" is ``cross(u, v)**2``: > 0
wherever the lines meet in one point, zero where they turn parallel (``valid_when`` reads
``cross(u, v) != 0``). Parallel lines are no meeting of two modes: no toggle of its own.

Stable floats: Cramer's rule from the points' differences (taken exactly, symbolically, so a
mechanism far from the origin loses nothing before the rounding).

>>> from sympy import Integer, symbols
>>> from algkin.scene.implicit import MeetSpec
>>> c, s = symbols("c s", real=True)
>>> O, E = (Integer(0), Integer(0)), (Integer(1), Integer(0))
>>> spec = MeetSpec("X", ("X_x", "X_y"), "unique", first=(O, (c, s)), second=((Integer(2), Integer(0)), (2 + s, 1 + c)))
>>> point, square = MeetAlgebra(spec).closed_form({}, sigma=1, inputs=[(c, s)])
>>> [sympy.simplify(v.subs({c: 0, s: 1})) for v in point]  # x = 0 meets the line through (2, 0) toward (3, 1)
[0, -2]
"""

from collections.abc import Sequence

import attrs
import numpy as np
import sympy

from ...evaluate.program import numpy_function
from ...scene.implicit import MeetSpec
from ...scene.implicit.algebra import Circles, reduce_on_circles
from ...scene.implicit.base import FloatArray
from ..algebra import reducer, tidy_ratio
from .base import BranchAlgebra, Fix, HalfAngle, Mode, StableEvaluator, Substitution

__all__ = ["MeetAlgebra"]


@attrs.frozen
class MeetAlgebra(BranchAlgebra):
    """A compiled meet's closed form and stable floats."""

    spec: MeetSpec
    square = True  # its discriminant is a square: the point exists where its base is not zero

    def modes(self, substitution: Substitution, *, inputs: Circles) -> Mode:
        reduce = reducer(substitution, inputs)
        (a, b), (c, d) = ([[reduce(v) for v in point] for point in line] for line in (self.spec.first, self.spec.second))
        ux, uy, vx, vy = reduce(b[0] - a[0]), reduce(b[1] - a[1]), reduce(d[0] - c[0]), reduce(d[1] - c[1])
        determinant = reduce(vx * uy - vy * ux)
        along = reduce(vx * (c[1] - a[1]) - vy * (c[0] - a[0])) / determinant
        square = sympy.Pow(_numerator(determinant, inputs), 2, evaluate=False)
        point = (tidy_ratio(a[0] + along * ux), tidy_ratio(a[1] + along * uy))
        return lambda sigma: (point, square)  # one point: no mode of its own

    def toggle_conditions(self) -> dict[str, sympy.Expr]:
        return {}  # parallel lines send the point to infinity: no two modes meet there

    def stable_evaluator(self, *, fix: Fix, arguments: Sequence[sympy.Symbol], half_angles: Circles,
                         sigma: float) -> StableEvaluator:
        return _Stable(self.spec, fix=fix, arguments=arguments)


def _numerator(determinant: sympy.Expr, inputs: Circles) -> sympy.Expr:
    """The determinant's numerator, which vanishes where it does (a denominator of earlier points' forms
    is theirs to vanish), its positive content dropped: grouped by the square roots it holds, each
    coefficient reduced on the circles and factored."""
    numerator = sympy.fraction(sympy.together(determinant))[0]
    roots = sorted((p for p in numerator.atoms(sympy.Pow) if p.exp == sympy.Rational(1, 2)), key=str)
    grouped = sympy.collect(sympy.expand(numerator), roots, evaluate=False)
    total = sympy.Add(*[sympy.factor(reduce_on_circles(coefficient, inputs)) * root
                        for root, coefficient in grouped.items()])
    return total.as_content_primitive()[1]


class _Stable:
    """Cramer's rule in floats, from ``A``, ``u``, ``v`` and ``C - A`` compiled exactly."""

    def __init__(self, meet: MeetSpec, *, fix: Fix, arguments: Sequence[sympy.Symbol]) -> None:
        (a, b), (c, d) = meet.first, meet.second
        parts = (*a, b[0] - a[0], b[1] - a[1], d[0] - c[0], d[1] - c[1], c[0] - a[0], c[1] - a[1])
        self.unknowns = meet.unknowns
        self.formula = numpy_function(arguments, [fix(e) for e in parts])

    def __call__(self, values: Sequence[FloatArray], half: Sequence[HalfAngle]) -> tuple[FloatArray, FloatArray]:
        ax, ay, ux, uy, vx, vy, wx, wy = self.formula(*values)
        with np.errstate(divide="ignore", invalid="ignore"):  # parallel lines: no point (inf or nan)
            along = (vx * wy - vy * wx) / (vx * uy - vy * ux)
        return ax + along * ux, ay + along * uy
