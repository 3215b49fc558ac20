"""One point's limit positions on every branch: the eliminant's roots, each certified per branch
or dropped with why."""

from __future__ import annotations

from typing import Any

import attrs
import flint
import sympy

from ...branches import Branch
from ...derivation.prepared import prepare
from ...evaluate import ARB, evaluate
from ...runtime.budget import Deadline
from ...runtime.frozen import FrozenDict
from ...scene import Compiled
from ...scene.model import Scene
from ..frozen import frozen_rows
from ..toggles import single_input
from .certificate import CHECK_BITS, angle_values, certify, interval
from .condition import Stationary, eliminant, stationary_condition
from .exact import exact_point
from .isolation import ROOT_BITS, angle_roots
from .position import centre_name, kind, middle, position
from .results import Json, Limit

__all__ = ["PointLimits", "point_limits"]


def _tuple(items: Any) -> tuple[Any, ...]:
    return tuple(items)


@attrs.frozen
class PointLimits:
    """One point's limit positions on every branch, the roots that are none, or why it has none."""

    point: str
    compiled: Compiled
    stationary: Stationary | None
    branches: tuple[Branch, ...] = attrs.field(converter=_tuple)
    limits: tuple[Limit, ...] = attrs.field(converter=_tuple)
    dropped: tuple[FrozenDict[str, Any], ...] = attrs.field(converter=frozen_rows)
    skipped: str | None  # why the point has no limit positions to look for


def point_limits(scene: Scene, point: str, lo: float, hi: float, deadline: Deadline | None = None) -> PointLimits:
    """The limits of one point (every branch), the roots dropped, or why the point has none (its
    elimination keeping to ``deadline``, if any)."""
    prepared = prepare(scene, outputs=[point], deadline=deadline)
    compiled = prepared.compiled
    _, line = single_input(compiled, "limit positions")
    c, s = line.variables
    stationary = stationary_condition(compiled, point)
    if isinstance(stationary, str):
        return PointLimits(point, compiled, None, [], [], [], stationary)
    condition, dropped_factors = eliminant(stationary, c, s, deadline)
    t = sympy.Symbol("t")
    with flint.ctx.workprec(ROOT_BITS):
        roots = angle_roots([condition], c, s, t)
        others = [r.degrees for r in roots] + [r.degrees for r in angle_roots(dropped_factors, c, s, t)]
    branches = list(prepared.branches)
    centre = centre_name(scene, compiled, stationary.path)
    found: list[Limit] = []
    dropped: list[Json] = []
    with flint.ctx.workprec(CHECK_BITS):
        for root in roots:
            degrees = middle(root.degrees)
            turns = [turn for turn in (-360, 0, 360) if lo <= degrees + turn <= hi]
            if not turns:
                continue
            around = interval(root, others)
            verdicts = [(b, "undecided", "another root of the eliminant is too close") for b in branches] \
                if around is None else \
                [(b, *certify(stationary.condition, b, around, str(c), str(s))) for b in branches]
            for branch, verdict, _ in verdicts:
                if verdict != "yes":
                    continue
                assert around is not None
                width = float((around[1] - around[0]).upper())
                values = angle_values(root.degrees, str(c), str(s))
                values.update({u: evaluate(v, values, ARB) for u, v in branch.values.items()})
                x, y = (values[str(u)] for u in stationary.unknowns)
                place = position(stationary.path, (x, y), exact_point(branch, stationary.unknowns, root, c, s),
                                 centre)
                certificate = (f"on branch {branch.label} every discriminant is > 0 and the stationarity "
                               f"condition changes sign across a {width:.1e} deg interval holding no other "
                               "root of the eliminant (ball arithmetic)")
                how = kind(scene, compiled, point, values)
                found += [Limit(degrees + turn, root.degrees + turn, root.exact_deg + turn, root.factor, point,
                                branch.label, branch.selected, how, place, certificate) for turn in turns]
            if not any(v == "yes" for _, v, _ in verdicts):
                reasons = "; ".join(sorted({f"{b.label}: {why}" for b, _, why in verdicts}))
                verdict = "undecided: " if any(v == "undecided" for _, v, _ in verdicts) else "not a limit (certified): "
                dropped += [{"point": point, "input_deg": degrees + turn,
                             "t_factor": None if root.factor is None else str(root.factor), "why": verdict + reasons}
                            for turn in turns]
    return PointLimits(point, compiled, stationary, branches, found, dropped, None)
