"""The geared five-bar and the four-bar's instant centre, checked against hand geometry in mpmath.

geared-five-bar: the crank A = (cos t, sin t) about O1 = (0, 0); the crank B about O2 = (4, 0),
length 1, at the angle -2 t + atan2(4, 3) (external gears, ratio -2, a phase with cos 3/5 and
sin 4/5); C 3 from A and 4 from B, left of A -> B; P at (1/2, 1/2) in the frame of the bar AC.
fourbar-instant-centre: the catalog's crank-rocker (crank 1, ground 4, coupler 3, rocker 7/2),
its instant centre I where the lines OA and DB meet (Kennedy's theorem).
"""

import mpmath
import pytest

from algkin.scene import dump_scene, load_scene, load_scene_text

from .geometry import at_angle, branch, circles, curve_at, rigid, run

SAMPLES = [-160, -75, 0, 20, 45, 110, 190, 250, 333]


def five_bar(degrees):
    t = mpmath.radians(degrees)
    a = (mpmath.cos(t), mpmath.sin(t))
    b = (4 + mpmath.cos(-2 * t + mpmath.atan2(4, 3)), mpmath.sin(-2 * t + mpmath.atan2(4, 3)))
    c = circles(a, 3, b, 4, 1)
    return {"C": c, "P": rigid(a, c, mpmath.mpf(1) / 2, mpmath.mpf(1) / 2)}


def instant_centre(degrees):
    """I = O + k (A - O) on the line DB: k from cross(B - D, O + k A - D) = 0."""
    t = mpmath.radians(degrees)
    a = (mpmath.cos(t), mpmath.sin(t))
    b = circles(a, 3, (4, 0), mpmath.mpf(7) / 2, 1)
    u = (b[0] - 4, b[1])
    k = (u[0] * (0 - 0) - u[1] * (0 - 4)) / (u[1] * a[0] - u[0] * a[1])
    return {"B": b, "I": (k * a[0], k * a[1])}


@pytest.mark.parametrize("scene, hand", [("geared-five-bar", five_bar), ("fourbar-instant-centre", instant_centre)])
def test_closed_forms_are_the_hand_geometry(scene, hand):
    document = run("derive", scene)
    assert document["verification"]["passed"]
    left = branch(document, "left")
    with mpmath.workdps(50):
        for degrees in SAMPLES:
            for point, (x, y) in hand(degrees).items():
                got = [at_angle(left["values"][f"{point}_{axis}"], degrees, digits=50) for axis in "xy"]
                scale = max(1, abs(x), abs(y))
                assert abs(got[0] - x) < 1e-40 * scale and abs(got[1] - y) < 1e-40 * scale, (scene, point, degrees)


@pytest.mark.parametrize("scene, point, hand, degree", [("geared-five-bar", "P", five_bar, 12),
                                                         ("fourbar-instant-centre", "I", instant_centre, 8)])
def test_curve_holds_at_hand_computed_points(scene, point, hand, degree):
    document = run("curve", scene, "--point", point)
    assert document["degree"] == degree and document["verification"]["passed"]
    with mpmath.workdps(60):
        for degrees in SAMPLES:
            assert abs(curve_at(document, hand(degrees)[point])) < 1e-40, degrees


def test_instant_centre_toggles_are_its_four_bar_s():
    document = run("toggles", "fourbar-instant-centre")
    assert document["toggles"] == run("toggles", "fourbar")["toggles"]  # a crank-rocker: none


@pytest.mark.parametrize("scene", ["geared-five-bar", "fourbar-instant-centre"])
def test_catalog_scene_dumps_and_loads_back(scene):
    loaded = load_scene(scene)
    assert load_scene_text(dump_scene(loaded), scene) == loaded


def test_show_names_the_geared_input():
    document = run("show", "geared-five-bar")
    assert document["geared"] == {"phi": {"driven_by": "theta", "ratio": "-2"}}
    assert list(document["inputs"]) == ["theta"]
