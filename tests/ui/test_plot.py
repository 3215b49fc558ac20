"""Figures: one command each, drawn from closed forms, with the certified points on them."""

import io
import json
import pathlib
import subprocess
import sys

import attrs
import numpy as np
import pytest

pytest.importorskip("matplotlib")

import matplotlib  # noqa: E402

from algkin.bench.accuracy import Accuracy  # noqa: E402
from algkin.errors import SceneError  # noqa: E402
from algkin.analyses.quantities import load_quantities  # noqa: E402
from algkin.ui.plot import accuracy_figure, minimum_figure, quantity_figure, save  # noqa: E402
from algkin.scene import load_scene, load_scene_text  # noqa: E402

from ..analyses.extremum.arm_by_hand import brute_minimum, hand_minimiser, hand_minimum  # noqa: E402
from .cli.in_process import run_main  # noqa: E402


def run(*args):
    return subprocess.run([sys.executable, "-m", "algkin", *args], capture_output=True, text=True)


@pytest.mark.parametrize("extra", [[], ["--derivative"], ["--against", "b=-400:400"]])
def test_each_figure_is_one_command(tmp_path, extra):
    out = tmp_path / "figure.png"
    # in this process: the figure written is the question (the bad requests' exit and line run apart)
    done = run_main(["plot", "arm-string", "--of", "AB", "--out", str(out), *extra], tmp_path)
    assert done.returncode == 0, done.stderr
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and out.stat().st_size > 10_000


def test_bad_figure_requests_write_nothing(tmp_path):
    # the first as the program, the others by main in this process: the same checks, exit code and stderr
    for apart, args in ((True, ["--out", str(tmp_path / "x.gif")]), (False, ["--out", str(tmp_path / "no" / "x.png")]),
                        (False, ["--out", str(tmp_path / "x.png"), "--against", "b"])):
        command = ["plot", "arm-string", "--of", "AB", *args]
        done = run(*command) if apart else run_main(command, tmp_path)
        assert done.returncode == 2 and len(done.stderr.strip().splitlines()) == 1
    assert list(tmp_path.iterdir()) == []


def test_minimum_is_marked_where_geometry_puts_it():
    quantity = load_quantities("arm-string").output("AB")
    backend = matplotlib.get_backend()
    figure = quantity_figure(quantity, quantity.extremum((0, 180)))
    curve, marker = figure.axes[0].lines
    assert marker.get_xdata()[0] == pytest.approx(hand_minimiser(400, 80), abs=1e-9)
    assert marker.get_ydata()[0] == pytest.approx(hand_minimum(400, 80), abs=1e-9)
    assert min(curve.get_ydata()) >= hand_minimum(400, 80) - 1e-9
    assert matplotlib.get_backend() == backend  # no global state changed


def test_derivative_crosses_zero_at_the_minimiser():
    quantity = load_quantities("arm-string").output("AB")
    figure = quantity_figure(quantity, quantity.extremum((0, 180)), derivative=True)
    curve = figure.axes[0].lines[0]
    xs, ys = curve.get_xdata(), curve.get_ydata()
    crossing = [x for x, y0, y1 in zip(xs, ys, ys[1:]) if y0 < 0 <= y1]
    assert len(crossing) == 1 and abs(crossing[0] - hand_minimiser(400, 80)) < 0.5


def test_minimum_against_b_follows_brute_force():
    quantity = load_quantities("arm-string", ["b"]).output("AB")
    figure = minimum_figure(quantity, quantity.extremum((0, 90)), "b", -400, 400)
    curves = [line for line in figure.axes[0].lines if len(line.get_xdata()) > 2]
    assert len(curves) == 3  # the end-point region, the stationary region, the certified dots
    for line in curves:
        for x, y in zip(line.get_xdata()[::25], line.get_ydata()[::25]):
            assert y == pytest.approx(brute_minimum(400, x, 0, 90)[0], abs=1e-6)
    cuts = [line.get_xdata()[0] for line in figure.axes[0].lines if len(line.get_xdata()) == 2]
    assert cuts == [0.0]  # the minimiser leaves [0, 90] at b = 0


ARM = (pathlib.Path(__file__).parents[2] / "algkin" / "catalog" / "arm-string.toml").read_text()


def measured(scene):
    """An accuracy result of one row, to draw without measuring."""
    return Accuracy(scene, "P", [{"strategy": "numeric", "case": "uniform", "ns_per_sample": 10.0,
                                  "max_rel_error": 1e-15}])


def test_a_dimension_named_like_a_python_keyword_is_refused_in_one_line():
    # plot --against sympified the name and crashed on `lambda`: a scene holds no name that
    # sympy.parse_expr would misread (the JSON's strings read back), and says so where it is loaded.
    with pytest.raises(SceneError, match="parameters.lambda: .*Python keyword"):
        load_scene_text(ARM.replace("\nb = 80", "\nlambda = 80").replace('"-b"', '"-lambda"'), "lambda.toml")


def test_a_scene_name_is_shown_as_text_not_mathtext():
    name = r"arm $x_{$ \frac{1}{2}$ $"
    quantity = load_quantities(attrs.evolve(load_scene("arm-string"), name=name)).output("AB")
    for figure in (quantity_figure(quantity, quantity.extremum((0, 180))), accuracy_figure(measured(name))):
        figure.savefig(io.BytesIO(), format="png")  # mathtext would raise here
        assert figure.axes[0].get_title().endswith(name)


def test_an_output_typed_with_a_newline_is_one_line_in_the_titles():
    # --of "dist(O,\nB)" (a newline is white space in it) broke the title in two, as it did the report
    quantity = load_quantities("fourbar").output("dist(O,\nB)")
    title = quantity_figure(quantity, quantity.extremum((0, 180))).axes[0].get_title()
    assert title == "dist(O,\\nB) in fourbar"
    assert accuracy_figure(Accuracy("s", "dist(O,\nB)", [])).axes[0].get_title() == "Speed against error: dist(O,\\nB) of s"


def test_an_interrupted_save_leaves_the_earlier_figure_and_no_temporary(tmp_path, interrupted_writes):
    out = tmp_path / "speed.png"
    out.write_text("a good figure")
    with pytest.raises(KeyboardInterrupt):
        save(accuracy_figure(measured("s")), out)
    assert out.read_text() == "a good figure" and list(tmp_path.iterdir()) == [out]


@pytest.mark.parametrize("command", [["plot", "arm-string", "--of", "AB", "--out"],
                                     ["accuracy", "chebyshev-lambda", "--plot"]])
def test_a_figure_path_that_is_a_directory_is_refused_at_once(tmp_path, command):
    (tmp_path / "figure.png").mkdir()
    done = run(*command, str(tmp_path / "figure.png"))
    assert done.returncode == 2 and len(done.stderr.strip().splitlines()) == 1, done.stderr
    assert "is a directory" in done.stderr and "Traceback" not in done.stderr


def drawn(figure):
    figure.canvas.draw()
    return figure.canvas.get_renderer()


def test_a_zero_error_is_drawn_on_the_axis_and_no_labels_overlap():
    rows = [{"strategy": s, "case": c, "ns_per_sample": ns, "max_rel_error": e}
            for s, ns, e in (("closed-form", 500.0, 3e-16), ("stabilised", 480.0, 2e-16),
                             ("numeric", 520.0, 4e-16), ("reference", 5e5, 0.0))
            for c in ("uniform", "far-1e7", "near-1e-6")]
    figure = accuracy_figure(Accuracy("s", "P", rows))
    renderer = drawn(figure)
    axes = figure.axes[0]
    low, high = axes.get_ylim()
    heights = [y for c in axes.collections for _, y in c.get_offsets()]
    exact = [y for c in axes.collections if not len(c.get_facecolors()) for _, y in c.get_offsets()]
    assert len(exact) == 3 and all(np.isfinite(y) and low < y < 2e-16 for y in exact)
    assert all(low < y < high for y in heights)
    assert [t.get_text() for t in axes.texts] == ["exact (0)"]
    boxes = [t.get_window_extent(renderer) for t in figure.findobj(matplotlib.text.Text)
             if t.get_visible() and t.get_text()]
    overlapping = [(a, b) for k, a in enumerate(boxes) for b in boxes[k + 1:] if a.overlaps(b)]
    assert not overlapping
    case_colours = [tuple(h.get_color()) if not isinstance(h.get_color(), str) else h.get_color()
                    for h in figure.legends[1].legend_handles]
    assert len(set(case_colours)) == 3


NO_INPUT = """
name = "arm-by-string"
[parameters]
u = { default = 300, range = [60, 700] }
[points]
O = { fixed = [0, 0] }
B = { fixed = [400, -80] }
A = { dyad = ["O", "B"], lengths = [350, "u"], branch = "right" }
[outputs]
A = "A"
"""


def test_a_scene_without_an_input_is_refused_in_one_line_and_writes_nothing(tmp_path):
    scene, out = tmp_path / "arm.toml", tmp_path / "arm.png"
    scene.write_text(NO_INPUT)
    done = subprocess.run([sys.executable, "-m", "algkin", "plot", str(scene), "--out", str(out)],
                          capture_output=True, text=True)
    assert done.returncode == 2 and len(done.stderr.strip().splitlines()) == 1, done.stderr
    assert "has no input" in done.stderr and 'unit = "length"' in done.stderr and not out.exists()


def test_the_quantity_curve_is_the_closed_form_at_each_plotted_angle():
    quantity = load_quantities("fourbar").dist("O", "P")  # a distance of a coupler point: the stabilised form drawn
    found = quantity.extremum()
    x, y = quantity_figure(quantity, found, points=37).axes[0].lines[0].get_data()
    expected = [quantity.at(theta=float(a)) for a in x]  # the closed form in mpmath at 30 digits, one by one
    np.testing.assert_allclose(y, expected, rtol=1e-13)


def test_lengths_carry_the_scenes_unit_and_names_are_typeset():
    quantity = load_quantities("arm-string", ["b"]).output("AB")  # the catalog scene says unit = "mm"
    figure = quantity_figure(quantity, quantity.extremum((0, 180)))
    axes = figure.axes[0]
    assert axes.get_ylabel() == "$|AB|$ (mm)" and axes.get_xlabel() == r"$\theta$ (degrees)"
    assert axes.get_legend().get_texts()[1].get_text().startswith("minimum of $|AB|$: ")
    against = minimum_figure(quantity, quantity.extremum((0, 90)), "b", -400, 400).axes[0]
    assert against.get_xlabel() == "$b$ (mm)" and against.get_ylabel() == "minimum of $|AB|$ (mm)"
    legend = [t.get_text() for t in against.get_legend().get_texts()]
    assert all(t.startswith("$") and "**" not in t and "sqrt(" not in t for t in legend[:-1])
    for drawn in (figure, against.figure):
        drawn.savefig(io.BytesIO(), format="png")  # the mathtext parses


@pytest.mark.parametrize("name", ["連杆機構", "lambda\x1b[31m\r"], ids=["cjk", "control"])
def test_a_scene_name_the_font_cannot_draw_says_nothing_on_stderr(tmp_path, name):
    # matplotlib warned of each missing glyph (two lines each) on stderr, which holds at most one line
    scene = tmp_path / "named.toml"
    scene.write_text(ARM.replace('name = "arm-string"', f"name = {json.dumps(name)}"), encoding="utf-8")
    for out, extra in ((tmp_path / "mechanism.png", []), (tmp_path / "quantity.svg", ["--of", "AB"])):
        done = run("plot", str(scene), "--out", str(out), *extra)
        assert (done.returncode, done.stderr) == (0, "") and out.stat().st_size > 0
