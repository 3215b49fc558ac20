"""Jupyter sliders: the callback's logic without a notebook server, and the widgets it builds."""

import subprocess
import sys

import numpy as np
import pytest
import sympy

from algkin.errors import UsageError
from algkin.ui.widgets import Explorer

from ..hand_linkages import CHEBYSHEV, FOURBAR, fourbar

pytest.importorskip("matplotlib")


def test_one_slider_per_input_and_symbolic_dimension():
    assert [s["name"] for s in Explorer("chebyshev-lambda").sliders] == ["angle"]  # dimensions exact
    sliders = {s["name"]: s for s in Explorer("fourbar").sliders}
    assert list(sliders) == ["theta", "a", "d", "l", "m", "p", "q"]
    assert (sliders["theta"]["lo"], sliders["theta"]["hi"]) == (0, 360)
    assert sliders["m"]["value"] == 3.5 and sliders["m"]["lo"] < 3.5 < sliders["m"]["hi"]


def test_slider_values_draw_the_hand_configuration():
    figure = Explorer("fourbar").figure(theta=123.4, l=2.5, m=3.2, branch="right")
    hand = fourbar(123.4, **dict(FOURBAR, l=2.5, m=3.2), branch="right")
    drawn = sorted(xy for line in figure.axes[0].lines if line.get_linestyle() == "None"
                   for xy in zip(line.get_xdata(), line.get_ydata()))
    assert np.max(np.abs(np.array(drawn) - np.array(sorted(hand.values())))) < 1e-12
    assert figure.axes[0].get_title() == "right: theta = 123.4°"


def test_cannot_assemble_is_the_caption_not_nans():
    explorer = Explorer("fourbar")
    assert fourbar(180, **dict(FOURBAR, l=0.75)) is None
    figure = explorer.figure(theta=180, l=0.75)
    assert figure.axes[0].get_title().startswith("left: cannot assemble at theta = 180°")
    [text] = [t.get_text() for t in figure.axes[0].texts if t.get_visible() and t.get_text().startswith("cannot")]
    assert text.startswith("cannot assemble B:\nthe circles about A (radius l = 0.75) and D")


def test_sliders_only_evaluate(monkeypatch):
    """Moving sliders never derives again: the pipeline is not called after construction."""
    import algkin.analyses.motion

    explorer = Explorer("chebyshev-lambda")
    monkeypatch.setattr(algkin.analyses.motion, "closed_forms", lambda *a: pytest.fail("derived again"))
    monkeypatch.setattr(algkin.analyses.motion, "compile_scene", lambda *a: pytest.fail("compiled again"))
    for angle in (0, 90, 180):
        assert explorer.pose(angle=angle).points["P"] == pytest.approx(fourbar(angle, **CHEBYSHEV)["P"], abs=1e-12)


def test_interact_builds_the_widgets(monkeypatch):
    ipywidgets = pytest.importorskip("ipywidgets")
    import algkin
    from algkin.ui import widgets as module

    shown = []
    monkeypatch.setattr(module.Explorer, "png", lambda self, **values: shown.append(values) or b"")
    box = algkin.interact("chebyshev-lambda")
    controls = box.children[0].children
    slider, mode = controls
    assert isinstance(slider, ipywidgets.FloatSlider) and slider.description == "angle"
    assert (slider.min, slider.max, slider.value) == (0, 360, 63)
    assert list(mode.options) == ["left", "right"] and mode.value == "left"
    slider.value = 100
    mode.value = "right"
    assert shown[-2:] == [{"angle": 100, "branch": "left"}, {"angle": 100, "branch": "right"}]


def test_import_algkin_stays_cheap():
    code = ("import sys, algkin; heavy = [m for m in ('matplotlib', 'ipywidgets', 'IPython') if m in sys.modules];"
            "print(heavy)")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert done.stdout.strip() == "[]", done.stderr


RANGED = """
name = "ranged"
[parameters]
a = { default = 1, range = ["1/2", 2] }
[inputs]
t = { range = [0, 360], unit = "deg" }
[points]
O = { fixed = [0, 0] }
A = { crank = "O", length = "a", input = "t" }
[outputs]
A = "A"
"""


def test_a_declared_range_drives_the_sliders_and_an_override_wins(tmp_path):
    from algkin.ui.html import model
    from algkin.analyses.motion import Motion
    from algkin.scene import load_scene_text
    from algkin.ui.widgets import Explorer

    motion = Motion(load_scene_text(RANGED, "ranged.toml"))
    assert motion.scene.parameter_ranges == {"a": (sympy.Rational(1, 2), 2)}
    assert [(p["lo"], p["hi"]) for p in model(motion)["params"]] == [(0.5, 2.0)]
    assert [(s["lo"], s["hi"]) for s in Explorer(motion).sliders if s["name"] == "a"] == [(0.5, 2.0)]
    overridden = Explorer(motion, ranges={"a": (0.25, 3)}).sliders
    assert [(s["lo"], s["hi"]) for s in overridden if s["name"] == "a"] == [(0.25, 3.0)]
    assert [(p["lo"], p["hi"]) for p in model(motion, ranges={"a": (0.25, 3)})["params"]] == [(0.25, 3.0)]


@pytest.mark.parametrize("ranges", [
    {"a": (2, 1)},  # ipywidgets' TraitError (max below min) once a slider was made of it
    {"a": (float("nan"), 2)},  # sympy's TypeError
    {"a": "1:2"},  # a ValueError from the characters taken as numbers
    {"a": (1, 2, 3)},  # taken: its first two
    {"a": (True, 2)},
    [("a", (1, 2))],  # not a mapping
], ids=["reversed", "nan", "text", "three", "bool", "list"])
def test_slider_ranges_that_are_no_ranges_are_refused_naming_ranges(ranges):
    with pytest.raises(UsageError, match=r"^ranges=.*: expected \(lo, hi\) of each dimension"):
        Explorer("fourbar", params=["a"], ranges=ranges)


def test_the_library_names_its_own_arguments_not_the_flags():
    with pytest.raises(UsageError, match=r"^ranges='zz': not a symbolic dimension of fourbar"):
        Explorer("fourbar", params=["a"], ranges={"zz": (1, 2)}).sliders
    with pytest.raises(UsageError, match=r"^params='ad': expected a list of names"):  # was the sliders a and d
        Explorer("fourbar", params="ad")


def drawn(artists):
    """What the live figure shows: point -> (x, y) from the joint and ground markers, the
    labels' anchors and the bars' ends, each checked against the others."""
    markers = np.column_stack([np.concatenate([line.get_xdata() for line in (artists.ground, artists.joints)]),
                               np.concatenate([line.get_ydata() for line in (artists.ground, artists.joints)])])
    labels = {name: label.xy for name, label in artists.labels.items() if label.get_visible()}
    assert sorted(map(tuple, markers)) == sorted(labels.values())
    for line, (p, q) in zip(artists.bars, artists.bar_ends):
        assert list(zip(line.get_xdata(), line.get_ydata())) == ([labels[p], labels[q]] if {p, q} <= set(labels)
                                                                 else [])
    return labels


def assert_hand(explorer, theta, branch, **dimensions):
    """The live figure (joints, labels, bars, trajectory, red text) against hand geometry."""
    hand = fourbar(theta, **dict(FOURBAR, **dimensions), branch=branch)
    artists = explorer.live.artists
    assert artists.blocked.get_visible() == (hand is None)
    points = drawn(artists)
    assert (set(points) == {"O", "D", "A"}) if hand is None else (  # what is built stays
        max(abs(np.subtract(points[n], hand[n])).max() for n in hand) < 1e-12)
    # The trajectory is P's over the turn at these dimensions (721 samples: half a degree apart).
    xs, ys = explorer.live.paths["P"].get_data()
    for k in range(0, 721, 45):
        at = fourbar(k / 2, **dict(FOURBAR, **dimensions), branch=branch)
        assert np.isnan(xs[k]) if at is None else abs(xs[k] - at["P"][0]) + abs(ys[k] - at["P"][1]) < 1e-12


def test_a_move_updates_the_one_figure_and_sweeps_only_for_a_dimension_or_branch(monkeypatch):
    explorer = Explorer("fourbar")
    explorer.png(theta=50)
    figure, sweeps = explorer.live.figure, []
    sweep = explorer.motion.sweep
    monkeypatch.setattr(explorer.motion, "sweep", lambda *a, **k: sweeps.append(a) or sweep(*a, **k))
    every = len(explorer.motion.branches)  # a dimension sweeps every branch (limits), a branch none
    steps = [(dict(theta=123.4), "left", 0), (dict(theta=123.4, l=2.5), "left", every),
             (dict(theta=123.4, l=2.5, branch="right"), "right", 0), (dict(theta=180, l=0.75), "left", every),
             (dict(theta=123.4, l=2.5), "left", every)]
    for values, branch, swept in steps:
        before = len(sweeps)
        assert explorer.png(**values)[:8] == b"\x89PNG\r\n\x1a\n"
        dimensions = {k: v for k, v in values.items() if k not in ("theta", "branch")}
        assert_hand(explorer, values["theta"], branch, **dimensions)
        assert len(sweeps) - before == swept
        assert explorer.live.axes.get_title() == explorer.caption(**values)
    assert explorer.live.figure is figure


def test_interact_shows_the_live_figure_in_an_image_widget():
    ipywidgets = pytest.importorskip("ipywidgets")
    import algkin

    box = algkin.interact("chebyshev-lambda")
    (slider, mode), image = box.children[0].children, box.children[1]
    assert isinstance(image, ipywidgets.Image) and image.value[:8] == b"\x89PNG\r\n\x1a\n"
    first = image.value
    slider.value = 100
    assert image.value != first and image.value[:8] == b"\x89PNG\r\n\x1a\n"
    moved = image.value
    mode.value = "right"
    assert image.value not in (first, moved)


def platforms(figure):
    """Each panel's title and its platform's corners, sorted, from the polygon drawn (gid ``mode-k-platform-0``)."""
    drawn = {}
    for axes in figure.axes:
        (polygon,) = [p for p in axes.patches if (p.get_gid() or "").endswith("platform-0")]
        drawn[axes.get_title()] = sorted(map(tuple, np.asarray(polygon.get_xy())[:3]))
    return drawn


def test_a_group_scene_slider_draws_each_mode_where_solve_puts_it():
    """3rpr: at two slider values, each panel's platform P1 P2 P3 is one of algkin.solve's modes
    (Motion refused the scene before: no sliders for points solved together)."""
    import algkin
    from algkin.ui.widgets import GroupExplorer, explorer

    chosen = explorer("3rpr")
    assert isinstance(chosen, GroupExplorer) and [s["name"] for s in chosen.sliders] == ["r1"]
    for r1 in (6, 12):
        solved = algkin.solve("3rpr", {"r1": sympy.Rational(str(r1))}).configurations
        expected = {c.mode: sorted((float(c.points[p][0]), float(c.points[p][1])) for p in ("P1", "P2", "P3"))
                    for c in solved}
        drawn = platforms(chosen.figure(r1=r1))
        assert len(drawn) == len(expected) > 0
        for title, corners in drawn.items():
            mode = title.split(" ")[0]
            assert np.max(np.abs(np.subtract(corners, expected[mode]))) < 1e-9, (r1, mode)
    assert chosen.png(r1=6)[:8] == b"\x89PNG\r\n\x1a\n"


def test_a_group_scene_with_no_mode_says_not_assembled(monkeypatch):
    """3rpr at r1 = 9 has no real mode (solve finds none): one panel, the ground drawn, the red line."""
    from algkin.ui.groupmotion import GroupMotion
    from algkin.ui.widgets import GroupExplorer

    monkeypatch.setattr(GroupMotion, "paths", ())  # the modes' paths are the slow part and not what is shown here
    (axes,) = GroupExplorer("3rpr").figure(r1=9).axes
    assert axes.get_title() == "no mode"
    assert [t.get_text() for t in axes.texts if t.get_text().startswith("not assembled here")] == [
        "not assembled here: no real mode of P1, P2 at r1 = 9"]


def test_interact_on_a_group_scene_has_the_input_slider_only(monkeypatch):
    ipywidgets = pytest.importorskip("ipywidgets")
    import algkin
    from algkin.ui import widgets as module

    shown = []
    monkeypatch.setattr(module.GroupExplorer, "png", lambda self, **values: shown.append(values) or b"")
    (slider,) = algkin.interact("3rpr").children[0].children
    assert isinstance(slider, ipywidgets.FloatSlider) and (slider.description, slider.min, slider.max) == ("r1", 5, 12)
    slider.value = 6
    assert shown[-1] == {"r1": 6}
