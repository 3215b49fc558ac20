"""Pictures of scenes with points solved together (``unknown = true``): every real mode at the
input drawn with its platform where ``algkin solve`` puts it; the .html page's slider moving the
platform along each mode's followed path, checked in a headless browser against ``solve`` (and
``follow`` where ``solve`` cannot take the angle); bad input one line, exit 2, nothing written."""


import numpy as np
import pytest

from algkin.analyses.follow import follow
from algkin.analyses.solve import solve
from algkin.ui.groupdraw import modes_figure
from algkin.ui.groupmotion import GroupMotion

from ..cli.in_process import first_apart, run_main
from ..cli.test_usage import run_cli
from .browser import load

DRAWN = 1e-3  # the page interpolates between its path's samples: a fiftieth of a pixel on a 15-wide drawing


def solved(scene, at):
    """Each mode's label -> point -> (x, y), from ``algkin solve``."""
    return {c.mode: {p: (float(x), float(y)) for p, (x, y) in c.points.items()}
            for c in solve(scene, at, digits=20).configurations}


@pytest.mark.slow
def test_the_svg_draws_each_real_mode_platform_where_solve_puts_it(tmp_path):
    out = tmp_path / "3rpr.svg"
    done = run_cli(["plot", "3rpr", "--out", str(out), "--input", "r1=6"], tmp_path)
    assert done.returncode == 0, done.stderr
    text = out.read_text()
    expected = solved("3rpr", {"r1": 6})
    assert len(expected) == 2
    for k in range(len(expected)):
        assert f'id="mode-{k}-platform-0"' in text
    figure = modes_figure(GroupMotion("3rpr"), 6)
    for axes, (label, points) in zip(figure.axes, expected.items()):
        assert axes.get_title() == f"{label} (certified)"
        platform, = [p for p in axes.patches if (p.get_gid() or "").endswith("platform-0")]
        corners = platform.get_xy()[:3]
        np.testing.assert_allclose(corners, [points["P1"], points["P2"], points["P3"]], atol=1e-12)


def test_no_mode_at_the_input_keeps_the_ground_and_says_so():
    figure = modes_figure(GroupMotion("3rpr"), 9)  # the modes meet at 7.92 and come back at 11.2
    axes, = figure.axes
    assert any("not assembled here" in t.get_text() and "P1, P2" in t.get_text() for t in axes.texts)
    assert any(line.get_marker() == "^" and len(line.get_xdata()) == 3 for line in axes.lines)  # A1, A2, A3


@pytest.mark.parametrize("args, words, apart", first_apart([
    (["plot", "3rpr", "--out", "x.svg", "--input", "r1=30"], ["--input", "r1=30", "[5, 12]"]),
    (["plot", "3rpr", "--out", "x.svg", "--branch", "+++"], ["--branch"]),
    (["plot", "3rpr", "--out", "x.mp4"], ["--out", ".gif"]),
    (["export", "3rpr", "--to", "c"], ["--to", "numpy"]),
    (["export", "3rpr", "--to", "numpy", "--outputs", "Z"], ["--outputs", "Z"]),
]))
def test_bad_input_is_one_line_exit_2_nothing_written(tmp_path, args, words, apart):
    done = run_cli(args, tmp_path) if apart else run_main(args, tmp_path)
    assert done.returncode == 2 and len(done.stderr.strip().splitlines()) == 1, done.stderr
    assert all(w in done.stderr for w in words), done.stderr
    assert list(tmp_path.iterdir()) == []


@pytest.fixture(scope="module")
def pages(tmp_path_factory):
    folder = tmp_path_factory.mktemp("group-pages")
    for scene in ("3rpr", "stephenson-iii-triad"):  # the pages written are the question: in this process
        done = run_main(["plot", scene, "--out", str(folder / f"{scene}.html")], folder)
        assert done.returncode == 0, done.stderr
    return folder


def close(drawn, expected, tol=DRAWN):
    assert set(drawn) == set(expected)
    for name, (x, y) in expected.items():
        assert abs(drawn[name][0] - x) < tol and abs(drawn[name][1] - y) < tol, (name, drawn[name], (x, y))


def query(**values):
    from urllib.parse import urlencode
    return "?" + urlencode(values)


@pytest.mark.slow
@pytest.mark.parametrize("r1, label", [(6, "---"), (6, "+++"), (11.5, "-+-"), (11.5, "++-")])
def test_the_3rpr_slider_moves_the_platform_as_solve_places_it(pages, r1, label):
    state, circles, status = load(pages / "3rpr.html", query(r1=r1, branch=label))
    assert state["branch"] == label and state["values"] == {"r1": r1} and status == f"{label}: assembles"
    expected = solved("3rpr", {"r1": str(r1)})[label]
    close(state["positions"], expected)
    close(circles, expected)


@pytest.mark.slow
def test_the_3rpr_page_where_no_mode_exists(pages):
    state, circles, status = load(pages / "3rpr.html", query(r1=9, branch="---"))
    assert state["assembles"] == "false" and state["blocked"] == "P1 P2"
    assert set(circles) == {"A1", "A2", "A3"}
    assert "not assembled here" in status and "meets another mode at 7.92278" in status and "no mode here" in status


@pytest.mark.slow
def test_the_triad_page_agrees_with_solve_and_follow(pages):
    label = "+++ (from theta = 0°)"
    state, circles, _ = load(pages / "stephenson-iii-triad.html", query(theta=0, branch=label))
    close(state["positions"], solved("stephenson-iii-triad", {"theta": 0})["+++"])
    # the page's paths are follow's (certified continuation from 0 degrees) to 20 degrees
    state, circles, _ = load(pages / "stephenson-iii-triad.html", query(theta=20, branch=label))
    path = follow("stephenson-iii-triad", mode="+++", start={"theta": 0}, stop=20, digits=20)
    expected = {p: (float(x), float(y)) for p, (x, y) in path.samples[-1].points.items()}
    close(state["positions"], expected)
    close(circles, expected)


@pytest.mark.slow
def test_the_gif_moves_every_mode(tmp_path):
    from PIL import Image

    from algkin.ui.groupdraw import animate_modes

    out = animate_modes(GroupMotion("3rpr"), tmp_path / "3rpr.gif", frames=3)
    assert Image.open(out).n_frames == 3


def test_the_page_keeps_a_hostile_scene_name_data(tmp_path):
    from importlib import resources

    from algkin.scene import load_scene_text
    from algkin.ui.html.groups import group_page

    hostile = "</script><script>alert(1)</script><!--"
    text = resources.files("algkin.catalog").joinpath("3rpr.toml").read_text()
    scene = load_scene_text(text.replace('name = "3rpr"', f'name = "{hostile}"'), "hostile.toml")
    page = group_page(GroupMotion(scene))
    assert page.count("<script>") == 1 and page.count("</script>") == 1 and "<!--" not in page
    assert "&lt;/script&gt;&lt;script&gt;alert(1)" in page  # the title, escaped
