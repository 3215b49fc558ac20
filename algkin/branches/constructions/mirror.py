"""A second intersection's branch algebra (``MirrorSpec``: the circles' other intersection, an inversor's point).

``X = 2 F - Y``, the mirror image of the earlier point ``Y`` in the foot ``F`` of the
circles' chord: no mode of its own, and no toggle of its own (it meets ``Y`` only where the
circles touch, a toggle of the points they are built on).

>>> from sympy import Integer, sqrt
>>> from algkin.scene.implicit import MirrorSpec
>>> spec = MirrorSpec("P", ("P_x", "P_y"), "right", base_p=(Integer(0), Integer(0)), base_q=(Integer(2), Integer(0)),
...                   lengths=(sqrt(2), sqrt(2)), other="A", other_at=(Integer(1), Integer(1)))
>>> MirrorAlgebra(spec).closed_form({}, sigma=1, inputs=[])[0]  # radius sqrt(2) about (0, 0) and (2, 0) meet at (1, 1)
(1, -1)
"""

from collections.abc import Sequence

import attrs
import sympy

from ...evaluate.program import numpy_function
from ...scene.implicit import MirrorSpec
from ...scene.implicit.algebra import Circles
from ...scene.implicit.base import FloatArray
from ...scene.implicit.mirror import mirror_parts
from ..algebra import reducer, tidy_ratio
from .base import BranchAlgebra, Fix, HalfAngle, Mode, StableEvaluator, Substitution

__all__ = ["MirrorAlgebra"]


@attrs.frozen
class MirrorAlgebra(BranchAlgebra):
    """A compiled second intersection's closed form and stable floats."""

    spec: MirrorSpec

    def modes(self, substitution: Substitution, *, inputs: Circles) -> Mode:
        reduce = reducer(substitution, inputs)
        (px, py), (qx, qy) = [[reduce(v) for v in point] for point in (self.spec.base_p, self.spec.base_q)]
        ox, oy = (reduce(v) for v in self.spec.other_at)
        dx, dy = reduce(qx - px), reduce(qy - py)
        span = reduce(dx**2 + dy**2)
        l1, l2 = self.spec.lengths
        along = tidy_ratio((l1**2 - l2**2 + span) / span)  # twice the foot's fraction along d
        point = (px + along * dx - ox + px, py + along * dy - oy + py)
        return lambda sigma: (point, span)  # no mode of its own

    def toggle_conditions(self) -> dict[str, sympy.Expr]:
        return {}  # it meets ``other`` only where their circles touch: a toggle of the points they are built on

    def stable_evaluator(self, *, fix: Fix, arguments: Sequence[sympy.Symbol], half_angles: Circles,
                         sigma: float) -> StableEvaluator:
        return _Stable(self.spec, fix=fix, arguments=arguments)


class _Stable:
    """The mirror image in floats: ``2 U + a d - Y`` with ``a`` from the lengths (no cancellation to fear
    beyond the foot's, which the dyads it is built on already carry)."""

    def __init__(self, mirror: MirrorSpec, *, fix: Fix, arguments: Sequence[sympy.Symbol]) -> None:
        self.unknowns = mirror.unknowns
        self.formula = numpy_function(arguments, [fix(e) for e in mirror_parts(mirror)])

    def __call__(self, values: Sequence[FloatArray], half: Sequence[HalfAngle]) -> tuple[FloatArray, FloatArray]:
        bx, by, dx, dy, along = self.formula(*values)
        return bx + along * dx, by + along * dy
