"""Figures: one command each, drawn from closed forms, with the certified points on them."""

import subprocess
import sys

import pytest

pytest.importorskip("matplotlib")

import matplotlib  # noqa: E402

from algkin.mechanism import load  # noqa: E402
from algkin.plot import minimum_figure, quantity_figure  # noqa: E402

from .analyses.extremum.arm_by_hand import brute_minimum, hand_minimiser, hand_minimum  # noqa: E402


def run(*args):
    return subprocess.run([sys.executable, "-m", "algkin", *args], capture_output=True, text=True)


@pytest.mark.parametrize("extra", [[], ["--derivative"], ["--against", "b=-400:400"]])
def test_each_figure_is_one_command(tmp_path, extra):
    out = tmp_path / "figure.png"
    done = run("plot", "arm-string", "--of", "AB", "--out", str(out), *extra)
    assert done.returncode == 0, done.stderr
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and out.stat().st_size > 10_000


def test_bad_figure_requests_write_nothing(tmp_path):
    for args in (["--out", str(tmp_path / "x.gif")], ["--out", str(tmp_path / "no" / "x.png")],
                 ["--out", str(tmp_path / "x.png"), "--against", "b"]):
        done = run("plot", "arm-string", "--of", "AB", *args)
        assert done.returncode == 2 and len(done.stderr.strip().splitlines()) == 1
    assert list(tmp_path.iterdir()) == []


def test_minimum_is_marked_where_geometry_puts_it():
    quantity = load("arm-string").output("AB")
    backend = matplotlib.get_backend()
    figure = quantity_figure(quantity, quantity.extremum((0, 180)))
    curve, marker = figure.axes[0].lines
    assert marker.get_xdata()[0] == pytest.approx(hand_minimiser(400, 80), abs=1e-9)
    assert marker.get_ydata()[0] == pytest.approx(hand_minimum(400, 80), abs=1e-9)
    assert min(curve.get_ydata()) >= hand_minimum(400, 80) - 1e-9
    assert matplotlib.get_backend() == backend  # no global state changed


def test_derivative_crosses_zero_at_the_minimiser():
    quantity = load("arm-string").output("AB")
    figure = quantity_figure(quantity, quantity.extremum((0, 180)), derivative=True)
    curve = figure.axes[0].lines[0]
    xs, ys = curve.get_xdata(), curve.get_ydata()
    crossing = [x for x, y0, y1 in zip(xs, ys, ys[1:]) if y0 < 0 <= y1]
    assert len(crossing) == 1 and abs(crossing[0] - hand_minimiser(400, 80)) < 0.5


def test_minimum_against_b_follows_brute_force():
    quantity = load("arm-string", ["b"]).output("AB")
    figure = minimum_figure(quantity, quantity.extremum((0, 90)), "b", -400, 400)
    curves = [line for line in figure.axes[0].lines if len(line.get_xdata()) > 2]
    assert len(curves) == 3  # the end-point region, the stationary region, the certified dots
    for line in curves:
        for x, y in zip(line.get_xdata()[::25], line.get_ydata()[::25]):
            assert y == pytest.approx(brute_minimum(400, x, 0, 90)[0], abs=1e-6)
    cuts = [line.get_xdata()[0] for line in figure.axes[0].lines if len(line.get_xdata()) == 2]
    assert cuts == [0.0]  # the minimiser leaves [0, 90] at b = 0
