"""The notebook widget's cost per slider move: a new figure each time against one figure moved.

The old way (what ``Explorer.png`` did before the live figure): ``Explorer.figure`` builds
a new matplotlib figure (trajectories swept, every artist made) and saves it as PNG. The
new way: ``Explorer.png`` moves its one ``LiveFigure`` (artists' data set; trajectories
swept again only for a dimension or a branch) and renders it to PNG. Both are timed in the
same run on the same moves: ``--moves`` steps of the input, then ``--dimension-moves``
steps of a dimension (where the scene has one). After each new-way move, the drawn joints
and labels are asserted equal to ``Motion.at`` at those values, so the time measured is
that of the real picture.

Run: ``python benchmarks/bench_widget.py [--scenes NAME ...] [--moves N] [--dimension-moves N]``.
"""

import argparse
import io
import time

import numpy as np

from algkin.ui.widgets import Explorer

SCENES = ("chebyshev-lambda", "fourbar")


def old_png(explorer, values):
    """The picture as before: a whole new figure, saved as PNG at the widget's dpi."""
    buffer = io.BytesIO()
    explorer.figure(**values).savefig(buffer, format="png", dpi=90)
    return buffer.getvalue()


def moves(explorer, count, dimension_count):
    """Slider values: the input turned in ``count`` steps, then a dimension in ``dimension_count``."""
    sliders = explorer.sliders
    turn, dimensions = sliders[0], sliders[len(explorer.motion.inputs):]
    values = [{turn["name"]: a} for a in np.linspace(turn["lo"], turn["hi"], count, endpoint=False)]
    if dimensions:
        d = dimensions[0]
        middle = {turn["name"]: turn["value"]}
        # Between the default and a little over it, so the mechanism keeps assembling mostly.
        values += [{**middle, d["name"]: v} for v in np.linspace(d["value"], d["value"] * 1.2, dimension_count)]
    return values


def check(explorer, values):
    """The live figure's joints and labels are where ``Motion.at`` puts the points."""
    pose = explorer.pose(**values)
    artists = explorer.live.artists
    if not pose.assembles:
        assert artists.blocked.get_visible() and not len(artists.joints.get_xdata())
        return
    moving = [p for p in pose.points if p not in artists.fixed]
    drawn = np.column_stack(artists.joints.get_data())
    assert np.array_equal(drawn, np.array([pose.points[p] for p in moving])), "joints not at Motion.at"
    assert all(artists.labels[p].xy == pose.points[p] for p in pose.points), "labels not at Motion.at"


def per_move(function, values):
    """Seconds per move, over every move after one warm-up call."""
    function(values[0])
    start = time.perf_counter()
    for v in values:
        function(v)
    return (time.perf_counter() - start) / len(values)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scenes", nargs="+", default=SCENES)
    parser.add_argument("--moves", type=int, default=50, help="moves of the input")
    parser.add_argument("--dimension-moves", type=int, default=10, help="moves of a dimension")
    args = parser.parse_args()
    print(f"{'scene':18} {'moves':>6} {'new figure':>12} {'live figure':>12} {'ratio':>7}")
    for name in args.scenes:
        explorer = Explorer(name)
        values = moves(explorer, args.moves, args.dimension_moves)
        for v in values:
            explorer.png(**v)
            check(explorer, v)
        old = per_move(lambda v: old_png(explorer, v), values)
        new = per_move(lambda v: explorer.png(**v), values)
        print(f"{name:18} {len(values):6} {old * 1e3:9.1f} ms {new * 1e3:9.1f} ms {old / new:6.1f}x")


if __name__ == "__main__":
    main()
