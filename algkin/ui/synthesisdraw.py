"""A synthesis drawn: the poses (or path points), the curves or solutions, each four-bar in each position.

Four poses: the centre-point curve (fixed frame) and the circle-point curve (moving frame, drawn
where it is in the first pose), a few centre points joined to their circle points. Five poses,
angle pairs, path points: one panel per four-bar, drawn in every precision position, its pivots
and the poses or points it must reach.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from fractions import Fraction
from typing import TYPE_CHECKING

import numpy as np

from .plot import new_figure

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from ..eliminate.group import Polynomial
    from ..synthesis import Synthesis
    from ..synthesis.data import Pose
    from ..synthesis.fourbar import FourBar

__all__ = ["synthesis_figure"]

_POSE = "#444444"
_COLOURS = ("#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b")


def synthesis_figure(found: Synthesis) -> Figure:
    """The figure of a synthesis (see the module's docstring)."""
    from ..synthesis.motion import FourPoses

    if isinstance(found.result, FourPoses):
        return _curves_figure(found.result.poses, found.result.centre_curve, found.result.circle_curve)
    designs = [m.design for m in found.mechanisms]
    figure = new_figure()
    if not designs:
        axes = figure.add_subplot()
        _targets(axes, found, 0.4)
        axes.set_title(f"{found.task.name}: no real solution")
        axes.set_aspect("equal", adjustable="datalim")
        return figure
    columns = min(3, len(designs))
    rows = math.ceil(len(designs) / columns)
    figure.set_size_inches(4.2 * columns, 3.8 * rows)
    size = 0.06 * _extent(designs)
    for index, (design, mechanism) in enumerate(zip(designs, found.mechanisms)):
        axes = figure.add_subplot(rows, columns, index + 1)
        _targets(axes, found, size)
        _four_bar(axes, design, _coupler_points(found))
        verdict = "usable" if mechanism.checked.usable else ", ".join(k for k, _ in mechanism.checked.defects)
        axes.set_title(f"{design.name}: {verdict or 'not reached'}", fontsize=9)
        axes.set_aspect("equal", adjustable="datalim")
    return figure


def _extent(designs: Sequence[FourBar]) -> float:
    """The largest spread of the designs' pivots and joints (the scale arrows are drawn at)."""
    points = [(float(p[0].mid()), float(p[1].mid())) for d in designs
              for p in (d.crank_pivot, d.rocker_pivot, *(q for pos in d.positions for q in (pos.crank_tip, pos.rocker_tip)))]
    xs, ys = zip(*points)
    return max(max(xs) - min(xs), max(ys) - min(ys), 1e-9)


def _coupler_points(found: Synthesis) -> list[tuple[float, float]]:
    """Where the coupler point must be at each position: the poses' origins, or the path's points."""
    if found.task.poses:
        return [(float(p.x), float(p.y)) for p in found.task.poses]
    return [(float(x), float(y)) for x, y in found.task.points]


def _targets(axes: Axes, found: Synthesis, size: float) -> None:
    """The poses as small frames (origin and x axis), or the path points, in grey."""
    for pose in found.task.poses:
        _pose(axes, pose, size)
    if found.task.points:
        xs, ys = zip(*[(float(x), float(y)) for x, y in found.task.points])
        axes.plot(xs, ys, "o", color=_POSE, ms=4, zorder=5)


def _pose(axes: Axes, pose: Pose, size: float) -> None:
    x, y, c, s = (float(v) for v in (pose.x, pose.y, pose.angle.cos, pose.angle.sin))
    axes.annotate("", xy=(x + size * c, y + size * s), xytext=(x, y),
                  arrowprops={"arrowstyle": "->", "color": _POSE, "lw": 1.2})
    axes.plot([x], [y], "o", color=_POSE, ms=3)


def _four_bar(axes: Axes, design: FourBar, coupler_points: Sequence[tuple[float, float]]) -> None:
    """The four-bar in each position: ground pivots as triangles, links in colour (the first
    position solid, the others lighter), the coupler joined to its point by dashes."""
    o = [float(v.mid()) for v in design.crank_pivot]
    d = [float(v.mid()) for v in design.rocker_pivot]
    axes.plot([o[0], d[0]], [o[1], d[1]], "^", color="black", ms=8, zorder=6)
    count = len(design.positions)
    for index, position in enumerate(design.positions):
        a = [float(v.mid()) for v in position.crank_tip]
        b = [float(v.mid()) for v in position.rocker_tip]
        alpha = 1.0 if index == 0 else 0.35 + 0.4 * index / count
        colour = _COLOURS[index % len(_COLOURS)]
        axes.plot([o[0], a[0], b[0], d[0]], [o[1], a[1], b[1], d[1]], "-o", color=colour, alpha=alpha, lw=1.4, ms=3)
        if index < len(coupler_points):
            p = coupler_points[index]
            axes.plot([a[0], p[0], b[0]], [a[1], p[1], b[1]], "--", color=colour, alpha=alpha, lw=0.8)


def _curves_figure(poses: Sequence[Pose], centre: Polynomial, circle: Polynomial) -> Figure:
    """The centre-point curve and the circle-point curve (placed in the first pose), with the poses."""
    figure = new_figure()
    axes = figure.add_subplot()
    xs = [float(p.x) for p in poses]
    ys = [float(p.y) for p in poses]
    span = max(max(xs) - min(xs), max(ys) - min(ys), 1.0)
    lo_x, hi_x = min(xs) - 1.5 * span, max(xs) + 1.5 * span
    lo_y, hi_y = min(ys) - 1.5 * span, max(ys) + 1.5 * span
    grid_x, grid_y = np.meshgrid(np.linspace(lo_x, hi_x, 400), np.linspace(lo_y, hi_y, 400))
    axes.contour(grid_x, grid_y, _values(centre, grid_x, grid_y), levels=[0], colors=_COLOURS[0])
    # the circle points in the moving frame, seen where the first pose puts that frame
    first = poses[0]
    c, s = float(first.angle.cos), float(first.angle.sin)
    local_x = c * (grid_x - float(first.x)) + s * (grid_y - float(first.y))
    local_y = -s * (grid_x - float(first.x)) + c * (grid_y - float(first.y))
    axes.contour(grid_x, grid_y, _values(circle, local_x, local_y), levels=[0], colors=_COLOURS[1],
                 linestyles="dashed")
    for pose in poses:
        _pose(axes, pose, size=0.15 * span)
    for fixed, moving in _matched(poses, centre, np.linspace(lo_x, hi_x, 9)[1:-1], (lo_y, hi_y)):
        axes.plot([fixed[0], moving[0]], [fixed[1], moving[1]], "-", color="#999999", lw=0.8)
        axes.plot([fixed[0]], [fixed[1]], "^", color=_COLOURS[0], ms=5)
        axes.plot([moving[0]], [moving[1]], "o", color=_COLOURS[1], ms=4)
    axes.plot([], [], color=_COLOURS[0], label="centre-point curve")
    axes.plot([], [], color=_COLOURS[1], ls="--", label="circle-point curve (first pose)")
    axes.legend(loc="upper right", fontsize=8)
    axes.set_xlim(lo_x, hi_x)
    axes.set_ylim(lo_y, hi_y)
    axes.set_aspect("equal")
    axes.set_title("four poses: centre-point and circle-point curves")
    return figure


def _matched(poses: Sequence[Pose], centre: Polynomial, xs: np.ndarray, span: tuple[float, float]
             ) -> list[tuple[tuple[float, float], tuple[float, float]]]:
    """Centre points on the curve (at the abscissas ``xs``, within ``span``) with their circle
    points, placed in the first pose: the dyad each makes. The circle point ``c`` keeps one
    distance from the centre ``C`` in every pose: ``2 (R_i^T (p_i - C) - R_1^T (p_1 - C)) . c =
    |p_1 - C|**2 - |p_i - C|**2`` for i = 2, 3, 4, solved in least squares (floats: drawn only)."""
    found = []
    for x in xs:
        for y in _roots_in_y(centre, float(x)):
            if not span[0] <= y <= span[1]:
                continue
            point = np.array([float(x), y])
            rows, right = [], []
            first = _turned_back(poses[0], point)
            for pose in poses[1:]:
                rows.append(2 * (_turned_back(pose, point) - first))
                right.append(_squared(poses[0], point) - _squared(pose, point))
            circle, *_ = np.linalg.lstsq(np.array(rows), np.array(right), rcond=None)
            c, s = float(poses[0].angle.cos), float(poses[0].angle.sin)
            placed = (float(poses[0].x) + c * circle[0] - s * circle[1], float(poses[0].y) + s * circle[0] + c * circle[1])
            found.append(((float(x), y), placed))
    return found


def _roots_in_y(poly: Polynomial, x: float) -> list[float]:
    """The real roots in Y of the curve at X = ``x`` (floats)."""
    coefficients = np.zeros(poly.degree("Y") + 1)
    scale = max((abs(Fraction(p, q)) for _, p, q in poly.terms), default=Fraction(1)) or Fraction(1)
    for exponents, p, q in poly.terms:
        coefficients[exponents[1]] += float(Fraction(p, q) / scale) * x ** exponents[0]
    roots = np.roots(coefficients[::-1]) if np.any(coefficients[1:]) else np.array([])
    return [float(r.real) for r in roots if abs(r.imag) < 1e-9 * (1 + abs(r))]


def _turned_back(pose: Pose, point: np.ndarray) -> np.ndarray:
    """``R^T (p - C)``: the pose's origin seen from ``point``, in the moving frame's axes."""
    c, s = float(pose.angle.cos), float(pose.angle.sin)
    d = np.array([float(pose.x), float(pose.y)]) - point
    return np.array([c * d[0] + s * d[1], -s * d[0] + c * d[1]])


def _squared(pose: Pose, point: np.ndarray) -> float:
    return float(np.sum((np.array([float(pose.x), float(pose.y)]) - point) ** 2))


def _values(poly: Polynomial, x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """The polynomial (in two variables, in the order of its names) on a grid, in floats, scaled
    by its largest coefficient (only its sign and zero set are drawn)."""
    scale = max((abs(Fraction(p, q)) for _, p, q in poly.terms), default=Fraction(1)) or Fraction(1)
    total = np.zeros_like(x)
    for exponents, p, q in poly.terms:
        total += float(Fraction(p, q) / scale) * x ** exponents[0] * y ** exponents[1]
    return total
