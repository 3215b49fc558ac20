"""Sliders on a moving line (``slider = { through = C, toward = A }``) against hand geometry.

Quick return of a shaper (crank and slotted lever), ``whitworth-quick-return``: the crank
OA (r = 3) about O = (0, 0), the lever's pivot C = (0, -c), c = 5. The lever is the line
C -> A, so with theta the crank angle, by the law of cosines
|CA|**2 = r**2 + c**2 - 2 r c cos(angle AOC) = r**2 + c**2 + 2 r c sin(theta) (OC points down,
at -90 deg). The lever's end B is R = 10 from C along it, B = C + R (A - C)/|CA|, and the ram D
on y = h = 6 is L = 6 from B, ahead (+x): D = (B_x + sqrt(L**2 - (h - B_y)**2), h).

The lever stops where CA touches the crank circle (OA perpendicular to CA): the triangle OAC
has its right angle at A, so angle AOC = acos(r/c), i.e. theta = -90 +- acos(r/c), and the
lever leans asin(r/c) either side of the vertical. The crank turns 2 acos(r/c) =
180 - 2 asin(r/c) deg between them on the side of C (the quick return) and
180 + 2 asin(r/c) deg on the other (the working stroke): Q = (180 + 2 asin(r/c)) / (180 -
2 asin(r/c)). The ram stops exactly there too: D' = 0 when B' = 0 or when D, B, C are in line
(never here: the link BD is within 30 deg of the horizontal, the lever within 37 deg of the
vertical), and it travels 2 R r / c between the two (B at (-+R r/c, R sqrt(c**2 - r**2)/c - c),
the same height).

Oscillating-cylinder engine, ``inverted-slider-crank``: crank OA (r = 2), the cylinder's
trunnion C = (c, 0), c = 5, its axis the line C -> A. |CA|**2 = r**2 + c**2 - 2 r c cos(theta),
and by the law of sines the axis leans asin(r sin(theta)/|CA|) from C -> O, so its direction
angle(C, A) = 180 - asin(r sin(theta)/|CA|) deg. The head H = C + k (A - C)/|CA|, k = 2. The
cylinder swings back where CA touches the crank circle, cos(theta) = r/c: the time ratio is
again (180 + 2 asin(r/c)) / (180 - 2 asin(r/c)) and the swing 2 asin(r/c).
"""

import mpmath
import pytest
import sympy

from algkin.ui.cli import main

from .geometry import at_angle, branch, curve_at, run

ANGLES = [0, 17, 90, 135, 200, 216, 270, 300, 323, 359]
AGREE = mpmath.mpf(10) ** -30


def whitworth(theta, r=3, c=5, R=10, h=6, L=6):
    """A, B, D and the lever's direction (deg) by hand, in mpmath."""
    t = mpmath.radians(theta)
    a = (r * mpmath.cos(t), r * mpmath.sin(t))
    ca = mpmath.sqrt(r**2 + c**2 + 2 * r * c * mpmath.sin(t))  # law of cosines
    b = (R * a[0] / ca, -c + R * (a[1] + c) / ca)
    d = (b[0] + mpmath.sqrt(L**2 - (h - b[1]) ** 2), mpmath.mpf(h))
    lever = mpmath.degrees(mpmath.atan2(a[1] + c, a[0]))
    return a, b, d, lever


def cylinder(theta, r=2, c=5, k=2):
    """A, |CA|, the axis direction angle(C, A) in deg, and H by hand, in mpmath."""
    t = mpmath.radians(theta)
    a = (r * mpmath.cos(t), r * mpmath.sin(t))
    ca = mpmath.sqrt(r**2 + c**2 - 2 * r * c * mpmath.cos(t))  # law of cosines
    swing = 180 - mpmath.degrees(mpmath.asin(r * mpmath.sin(t) / ca))  # law of sines
    h = (c + k * (a[0] - c) / ca, k * a[1] / ca)
    return a, ca, swing, h


def time_ratio(r, c):
    alpha = 2 * mpmath.degrees(mpmath.asin(mpmath.mpf(r) / c))
    return (180 + alpha) / (180 - alpha), alpha


def _close(got, want, size=1):
    return abs(got - want) < AGREE * max(1, abs(size))


@pytest.fixture(scope="module")
def whitworth_derived():
    return run("derive", "whitworth-quick-return", "--samples", "12")


@pytest.fixture(scope="module")
def cylinder_derived():
    return run("derive", "inverted-slider-crank", "--samples", "12")


@pytest.mark.parametrize("theta", ANGLES)
def test_whitworth_lever_and_ram_by_the_law_of_cosines(whitworth_derived, theta):
    values = branch(whitworth_derived, "B:ahead D:ahead")["values"]
    with mpmath.workdps(50):
        _, b, d, lever = whitworth(theta)
        got = {u: at_angle(v, theta) for u, v in values.items()}
        assert _close(got["B_x"], b[0]) and _close(got["B_y"], b[1])
        assert _close(got["D_x"], d[0]) and _close(got["D_y"], d[1])
        angle = mpmath.degrees(mpmath.atan2(got["sin_lever"], got["cos_lever"]))
        assert _close(angle, lever, 180)


def test_whitworth_other_lever_mode_is_the_lever_turned_half_a_turn(whitworth_derived):
    # behind: B on the ray from C away from A, at R from C
    values = branch(whitworth_derived, "B:behind D:ahead")["values"]
    with mpmath.workdps(50):
        for theta in ANGLES:
            _, b, _, _ = whitworth(theta)
            assert _close(at_angle(values["B_x"], theta), -b[0])
            assert _close(at_angle(values["B_y"], theta), -10 - b[1])  # 2 C_y - B_y


def test_whitworth_derive_verifies_every_branch(whitworth_derived):
    assert whitworth_derived["verification"]["passed"]
    assert whitworth_derived["verification"]["compared"] > 0
    assert whitworth_derived["outputs"] == {"lever": ["cos_lever", "sin_lever"], "B": ["B_x", "B_y"],
                                            "D": ["D_x", "D_y"], "x": ["D_x"]}
    assert [b["label"] for b in whitworth_derived["branches"]] == [
        "B:ahead D:ahead", "B:ahead D:behind", "B:behind D:ahead", "B:behind D:behind"]


@pytest.mark.parametrize("theta", ANGLES)
def test_cylinder_axis_stroke_and_head_by_the_laws_of_cosines_and_sines(cylinder_derived, theta):
    values = branch(cylinder_derived, "ahead")["values"]
    with mpmath.workdps(50):
        _, ca, swing, h = cylinder(theta)
        got = {u: at_angle(v, theta) for u, v in values.items()}
        assert _close(got["stroke"], ca)
        assert _close(got["H_x"], h[0]) and _close(got["H_y"], h[1])
        angle = mpmath.degrees(mpmath.atan2(got["sin_swing"], got["cos_swing"])) % 360
        assert _close(angle, swing, 360)


def test_cylinder_derive_verifies(cylinder_derived):
    assert cylinder_derived["verification"]["passed"] and cylinder_derived["verification"]["compared"] > 0
    assert cylinder_derived["outputs"] == {"H": ["H_x", "H_y"], "stroke": ["stroke"],
                                          "swing": ["cos_swing", "sin_swing"]}


@pytest.mark.parametrize("scene, r, c, point", [("whitworth-quick-return", 3, 5, "D"),
                                                ("inverted-slider-crank", 2, 5, "H")])
def test_time_ratio_of_the_quick_return_by_hand(scene, r, c, point):
    document = run("toggles", scene)
    assert document["toggles"] == []  # the crank turns fully: c > r, and the ram's link always reaches
    # every other factor of the discriminants certified: B's two modes share B_x = 0 at theta = 90
    # and 270 deg but are apart (the ram cannot reach from the lower one: that branch is left out)
    assert document["artefacts"] and all(a["why"].endswith("(certified)") for a in document["artefacts"])
    found = document["time_ratio"]
    with mpmath.workdps(50):
        ratio, alpha = time_ratio(r, c)
        assert found["point"] == point
        assert abs(found["ratio"] - ratio) < 1e-12 and abs(found["alpha_deg"] - alpha) < 1e-10
        assert abs(mpmath.mpf(sympy.N(sympy.sympify(found["exact"]), 50)) - ratio) < AGREE
        working, quick = found["strokes"]
        assert abs(working["crank_deg"] - (180 + alpha)) < 1e-10 and abs(quick["crank_deg"] - (180 - alpha)) < 1e-10
        # the stops: theta = -90 +- acos(r/c) for the lever below O, +-acos(r/c) for the cylinder beside it
        stops = sorted(float((base + sign * mpmath.degrees(mpmath.acos(mpmath.mpf(r) / c))) % 360)
                       for sign in (1, -1) for base in ([-90] if point == "D" else [0]))
        assert sorted(s["from_deg"] % 360 for s in found["strokes"]) == pytest.approx(stops, abs=1e-10)
        stroke = found["stroke"]
        if point == "D":  # the ram's travel, 2 R r / c
            assert stroke["kind"] == "travel" and sympy.sympify(stroke["exact"]) == 12
            assert abs(stroke["length"] - 12) < 1e-12
        else:  # the cylinder's swing, 2 asin(r/c)
            assert stroke["kind"] == "swing" and abs(stroke["angle_deg"] - alpha) < 1e-10
            assert abs(mpmath.mpf(sympy.N(sympy.sympify(stroke["exact"]), 50)) - alpha) < AGREE


def test_whitworth_lever_stops_where_its_line_touches_the_crank_circle():
    limits = [g for g in run("toggles", "whitworth-quick-return")["limits"] if g["point"] == "B" and g["selected"]]
    assert len(limits) == 2
    for limit in limits:
        x, y = (sympy.sympify(limit["position"]["exact"][k]) for k in ("x", "y"))
        assert abs(x) == 6 and y == 3  # C + R (+-r/c, sqrt(c**2 - r**2)/c) = (0, -5) + 10 (+-3/5, 4/5)
        with mpmath.workdps(50):
            a, b, _, _ = whitworth(limit["input_deg"])
            assert abs(a[0] * (b[0] - a[0]) + a[1] * (b[1] - a[1])) < 1e-10  # OA . AB = 0: tangent


@pytest.mark.parametrize("scene, point, curve", [
    ("whitworth-quick-return", "B", lambda x, y: x**2 + (y + 5) ** 2 - 100),  # the circle about C of radius R
    ("whitworth-quick-return", "D", lambda x, y: y - 6),                       # the ram's line
    ("inverted-slider-crank", "H", lambda x, y: (x - 5) ** 2 + y**2 - 4),      # the circle about C of radius k
])
def test_curves_are_the_circles_and_lines_by_hand(scene, point, curve):
    document = run("curve", scene, "--point", point)
    x, y = (sympy.Symbol(v) for v in document["variables"])
    found = sympy.parse_expr(document["curve"])
    assert sympy.simplify(found / curve(x, y)).is_number
    assert document["verification"]["passed"]
    with mpmath.workdps(50):
        for theta in (10, 100, 250):
            here = whitworth(theta)[1 if point == "B" else 2] if point != "H" else cylinder(theta)[3]
            assert abs(curve_at(document, here)) < 1e-30


@pytest.mark.parametrize("scene", ["whitworth-quick-return", "inverted-slider-crank"])
def test_verify_and_plot(scene, tmp_path):
    verification = run("verify", scene)["verification"]
    assert verification["passed"] and verification["compared"] > 0
    out = tmp_path / f"{scene}.png"
    assert main(["plot", scene, "--out", str(out)]) == 0 and out.stat().st_size > 1000
