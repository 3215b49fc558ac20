"""The time ratio of an output's strokes, and its stroke (a rocker's swing, a slider's travel).

With the input turning fully and the output on the scene's branch turning back exactly twice per
turn, at crank angles ``theta1 < theta2``, the working stroke takes the larger of
``theta2 - theta1`` and ``360 - (theta2 - theta1)`` (``180 + alpha``), the return the other, and
``Q = (180 + alpha) / (180 - alpha)``.
"""

from __future__ import annotations

import math

import flint
import sympy

from ...evaluate import ARB, evaluate
from ...runtime.budget import Deadline
from ...scene import Compiled
from ..toggles import single_input, toggle_conditions
from .certificate import CHECK_BITS, angle_values
from .condition import Path
from .exact import tidy
from .isolation import ROOT_BITS
from .points import PointLimits
from .position import middle
from .results import Json, Limit, TimeRatio

__all__ = ["time_ratio", "turns_fully", "stroke"]


def turns_fully(compiled: Compiled, lo: float, hi: float, deadline: Deadline | None = None) -> str | None:
    """None when the input turns fully with every point the output needs assembled; else why not
    (the toggle conditions' eliminations keeping to ``deadline``, if any)."""
    if hi - lo < 360:
        return f"the input's range [{lo:g}, {hi:g}] deg is less than a full turn"
    _, line = single_input(compiled, "limit positions")
    with flint.ctx.workprec(ROOT_BITS):
        for spec in compiled.implicit:
            for name, condition in toggle_conditions(compiled, spec, deadline=deadline).items():
                balls = line.roots(condition)
                if balls:
                    angles = ", ".join(f"{float(b.mid()):.6g}" for b in balls)
                    return f"the input does not turn fully: {spec.point} has dead centres ({name}) at {angles} deg"
    return None


def time_ratio(found: PointLimits, lo: float, hi: float, deadline: Deadline | None = None
               ) -> tuple[TimeRatio | None, str | None]:
    """The time ratio of ``found``'s point on the scene's branch, or why it has none (its
    eliminations keeping to ``deadline``, if any)."""
    point, compiled, stationary = found.point, found.compiled, found.stationary
    assert stationary is not None
    why = turns_fully(compiled, lo, hi, deadline)
    if why is not None:
        return None, why
    branch = next(b for b in found.branches if b.selected)
    _, line = single_input(compiled, "limit positions")
    c, s = line.variables
    with flint.ctx.workprec(CHECK_BITS):
        if not all(evaluate(d, angle_values(flint.arb(lo), str(c), str(s)), ARB) > 0
                   for d in branch.discriminants.values()):
            return None, f"the scene's branch {branch.label} does not assemble"
    mine = {round(g.input_deg % 360, 9): g for g in found.limits if g.selected}
    if len(mine) != 2:
        what = "none: it turns without stopping" if not mine else f"{len(mine)} per turn"
        return None, f"{point} on branch {branch.label} has limit positions {what}, not exactly two"
    first, second = sorted(mine.values(), key=lambda g: g.input_deg % 360)
    with flint.ctx.workprec(CHECK_BITS):
        (a1, b1, e1), (a2, b2, e2) = (_per_turn(g) for g in (first, second))
        forward = {"from_deg": a1, "to_deg": a2, "from_kind": first.kind, "to_kind": second.kind,
                   "crank_deg": b2 - b1, "exact": e2 - e1}
        backward = {"from_deg": a2, "to_deg": a1 + 360, "from_kind": second.kind, "to_kind": first.kind,
                    "crank_deg": 360 - (b2 - b1), "exact": 360 - (e2 - e1)}
        working, quick = (forward, backward) if a2 - a1 >= 180 else (backward, forward)
        ratio = working["crank_deg"] / quick["crank_deg"]
    strokes = [{**part, "stroke": name, "crank_deg": middle(part["crank_deg"]),
                "enclosure_deg": part["crank_deg"].str(20), "exact": str(tidy(part["exact"]))}
               for name, part in (("working", working), ("return", quick))]
    return TimeRatio(point, branch.label, middle(ratio), ratio, tidy(working["exact"] / quick["exact"]), strokes,
                     middle(working["crank_deg"]) - 180, stroke(stationary.path, first, second)), None


def _per_turn(limit: Limit) -> tuple[float, flint.arb, sympy.Expr]:
    """The limit's input angle in [0, 360) deg: a float, its enclosure, exactly."""
    turns = 360 * math.floor(limit.input_deg / 360)
    return limit.input_deg - turns, limit.enclosure - turns, limit.exact_deg - turns


def stroke(path: Path, first: Limit, second: Limit) -> Json:
    """The output's swing about its pivot (degrees) or its travel along its line."""
    one, two = first.position, second.position
    exact_one, exact_two = one.get("exact"), two.get("exact")
    if path.centre is not None:
        swing = abs(two["angle_deg"] - one["angle_deg"])
        swing = min(swing, 360 - swing)
        exact = None
        if exact_one and exact_two:
            difference = sympy.sympify(exact_two["angle_deg"]) - sympy.sympify(exact_one["angle_deg"])
            difference = difference if float(difference) >= 0 else -difference
            exact = str(tidy(difference if float(difference) <= 180 else 360 - difference))  # as the float
        return {"kind": "swing", "about": one["about"], "angle_deg": swing, "exact": exact}
    travel = abs(two["along"] - one["along"])
    exact = None
    if exact_one and exact_two:
        difference = sympy.sympify(exact_two["along"]) - sympy.sympify(exact_one["along"])
        exact = str(tidy(difference if float(difference) >= 0 else -difference))
    return {"kind": "travel", "length": travel, "exact": exact}
