"""Mechanisms drawn with matplotlib: a configuration, trajectories, implicit curves, animations.

Built on ``algkin.analyses.motion`` (closed forms evaluated, never re-derived) and, like
``algkin.ui.plot``, on ``matplotlib.figure.Figure`` with no ``pyplot`` state. The implicit
curve comes from ``pipeline.curve`` (a second derivation, by elimination) and is drawn as
the zero contour of ``F(x, y)``: it must pass through the closed-form trajectory.

>>> from algkin.analyses.motion import Motion
>>> figure = mechanism_figure(Motion("chebyshev-lambda"), {"angle": 63})
>>> [line.get_label() for line in figure.axes[0].lines if not line.get_label().startswith("_")]
['trajectory of P (left)', 'implicit curve of P (every assembly mode)']
"""

from __future__ import annotations

import io
import os
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from typing import TYPE_CHECKING, Any, TypeVar, Union

import numpy as np
import sympy

from ..errors import UsageError
from ..runtime.budget import Budget, Deadline, started
from ..runtime.files import atomic_output, bytes_written, check_output, write_atomic
from ..runtime.terminal import one_line
from ..runtime.validation import real
from ..scene.load import as_scene
from .plot import FORMATS as FIGURE_FORMATS, new_figure

if TYPE_CHECKING:
    from matplotlib.artist import Artist
    from matplotlib.axes import Axes
    from matplotlib.contour import QuadContourSet
    from matplotlib.figure import Figure
    from matplotlib.lines import Line2D
    from numpy.typing import NDArray

    from ..analyses.motion import Motion, Pose, Trajectories
    from ..derivation.pipeline import CurveResult
    from ..scene import Scene

Bounds = tuple[float, float, float, float]  # xmin, xmax, ymin, ymax
PathT = TypeVar("PathT", bound=Union[str, "os.PathLike[str]"])  # a path given back as it came

__all__ = ["mechanism_figure", "modes_figure", "draw_pose", "PoseArtists", "LiveFigure", "draw_curve", "animate", "parse_inputs", "parse_ranges", "plot_mechanism", "mechanism_file", "FORMATS"]

FORMATS = FIGURE_FORMATS + (".gif", ".mp4", ".html")  # a still figure, or the motion animated
# matplotlib's keyword arguments, of many types
_BAR: dict[str, Any] = dict(color="tab:blue", linewidth=2.5, solid_capstyle="round", zorder=2)
_JOINT: dict[str, Any] = dict(marker="o", markersize=6, color="black", markerfacecolor="white", zorder=4)


def _xy(at: Mapping[str, tuple[float, float]], names: Sequence[str]) -> tuple[list[float], list[float]]:
    """The x and y lists of the points ``names`` in ``at`` (empty when nothing is drawn)."""
    pairs = [at[n] for n in names if n in at]
    return [x for x, _ in pairs], [y for _, y in pairs]


class PoseArtists:
    """Bars, joints, ground pivots, slider guides, strings and labels of one configuration,
    made once on ``axes`` and moved by ``show(pose)``: a slider or an animation frame sets
    their data instead of drawing anew."""

    def __init__(self, axes: Axes, motion: Motion, color: str | None = None) -> None:
        from matplotlib.patches import Circle, Polygon

        # The scene's structure is read once: ``motion.guides`` substitutes into sympy.
        self.bar_ends, self.string_ends, self.guide_lines = motion.bars, motion.strings, motion.guides
        self.motion, self.axes = motion, axes
        # A fixed point that only places a slider's line is no pivot: the rail is drawn instead.
        self.rail_only = set(motion.anchors)
        self.fixed = [p for p in motion.ground if p not in self.rail_only]
        style = dict(_BAR, color=color) if color else _BAR
        self.bars = [axes.plot([], [], **style)[0] for _ in self.bar_ends]
        self.strings = [axes.plot([], [], color="tab:gray", linestyle="--", linewidth=1, zorder=1)[0]
                        for _ in self.string_ends]
        # A rail: the slot's two edges, parallel to the slider's line; the block slides between them.
        self.guides = [axes.axline((0, 0), direction, color="dimgray", linewidth=1.2, zorder=1)
                       for _, _, direction in self.guide_lines for _ in range(2)]
        self.blocks = [Polygon(np.zeros((4, 2)), closed=True, facecolor="lightgray", edgecolor="black",
                               linewidth=1.2, zorder=3) for _ in self.guide_lines]
        for block in self.blocks:
            axes.add_patch(block)
        self.ground = axes.plot([], [], linestyle="none", marker="^", markersize=11, color="dimgray", zorder=3)[0]
        self.joints = axes.plot([], [], linestyle="none", **_JOINT)[0]
        self.labels = {name: axes.annotate(name, (0, 0), textcoords="offset points", xytext=(6, 6), fontsize="small")
                       for name in motion.points[0] if name not in self.rail_only}
        self.blocked = axes.text(0.5, 0.97, "", transform=axes.transAxes, ha="center", va="top", color="tab:red",
                                 fontsize="medium", visible=False, zorder=5,
                                 bbox=dict(facecolor="white", edgecolor="none", alpha=0.8))
        # The two circles that fail to meet where a dyad cannot assemble.
        self.circles = [Circle((0, 0), 1, fill=False, color="tab:red", linestyle="--", linewidth=1, zorder=1,
                               visible=False) for _ in range(2)]
        for circle in self.circles:
            axes.add_patch(circle)

    def all(self) -> list[Artist]:
        """Every artist made, for an animation that redraws only them."""
        return [*self.bars, *self.strings, *self.guides, *self.blocks, self.ground, self.joints, *self.labels.values(),
                *self.circles, self.blocked]

    def show(self, pose: Pose) -> None:
        """Move every artist to ``pose``; where it cannot assemble, what is built stays drawn, with
        the two circles that fail to meet and a red text naming them."""
        at = {p: xy for p, xy in pose.points.items() if xy is not None} if pose.assembles else built(self.motion, pose)
        unmet = [] if pose.assembles else unmet_circles(self.motion, pose, at)
        self.blocked.set_text(_blocked_text(pose, unmet))
        self.blocked.set_visible(not pose.assembles)
        for patch, (_, center, _, radius) in zip(self.circles, unmet):
            patch.set_center(at[center])
            patch.set_radius(radius)
        for k, patch in enumerate(self.circles):
            patch.set_visible(k < len(unmet))
        for line, ends in zip(self.bars + self.strings, self.bar_ends + self.string_ends):
            line.set_data(*_xy(at, ends if all(e in at for e in ends) else ()))  # a bar half built is not drawn
        self._rails(at)
        self.ground.set_data(*_xy(at, self.fixed))
        self.joints.set_data(*_xy(at, [p for p in at if p not in self.fixed and p not in self.rail_only]))
        for name, label in self.labels.items():
            label.set_visible(name in at)
            label.xy = at.get(name, (0, 0))

    def _rails(self, at: Mapping[str, tuple[float, float]]) -> None:
        """Each slider's rail (two edges through its line's point) and its block at the slider point,
        sized from the axes' width so that they read alike at any scale."""
        xlo, xhi = self.axes.get_xlim()
        half = 0.015 * (xhi - xlo)  # half the block's height, the rail's half width
        for k, (slider, through, direction) in enumerate(self.guide_lines):
            along = np.asarray(direction, dtype=float) / np.hypot(*direction)
            across = np.array([-along[1], along[0]])
            for edge, side in zip(self.guides[2 * k:2 * k + 2], (1, -1)):
                edge.set_visible(through in at)
                if through in at:
                    start = np.asarray(at[through]) + side * half * across
                    edge.set_xy1(tuple(start))
                    edge.set_xy2(tuple(start + along))
            block = self.blocks[k]
            block.set_visible(slider in at)
            if slider in at:
                centre = np.asarray(at[slider])
                block.set_xy([centre + a * 2 * half * along + b * half * across
                              for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1))])


Unmet = tuple[str, str, str, float]  # the blocked point, a circle's centre, its radius as written, its value


def built(motion: Motion, pose: Pose) -> dict[str, tuple[float, float]]:
    """The points of ``pose`` that are built even where it cannot assemble: those constructed
    before the failing one and not from it (finite where the rest is nan)."""
    points, _ = motion.evaluate(motion.branch_index(pose.branch), motion.values(pose.inputs, pose.parameters))
    return {p: (float(x), float(y)) for p, (x, y) in points.items() if np.isfinite([x, y]).all()}


def unmet_circles(motion: Motion, pose: Pose, at: Mapping[str, tuple[float, float]]) -> list[Unmet]:
    """The two circles of the first blocked dyad whose centres are built: (point, centre, radius
    as written, radius); none when the failing point is no dyad.

    >>> from algkin.analyses.motion import Motion
    >>> motion = Motion("fourbar")
    >>> pose = motion.at({"theta": 180}, {"l": 0.75})
    >>> [(p, c, r, round(v, 6)) for p, c, r, v in unmet_circles(motion, pose, built(motion, pose))]
    [('B', 'A', 'l', 0.75), ('B', 'D', 'm', 3.5)]
    """
    from ..evaluate import NUMPY, evaluate
    from ..scene.constructions import Dyad

    values = motion.values(pose.inputs, pose.parameters)
    for name in pose.blocked:
        made = motion.scene.points[name]
        if isinstance(made, Dyad) and all(b in at for b in made.bases):
            return [(name, base, str(length), float(evaluate(length, values, NUMPY)))
                    for base, length in zip(made.bases, made.lengths)]
    return []


def _blocked_text(pose: Pose, unmet: Sequence[Unmet]) -> str:
    """What the red text says where ``pose`` cannot assemble."""
    if not unmet:
        return f"cannot assemble: {', '.join(pose.blocked)}"
    (point, p, lp, vp), (_, q, lq, vq) = unmet
    return (f"cannot assemble {point}:\nthe circles about {p} (radius {lp} = {vp:.4g}) "
            f"and {q} (radius {lq} = {vq:.4g}) do not meet")


def draw_pose(axes: Axes, motion: Motion, pose: Pose, color: str | None = None) -> PoseArtists:
    """Bars, joints, ground pivots, slider guides and strings of ``pose`` on ``axes``."""
    artists = PoseArtists(axes, motion, color)
    artists.show(pose)
    return artists


# One colour per traced point, none of them the bars' blue, the joints' black and grey, nor the
# implicit curves' green: a dashed green line is always the eliminant's zero set, drawn over the
# trajectory it must cover (the tutorials say "the trajectory (orange) and F (dashed green)").
_TRACES = ("tab:orange", "tab:purple", "tab:red", "tab:brown", "tab:pink", "tab:olive", "tab:cyan")
IMPLICIT_COLOR = "tab:green"


def trace_color(motion: Motion, name: str) -> str:
    """The colour of traced point ``name``'s trajectory (never ``IMPLICIT_COLOR``)."""
    return _TRACES[motion.traced.index(name) % len(_TRACES)]


def _trajectories(axes: Axes, motion: Motion, points: Trajectories, label: str | None = None) -> dict[str, Line2D]:
    """Each traced point's path from ``points`` (a sweep), labelled with the branch if given:
    point -> its line."""
    return {name: axes.plot(*points[name], color=trace_color(motion, name), linewidth=1.5, zorder=1,
                            label=_trajectory_label(name, label))[0]
            for name in motion.traced}


def _trajectory_label(name: str, branch: str | None = None) -> str:
    return f"trajectory of {name}" + (f" ({branch})" if branch else "")


def _sweeps(motion: Motion, parameters: Mapping[str, float] | None) -> dict[str, Trajectories]:
    """Every branch's sweep at ``parameters``: branch label -> point -> (x, y) arrays."""
    return {b.label: motion.sweep(parameters, b.label)[1] for b in motion.branches}


def _bounds(motion: Motion, parameters: Mapping[str, float] | None,
            sweeps: Mapping[str, Trajectories] | None = None) -> Bounds:
    """Box around every point on every branch over the whole sweep (nan-free); ``sweeps``:
    those of ``_sweeps(motion, parameters)`` when already made."""
    xs, ys = [], []
    for points in (sweeps or _sweeps(motion, parameters)).values():
        for x, y in points.values():
            xs.append(x[np.isfinite(x)])
            ys.append(y[np.isfinite(y)])
    x, y = np.concatenate(xs), np.concatenate(ys)
    pad = 0.08 * max(np.ptp(x), np.ptp(y), 1e-9)
    return x.min() - pad, x.max() + pad, y.min() - pad, y.max() + pad


def draw_curve(axes: Axes, result: CurveResult, bounds: Bounds, grid: int = 500,
               color: str = IMPLICIT_COLOR) -> QuadContourSet:
    """The zero set of ``result.elimination.polynomial`` (a ``CurveResult``) over ``bounds``, dashed."""
    poly = result.elimination.polynomial
    # A slider's curve may lack one coordinate (B_y = e is a line): a stand-in symbol keeps
    # F a function of both, constant along the missing one.
    named = {s.name: s for s in poly.free_symbols}
    x, y = (named.get(v, sympy.Dummy(v)) for v in result.variables)
    F = sympy.lambdify((x, y), poly, "numpy")
    xmin, xmax, ymin, ymax = bounds
    X, Y = np.meshgrid(np.linspace(xmin, xmax, grid), np.linspace(ymin, ymax, grid))
    contour = axes.contour(X, Y, np.broadcast_to(F(X, Y), X.shape), levels=[0], colors=color,
                           linewidths=0.8, linestyles="--", zorder=1)
    # A proxy line so the contour appears in the legend.
    axes.plot([], [], color=color, linewidth=0.8, linestyle="--",
              label=f"implicit curve of {result.point} (every assembly mode)")
    return contour


def _finish(axes: Axes, title: str, unit: str = "") -> None:
    # Fixed limits on every drawing: the box, not the data limits, keeps the scales equal.
    axes.set_aspect("equal", adjustable="box")
    if unit:  # the scene's lengths' unit (``unit = "mm"``)
        axes.set_xlabel(f"$x$ ({unit})")
        axes.set_ylabel(f"$y$ ({unit})")
    axes.grid(True, linewidth=0.3)
    axes.set_title(title, fontsize="medium", parse_math=False)  # a scene's name is text, never mathtext


def _pose_title(motion: Motion) -> Callable[[Pose], str]:
    """The title of a figure of one configuration: the scene, its input angles, its branch."""
    def title(pose: Pose) -> str:
        angles = ", ".join(f"{n} = {motion.inputs[n].shown(v)}" for n, v in pose.inputs.items())
        return f"{one_line(motion.scene.name)}: {angles}, {pose.branch}"
    return title


class LiveFigure:
    """One configuration with its trajectories, built once and then moved by ``update``.

    A move sets the artists' data (``PoseArtists``) and the title. Every branch is swept
    again (for the trajectories and the limits) only when a dimension changed; a new
    branch only picks its sweep. So a slider costs an evaluation and a render, not a new figure.
    ``title``: pose -> the text above the axes. ``every_mode``: the limits hold every assembly
    mode (a mode switched by a slider keeps the scale), else only the drawn one (an animation).
    """

    def __init__(self, motion: Motion, parameters: Mapping[str, float] | None = None, branch: str | None = None,
                 title: Callable[[Pose], str] | None = None, *, every_mode: bool = True) -> None:
        self.motion, self.title = motion, title or _pose_title(motion)
        self.parameters = motion.complete(None, parameters)[1]
        self.branch = motion.branches[motion.branch_index(branch)].label
        self.sweeps = _sweeps(motion, self.parameters)
        self.every_mode = every_mode
        self.bounds = self._fit()
        self.figure = new_figure()
        self._layout = self.figure.get_layout_engine()
        # A figure shaped like the mechanism's reach, so equal scales leave little empty space.
        ratio = (self.bounds[3] - self.bounds[2]) / (self.bounds[1] - self.bounds[0])
        self.figure.set_size_inches(6.4, min(max(6.4 * ratio, 3.6), 7.2))
        self.axes = self.figure.add_subplot()
        self.paths = _trajectories(self.axes, motion, self.sweeps[self.branch], self.branch)
        self.artists = PoseArtists(self.axes, motion)
        _finish(self.axes, "", motion.scene.unit)
        self._limit()

    def _fit(self, parameters: Mapping[str, float] | None = None, branch: str | None = None) -> Bounds:
        """The box of every mode's sweep, or of ``branch``'s (the drawn one's) alone."""
        branch = branch or self.branch
        sweeps = self.sweeps if self.every_mode else {branch: self.sweeps[branch]}
        return _bounds(self.motion, parameters or self.parameters, sweeps)

    def _limit(self) -> None:
        self._relayout = True
        self.axes.set_xlim(self.bounds[0], self.bounds[1])
        self.axes.set_ylim(self.bounds[2], self.bounds[3])

    def update(self, inputs: Mapping[str, float] | None = None, parameters: Mapping[str, float] | None = None,
               branch: str | None = None) -> Pose:
        """Move the figure to ``inputs`` (degrees), ``parameters`` and ``branch``; returns the pose."""
        return self.show(self.motion.at(inputs, parameters, branch))

    def show(self, pose: Pose) -> Pose:
        """Move the figure to ``pose`` (a ``Motion.at`` or ``Motion.poses`` configuration)."""
        if pose.parameters != self.parameters or (not self.every_mode and pose.branch != self.branch):
            self.sweeps = _sweeps(self.motion, pose.parameters)
            self.bounds = self._fit(pose.parameters, pose.branch)
            self._limit()
        if (pose.parameters, pose.branch) != (self.parameters, self.branch):
            for name, line in self.paths.items():
                line.set_data(*self.sweeps[pose.branch][name])
                line.set_label(_trajectory_label(name, pose.branch))
        self.parameters, self.branch = pose.parameters, pose.branch
        self.artists.show(pose)
        self.axes.title.set_text(self.title(pose))
        return pose

    def png(self, dpi: float = 90) -> bytes:
        """The figure as it stands, as PNG bytes at ``dpi``.

        The constrained layout costs a third of a render: it is computed on the first render
        and again after the limits changed (tick labels may widen), and kept in between.
        """
        if self.figure.dpi != dpi:
            self.figure.set_dpi(dpi)
        self.figure.set_layout_engine(self._layout if self._relayout else "none")
        from matplotlib.backends.backend_agg import FigureCanvasAgg

        canvas = self.figure.canvas
        assert isinstance(canvas, FigureCanvasAgg)  # new_figure's
        buffer = io.BytesIO()
        # Fast compression: the bytes go to the notebook next door, not to a file kept.
        canvas.print_png(buffer, pil_kwargs={"compress_level": 1})
        self._relayout = False
        return buffer.getvalue()


def mechanism_figure(motion: Motion, inputs: Mapping[str, float] | None = None,
                     parameters: Mapping[str, float] | None = None, branch: str | None = None,
                     curve: bool = True, *, budget: Budget | Deadline | None = None) -> Figure:
    """The configuration at ``inputs`` with each traced point's trajectory and implicit curve.

    The implicit curves are derived at the dimensions' defaults, so they are drawn only there;
    their eliminations keep to ``budget`` (a ``Budget``, or a running ``Deadline``), if any.
    """
    inputs = inputs if inputs is not None else motion.start(parameters, branch)
    live = LiveFigure(motion, parameters, branch)
    live.update(inputs, parameters, branch)
    at_defaults = all(v == motion.defaults[p] for p, v in motion.complete(inputs, parameters)[1].items())
    # With two inputs a point sweeps a region, not a curve: no implicit curve then.
    if curve and at_defaults and len(motion.inputs) == 1:
        from ..derivation.pipeline import curve as derive_curve

        deadline = started(budget)  # one for every curve: the budget bounds them all
        for name in motion.traced:
            draw_curve(live.axes, derive_curve(motion.scene, name, samples=0, budget=deadline), live.bounds)
    # Below the axes: inside, it would cover a curve on one scene or another.
    live.figure.legend(loc="outside lower center", ncols=2, fontsize="small")
    return live.figure


def modes_figure(motion: Motion, inputs: Mapping[str, float] | None = None,
                 parameters: Mapping[str, float] | None = None) -> Figure:
    """Every assembly mode at the same inputs, side by side, each with its trajectory."""
    inputs = inputs if inputs is not None else motion.start(parameters)
    sweeps = _sweeps(motion, parameters)
    bounds = _bounds(motion, parameters, sweeps)
    figure = new_figure()
    figure.set_size_inches(*_panels_size(bounds, len(motion.branches)))
    shared: Axes | None = None
    for k, branch in enumerate(motion.branches):
        axes = figure.add_subplot(1, len(motion.branches), k + 1, sharex=shared, sharey=shared)
        shared = shared or axes
        _trajectories(axes, motion, sweeps[branch.label])
        axes.set_xlim(bounds[0], bounds[1])
        axes.set_ylim(bounds[2], bounds[3])
        draw_pose(axes, motion, motion.at(inputs, parameters, branch.label))  # rails sized to the limits
        _finish(axes, f"{branch.label}" + (" (scene's choice)" if branch.selected else ""), motion.scene.unit)
        axes.label_outer()  # the shared y scale is read off the first panel
    angles = ", ".join(f"{n} = {motion.inputs[n].shown(v)}" for n, v in motion.complete(inputs)[0].items())
    figure.suptitle(f"{one_line(motion.scene.name)}: assembly modes at {angles}", parse_math=False)
    return figure


def _panels_size(bounds: Bounds, count: int, width: float = 3.6, tallest: float = 6.4) -> tuple[float, float]:
    """Inches for ``count`` equal-aspect panels of ``bounds`` side by side: each panel is
    shaped like the mechanism's reach, so the boxes fill the figure with no gap between."""
    ratio = (bounds[3] - bounds[2]) / (bounds[1] - bounds[0])
    width = min(width, tallest / ratio)
    return width * count + 0.6, width * ratio + 0.9  # room for tick labels and titles


def animate(motion: Motion, out: PathT, parameters: Mapping[str, float] | None = None, branch: str | None = None,
            frames: int = 72, fps: int = 24) -> PathT:
    """Turn the first input through its range and write ``out`` (.gif with pillow, .mp4 with ffmpeg).

    The axes are fitted to the drawn assembly mode. The still parts (axes, ticks, trajectories)
    are rendered once; each frame restores them and draws only the moving artists (blitting).
    """
    suffix = _check_movie(out)
    name = next(iter(motion.inputs))
    shown = motion.inputs[name].shown
    live = LiveFigure(motion, parameters, branch, every_mode=False,
                      title=lambda pose: f"{one_line(motion.scene.name)}: {name} = {shown(pose.inputs[name])}")
    poses = motion.poses(parameters, branch, frames)
    with atomic_output(out) as temporary:  # the writers infer the format from the kept suffix
        if suffix == ".gif":
            _write_gif(temporary, _frames(live, poses, dpi=80), fps)
        else:
            _write_mp4(temporary, live, poses, fps)
    return out


def _check_movie(out: str | os.PathLike[str]) -> str:
    """The suffix of ``out``, an animation's, refused if it cannot be written here (an .mp4 with no ffmpeg)."""
    from matplotlib import animation

    suffix = os.path.splitext(out)[1].lower()
    if suffix == ".mp4" and not animation.writers.is_available("ffmpeg"):
        raise UsageError("--out", str(out), "an .mp4 needs ffmpeg on PATH (not found); write a .gif instead")
    return suffix


def _frames(live: LiveFigure, poses: Sequence[Pose], dpi: float) -> Iterator[NDArray[np.uint8]]:
    """RGBA pixels of ``live`` moved to each of ``poses``, blitted on a background drawn once."""
    live.figure.set_dpi(dpi)
    moving = live.artists.all() + [live.axes.title]
    live.show(poses[0])
    canvas = live.figure.canvas
    canvas.draw()  # the layout is computed here, once, then frozen
    live.figure.set_layout_engine("none")
    for artist in moving:
        artist.set_animated(True)
    canvas.draw()
    background = canvas.copy_from_bbox(live.figure.bbox)  # type: ignore[attr-defined]  # Agg's
    for pose in poses:
        live.show(pose)
        canvas.restore_region(background)  # type: ignore[attr-defined]
        for artist in moving:
            live.figure.draw_artist(artist)
        yield np.array(canvas.buffer_rgba())  # type: ignore[attr-defined]


def _write_gif(path: os.PathLike[str], pictures: Iterable[NDArray[np.uint8]], fps: int) -> None:
    from PIL import Image

    images = [Image.fromarray(p).convert("RGB") for p in pictures]
    images[0].save(path, format="GIF", save_all=True, append_images=images[1:], duration=1000 / fps, loop=0)


def _write_mp4(path: os.PathLike[str], live: LiveFigure, poses: Sequence[Pose], fps: int) -> None:
    """Each pose drawn whole by matplotlib's ffmpeg writer, the layout computed once."""
    from matplotlib import animation

    writer = animation.FFMpegWriter(fps=fps)
    with writer.saving(live.figure, os.fspath(path), dpi=80):
        for k, pose in enumerate(poses):
            live.show(pose)
            writer.grab_frame()
            if k == 0:
                live.figure.set_layout_engine("none")


def parse_inputs(motion: Motion, texts: Sequence[str]) -> dict[str, float]:
    """``--input`` values: ``VALUE`` (a one-input scene) or ``NAME=VALUE``, degrees (a length input's
    length) within range.

    >>> from algkin.analyses.motion import Motion
    >>> parse_inputs(Motion("chebyshev-lambda"), ["angle=30"])
    {'angle': 30.0}
    """
    inputs: dict[str, float] = {}
    for text in texts:
        name, _, value = text.rpartition("=")
        name = name or (next(iter(motion.inputs)) if len(motion.inputs) == 1 else "")
        if name not in motion.inputs:
            raise UsageError("--input", text, f"expected NAME=DEGREES with NAME one of {', '.join(motion.inputs)}")
        try:
            degrees = real(value)
        except ValueError:
            degrees = float("nan")
        lo, hi = motion.inputs[name].span
        if not lo <= degrees <= hi:
            what = "a number of degrees" if motion.inputs[name].is_angle else "a length"
            raise UsageError("--input", text, f"expected {what} in [{lo:g}, {hi:g}]")
        if name in inputs:
            raise UsageError("--input", text, f"{name} given twice")
        inputs[name] = degrees
    return inputs


def parse_ranges(texts: Sequence[str], option: str = "--range-of") -> dict[str, tuple[float, float]]:
    """``NAME=LO:HI`` values (``--range-of``, ``--against``) -> {name: (lo, hi)}, finite numbers
    with lo below hi.

    >>> parse_ranges(["a=0.5:2", "l=1:3"])
    {'a': (0.5, 2.0), 'l': (1.0, 3.0)}
    """
    ranges: dict[str, tuple[float, float]] = {}
    for text in texts:
        name, _, span = text.partition("=")
        try:
            lo, hi = (real(v) for v in span.split(":"))
        except ValueError:
            lo = hi = float("nan")
        # nan fails lo < hi, so only infinities need their own check.
        if not (name.isidentifier() and lo < hi and np.isfinite([lo, hi]).all()):
            raise UsageError(option, text, "expected NAME=LO:HI, finite numbers with LO below HI, e.g. a=0.5:2")
        if name in ranges:
            raise UsageError(option, text, f"{name} given twice")
        ranges[name] = (lo, hi)
    return ranges


def plot_mechanism(scene: str | Scene, out: PathT, inputs: Sequence[str] = (), branch: str | None = None,
                   modes: bool = False, params: Sequence[str] | None = None, ranges: Sequence[str] = (), *,
                   budget: Budget | Deadline | None = None) -> PathT:
    """``algkin plot SCENE --out F``: ``mechanism_file`` written to ``out``; returns ``out``.

    A scene whose chosen assembly mode never assembles is refused before ``out`` is touched.
    """
    _format(out)
    check_output("--out", out)
    write_atomic(out, mechanism_file(scene, out, inputs, branch, modes, params, ranges, budget=budget))
    return out


def mechanism_file(scene: str | Scene, out: str | os.PathLike[str], inputs: Sequence[str] = (),
                   branch: str | None = None, modes: bool = False, params: Sequence[str] | None = None,
                   ranges: Sequence[str] = (), *, budget: Budget | Deadline | None = None) -> bytes:
    """What ``algkin plot SCENE --out OUT`` writes to ``out``, in the format of its suffix, as bytes;
    nothing is written to ``out`` (the command line writes it, once the work is done in its budget).

    ``ranges``: ``--range-of`` texts (``NAME=LO:HI``), the sliders' ranges of the .html page.
    ``budget`` (a ``Budget`` or a running ``Deadline``) bounds the implicit curves' eliminations.
    """
    from ..branches import check_assembly
    from ..analyses.motion import Motion
    from .plot import image

    suffix = _format(out)
    if modes and branch is not None:
        raise UsageError("--branch", branch, "--modes draws every assembly mode; leave out --branch")
    sliders = parse_ranges(ranges)
    loaded = as_scene(scene)
    if loaded.unknown_points:  # points solved together: every mode, from solve and follow
        from .groupdraw import groups_file

        if params:
            raise UsageError("--param", params[0], "points solved together take their dimensions' values: use --set")
        return groups_file(loaded, out, inputs=inputs, branch=branch, ranges=ranges)
    if sliders and suffix != ".html":
        raise UsageError("--range-of", ranges[0], "only the .html page has sliders; write a .html")
    motion = Motion(loaded, params)
    chosen = parse_inputs(motion, inputs) or None
    motion.branch_index(branch)  # a bad --branch fails before anything is drawn
    check_assembly(motion.compiled, motion.branches)
    if suffix == ".html":
        from .html import page

        return page(motion, chosen, branch, sliders).encode("utf-8")
    if suffix in (".gif", ".mp4"):
        _check_movie(out)
        return bytes_written(lambda path: animate(motion, path, branch=branch), suffix)
    figure = modes_figure(motion, chosen) if modes else mechanism_figure(motion, chosen, branch=branch, budget=budget)
    return image(figure, suffix)


def _format(out: str | os.PathLike[str]) -> str:
    """The suffix of ``out`` (lower case), one of ``FORMATS``."""
    suffix = os.path.splitext(out)[1].lower()
    if suffix not in FORMATS:
        raise UsageError("--out", out, f"unknown format; valid: {', '.join(FORMATS)}")
    return suffix
