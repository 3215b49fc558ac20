"""Limit positions of an output and the time ratio of its strokes, exact and certified.

An implicit point X (a dyad, a slider) whose own equations include one in X alone, ``C(X) = 0``
(a circle about a ground pivot: a rocker; a fixed line: a slider), moves along that curve as
the input turns. It is at a *limit position* where it stops there and turns back: where
``dX/dtheta = 0``. X's other equation ``G(X, u, c, s) = 0`` ties it to the moving points
(``u``: earlier points' unknowns, ``c, s``: the input's cosine and sine). Differentiating
both, ``grad C . X' = 0`` and ``grad G . X' + dG/dtheta = 0`` with ``dG/dtheta`` the derivative of
G *with X held*; where the point is not at a dead centre (``grad C``, ``grad G`` independent)
``X' = 0`` exactly where

    dG/dtheta|X held  =  c G_s - s G_c + G_u . u'  =  0,   with  u' = -J_u^-1 (c F_s - s F_c)

the earlier points' velocities by the implicit function theorem (``F``: their equations,
``J_u``: their Jacobian). Times ``det J_u`` this is a polynomial, the *stationarity condition*;
with the unknowns eliminated (resultants), a polynomial in ``c, s`` whose real roots, in the
half-angle ``t``, ``system.roots`` isolates with certified enclosures. For a four-bar (X = B on
the crank tip A and the ground pivot D) it is ``(B - A) . A' = 0``: crank and coupler in
line, ``|OB| = l + a`` (*extended*) or ``|OB| = l - a`` (*folded*); for a slider-crank the same.

Each root is certified, branch by branch: the closed form of the branch assembles over an
interval around the root (every discriminant > 0 in ball arithmetic), the condition evaluated
on it changes sign across the interval (so it has a zero there: the output turns back) and
the eliminant has no other root in it (so that zero is the exact root reported). Roots that
no branch certifies are listed as dropped, with why (an extraneous factor of the elimination,
where every branch's condition is bounded away from zero).

The *time ratio* of a crank-rocker or an offset slider-crank: with the input turning fully
(no dead centre in the range) and the output on the scene's branch turning back exactly twice
per turn, at crank angles ``theta1 < theta2``, the output takes ``theta2 - theta1`` of crank
angle one way and ``360 - (theta2 - theta1)`` the other. The working stroke is the slower one
(the larger angle, ``180 + alpha``), the return the quicker (``180 - alpha``), and
``Q = (180 + alpha) / (180 - alpha)``. The stroke of the output is the rocker's swing (the angle
between its limit positions about its pivot) or the slider's travel.

>>> found = limits("slider-crank")
>>> [(round(g.input_deg, 6), g.kind, g.branch) for g in found.limits if g.selected]
[(7.180756, 'extended', 'ahead'), (194.477512, 'folded', 'ahead')]
>>> round(found.time_ratio.ratio, 12), found.time_ratio.stroke["exact"]
(1.084500513743, '(-sqrt(15) + 3*sqrt(7))/2')

One module per step: ``condition`` (the stationarity condition and its eliminant), ``isolation``
(its real roots as angles), ``certificate`` (each root on each branch), ``exact`` and ``position``
(where the point is, tidied radicals), ``points`` (one point's limits), ``ratio`` (the time
ratio), ``results`` (the answers and their JSON).
"""

from __future__ import annotations

from collections.abc import Mapping

from ...errors import UsageError
from ...runtime.budget import Budget, Deadline, started
from ...runtime.exclusive import one_at_a_time
from ...scene import load_scene
from ...scene.model import Scene
from ...scene.settings import with_values
from .condition import stationary_condition
from .points import point_limits
from .ratio import time_ratio
from .results import Limit, Limits, TimeRatio

__all__ = ["limits", "stationary_condition", "Limit", "Limits", "TimeRatio"]


@one_at_a_time
def limits(scene: Scene | str, set: Mapping[str, object] | None = None, *,  # noqa: A002 - the public name (the command line's --set)
           budget: Budget | Deadline | None = None) -> Limits:
    """Every limit position of every dyad and slider with a fixed path, certified, and the time
    ratio of the last of them (the output) on the scene's branch. A ``Budget`` (or the
    ``Deadline`` of one running) bounds the time and the eliminants' terms."""
    deadline = started(budget)
    scene = with_values(scene if not isinstance(scene, str) else load_scene(scene), dict(set) if set else None)
    implicit = [n for n, p in scene.points.items() if p.labels]
    if not implicit:
        raise UsageError("scene", scene.name, "has no dyad or slider, so no output to stop and turn back")
    name = next(iter(scene.inputs)) if len(scene.inputs) == 1 else None
    if name is None:
        raise UsageError("scene", scene.name, "limit positions are computed for one-input scenes")
    if not scene.inputs[name].is_angle:
        raise UsageError("scene", scene.name, f"limit positions and the time ratio are for a turning input; "
                                              f"{name} is a length (its toggles end the strokes)")
    lo, hi = scene.inputs[name].span
    points = [point_limits(scene, point, lo, hi, deadline) for point in implicit]
    found = sorted((g for p in points for g in p.limits), key=lambda g: (g.input_deg, g.point, g.branch))
    dropped = [d for p in points for d in p.dropped]
    skipped = [{"point": p.point, "why": p.skipped} for p in points if p.skipped]
    moving = [p for p in points if p.stationary is not None]
    if not moving:
        return Limits(scene.name, name, (lo, hi), found, None, "no dyad or slider moves on a fixed path", dropped,
                      skipped)
    ratio, reason = time_ratio(moving[-1], lo, hi, deadline)
    return Limits(scene.name, name, (lo, hi), found, ratio, reason, dropped, skipped)
