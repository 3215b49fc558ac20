"""Limit positions and time ratios against hand geometry (the law of cosines, mpmath at 50 digits).

Nothing here calls algkin to get an expected value: the rocker's limit positions come from the
triangle O B D with |OB| = l + a (crank and coupler extended in line) or l - a (folded), the
slider's from |OB| = l +- r with B on its line, and a six-bar's from the zero of its rocker's
angular velocity found by mpmath on hand-solved circle intersections.
"""

from fractions import Fraction

import flint
import mpmath
import pytest
import sympy
from hypothesis import assume, given, settings, strategies as st

from algkin.analyses.limits import limits
from algkin.scene import load_scene

from .test_toggles import four_bar

TOLERANCE = mpmath.mpf(10) ** -30


@pytest.fixture(autouse=True)
def fifty_digits():
    """mpmath at 50 digits within each test here, and its precision as it was after (it is global)."""
    with mpmath.workdps(50):
        yield


def exact(text):
    """An exact form from the JSON (sympy syntax), at 50 digits."""
    return mpmath.mpf(str(sympy.N(sympy.sympify(text), 50)))


def contains(ball, value):
    return ball.overlaps(flint.arb(mpmath.nstr(value, 45)))


def law_of_cosines(a, d, l, m):
    """A four-bar's rocker limits by hand: O = (0, 0), D = (d, 0), crank a, coupler l, rocker m.

    Returns, for B above the ground line, {kind: (crank angle, rocker angle about D, B)} in
    degrees: extended where |OB| = l + a (A on OB), folded where |OB| = l - a (A opposite).
    """
    found = {}
    for kind, reach in (("extended", l + a), ("folded", l - a)):
        cosine = (d**2 + reach**2 - m**2) / (2 * d * reach)
        if not -1 < cosine < 1:
            continue
        phi = mpmath.acos(cosine)  # the angle of B about O, in the triangle O B D
        b = (reach * mpmath.cos(phi), reach * mpmath.sin(phi))
        crank = phi if kind == "extended" else phi + mpmath.pi
        found[kind] = (mpmath.degrees(crank), mpmath.degrees(mpmath.atan2(b[1], b[0] - d)), b)
    return found


def is_left(a, d, crank_deg, b):
    """B left of the directed line A -> D: the dyad's 'left' label, by hand."""
    theta = mpmath.radians(crank_deg)
    ax, ay = a * mpmath.cos(theta), a * mpmath.sin(theta)
    return (d - ax) * (b[1] - ay) - (0 - ay) * (b[0] - ax) > 0


def time_ratio(first_deg, second_deg):
    """Working over return stroke: the larger crank angle between the limits over the smaller."""
    span = (second_deg - first_deg) % 360
    return max(span, 360 - span) / min(span, 360 - span)


FOURBAR = {"a": 1, "d": 4, "l": 3, "m": Fraction(7, 2)}


def test_catalog_fourbar_limits_match_the_law_of_cosines():
    scene = load_scene("fourbar")
    assert {k: Fraction(str(scene.parameters[k])) for k in FOURBAR} == FOURBAR  # the defaults this test uses
    a, d, l, m = (mpmath.mpf(Fraction(v).numerator) / Fraction(v).denominator for v in FOURBAR.values())
    hand = law_of_cosines(a, d, l, m)
    assert set(hand) == {"extended", "folded"}
    assert all(is_left(a, d, crank, b) for crank, _, b in hand.values())  # above the ground: branch left

    found = limits("fourbar")
    on_left = {g.kind: g for g in found.limits if g.branch == "left"}
    on_right = {g.kind: g for g in found.limits if g.branch == "right"}
    assert len(found.limits) == 4 and set(on_left) == set(on_right) == {"extended", "folded"}
    for kind, (crank, rocker, b) in hand.items():
        for limit, sign in ((on_left[kind], 1), (on_right[kind], -1)):  # right: the mirror image
            expected = (sign * crank) % 360
            assert abs(exact(limit.exact_deg) - expected) < TOLERANCE
            assert contains(limit.enclosure, expected) and limit.enclosure.rad() < 1e-30
            assert abs(mpmath.mpf(limit.input_deg) - expected) < 1e-12
            assert abs(exact(limit.position["exact"]["angle_deg"]) - sign * rocker) < TOLERANCE
            assert abs(exact(limit.position["exact"]["x"]) - b[0]) < TOLERANCE
            assert abs(exact(limit.position["exact"]["y"]) - sign * b[1]) < TOLERANCE
            assert limit.position["about"] == "D" and limit.point == "B"
    assert all(g.selected == (g.branch == "left") for g in found.limits)

    ratio = found.time_ratio
    expected = time_ratio(hand["extended"][0], hand["folded"][0])
    assert ratio is not None and ratio.point == "B" and ratio.branch == "left"
    assert abs(exact(ratio.exact) - expected) < TOLERANCE and contains(ratio.enclosure, expected)
    alpha = max((hand["folded"][0] - hand["extended"][0]) % 360, (hand["extended"][0] - hand["folded"][0]) % 360) - 180
    assert abs(mpmath.mpf(ratio.alpha_deg) - alpha) < 1e-12
    assert abs(exact(ratio.exact) - (180 + alpha) / (180 - alpha)) < TOLERANCE
    working, quick = ratio.strokes
    assert abs(exact(working["exact"]) - (180 + alpha)) < TOLERANCE
    assert abs(exact(quick["exact"]) - (180 - alpha)) < TOLERANCE
    swing = abs(hand["extended"][1] - hand["folded"][1])
    assert ratio.stroke["kind"] == "swing" and abs(exact(ratio.stroke["exact"]) - swing) < TOLERANCE


def test_offset_slider_crank_stroke_and_time_ratio_by_hand():
    scene = load_scene("slider-crank")
    r, l, e = (mpmath.mpf(Fraction(str(scene.parameters[k])).numerator) / Fraction(str(scene.parameters[k])).denominator
               for k in ("r", "l", "e"))
    assert (r, l, e) == (1, 3, mpmath.mpf(1) / 2)
    # B on y = e at |OB| = l + r (A on OB) and |OB| = l - r (A opposite), ahead of A along +x
    far, near = mpmath.sqrt((l + r) ** 2 - e**2), mpmath.sqrt((l - r) ** 2 - e**2)
    extended = mpmath.degrees(mpmath.atan2(e, far))
    folded = mpmath.degrees(mpmath.atan2(e, near)) + 180
    alpha = mpmath.degrees(mpmath.asin(e / (l - r)) - mpmath.asin(e / (l + r)))  # the textbook quick-return angle
    stroke = far - near

    found = limits("slider-crank")
    mine = {g.kind: g for g in found.limits if g.selected}
    assert set(mine) == {"extended", "folded"} and all(g.branch == "ahead" for g in mine.values())
    for kind, expected, place in (("extended", extended, far), ("folded", folded, near)):
        assert abs(exact(mine[kind].exact_deg) - expected) < TOLERANCE
        assert contains(mine[kind].enclosure, expected)
        assert abs(exact(mine[kind].position["exact"]["along"]) - place) < TOLERANCE
    ratio = found.time_ratio
    assert ratio is not None
    assert abs(exact(ratio.exact) - (180 + alpha) / (180 - alpha)) < TOLERANCE
    assert abs(exact(ratio.exact) - time_ratio(extended, folded)) < TOLERANCE
    assert abs(mpmath.mpf(ratio.alpha_deg) - alpha) < 1e-12
    assert ratio.stroke["kind"] == "travel" and abs(exact(ratio.stroke["exact"]) - stroke) < TOLERANCE
    assert abs(mpmath.mpf(ratio.stroke["length"]) - stroke) < 1e-14
    # the other branch, behind, is the mirror image in the y axis
    behind = sorted(g.input_deg for g in found.limits if g.branch == "behind")
    assert behind == pytest.approx(sorted([float(180 - extended), float(540 - folded)]), abs=1e-12)


def test_triple_rocker_has_limits_but_no_time_ratio():
    found = limits("fourbar-nongrashof")  # crank 2, ground 5, coupler 3, rocker 7/2
    hand = law_of_cosines(mpmath.mpf(2), mpmath.mpf(5), mpmath.mpf(3), mpmath.mpf(7) / 2)
    assert set(hand) == {"extended"}  # |OB| = l - a = 1 cannot reach the rocker's circle: 5 - 7/2 > 1
    crank = hand["extended"][0]
    assert sorted((g.branch, g.kind) for g in found.limits) == [("left", "extended"), ("right", "extended")]
    for limit in found.limits:
        expected = crank if limit.branch == "left" else -crank
        assert abs(exact(limit.exact_deg) - expected) < TOLERANCE
    assert found.time_ratio is None
    assert "does not turn fully" in found.time_ratio_reason and "dead centres" in found.time_ratio_reason


def test_a_rocker_that_turns_fully_has_no_limit_and_no_time_ratio():
    found = limits(four_bar(3, 1, "7/2", "5/2"))  # ground shortest: a double crank
    assert found.limits == ()
    assert found.time_ratio is None and "turns without stopping" in found.time_ratio_reason


def test_a_range_short_of_a_turn_has_no_time_ratio():
    found = limits("chebyshev-straight-line")  # theta in [30, 110]
    assert found.time_ratio is None and "less than a full turn" in found.time_ratio_reason
    assert all(30 <= g.input_deg <= 110 for g in found.limits)


def test_a_point_on_two_moving_points_is_skipped_with_why():
    found = limits("watt-i")  # F hangs on E and C, both moving
    assert found.skipped == ({"point": "F", "why": "its path is not fixed: both its equations involve moving points"},)
    assert {g.point for g in found.limits} == {"B"}


def rocker_angle(theta, branch_b, branch_f):
    """Stephenson III by hand: B on circles about A(theta) and D, C on AB, F on circles about C and E;
    the angle of F about E, in radians. Branch: +1 left of the directed base line, -1 right."""
    def meet(p, q, r1, r2, sign):
        dx, dy = q[0] - p[0], q[1] - p[1]
        dist2 = dx**2 + dy**2
        along = (r1**2 - r2**2 + dist2) / (2 * dist2)
        across = sign * mpmath.sqrt(r1**2 - along**2 * dist2) / mpmath.sqrt(dist2)
        return (p[0] + along * dx - across * dy, p[1] + along * dy + across * dx)

    a = (mpmath.cos(theta), mpmath.sin(theta))
    b = meet(a, (4, 0), 3, mpmath.mpf(7) / 2, branch_b)
    c = (a[0] + (b[0] - a[0]) / 2 - (b[1] - a[1]) / 2, a[1] + (b[1] - a[1]) / 2 + (b[0] - a[0]) / 2)
    f = meet(c, (-1, 5), 3, 2, branch_f)
    return mpmath.atan2(f[1] - 5, f[0] + 1)


def test_six_bar_rocker_limits_are_where_its_angular_velocity_vanishes():
    # F of Stephenson III hangs on the coupler point C and the ground pivot E: no crank and
    # coupler to line up, so its limits are "stationary", found through the implicit function theorem.
    found = limits("stephenson-iii")
    mine = [g for g in found.limits if g.point == "F" and g.selected]
    assert [g.kind for g in mine] == ["stationary", "stationary"] and mine[0].branch == "B:left F:left"
    for limit in mine:
        speed = lambda deg: mpmath.diff(lambda x: rocker_angle(mpmath.radians(x), 1, 1), deg)  # noqa: E731
        root = mpmath.findroot(speed, mpmath.mpf(limit.input_deg))
        assert abs(root - mpmath.mpf(limit.input_deg)) < 1e-9 and contains(limit.enclosure, root)
        assert speed(root - mpmath.mpf("0.01")) * speed(root + mpmath.mpf("0.01")) < 0  # it turns back
    ratio = found.time_ratio
    assert ratio is not None and ratio.point == "F"
    assert ratio.ratio == pytest.approx(float(time_ratio(mine[0].input_deg, mine[1].input_deg)), rel=1e-12)


lengths = st.fractions(min_value=Fraction(1, 2), max_value=8, max_denominator=12)


@pytest.mark.slow  # one of the largest property runs (10-25 s): the slow set, which CI runs
@settings(max_examples=12, deadline=None)
@given(st.lists(lengths, min_size=4, max_size=4, unique=True), st.permutations([0, 1, 2]))
def test_random_crank_rockers_match_the_law_of_cosines(drawn, order):
    bars = sorted(drawn)
    assume(bars[0] + bars[3] < bars[1] + bars[2])  # Grashof, the crank shortest: a crank-rocker
    crank = bars[0]
    ground, coupler, rocker = (bars[1 + i] for i in order)
    a, d, l, m = (mpmath.mpf(v.numerator) / v.denominator for v in (crank, ground, coupler, rocker))
    hand = law_of_cosines(a, d, l, m)
    assume(set(hand) == {"extended", "folded"})
    assume(all(min(abs(mpmath.sin(mpmath.radians(v[0]))), abs(mpmath.sin(mpmath.radians(v[1])))) > 1e-6
               for v in hand.values()))
    found = limits(four_bar(crank, ground, coupler, rocker))
    left = all(is_left(a, d, crank_deg, b) for crank_deg, _, b in hand.values())
    mine = {g.kind: g for g in found.limits if g.branch == ("left" if left else "right")}
    for kind, (crank_deg, _, _) in hand.items():
        assert abs(exact(mine[kind].exact_deg) % 360 - crank_deg % 360) < TOLERANCE
    assert found.time_ratio is not None
    assert abs(exact(found.time_ratio.exact) - time_ratio(hand["extended"][0], hand["folded"][0])) < TOLERANCE
