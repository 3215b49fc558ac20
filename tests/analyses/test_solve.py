"""``algkin.analyses.solve``: every configuration at an input, against hand geometry in mpmath."""

from fractions import Fraction

import mpmath
import pytest

from algkin.analyses.solve import MAX_DIGITS, solve
from algkin.errors import UsageError


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
            assert all(len(v.lstrip("-").replace(".", "").lstrip("0")) == 30 for v in configuration.points["B"])


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
    ({"theta": 30}, {"digits": 0}, "digits"),
    ({"theta": 30}, {"digits": MAX_DIGITS + 1}, "digits"),
    ({"theta": 30}, {"mode": "up"}, "mode"),
])
def test_bad_arguments_name_the_argument(at, options, argument):
    with pytest.raises(UsageError) as caught:
        solve("fourbar", at=at, **options)
    assert caught.value.argument == argument


def test_the_facade_has_it():
    import algkin

    found = algkin.solve("fourbar", at={"theta": 0}, digits=5)
    assert isinstance(found, algkin.Solution) and len(found.configurations) == 2
