"""Scenes with points solved together drawn: every real mode at an input, each mode's path, the motion animated.

The configurations and paths are ``GroupMotion``'s (``algkin solve`` and ``algkin follow``,
certified). Each constraint ``dist(P, Q) = L`` is drawn as a bar (a leg), ``on(P, line(A, B))``
as a rail through A and B, each frame point's triangle on its two bases as the rigid body it
is (the platform), cranks as bars, ground points as triangles. Where no mode exists at the
input, what does not depend on the group is still drawn, with a red line saying so.

>>> from algkin.ui.groupmotion import GroupMotion
>>> figure = modes_figure(GroupMotion("3rpr"), 6)
>>> [axes.get_title() for axes in figure.axes]
['--- (certified)', '+++ (certified)']
"""

from __future__ import annotations

import os
import pathlib
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any, TypeVar, Union

import numpy as np

from ..errors import UsageError
from ..runtime.files import atomic_output, bytes_written
from ..runtime.terminal import one_line
from ..runtime.validation import real
from .groupmotion import GroupMotion, Placed
from .plot import new_figure

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from ..scene import Scene

PathT = TypeVar("PathT", bound=Union[str, "os.PathLike[str]"])  # a path given back as it came
Bounds = tuple[float, float, float, float]

__all__ = ["modes_figure", "draw_configuration", "animate_modes", "groups_file"]

_BAR: dict[str, Any] = dict(color="tab:blue", linewidth=2.5, solid_capstyle="round", zorder=2)
_JOINT: dict[str, Any] = dict(marker="o", markersize=6, color="black", markerfacecolor="white", zorder=4)
_MODES = ("tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple", "tab:brown")


def _bounds(motion: GroupMotion) -> Bounds:
    """A box around every point of every path and every point known from the input alone."""
    xs = [xy[:, 0] for path in motion.paths for xy in path.points.values()]
    ys = [xy[:, 1] for path in motion.paths for xy in path.points.values()]
    lo, hi = motion.input.span
    for value in np.linspace(lo, hi, 73):
        built = motion.place([0.0] * len(motion.unknowns), float(value))
        xs.append(np.array([built[p][0] for p in motion.built]))
        ys.append(np.array([built[p][1] for p in motion.built]))
    x, y = np.concatenate(xs), np.concatenate(ys)
    pad = 0.08 * max(np.ptp(x), np.ptp(y), 1e-9)
    return x.min() - pad, x.max() + pad, y.min() - pad, y.max() + pad


def draw_configuration(axes: Axes, motion: GroupMotion, at: Mapping[str, tuple[float, float]], *,
                       color: str = "tab:blue", gid: str = "", named: Sequence[str] | None = None) -> None:
    """Rails, legs, cranks, platforms, ground and joints of the configuration ``at`` (point -> (x, y));
    the platforms' polygons get the id ``gid`` + ``platform-k`` (an SVG group's id); the points
    ``named`` (default: all) get their name beside them."""
    for rail in motion.rails:
        _, a, b = rail.points
        if a in at and b in at and at[a] != at[b]:
            axes.axline(at[a], at[b], color="tab:gray", linewidth=1, zorder=1)
    for k, base in enumerate(motion.platforms):
        if all(p in at for p in base):
            polygon = axes.fill([at[p][0] for p in base], [at[p][1] for p in base], color=color, alpha=0.25,
                                edgecolor=color, linewidth=1.5, zorder=2)[0]
            polygon.set_gid(f"{gid}platform-{k}")
    ends = [c.points for c in motion.legs] + list(motion.cranks)
    for p, q in ends:
        if p in at and q in at:
            axes.plot([at[p][0], at[q][0]], [at[p][1], at[q][1]], **dict(_BAR, color=color))
    ground = [at[p] for p in motion.ground if p in at]
    axes.plot([x for x, _ in ground], [y for _, y in ground], linestyle="none", marker="^", markersize=11,
              color="dimgray", zorder=3)
    joints = [at[p] for p in at if p not in motion.ground]
    axes.plot([x for x, _ in joints], [y for _, y in joints], linestyle="none", **_JOINT)
    for name, (x, y) in at.items():
        if named is not None and name not in named:
            continue
        axes.annotate(name, (x, y), textcoords="offset points", xytext=(6, 6), fontsize="small",
                      annotation_clip=True).set_parse_math(False)  # a point's name is text


def _paths(axes: Axes, motion: GroupMotion) -> None:
    """Each mode's path of the traced points, thin, a dot where it meets another mode."""
    for k, path in enumerate(motion.paths):
        color = _MODES[k % len(_MODES)]
        for name in motion.traced:
            xy = path.points[name]
            axes.plot(xy[:, 0], xy[:, 1], color=color, linewidth=0.8, alpha=0.6, zorder=1)
            for end, meets in zip((0, -1), path.meets):
                if meets is not None:
                    axes.plot([xy[end, 0]], [xy[end, 1]], marker="X", color="tab:red", markersize=7, zorder=3)


def _finish(axes: Axes, bounds: Bounds, title: str) -> None:
    axes.set_xlim(bounds[0], bounds[1])
    axes.set_ylim(bounds[2], bounds[3])
    axes.set_aspect("equal", adjustable="box")
    axes.grid(True, linewidth=0.3)
    axes.set_title(title, fontsize="medium", parse_math=False)


def _not_assembled(motion: GroupMotion, value: float) -> str:
    points = ", ".join(p for g in motion.compiled.groups for p in g.points)
    return f"not assembled here: no real mode of {points} at {motion.input.name} = {motion.input.shown(value)}"


def modes_figure(motion: GroupMotion, value: float | None = None) -> Figure:
    """Every real mode at the input ``value`` (default: where the most modes were found), one panel
    each, with every mode's path; one panel saying so where none exists."""
    value = float(motion.start() if value is None else value)
    found: list[Placed] = motion.configurations(value)
    bounds = _bounds(motion)
    figure = new_figure()
    count = max(len(found), 1)
    ratio = (bounds[3] - bounds[2]) / (bounds[1] - bounds[0])
    width = min(3.6, 6.4 / ratio)
    figure.set_size_inches(width * count + 0.6, width * ratio + 1.1)
    shared: Axes | None = None
    for k, placed in enumerate(found or [None]):
        axes = figure.add_subplot(1, count, k + 1, sharex=shared, sharey=shared)
        shared = shared or axes
        _paths(axes, motion)
        if placed is None:
            built = motion.place([0.0] * len(motion.unknowns), value)
            draw_configuration(axes, motion, {p: built[p] for p in motion.built})
            axes.text(0.5, 0.5, _not_assembled(motion, value), transform=axes.transAxes, ha="center", va="center",
                      color="tab:red", wrap=True, parse_math=False)
            _finish(axes, bounds, "no mode")
        else:
            draw_configuration(axes, motion, placed.points, color=_MODES[k % len(_MODES)], gid=f"mode-{k}-")
            _finish(axes, bounds, f"{placed.label} ({placed.how})")
        axes.label_outer()
    figure.suptitle(f"{one_line(motion.scene.name)}: every real mode at {motion.input.name} = {motion.input.shown(value)}",
                    parse_math=False)
    return figure


def animate_modes(motion: GroupMotion, out: PathT, *, frames: int = 72, fps: int = 24) -> PathT:
    """The input moved through its range, every mode that exists there drawn in its colour (``.gif``).

    The paths and the axes are drawn once; a frame replaces only the configurations' artists."""
    from matplotlib import animation

    bounds = _bounds(motion)
    figure = new_figure()
    axes = figure.add_subplot()
    _paths(axes, motion)
    _finish(axes, bounds, "")
    lo, hi = motion.input.span
    static = set(axes.get_children())

    def frame(value: float) -> None:
        for artist in [a for a in axes.get_children() if a not in static]:
            artist.remove()
        built = motion.place([0.0] * len(motion.unknowns), value)
        draw_configuration(axes, motion, {p: built[p] for p in motion.built})
        shown = [k for k, path in enumerate(motion.paths) if path.covers(value)]
        for k in shown:
            draw_configuration(axes, motion, motion.paths[k].at(value), color=_MODES[k % len(_MODES)],
                               named=motion.moving)  # the ground's names once, with the built points
        if not shown:
            axes.text(0.5, 0.5, _not_assembled(motion, value), transform=axes.transAxes, ha="center",
                      va="center", color="tab:red", wrap=True, parse_math=False)
        axes.set_xlim(bounds[0], bounds[1])  # axline and fill must not move the limits
        axes.set_ylim(bounds[2], bounds[3])
        axes.set_title(f"{one_line(motion.scene.name)}: {motion.input.name} = {motion.input.shown(value)}",
                       fontsize="medium", parse_math=False)

    movie = animation.FuncAnimation(figure, frame, frames=list(np.linspace(lo, hi, frames)), cache_frame_data=False)
    with atomic_output(out) as temporary:  # the writer infers the format from the kept suffix
        movie.save(str(temporary), writer=animation.PillowWriter(fps=fps), dpi=80)
    return out


def _value(motion: GroupMotion, texts: Sequence[str]) -> float | None:
    """The ``--input`` value (``VALUE`` or ``NAME=VALUE``), in the input's range."""
    if not texts:
        return None
    if len(texts) > 1:
        raise UsageError("--input", texts[1], f"{motion.scene.name}'s points move with one input: give it once")
    name, _, text = texts[0].rpartition("=")
    if name not in ("", motion.input.name):
        raise UsageError("--input", texts[0], f"expected NAME=VALUE with NAME {motion.input.name}")
    try:
        value = real(text)
    except ValueError:
        value = float("nan")
    lo, hi = motion.input.span
    if not lo <= value <= hi:
        what = "a number of degrees" if motion.input.is_angle else "a length"
        raise UsageError("--input", texts[0], f"expected {what} in [{lo:g}, {hi:g}]")
    return value


def groups_file(scene: Scene, out: str | os.PathLike[str], *, inputs: Sequence[str] = (), branch: str | None = None,
                ranges: Sequence[str] = ()) -> bytes:
    """What ``algkin plot`` writes to ``out`` for a scene with points solved together, as bytes (nothing
    written): every mode at the input (.png, .svg, .pdf), the motion (.gif), the page with the input's
    slider and a mode selector (.html)."""
    from .plot import image

    suffix = pathlib.Path(out).suffix.lower()
    if suffix == ".mp4":
        raise UsageError("--out", str(out), "with points solved together the motion is written as a .gif")
    if branch is not None:
        raise UsageError("--branch", branch, "every mode is drawn with points solved together; leave out --branch")
    if ranges:
        raise UsageError("--range-of", ranges[0], "points solved together take their dimensions' values: use --set")
    motion = GroupMotion(scene)
    value = _value(motion, inputs)
    if suffix == ".html":
        from .html.groups import group_page

        return group_page(motion, value).encode("utf-8")
    if suffix == ".gif":
        return bytes_written(lambda path: animate_modes(motion, path), suffix)
    return image(modes_figure(motion, value), suffix)
