"""``algkin.analyses.solve``: every configuration at an input, against hand geometry in mpmath."""

from fractions import Fraction

import flint
import mpmath
import pytest

from algkin.analyses.solve import MAX_DIGITS, solve
from algkin.errors import SceneError, UsageError


def _circles(centre1, r1, centre2, r2):
    """The two intersections of two circles, by the textbook formula (mpmath), left of centre1->centre2 first."""
    (x1, y1), (x2, y2) = centre1, centre2
    d = mpmath.sqrt((x2 - x1) ** 2 + (y2 - y1) ** 2)
    a = (r1 ** 2 - r2 ** 2 + d ** 2) / (2 * d)
    h = mpmath.sqrt(r1 ** 2 - a ** 2)
    mx, my = x1 + a * (x2 - x1) / d, y1 + a * (y2 - y1) / d
    return (mx - h * (y2 - y1) / d, my + h * (x2 - x1) / d), (mx + h * (y2 - y1) / d, my - h * (x2 - x1) / d)


def _close(text_pair, exact_pair, tolerance):
    return all(abs(mpmath.mpf(t) - e) < tolerance for t, e in zip(text_pair, exact_pair))


def test_the_fourbar_at_30_degrees_has_its_two_circle_intersections():
    """fourbar's defaults: crank 1 about O, ground 4, coupler 3, rocker 7/2, P = A + (B-A)/2 + rot90(B-A)/2."""
    with mpmath.workdps(50):
        a = (mpmath.cos(mpmath.pi / 6), mpmath.sin(mpmath.pi / 6))
        left, right = _circles(a, 3, (4, 0), mpmath.mpf(7) / 2)
        found = solve("fourbar", at={"theta": 30})
        assert [c.mode for c in found.configurations] == ["left", "right"]
        for configuration, b in zip(found.configurations, (left, right)):
            p = (a[0] + (b[0] - a[0]) / 2 - (b[1] - a[1]) / 2, a[1] + (b[1] - a[1]) / 2 + (b[0] - a[0]) / 2)
            assert _close(configuration.points["B"], b, mpmath.mpf(10) ** -29)
            assert _close(configuration.points["P"], p, mpmath.mpf(10) ** -29)
            assert _close(configuration.points["A"], a, mpmath.mpf(10) ** -29)
            assert configuration.points["D"] == ("4", "0")
            assert 0 < configuration.radius < 1e-30
            # 30 significant digits, trailing zeros left out: sin 30 degrees, 1/2 in a ball, is 0.5
            significant = [len(v.lstrip("-").replace(".", "").strip("0")) for v in configuration.points["P"] + configuration.points["B"]]
            assert max(significant) == 30
            assert configuration.points["A"][1] == "0.5"


def test_the_slider_crank_at_a_third_of_a_degree():
    """B on y = 1/2 at distance 3 from A = (cos t, sin t): x = cos t +- sqrt(9 - (1/2 - sin t)**2)."""
    with mpmath.workdps(50):
        t = mpmath.pi / 540
        c, s = mpmath.cos(t), mpmath.sin(t)
        half = mpmath.sqrt(9 - (mpmath.mpf(1) / 2 - s) ** 2)
        found = solve("slider-crank", at={"theta": "1/3"}, digits=40)
        assert found.at == {"theta": Fraction(1, 3)}
        ahead, behind = found.configurations
        assert (ahead.mode, behind.mode) == ("ahead", "behind")
        assert _close(ahead.points["B"], (c + half, mpmath.mpf(1) / 2), mpmath.mpf(10) ** -39)
        assert _close(behind.points["B"], (c - half, mpmath.mpf(1) / 2), mpmath.mpf(10) ** -39)


def test_nothing_assembles_past_the_dead_centre_a_valid_empty_answer():
    """fourbar-nongrashof assembles while cos(theta) >= -53/80 (|theta| <= 131.49 degrees)."""
    found = solve("fourbar-nongrashof", at={"theta": 150})
    assert found.configurations == ()
    assert found.to_json()["configurations"] == []
    assert len(solve("fourbar-nongrashof", at={"theta": 131}).configurations) == 2


def test_at_a_right_angle_the_inputs_are_exact():
    """At 90 degrees cos and sin are 0 and 1 exactly: A = (0, 1) written exactly."""
    found = solve("fourbar", at={"theta": 90}, mode="right")
    (configuration,) = found.configurations
    assert configuration.points["A"] == ("0", "1")


def test_json_keys():
    document = solve("chebyshev-lambda", at={"angle": 0}, digits=12).to_json()
    assert set(document) >= {"scene", "at", "configurations"}
    assert "complex_count" not in document  # no group solved together
    assert document["at"] == {"angle": "0"}
    assert set(document["configurations"][0]) == {"mode", "points", "radius"}


@pytest.mark.parametrize(("at", "options", "argument"), [
    ({}, {}, "at"),
    ({"theta": 30, "phi": 1}, {}, "at"),
    ({"theta": 361}, {}, "at"),
    ({"theta": "x"}, {}, "at"),
    (30, {}, "at"),  # a number, not a mapping: was a TypeError from iterating it
    (None, {}, "at"),
    (["theta"], {}, "at"),
    ({"theta": 30}, {"digits": 0}, "digits"),
    ({"theta": 30}, {"digits": MAX_DIGITS + 1}, "digits"),
    ({"theta": 30}, {"mode": "up"}, "mode"),
    # numbers Python will not write (more than 4300 digits): the error's own message was a ValueError
    ({"theta": 10**5000}, {}, "at"),
    ({"theta": Fraction(1, 10**5000)}, {}, "at"),
    ({"theta": 30}, {"digits": 10**5000}, "digits"),
])
def test_bad_arguments_name_the_argument(at, options, argument):
    with pytest.raises(UsageError) as caught:
        solve("fourbar", at=at, **options)
    assert caught.value.argument == argument


@pytest.mark.parametrize("value", ["1e-100000", "1e-1000000000", "0." + "0" * 400 + "1"])
def test_an_input_too_precise_to_read_is_refused_naming_it(value):
    # 1e-100000 was read, then failed printing its 100,000-digit denominator (a traceback);
    # 1e-1000000000 never came back from Fraction("1e-1000000000")
    with pytest.raises(UsageError, match="exponent out of range|more than 1024 bits") as caught:
        solve("fourbar", at={"theta": value})
    assert caught.value.argument == "at"


def test_numpy_integers_give_the_digits():
    import numpy as np

    # refused before ("expected a whole number of digits") where samples= took them
    assert solve("fourbar", at={"theta": 30}, digits=np.int64(12)) == solve("fourbar", at={"theta": 30}, digits=12)


def test_the_facade_has_it():
    import algkin

    found = algkin.solve("fourbar", at={"theta": 0}, digits=5)
    assert isinstance(found, algkin.Solution) and len(found.configurations) == 2


# Points solved together: the SPEC's 3-RPR, and Gosselin's design with six real assembly modes,
# checked against the loop equations solved independently (the platform's pose (x, y, theta):
# mpmath's Newton method at 50 digits from many starts, deduplicated; tests/eliminate/test_group.py).
from tests.eliminate.test_group import GOSSELIN, GOSSELIN_LEGS, Platform  # noqa: E402
from tests.scene.test_groups import SPEC_3RPR  # noqa: E402

from algkin.scene import load_scene_text  # noqa: E402


def _fmpq(value):
    exact = Fraction(value)
    return flint.fmpq(exact.numerator, exact.denominator)


def _matches(found, poses):
    """Each numeric pose matched to one configuration within 1e-30, none missing, none extra."""
    assert len(found.configurations) == len(poses)
    left = list(poses)
    with mpmath.workdps(50):
        for configuration in found.configurations:
            mine = [mpmath.mpf(v) for p in ("P1", "P2") for v in configuration.points[p]]
            errors = [max(abs(a - b) for a, b in zip(mine, pose)) for pose in left]
            best = min(range(len(left)), key=errors.__getitem__)
            assert errors[best] < 1e-30
            left.pop(best)
            assert configuration.radius < 1e-30


@pytest.mark.parametrize("r1", [6, 12, "37/4"])
def test_the_spec_3rpr_configurations_are_the_loop_equations_real_solutions(r1):
    found = solve(load_scene_text(SPEC_3RPR, "3rpr.toml"), at={"r1": r1}, digits=40)
    assert found.complex_count == 6
    poses = Platform([(0, 0), (10, 0), (3, 8)], 5, flint.fmpq(1, 2), flint.fmpq(3, 4)).poses([_fmpq(r1), 9, 8])
    _matches(found, poses)
    labels = [c.mode for c in found.configurations]
    assert len(set(labels)) == len(labels)


def _gosselin_scene():
    (a2x, _), side, a, b = GOSSELIN.bases[1], GOSSELIN.side, GOSSELIN.a, GOSSELIN.b
    return load_scene_text(f'''
[inputs]
r1 = {{ range = [10, 20], unit = "length" }}
[parameters]
r2 = "{GOSSELIN_LEGS['r2']}"
r3 = "{GOSSELIN_LEGS['r3']}"
[points]
A1 = {{ fixed = [0, 0] }}
A2 = {{ fixed = ["{a2x}", 0] }}
A3 = {{ fixed = [0, 10] }}
P1 = {{ unknown = true }}
P2 = {{ unknown = true }}
P3 = {{ frame = ["P1", "P2"], at = ["{a}", "{b}"] }}
[constraints]
leg1 = "dist(A1, P1) = r1"
leg2 = "dist(A2, P2) = r2"
leg3 = "dist(A3, P3) = r3"
side = "dist(P1, P2) = {side}"
''', "gosselin.toml")


def test_gosselins_3rpr_has_six_real_modes_each_labelled_and_one_asked_by_its_label():
    r1 = GOSSELIN_LEGS["r1"]
    found = solve(_gosselin_scene(), at={"r1": f"{r1.p}/{r1.q}"}, digits=40)
    assert found.complex_count == 6
    _matches(found, GOSSELIN.poses([GOSSELIN_LEGS[n] for n in ("r1", "r2", "r3")]))
    labels = [c.mode for c in found.configurations]
    assert len(set(labels)) == 6
    assert all(set(label) <= set("+-") and len(label) == 3 for label in labels)  # a sign per leg told them apart
    (one,) = solve(_gosselin_scene(), at={"r1": f"{r1.p}/{r1.q}"}, mode=labels[2], digits=40).configurations
    assert one == found.configurations[2]


def test_an_angle_with_irrational_cos_is_solved_in_balls_beside_points_solved_together():
    """Once refused (only multiples of 90 degrees); P is where the circles about A and D meet."""
    scene = load_scene_text('''
[inputs]
t = { range = [0, 360] }
[points]
O = { fixed = [0, 0] }
A = { crank = "O", length = 1, input = "t" }
D = { fixed = [3, 0] }
P = { unknown = true }
[constraints]
a = "dist(A, P) = 2"
b = "dist(D, P) = 2"
''', "crank.toml")
    assert len(solve(scene, at={"t": 90}).configurations) == 2
    found = solve(scene, at={"t": 30}, digits=30).configurations
    with mpmath.workdps(40):
        a = (mpmath.cos(mpmath.pi / 6), mpmath.sin(mpmath.pi / 6))
        expected = _circles(a, 2, (3, 0), 2)
        assert len(found) == 2
        assert all(any(_close(c.points["P"], e, 1e-28) for c in found) for e in expected)


def _triad_poses(theta):
    """stephenson-iii-triad's real configurations (A, B) at theta degrees, solved independently of
    the eliminant: A = (cos a, sin a) on its crank, B where the circles of radius 3 about A and 7/2
    about D meet (either), and C = A + (B - A)/2 + rot90(B - A)/2 at distance 3 from F: a function of
    a alone whose sign changes over a fine scan are refined by mpmath's root finder."""
    f = (-1 + 2 * mpmath.cos(mpmath.radians(theta)), 5 + 2 * mpmath.sin(mpmath.radians(theta)))

    def pose(alpha, side):
        a = (mpmath.cos(alpha), mpmath.sin(alpha))
        b = _circles(a, 3, (4, 0), mpmath.mpf(7) / 2)[side]
        c = (a[0] + (b[0] - a[0]) / 2 - (b[1] - a[1]) / 2, a[1] + (b[1] - a[1]) / 2 + (b[0] - a[0]) / 2)
        return a, b, (c[0] - f[0]) ** 2 + (c[1] - f[1]) ** 2 - 9

    poses = []
    steps = [2 * mpmath.pi * k / 720 for k in range(721)]
    for side in (0, 1):
        residual = [pose(alpha, side)[2] for alpha in steps]
        for k in range(720):
            if residual[k] * residual[k + 1] < 0:
                alpha = mpmath.findroot(lambda x: pose(x, side)[2], (steps[k], steps[k + 1]), solver="anderson")
                poses.append(pose(alpha, side)[:2])
    return poses


def _on_the_triad(configuration):
    """Whether the configuration keeps the catalog scene's lengths, to 1e-27."""
    (ax, ay), (bx, by), (cx, cy), (fx, fy) = ([mpmath.mpf(v) for v in configuration.points[p]] for p in "ABCF")
    return all(abs(e) < 1e-27 for e in (ax ** 2 + ay ** 2 - 1, (bx - 4) ** 2 + by ** 2 - mpmath.mpf(49) / 4,
                                        (bx - ax) ** 2 + (by - ay) ** 2 - 9, (cx - fx) ** 2 + (cy - fy) ** 2 - 9))


@pytest.mark.parametrize("theta", [10, 200, 350])
def test_the_triad_at_any_angle_has_the_loop_equations_real_solutions(theta):
    found = solve("stephenson-iii-triad", at={"theta": theta}, digits=30).configurations
    with mpmath.workdps(40):
        poses = _triad_poses(theta)
        assert len(found) == len(poses) > 0
        for configuration in found:
            assert _on_the_triad(configuration)
            a, b = ([mpmath.mpf(v) for v in configuration.points[p]] for p in "AB")
            assert any(_close((*a, *b), (*pa, *pb), 1e-27) for pa, pb in poses)


def test_the_triad_a_ten_thousandth_of_a_degree_before_its_toggle_is_certified():
    """Two modes meet between 32.3086 and 32.3087 degrees, their roots a thousandth apart:
    the balls still tell them apart, and past the toggle that nothing assembles."""
    found = solve("stephenson-iii-triad", at={"theta": "32.3086"}, digits=30).configurations
    with mpmath.workdps(40):
        assert len(found) == 2 and all(_on_the_triad(c) for c in found)
    assert solve("stephenson-iii-triad", at={"theta": "32.3087"}).configurations == ()


def test_a_thousand_digits_are_certified_too():
    """MAX_DIGITS: the enclosures compared in balls (as floats, 10**1001 overflowed)."""
    with mpmath.workdps(1020):
        a = (mpmath.cos(mpmath.pi / 6), mpmath.sin(mpmath.pi / 6))
        left, _ = _circles(a, 3, (4, 0), mpmath.mpf(7) / 2)
        found = solve("fourbar", at={"theta": 30}, digits=MAX_DIGITS, mode="left")
        (configuration,) = found.configurations
        assert _close(configuration.points["B"], left, mpmath.mpf(10) ** -998)
        assert 0 < configuration.radius  # an upper bound, the smallest float where the radius underflows


def test_groups_solved_in_sequence_give_every_configuration_of_both():
    """Q hangs on P: its group's equations hold P's coordinates (irrational balls), solved after
    P's. By hand: P = (2, +-sqrt(5)); Q on the x axis at 3 from P: Q = (2 +- 2, 0), four in all."""
    scene = load_scene_text('''
[points]
A = { fixed = [0, 0] }
B = { fixed = [4, 0] }
P = { unknown = true }
Q = { unknown = true }
[constraints]
a = "dist(A, P) = 3"
b = "dist(B, P) = 3"
c = "dist(P, Q) = 3"
d = "on(Q, line(A, B))"
''', "two.toml")
    found = solve(scene, at={}, digits=40)
    with mpmath.workdps(60):
        points = sorted((tuple(map(mpmath.mpf, c.points["P"])), tuple(map(mpmath.mpf, c.points["Q"])))
                        for c in found.configurations)
        root5 = mpmath.sqrt(5)
        expected = sorted(((2, y), (x, 0)) for y in (-root5, root5) for x in (0, 4))
        assert len(points) == 4 and found.complex_count == 4
        for (p, q), (ep, eq) in zip(points, expected):
            assert _close(p, ep, mpmath.mpf(10) ** -38) and _close(q, eq, mpmath.mpf(10) ** -38)


# Modes named by a configuration (``mode = { at, near }``): solve keeps the configurations on them.

def test_the_hart_inversor_solved_keeps_its_named_crossed_mode():
    """At 290 deg (between D's toggle and the flat configuration, where C's `left` is the
    parallelogram) the kept configurations are the crossed ones: Q on x = -3/2, by hand."""
    found = solve("hart-inversor", at={"angle": 290}, digits=35)
    assert found.named_modes == ("C",) and found.left_out == 2
    assert [c.mode for c in found.configurations] == ["D:left C:right", "D:right C:right"]
    assert all(mpmath.mpf(c.points["Q"][0]) == mpmath.mpf("-1.5") for c in found.configurations)
    document = found.to_json()
    assert document["named_modes"] == ["C"] and document["left_out"] == 2
    assert "named_modes" not in solve("fourbar", at={"theta": 0}).to_json()


def _3rpr_named(near):
    return load_scene_text(SPEC_3RPR.replace('P1 = { unknown = true }',
                                             f'P1 = {{ unknown = true, mode = {{ at = 6, near = {near} }} }}'), "3rpr.toml")


def test_a_3rpr_mode_named_at_one_leg_length_is_kept_at_another():
    # at r1 = 6 the two real modes put P1 near (3.86, 4.60) and (5.89, 1.15) (test above: the loop equations)
    found = solve(_3rpr_named("[3.8, 4.6]"), at={"r1": 7}, digits=40)
    (kept,) = found.configurations
    everything = solve(load_scene_text(SPEC_3RPR, "3rpr.toml"), at={"r1": 7}, digits=40).configurations
    assert found.left_out == 1 and kept in everything
    at_six = solve(load_scene_text(SPEC_3RPR, "3rpr.toml"), at={"r1": 6}, digits=40).configurations
    assert kept.mode == min(at_six, key=lambda c: abs(float(c.points["P1"][0]) - 3.8)).mode


def test_a_3rpr_mode_named_far_from_every_configuration_is_refused_naming_the_nearest():
    with pytest.raises(SceneError, match=r"points\.P1\.mode\.near: \[5, 3\] is not close to a configuration of P1 "
                                         r"at r1 = 6: the nearest is \[3\.85685, 4\.59616\]"):
        solve(_3rpr_named("[5, 3]"), at={"r1": 7})


def test_a_slider_and_a_meet_on_points_solved_together_are_solved_after_them():
    """P = (2, +-sqrt(5)) (circles about A and B); S on the horizontal line through P, 5 from A:
    S = (+-sqrt(20), P_y), `ahead` where S_x > 0 (along (1, 0) past A's foot); M where the lines
    A-P and B-S meet, by Cramer's rule. Four configurations, each by hand."""
    scene = load_scene_text('''
[points]
A = { fixed = [0, 0] }
B = { fixed = [4, 0] }
P = { unknown = true }
S = { slider = { through = "P", direction = [1, 0] }, distance = { to = "A", length = 5 }, branch = "ahead" }
M = { meet = [["A", "P"], ["B", "S"]] }
[constraints]
a = "dist(A, P) = 3"
b = "dist(B, P) = 3"
''', "slider.toml")
    found = solve(scene, at={}, digits=40)
    assert len(found.configurations) == 4
    with mpmath.workdps(60):
        for configuration in found.configurations:
            (px, py), (sx, sy), (mx, my) = ([mpmath.mpf(v) for v in configuration.points[p]] for p in "PSM")
            assert abs(px - 2) < 1e-38 and abs(abs(py) - mpmath.sqrt(5)) < 1e-38 and abs(sy - py) < 1e-38
            assert abs(abs(sx) - mpmath.sqrt(20)) < 1e-38
            assert configuration.mode.split(" ")[1] == ("S:ahead" if sx > 0 else "S:behind")
            # M = k (P - A) = B + l (S - B): two linear equations in k and l
            det = px * -(sy - 0) - py * -(sx - 4)
            k = (4 * -(sy - 0) - 0 * -(sx - 4)) / det
            assert abs(mx - k * px) < 1e-35 and abs(my - k * py) < 1e-35
