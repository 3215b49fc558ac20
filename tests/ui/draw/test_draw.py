"""Drawings: positions against hand geometry, trajectory on the implicit curve, modes, animations."""

import io
import json
import os
import pathlib
import re
import shutil
import subprocess
import sys
import types
from xml.etree import ElementTree

import attrs
import numpy as np

import pytest
import sympy

pytest.importorskip("matplotlib")

from algkin import curve  # noqa: E402
from algkin.errors import UsageError  # noqa: E402
from algkin.ui.draw import animate, mechanism_figure, modes_figure, parse_inputs, parse_ranges  # noqa: E402
from algkin.analyses.motion import Motion  # noqa: E402
from algkin.scene import load_scene  # noqa: E402
from algkin.ui.cli import main  # noqa: E402

from ...derivation.test_still_points import STILL  # noqa: E402
from ..cli.in_process import first_apart, run_main  # noqa: E402
from ...hand_linkages import CHEBYSHEV, fourbar  # noqa: E402

CATALOG = pathlib.Path(__file__).parents[3] / "algkin" / "catalog"


def joints(axes):
    """Every drawn joint marker (ground triangles and moving circles) as (x, y) pairs."""
    found = []
    for line in axes.lines:
        if line.get_linestyle() == "None" and len(line.get_xdata()):
            found += list(zip(line.get_xdata(), line.get_ydata()))
    return np.array(sorted(found))


def by_hand(theta, branch="left"):
    return np.array(sorted(fourbar(theta, **CHEBYSHEV, branch=branch).values()))


def test_configuration_is_drawn_where_hand_geometry_puts_it():
    figure = mechanism_figure(Motion("chebyshev-lambda"), {"angle": 63}, curve=False)
    axes = figure.axes[0]
    assert np.max(np.abs(joints(axes) - by_hand(63))) < 1e-12
    assert axes.get_aspect() == 1.0  # equal aspect: the linkage is not distorted


def test_trajectory_and_implicit_curve_coincide():
    motion = Motion("chebyshev-lambda")
    figure = mechanism_figure(motion, {"angle": 63})
    axes = figure.axes[0]
    (trajectory,) = [line for line in axes.lines if line.get_label().startswith("trajectory")]
    xs, ys = trajectory.get_xdata(), trajectory.get_ydata()
    # The curve comes from elimination, the trajectory from closed forms: every trajectory
    # point is on F = 0, to within rounding in the distance |F| / |grad F|.
    result = curve("chebyshev-lambda", "P", samples=0)
    x, y = (sympy.Symbol(v) for v in result.variables)
    poly = result.elimination.polynomial.xreplace({s: sympy.Symbol(s.name) for s in result.elimination.polynomial.free_symbols})
    F, Fx, Fy = (sympy.lambdify((x, y), e, "numpy") for e in (poly, poly.diff(x), poly.diff(y)))
    assert np.max(np.abs(F(xs, ys)) / np.hypot(Fx(xs, ys), Fy(xs, ys))) < 1e-12
    # ... and every drawn vertex of the contour lies near the trajectory of one branch
    # (the implicit curve is traced by both assembly modes), within the contour's grid step.
    (contour,) = axes.collections
    vertices = np.concatenate([path.vertices for path in contour.get_paths()])
    assert len(vertices) > 500
    traced = np.concatenate([np.column_stack(motion.sweep(branch=b, samples=20001)[1]["P"])
                             for b in ("left", "right")])
    step = (axes.dataLim.width + axes.dataLim.height) / 500
    nearest = np.min(np.hypot(*(vertices[:, None, :] - traced[None, ::5, :]).transpose(2, 0, 1)), axis=1)
    assert np.max(nearest) < step


def test_the_implicit_curve_is_dashed_green_over_the_orange_trajectory():
    # Issue 35: the Chebyshev tutorial says "the trajectory (orange) and the zero set of F (dashed
    # green)" while both were drawn orange, so the overlay could not be seen.
    from matplotlib.colors import to_hex

    axes = mechanism_figure(Motion("chebyshev-lambda"), {"angle": 63}).axes[0]
    (trajectory,) = [line for line in axes.lines if line.get_label().startswith("trajectory")]
    (contour,) = axes.collections
    assert to_hex(trajectory.get_color()) == to_hex("tab:orange") and trajectory.get_linestyle() == "-"
    assert {to_hex(c) for c in contour.get_edgecolor()} == {to_hex("tab:green")}
    assert all(tuple(dashes) for _, dashes in contour.get_linestyle())  # dashed, not solid
    legend = {text.get_text(): handle for text, handle in zip(axes.figure.legends[0].get_texts(),
                                                              axes.figure.legends[0].legend_handles)}
    shown = legend["implicit curve of P (every assembly mode)"]
    assert to_hex(shown.get_color()) == to_hex("tab:green") and shown.get_linestyle() == "--"
    tutorial = (pathlib.Path(__file__).parents[3] / "docs" / "tutorials" / "chebyshev-lambda.md").read_text()
    assert "trajectory from the closed forms (orange) and the zero set of F (dashed green)" in tutorial


def test_no_trajectory_is_drawn_in_the_implicit_curves_green():
    from algkin.ui.draw import IMPLICIT_COLOR, trace_color

    many = types.SimpleNamespace(traced=list("PQRSTUVWXYZ"))  # more traced points than colours
    assert IMPLICIT_COLOR not in {trace_color(many, name) for name in many.traced}


def test_both_assembly_modes_side_by_side():
    figure = modes_figure(Motion("chebyshev-lambda"), {"angle": 200})
    left, right = figure.axes
    assert left.get_title().startswith("left") and right.get_title() == "right"
    for axes, side in ((left, "left"), (right, "right")):
        assert np.max(np.abs(joints(axes) - by_hand(200, side))) < 1e-12


def test_cannot_assemble_keeps_what_is_built_and_draws_the_circles_that_fail_to_meet():
    # theta = 180: A = (-1, 0), D = (4, 0), |AD| = 5 > l + m = 0.75 + 3.5: no B
    figure = mechanism_figure(Motion("fourbar"), {"theta": 180}, {"l": 0.75}, curve=False)
    axes = figure.axes[0]
    assert np.allclose(joints(axes), [(-1, 0), (0, 0), (4, 0)])  # A, O and D
    assert any(line.get_xydata().shape == (2, 2) and np.allclose(line.get_xydata(), [(0, 0), (-1, 0)])
               for line in axes.lines)  # the crank OA
    circles = sorted((p.get_center(), p.get_radius()) for p in axes.patches if p.get_visible())
    assert np.allclose([c for c, _ in circles], [(-1, 0), (4, 0)]) and np.allclose([r for _, r in circles], [0.75, 3.5])
    [text] = [t.get_text() for t in axes.texts if t.get_visible() and t.get_text().startswith("cannot")]
    assert text.startswith("cannot assemble B:\nthe circles about A (radius l = 0.75) and D (radius m = 3.5)")


def test_gif_has_one_frame_per_angle(tmp_path):
    from PIL import Image

    out = animate(Motion("chebyshev-lambda"), tmp_path / "turn.gif", frames=12)
    with Image.open(out) as gif:
        assert gif.format == "GIF" and gif.n_frames == 12


def plot(*args):
    return subprocess.run([sys.executable, "-m", "algkin", "plot", *map(str, args)], capture_output=True, text=True)


def drawn(*args, cwd):
    """``algkin plot args...`` in this process (``main``), for the tests of what it draws and writes, and of
    most of what it refuses (``first_apart``); those of its exit code and its one line on stderr otherwise run
    it in a process of its own (``plot``)."""
    return run_main(["plot", *map(str, args)], cwd)


def refused_plot(*args, apart, cwd):
    return plot(*args) if apart else drawn(*args, cwd=cwd)


def test_mp4_needs_ffmpeg(tmp_path):
    done = plot("chebyshev-lambda", "--out", tmp_path / "turn.mp4")
    if shutil.which("ffmpeg"):
        assert done.returncode == 0 and (tmp_path / "turn.mp4").stat().st_size > 10_000
    else:
        assert done.returncode == 2 and "needs ffmpeg" in done.stderr and len(done.stderr.splitlines()) == 1
        assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("suffix", [".png", ".svg", ".html"])
def test_plot_command_writes_the_format_of_the_suffix(tmp_path, suffix):
    out = tmp_path / f"lambda{suffix}"
    done = drawn("chebyshev-lambda", "--out", out, "--input", "63", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    head = out.read_bytes()[:64]
    assert {".png": head.startswith(b"\x89PNG"), ".svg": b"<svg" in out.read_bytes()[:2000],
            ".html": head.startswith(b"<!DOCTYPE html>")}[suffix]


def test_plot_json_is_one_document_naming_what_was_written(tmp_path):
    out = tmp_path / "lambda.svg"
    done = drawn("chebyshev-lambda", "--out", out, "--json", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert json.loads(done.stdout) == {"scene": "chebyshev-lambda", "out": str(out), "format": "svg", "of": None}
    assert b"<svg" in out.read_bytes()[:2000]


@pytest.mark.parametrize("args, apart", first_apart([
    ["--out", "x.jpeg"],                      # unknown format
    ["--out", "x.png", "--input", "abc"],     # not a number
    ["--out", "x.png", "--input", "361"],     # outside the input's range
    ["--out", "x.png", "--input", "nan"],
    ["--out", "x.png", "--input", "theta=3"],  # no such input
    ["--out", "x.png", "--branch", "up"],
    ["--out", "x.png", "--modes", "--branch", "left"],
    ["--out", "x.html", "--param", "zz"],
    ["--out", "x.png", "--derivative"],       # goes with --of
    ["--out", "x.png", "--of", "P.x", "--input", "3"],
]))
def test_bad_requests_exit_2_with_one_line_and_write_nothing(tmp_path, args, apart):
    args = [str(tmp_path / a) if a.startswith("x.") else a for a in args]
    done = refused_plot("chebyshev-lambda", *args, apart=apart, cwd=tmp_path)
    assert done.returncode == 2 and len(done.stderr.strip().splitlines()) == 1, done.stderr
    assert "Traceback" not in done.stderr and list(tmp_path.iterdir()) == []


def page_model(path):
    """The page's MODEL: the JSON on the script line ``const MODEL = {...};``."""
    (line,) = [line for line in path.read_text().splitlines() if line.startswith("const MODEL = ")]
    return json.loads(line.removeprefix("const MODEL = ").removesuffix(";"))


def test_range_of_sets_a_slider_of_the_page(tmp_path):
    out = tmp_path / "page.html"
    done = drawn("fourbar", "--out", out, "--range-of", "a=0.5:2", "--range-of", "l=1:4", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    sliders = {p["name"]: p for p in page_model(out)["params"]}
    assert (sliders["a"]["lo"], sliders["a"]["hi"]) == (0.5, 2) and (sliders["l"]["lo"], sliders["l"]["hi"]) == (1, 4)
    assert drawn("fourbar", "--out", tmp_path / "plain.html", cwd=tmp_path).returncode == 0
    plain = {p["name"]: p for p in page_model(tmp_path / "plain.html")["params"]}
    assert plain["d"] == sliders["d"] and plain["a"] != sliders["a"]  # only the named sliders change


@pytest.mark.parametrize("args, apart", first_apart([
    ["--out", "x.html", "--range-of", "a=2:1"],      # lo above hi
    ["--out", "x.html", "--range-of", "a=x:1"],      # not a number
    ["--out", "x.html", "--range-of", "a=0:inf"],    # not finite
    ["--out", "x.html", "--range-of", "a=nan:2"],
    ["--out", "x.html", "--range-of", "a=1:1"],      # lo at hi
    # a, l and m are lengths in fourbar.toml (the crank's, the dyad's): positive at both ends
    ["--out", "x.html", "--range-of", "a=-1:1"],
    ["--out", "x.html", "--range-of", "a=0:1"],
    ["--out", "x.html", "--range-of", "m=-4:-1"],
    ["--out", "x.html", "--range-of", "a0.5:2"],     # no name
    ["--out", "x.html", "--range-of", "zz=1:2"],     # not a dimension
    ["--out", "x.png", "--range-of", "a=0.5:2"],     # no sliders in a .png
    ["--out", "x.png", "--of", "P", "--range-of", "a=0.5:2"],  # draws a quantity, no sliders
]))
def test_a_bad_range_of_exits_2_with_one_line_and_writes_nothing(tmp_path, args, apart):
    done = refused_plot("fourbar", *[str(tmp_path / a) if a.startswith("x.") else a for a in args], apart=apart, cwd=tmp_path)
    assert one_line(done, 2) and done.stderr.startswith("algkin: error: --range-of="), done.stderr
    assert list(tmp_path.iterdir()) == []


def test_a_range_of_a_dimension_that_is_no_length_may_cross_zero(tmp_path):
    # In fourbar.toml d places the fixed pivot D = (d, 0) and p, q the coupler point in the frame of AB:
    # coordinates, which any sign keeps a valid scene.
    out = tmp_path / "page.html"
    assert drawn("fourbar", "--out", out, "--range-of", "d=-5:5", "--range-of", "p=-1:1", cwd=tmp_path).returncode == 0
    sliders = {p["name"]: (p["lo"], p["hi"]) for p in page_model(out)["params"]}
    assert sliders["d"] == (-5, 5) and sliders["p"] == (-1, 1)


def test_a_range_the_scene_declares_reaching_a_negative_length_is_the_files_error(tmp_path):
    # the crank's length a declared with a slider range [-1, 2]: the page drew a negative crank
    scene = tmp_path / "negative.toml"
    scene.write_text((CATALOG / "fourbar.toml").read_text().replace(
        "a = 1          # crank |OA|", "a = { default = 1, range = [-1, 2] }"))
    out = tmp_path / "page.html"
    done = plot(scene, "--out", out)
    assert one_line(done, 2), done.stderr
    assert done.stderr == (f"algkin: error: {scene}: parameters.a.range: the length a would be -1 at a = -1; "
                           "a length must be positive\n")
    assert not out.exists()


NEVER = (CATALOG / "chebyshev-lambda.toml").read_text().replace("fixed = [2, 0]", "fixed = [20, 0]")


def one_line(done, code):
    lines = done.stderr.strip().splitlines()
    return done.returncode == code and len(lines) == 1 and "Traceback" not in done.stderr


@pytest.mark.parametrize("suffix, apart", first_apart([".html", ".png", ".gif"], ["html", "png", "gif"]))
def test_a_scene_that_never_assembles_leaves_the_output_alone(tmp_path, suffix, apart):
    (tmp_path / "never.toml").write_text(NEVER)
    out = tmp_path / f"never{suffix}"
    out.write_bytes(b"a good file")
    done = refused_plot(tmp_path / "never.toml", "--out", out, apart=apart, cwd=tmp_path)
    assert one_line(done, 2) and "can never assemble" in done.stderr, done.stderr
    assert out.read_bytes() == b"a good file"


def test_an_interrupted_gif_leaves_the_earlier_file_and_no_temporary(tmp_path, monkeypatch):
    from PIL import Image

    def interrupted(image, target, *args, **kwargs):
        with open(target, "wb") as handle:
            handle.write(b"GIF89a half a movie")
        raise KeyboardInterrupt

    out = tmp_path / "turn.gif"
    out.write_bytes(b"a good movie")
    monkeypatch.setattr(Image.Image, "save", interrupted)
    with pytest.raises(KeyboardInterrupt):
        animate(Motion("chebyshev-lambda"), out, frames=3)
    assert out.read_bytes() == b"a good movie" and list(tmp_path.iterdir()) == [out]


def test_an_output_that_is_a_directory_is_refused_at_once(tmp_path):
    (tmp_path / "lambda.png").mkdir()
    done = plot("chebyshev-lambda", "--out", tmp_path / "lambda.png")
    assert one_line(done, 2) and done.stderr.startswith("algkin: error: --out="), done.stderr


@pytest.mark.skipif(os.geteuid() == 0, reason="root writes read-only files anyway")
def test_a_read_only_output_is_refused_at_once(tmp_path):
    out = tmp_path / "lambda.png"
    out.write_bytes(b"kept")
    out.chmod(0o444)
    done = plot("chebyshev-lambda", "--out", out)
    assert one_line(done, 2) and "read-only" in done.stderr and out.read_bytes() == b"kept", done.stderr


@pytest.mark.skipif(not os.path.exists("/dev/full"), reason="needs /dev/full")
@pytest.mark.parametrize("suffix, apart", first_apart([".png", ".html"], ["png", "html"]))
def test_a_write_that_fails_is_one_line(tmp_path, suffix, apart):
    out = tmp_path / f"full{suffix}"
    out.symlink_to("/dev/full")
    done = refused_plot("chebyshev-lambda", "--out", out, apart=apart, cwd=tmp_path)
    assert one_line(done, 1) and done.stderr.startswith("algkin: failed: "), done.stderr
    assert list(tmp_path.iterdir()) == [out]


@pytest.mark.parametrize("args", [[], ["--modes"], ["--of", "dist(P, D)"]], ids=["mechanism", "modes", "quantity"])
def test_a_scene_name_with_control_characters_is_written_out_in_a_figure(tmp_path, args):
    # An SVG holds each title as text (a comment): no raw control byte, which no XML may hold.
    scene = tmp_path / "controls.toml"
    scene.write_text((CATALOG / "fourbar.toml").read_text().replace(
        'name = "fourbar"', 'name = "four\\u001b[31mbar\\u0007\\u0000\\nx"'))
    out = tmp_path / "drawing.svg"
    assert main(["plot", str(scene), "--out", str(out), *args]) == 0
    data = out.read_bytes()
    assert not re.search(rb"[\x00-\x08\x0b\x0c\x0e-\x1f\x7f]", data)
    assert rb"four\x1b[31mbar\x07\x00\nx" in data  # by hand: each as Python writes its escape
    ElementTree.fromstring(data)  # well-formed


def test_a_scene_name_is_shown_as_text_not_mathtext():
    name = r"cost $x_{$ \frac{1}{2}$ $"
    motion = Motion(attrs.evolve(load_scene("chebyshev-lambda"), name=name))
    for figure in (mechanism_figure(motion, {"angle": 63}, curve=False), modes_figure(motion, {"angle": 63})):
        figure.savefig(io.BytesIO(), format="png")  # mathtext would raise here
        titles = [figure.axes[0].get_title(), figure.get_suptitle()]
        assert any(t.startswith(name + ":") for t in titles), titles


def test_a_slider_curve_without_one_coordinate_is_drawn_as_its_line():
    # The slider B of slider-crank runs on the line y = e (e = 1/2 in the scene): its
    # implicit curve 2*B_y - 1 has no B_x, and its zero set is that horizontal line.
    figure = mechanism_figure(Motion("slider-crank"), {"theta": 63})
    axes = figure.axes[0]
    (contour,) = axes.collections
    vertices = np.concatenate([path.vertices for path in contour.get_paths()])
    assert np.ptp(vertices[:, 0]) > 0.8 * axes.dataLim.width  # across the drawing
    assert np.max(np.abs(vertices[:, 1] - 0.5)) < 1e-9


def test_a_point_that_does_not_move_is_not_traced(tmp_path):
    # F = O + (D - O)/2 + rot90(D - O) = (1, 2) whatever t is: no trajectory, no curve.
    (tmp_path / "still.toml").write_text(STILL)
    motion = Motion(load_scene(tmp_path / "still.toml"))
    assert motion.traced == ["A"]
    done = drawn(tmp_path / "still.toml", "--out", tmp_path / "still.png", cwd=tmp_path)
    assert done.returncode == 0, done.stderr


def test_modes_panels_sit_side_by_side_without_a_gap():
    figure = modes_figure(Motion("chebyshev-lambda"), {"angle": 63})
    figure.canvas.draw()
    left, right = (a.get_window_extent() for a in figure.axes)
    assert right.x0 - left.x1 < 0.03 * figure.bbox.width
    assert min(left.width, right.width) > 0.4 * figure.bbox.width  # the panels fill the figure


TWO_TRACED = (CATALOG / "chebyshev-lambda.toml").read_text().replace('[outputs]\nP = "P"', '[outputs]\nP = "P"\nB = "B"')


def test_each_traced_point_has_its_own_colour(tmp_path):
    (tmp_path / "two.toml").write_text(TWO_TRACED)
    motion = Motion(load_scene(tmp_path / "two.toml"))
    assert motion.traced == ["B", "P"]
    figure = mechanism_figure(motion, {"angle": 63}, curve=False)
    colours = {line.get_label(): line.get_color() for line in figure.axes[0].lines
               if line.get_label().startswith("trajectory")}
    assert len(colours) == 2 and len(set(colours.values())) == 2
    legend = {t.get_text(): h.get_color() for t, h in zip(figure.legends[0].get_texts(), figure.legends[0].legend_handles)}
    assert legend["trajectory of B (left)"] != legend["trajectory of P (left)"]


def test_a_gif_moves_the_crank_in_every_frame_within_the_drawn_modes_box(tmp_path, monkeypatch):
    from PIL import Image

    import algkin.ui.draw as draw

    made, original = [], draw.new_figure

    def recorded():
        made.append(original())
        return made[-1]

    monkeypatch.setattr(draw, "new_figure", recorded)
    out = animate(Motion("chebyshev-lambda"), tmp_path / "turn.gif", frames=12)
    with Image.open(out) as gif:
        frames = []
        for k in range(gif.n_frames):
            gif.seek(k)
            frames.append(np.asarray(gif.convert("RGB"), dtype=int))
    # each frame differs from the one before (the crank turned) by more than a palette's noise
    assert all(np.mean(np.abs(a - b).sum(axis=2) > 100) > 1e-3 for a, b in zip(frames, frames[1:]))
    ys = [y for t in range(360) for _, y in fourbar(t, **CHEBYSHEV, branch="left").values()]
    span = max(ys) - min(ys)
    low, high = made[0].axes[0].get_ylim()
    assert min(ys) - 0.15 * span <= low <= min(ys) and max(ys) <= high <= max(ys) + 0.15 * span


def test_a_mechanism_drawing_says_the_scenes_unit_on_its_axes():
    axes = mechanism_figure(Motion("chebyshev-lambda"), {"angle": 63}, curve=False).axes[0]
    assert (axes.get_xlabel(), axes.get_ylabel()) == ("$x$ (mm)", "$y$ (mm)")
    assert modes_figure(Motion("chebyshev-lambda")).axes[0].get_xlabel() == "$x$ (mm)"


def test_a_slider_is_a_block_on_a_rail_and_its_lines_point_no_pivot():
    import matplotlib.lines
    import matplotlib.patches

    # theta = 90: A = (0, 1); B on y = 1/2 at 3 from A, ahead: B = (sqrt(9 - 1/4), 1/2)
    axes = mechanism_figure(Motion("slider-crank"), {"theta": 90}, curve=False).axes[0]
    b = np.array([np.sqrt(9 - 0.25), 0.5])
    [block] = [p for p in axes.patches if p.get_visible() and isinstance(p, matplotlib.patches.Polygon)]
    corners = block.get_xy()[:4]
    assert np.allclose(corners.mean(axis=0), b) and np.ptp(corners[:, 0]) > np.ptp(corners[:, 1]) > 0
    rails = [line for line in axes.get_lines() if isinstance(line, matplotlib.lines.AxLine)]
    assert len(rails) == 2 and all(line.get_visible() for line in rails)
    heights = sorted(line.get_xy1()[1] for line in rails)  # each edge horizontal, one either side of y = 1/2
    assert heights[0] < 0.5 < heights[1] and all(line.get_xy1()[1] == line.get_xy2()[1] for line in rails)
    assert (0.0, 0.5) not in [tuple(xy) for xy in joints(axes)]  # L, the line's point, is no ground pivot


@pytest.mark.parametrize("parse, texts, said", [
    (lambda texts: parse_inputs(Motion("chebyshev-lambda"), texts), ["angle=30", "40"],
     "--input='40': angle given twice"),
    (parse_ranges, ["a=1:2", "a=3:4"], "--range-of='a=3:4': a given twice"),
])
def test_a_value_given_twice_is_refused(parse, texts, said):
    # the last one was drawn, the first silently dropped (solve's --at refuses the same)
    with pytest.raises(UsageError) as caught:
        parse(texts)
    assert str(caught.value) == said
