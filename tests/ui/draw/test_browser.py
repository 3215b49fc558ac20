"""The .html page in a real headless browser: move sliders, read the drawn positions back.

The page's JavaScript evaluates closed forms printed from sympy; the positions it draws
must match hand geometry (law of cosines, no algkin) and algkin's own values to ~1e-9.
"""

import functools
import math
import re

import pytest

from algkin.ui.draw import built
from algkin.ui.html import write
from algkin.analyses.motion import Motion

from .browser import dump_dom, load, state_of
from ..cli.in_process import run_main
from ...hand_linkages import CHEBYSHEV, FOURBAR, fourbar


@pytest.fixture(scope="module")
def pages(tmp_path_factory):
    """``algkin plot SCENE --out SCENE.html`` (in this process: the pages are the question) for the two
    scenes; each page's document after its scripts ran, for a query, by one browser run each:
    ``pages("fourbar", "?theta=30")``."""
    folder = tmp_path_factory.mktemp("pages")
    for scene in ("chebyshev-lambda", "fourbar"):
        done = run_main(["plot", scene, "--out", str(folder / f"{scene}.html")], folder)
        assert done.returncode == 0, done.stderr
    return functools.cache(lambda scene, query: dump_dom(folder / f"{scene}.html", query))


def close(drawn, expected, tol=1e-9):
    assert set(drawn) == set(expected)
    for name, (x, y) in expected.items():
        assert abs(drawn[name][0] - x) < tol and abs(drawn[name][1] - y) < tol, (name, drawn[name], (x, y))


def test_chebyshev_slider_moves_the_drawing(pages):
    state, circles, status = state_of(pages("chebyshev-lambda", "?angle=37.3"))
    assert state["values"] == {"angle": 37.3} and state["assembles"] == "true"
    hand = fourbar(37.3, **CHEBYSHEV)
    close(state["positions"], hand)
    close(circles, hand)  # the SVG joints themselves
    python = Motion("chebyshev-lambda").at({"angle": 37.3}).points
    close(state["positions"], python, 1e-12)
    assert status == "left: assembles"


def test_the_other_assembly_mode(pages):
    state, circles, _ = state_of(pages("chebyshev-lambda", "?angle=200&branch=right"))
    assert state["branch"] == "right"
    close(circles, fourbar(200, **CHEBYSHEV, branch="right"))


def test_a_slider_per_dimension(pages):
    state, circles, _ = state_of(pages("fourbar", "?theta=123.4&l=2.5&m=3.2&q=0.2"))
    assert state["values"] == {"theta": 123.4, "a": 1, "d": 4, "l": 2.5, "m": 3.2, "p": 0.5, "q": 0.2}
    hand = fourbar(123.4, **dict(FOURBAR, l=2.5, m=3.2, q=0.2))
    close(state["positions"], hand)
    close(circles, hand)


def test_cannot_assemble_where_the_discriminant_is_negative(pages):
    # |DA| = 5 at theta = 180 exceeds l + m = 0.75 + 3.5: by hand, no B.
    assert fourbar(180, **dict(FOURBAR, l=0.75)) is None
    state, circles, status = state_of(pages("fourbar", "?theta=180&l=0.75"))
    assert state["assembles"] == "false" and state["blocked"] == "B" and state["positions"] == {}
    # what is built stays: O, D and the crank's A = (-1, 0); the circles about A and D are named
    close(circles, {"O": (0, 0), "D": (4, 0), "A": (-1, 0)})
    assert "B: the circles about A (radius l = 0.75) and D (radius m = 3.5) do not meet" in status
    unmet = re.findall(r'<circle[^>]*class="unmet"[^>]*>', pages("fourbar", "?theta=180&l=0.75"))
    radii = sorted(float(re.search(r' r="([^"]+)"', c).group(1)) for c in unmet)
    assert radii == [0.75, 3.5]


@pytest.mark.parametrize("scene, query, values", [
    ("five-bar", "?t1=100&t2=60", {"t1": 100, "t2": 60}),              # two inputs
    ("slider-crank", "?theta=200&e=0.3", {"theta": 200}),              # a slider, its offset a dimension
    ("watt-straight-line", "?phi=-12.5&r=2.5", {"phi": -12.5}),        # sqrt(r**2) = |r| in the forms
    ("stephenson-iii", "?theta=77&branch=B:left F:right", {"theta": 77}),  # four modes
    ("stephenson-iii", "?theta=77&branch=B:right F:left", {"theta": 77}),  # ... one that never assembles
    ("hydraulic-boom", "?s=1.7", {"s": 1.7}),                          # a length input: no cos and sin
])
def test_generated_javascript_agrees_with_python(tmp_path, scene, query, values):
    """The page's JavaScript and algkin's numpy evaluation of the same closed forms."""
    motion = Motion(scene)
    state, circles, _ = load(write(motion, tmp_path / "page.html"), query.replace(" ", "%20"))
    parameters = {k: v for k, v in state["values"].items() if k in motion.params}
    assert {k: state["values"][k] for k in values} == values
    pose = motion.at(values, parameters, state["branch"])
    assert state["assembles"] == str(pose.assembles).lower() and state["blocked"] == " ".join(pose.blocked)
    joints = lambda points: {p: xy for p, xy in points.items() if p not in motion.anchors}  # noqa: E731 - rails
    if pose.assembles:
        close(state["positions"], pose.points)
        close(circles, joints(pose.points))
    else:  # what is built is drawn, as the matplotlib drawing draws it
        assert state["positions"] == {}
        close(circles, joints(built(motion, pose)))


def test_a_length_slider_moves_the_boom_as_the_law_of_cosines_does(tmp_path):
    """The cylinder's length s: A at 1 from O and s from C = (3/2, -1/2), left of O -> C."""
    state, circles, _ = load(write(Motion("hydraulic-boom"), tmp_path / "boom.html"), "?s=1.7")
    assert state["values"]["s"] == 1.7 and state["assembles"] == "true"
    oc = math.hypot(1.5, 0.5)
    boom = math.atan2(-0.5, 1.5) + math.acos((1 + oc**2 - 1.7**2) / (2 * oc))
    hand = {"O": (0, 0), "C": (1.5, -0.5), "A": (math.cos(boom), math.sin(boom)),
            "T": (3 * math.cos(boom), 3 * math.sin(boom))}
    close(state["positions"], hand)


def _numbers(text):
    return [float(v) for v in re.split(r"[ ,]+", text.strip())]


def test_a_slider_is_a_block_between_its_rails_edges_and_its_lines_point_no_pivot(tmp_path):
    # Issue 35: the page drew the slider's line as one guide, no block, and its point L = (0, e)
    # as a ground pivot. As the matplotlib drawing (and a textbook): the rail's two edges parallel
    # to y = e, a block centred at B between them, L drawn as neither pivot nor joint.
    dom = dump_dom(write(Motion("slider-crank"), tmp_path / "slider.html"), "?theta=60")
    # B by hand: A = (cos 60, sin 60); B on y = 1/2 at 3 from A, ahead (x greater than A's)
    ax, ay = math.cos(math.radians(60)), math.sin(math.radians(60))
    bx = ax + math.sqrt(9 - (0.5 - ay) ** 2)
    (block,) = re.findall(r'<polygon[^>]*class="block"[^>]*>', dom)
    assert 'data-slider="B"' in block
    xs, ys = (lambda v: (v[0::2], [-y for y in v[1::2]]))(_numbers(re.search(r' points="([^"]+)"', block).group(1)))
    assert abs(sum(xs) / 4 - bx) < 1e-9 and abs(sum(ys) / 4 - 0.5) < 1e-9
    width, height = max(xs) - min(xs), max(ys) - min(ys)
    assert abs(width - 2 * height) < 1e-9 and height > 0  # along the rail, twice as long as it is high
    edges = [(float(re.search(r' y1="([^"]+)"', e).group(1)), float(re.search(r' y2="([^"]+)"', e).group(1)))
             for e in re.findall(r'<line[^>]*class="guide"[^>]*>', dom)]
    assert sorted(-y for y, _ in edges) == pytest.approx([0.5 - height / 2, 0.5 + height / 2], abs=1e-9)
    assert all(y1 == y2 for y1, y2 in edges)  # parallel to the line y = e
    grounds = re.findall(r'<polygon[^>]*class="ground"[^>]*>', dom)
    assert len(grounds) == 1 and 'data-point="L"' not in dom and ">L</text>" not in dom  # O only


def test_the_scenes_unit_of_length_is_on_the_page():
    # Issue 35: chebyshev-lambda says unit = "mm": the page says its lengths are in mm
    from algkin.ui.html import model

    assert model(Motion("chebyshev-lambda"))["length_unit"] == "mm" and model(Motion("fourbar"))["length_unit"] == ""


def test_the_page_says_the_unit_of_its_lengths(pages):
    # the documents the tests above read (one browser run each)
    assert re.search(r'<p id="unit">lengths in mm</p>', pages("chebyshev-lambda", "?angle=37.3"))
    assert re.search(r'<p id="unit"></p>', pages("fourbar", "?theta=123.4&l=2.5&m=3.2&q=0.2"))
