"""Mechanisms drawn with matplotlib: a configuration, trajectories, implicit curves, animations.

Built on ``algkin.motion`` (closed forms evaluated, never re-derived) and, like
``algkin.plot``, on ``matplotlib.figure.Figure`` with no ``pyplot`` state. The implicit
curve comes from ``pipeline.curve`` (a second derivation, by elimination) and is drawn as
the zero contour of ``F(x, y)``: it must pass through the closed-form trajectory.

>>> from algkin.motion import Motion
>>> figure = mechanism_figure(Motion("chebyshev-lambda"), {"angle": 63})
>>> [line.get_label() for line in figure.axes[0].lines if not line.get_label().startswith("_")]
['trajectory of P (left)', 'implicit curve of P (every assembly mode)']
"""

import numpy as np
import sympy

from .errors import UsageError
from .files import atomic_output, check_output
from .plot import _figure

__all__ = ["mechanism_figure", "modes_figure", "draw_pose", "draw_curve", "animate", "parse_inputs", "plot_mechanism", "FORMATS"]

FORMATS = (".png", ".svg", ".pdf", ".gif", ".mp4", ".html")
_BAR = dict(color="tab:blue", linewidth=2.5, solid_capstyle="round", zorder=2)
_JOINT = dict(marker="o", markersize=6, color="black", markerfacecolor="white", zorder=4)


def draw_pose(axes, motion, pose, color=None):
    """Bars, joints, ground pivots, slider guides and strings of ``pose`` on ``axes``."""
    if not pose.assembles:
        axes.text(0.5, 0.5, f"cannot assemble: {', '.join(pose.blocked)}", transform=axes.transAxes,
                  ha="center", va="center", color="tab:red", fontsize="large")
        return
    at = pose.points
    style = dict(_BAR, color=color) if color else _BAR
    for p, q in motion.bars:
        axes.plot(*zip(at[p], at[q]), **style)
    for p, q in motion.strings:
        axes.plot(*zip(at[p], at[q]), color="tab:gray", linestyle="--", linewidth=1, zorder=1)
    for point, through, (dx, dy) in motion.guides:
        x, y = at[through]
        axes.axline((x, y), (x + dx, y + dy), color="tab:gray", linewidth=1, zorder=1)
    ground = motion.ground
    axes.plot(*zip(*(at[g] for g in ground)), linestyle="none", marker="^", markersize=11,
              color="dimgray", zorder=3)
    moving = [p for p in at if p not in ground]
    axes.plot(*zip(*(at[p] for p in moving)), linestyle="none", **_JOINT)
    for name, (x, y) in at.items():
        axes.annotate(name, (x, y), textcoords="offset points", xytext=(6, 6), fontsize="small")


# One colour per traced point, none of them the bars' blue or the joints' black and grey.
_TRACES = ("tab:orange", "tab:purple", "tab:red", "tab:green", "tab:brown", "tab:pink", "tab:olive", "tab:cyan")


def trace_color(motion, name):
    """The colour of traced point ``name``: its trajectory and its implicit curve share it."""
    return _TRACES[motion.traced.index(name) % len(_TRACES)]


def _trajectories(axes, motion, points, label=None):
    """Each traced point's path from ``points`` (a sweep), labelled with the branch if given."""
    for name in motion.traced:
        axes.plot(*points[name], color=trace_color(motion, name), linewidth=1.5, zorder=1,
                  label=f"trajectory of {name}" + (f" ({label})" if label else ""))


def _bounds(motion, parameters):
    """Box around every point on every branch over the whole sweep (nan-free)."""
    xs, ys = [], []
    for k in range(len(motion.branches)):
        _, points = motion.sweep(parameters, motion.branches[k].label)
        for x, y in points.values():
            xs.append(x[np.isfinite(x)])
            ys.append(y[np.isfinite(y)])
    x, y = np.concatenate(xs), np.concatenate(ys)
    pad = 0.08 * max(np.ptp(x), np.ptp(y), 1e-9)
    return x.min() - pad, x.max() + pad, y.min() - pad, y.max() + pad


def draw_curve(axes, result, bounds, grid=500, color="tab:green"):
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


def _finish(axes, title, adjustable="datalim"):
    axes.set_aspect("equal", adjustable=adjustable)
    axes.grid(True, linewidth=0.3)
    axes.set_title(title, fontsize="medium", parse_math=False)  # a scene's name is text, never mathtext


def mechanism_figure(motion, inputs=None, parameters=None, branch=None, curve=True):
    """The configuration at ``inputs`` with each traced point's trajectory and implicit curve.

    The implicit curves are derived at the dimensions' defaults, so they are drawn only there.
    """
    inputs = inputs if inputs is not None else motion.start(parameters, branch)
    pose = motion.at(inputs, parameters, branch)
    bounds = _bounds(motion, parameters)
    figure = _figure()
    # A figure shaped like the mechanism's reach, so equal scales leave little empty space.
    figure.set_size_inches(6.4, min(max(6.4 * (bounds[3] - bounds[2]) / (bounds[1] - bounds[0]), 3.6), 7.2))
    axes = figure.add_subplot()
    _trajectories(axes, motion, motion.sweep(parameters, branch)[1], pose.branch)
    at_defaults = all(v == motion.defaults[p] for p, v in motion.complete(inputs, parameters)[1].items())
    # With two inputs a point sweeps a region, not a curve: no implicit curve then.
    if curve and at_defaults and len(motion.inputs) == 1:
        from .pipeline import curve as derive_curve

        for name in motion.traced:
            draw_curve(axes, derive_curve(motion.scene, name, samples=0), bounds, color=trace_color(motion, name))
    draw_pose(axes, motion, pose)
    angles = ", ".join(f"{n} = {v:g}°" for n, v in pose.inputs.items())
    _finish(axes, f"{motion.scene.name}: {angles}, {pose.branch}")
    # Below the axes: inside, it would cover a curve on one scene or another.
    figure.legend(loc="outside lower center", ncols=2, fontsize="small")
    return figure


def modes_figure(motion, inputs=None, parameters=None):
    """Every assembly mode at the same inputs, side by side, each with its trajectory."""
    inputs = inputs if inputs is not None else motion.start(parameters)
    bounds = _bounds(motion, parameters)
    figure = _figure()
    figure.set_size_inches(*_panels_size(bounds, len(motion.branches)))
    shared = None
    for k, branch in enumerate(motion.branches):
        axes = figure.add_subplot(1, len(motion.branches), k + 1, sharex=shared, sharey=shared)
        shared = shared or axes
        _trajectories(axes, motion, motion.sweep(parameters, branch.label)[1])
        draw_pose(axes, motion, motion.at(inputs, parameters, branch.label))
        axes.set_xlim(bounds[0], bounds[1])
        axes.set_ylim(bounds[2], bounds[3])
        # Shared axes cannot each stretch their data limits: keep equal scales by the box.
        _finish(axes, f"{branch.label}" + (" (scene's choice)" if branch.selected else ""), "box")
        axes.label_outer()  # the shared y scale is read off the first panel
    angles = ", ".join(f"{n} = {v:g}°" for n, v in motion.complete(inputs)[0].items())
    figure.suptitle(f"{motion.scene.name}: assembly modes at {angles}", parse_math=False)
    return figure


def _panels_size(bounds, count, width=3.6, tallest=6.4):
    """Inches for ``count`` equal-aspect panels of ``bounds`` side by side: each panel is
    shaped like the mechanism's reach, so the boxes fill the figure with no gap between."""
    ratio = (bounds[3] - bounds[2]) / (bounds[1] - bounds[0])
    width = min(width, tallest / ratio)
    return width * count + 0.6, width * ratio + 0.9  # room for tick labels and titles


def animate(motion, out, parameters=None, branch=None, frames=72, fps=24):
    """Turn the first input through its range and write ``out`` (.gif with pillow, .mp4 with ffmpeg)."""
    import pathlib

    from matplotlib import animation

    suffix = pathlib.Path(out).suffix.lower()
    if suffix == ".mp4" and not animation.writers.is_available("ffmpeg"):
        raise UsageError("--out", str(out), "an .mp4 needs ffmpeg on PATH (not found); write a .gif instead")
    name = next(iter(motion.inputs))
    bounds = _bounds(motion, parameters)
    paths = motion.sweep(parameters, branch)[1]
    figure = _figure()
    axes = figure.add_subplot()

    def frame(pose):
        axes.clear()
        _trajectories(axes, motion, paths)
        draw_pose(axes, motion, pose)
        axes.set_xlim(bounds[0], bounds[1])
        axes.set_ylim(bounds[2], bounds[3])
        # Fixed limits on every frame: the box, not the data limits, keeps the scales equal.
        _finish(axes, f"{motion.scene.name}: {name} = {pose.inputs[name]:.1f}°", "box")

    movie = animation.FuncAnimation(figure, frame, frames=motion.poses(parameters, branch, frames),
                                    cache_frame_data=False)
    writer = animation.PillowWriter(fps=fps) if suffix == ".gif" else animation.FFMpegWriter(fps=fps)
    with atomic_output(out) as temporary:  # the writers infer the format from the kept suffix
        movie.save(str(temporary), writer=writer, dpi=80)
    return out


def parse_inputs(motion, texts):
    """``--input`` values: ``VALUE`` (a one-input scene) or ``NAME=VALUE``, degrees within range.

    >>> from algkin.motion import Motion
    >>> parse_inputs(Motion("chebyshev-lambda"), ["angle=30"])
    {'angle': 30.0}
    """
    inputs = {}
    for text in texts:
        name, _, value = text.rpartition("=")
        name = name or (next(iter(motion.inputs)) if len(motion.inputs) == 1 else "")
        if name not in motion.inputs:
            raise UsageError("--input", text, f"expected NAME=DEGREES with NAME one of {', '.join(motion.inputs)}")
        try:
            degrees = float(value)
        except ValueError:
            degrees = float("nan")
        lo, hi = motion.inputs[name].range_degrees
        if not lo <= degrees <= hi:
            raise UsageError("--input", text, f"expected a number of degrees in [{lo:g}, {hi:g}]")
        inputs[name] = degrees
    return inputs


def plot_mechanism(scene, out, inputs=(), branch=None, modes=False, params=None):
    """``algkin plot SCENE --out F``: the format follows the suffix of ``out``; returns ``out``.

    A scene whose chosen assembly mode never assembles is refused before ``out`` is touched.
    """
    import pathlib

    from .branches import check_assembly
    from .motion import Motion
    from .plot import save

    path = pathlib.Path(out)
    suffix = path.suffix.lower()
    if suffix not in FORMATS:
        raise UsageError("--out", out, f"unknown format; valid: {', '.join(FORMATS)}")
    check_output("--out", out)
    if modes and branch is not None:
        raise UsageError("--branch", branch, "--modes draws every assembly mode; leave out --branch")
    motion = Motion(scene, params)
    chosen = parse_inputs(motion, inputs) or None
    motion.branch_index(branch)  # a bad --branch fails before anything is drawn
    check_assembly(motion.compiled, motion.branches)
    if suffix == ".html":
        from .html import write

        return write(motion, out, chosen, branch)
    if suffix in (".gif", ".mp4"):
        return animate(motion, out, branch=branch)
    figure = modes_figure(motion, chosen) if modes else mechanism_figure(motion, chosen, branch=branch)
    return save(figure, out)
