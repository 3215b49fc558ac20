"""Extremes with dimensions given as ratios of 60-digit integers: the eliminant's factors tie but for
coefficients past a C int, where python-flint's ordering of them raised OverflowError."""

import mpmath
import pytest

from algkin.analyses.extremum import extremum

LONG = {"a": "509013598462587325135932320512135369791864271307440306429157/285009859192899578072793428742627415432465723795988388503791",
        "d": "406298730593612486073734275336960771685092202861481392138851/137509156817722511096475346274696397237877406543388156034215",
        "l": "975195360980233337640429877734724384353499663979132425121004/734179984022869560717829902294578648582357489552626443869607"}


def _intersections_y(theta):
    """The y of the two points B at distance l from A = a(cos, sin)(theta) and m = 7/2 from D = (d, 0)."""
    a, d, l = (mpmath.mpf(mpmath.fraction(*map(int, LONG[k].split("/")))) for k in "adl")
    m = mpmath.mpf(7) / 2
    ax, ay = a * mpmath.cos(theta), a * mpmath.sin(theta)
    dx, dy = d - ax, -ay
    dist = mpmath.hypot(dx, dy)
    along = (dist**2 + l**2 - m**2) / (2 * dist)
    across = mpmath.sqrt(l**2 - along**2)
    return [ay + (along * dy + sign * across * dx) / dist for sign in (1, -1)]


def test_the_extremes_with_dimensions_of_sixty_digits_are_stationary_points_of_the_geometry():
    found = extremum("fourbar", "B.y", set=LONG)
    stationary = [p for p in found.to_json()["critical_points"] if p["kind"] in ("maximum", "minimum")]
    assert stationary
    with mpmath.workdps(50):
        for point in stationary:
            theta = mpmath.radians(point["input_deg"])
            ys = _intersections_y(theta)
            k = min(range(2), key=lambda j: abs(ys[j] - point["value"]))
            assert float(ys[k]) == pytest.approx(point["value"], abs=1e-9)
            assert abs(mpmath.diff(lambda x: _intersections_y(x)[k], theta)) < 1e-9
