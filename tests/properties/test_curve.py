"""The implicit curve of the coupler point vanishes on its trajectory, drawn by hand geometry."""

import mpmath
import sympy
import pytest
from hypothesis import given, settings

from algkin.derivation.pipeline import curve
from algkin.testing import strategies

from .hand import trajectory

ANGLES = range(7, 360, 45)


def relative_value(poly, point):
    """|F(point)| over the sum of its terms' sizes: 0 up to the working precision on the curve."""
    total = size = mpmath.mpf(0)
    for (i, j), coef in poly.terms():
        term = mpmath.mpf(int(coef.p)) / int(coef.q) * point[0] ** i * point[1] ** j
        total, size = total + term, size + abs(term)
    return abs(total) / size


@pytest.mark.slow
@settings(max_examples=150)
@given(strategies.scenes())
def test_curve_vanishes_on_the_trajectory(scene):
    result = curve(scene, "P", samples=0)
    x, y = (sympy.Symbol(v, real=True) for v in result.variables)
    poly = sympy.Poly(result.elimination.polynomial, x, y)
    # A four-bar's coupler curve is at most a sextic, a slider-crank's at most a quartic; a point
    # rigid with a slider on the line through L and the crank tip, at most a sextic too (on the
    # line at a fixed distance from a point of it, a conchoid of the crank's circle); an
    # inversor's P a four-bar's coupler point (a kite) or the inverse of the crank's circle (a cell).
    assert poly.total_degree() <= (4 if scene.name == "slider-crank" else 6)
    labels = ("left", "right") if "D" in scene.points else ("ahead", "behind")
    with mpmath.workdps(60):
        checked = _check_at(scene, poly, labels, ANGLES)
        if not checked:  # a four-bar that assembles on a narrow range only: look closer
            checked = _check_at(scene, poly, labels, [k / 4 for k in range(1, 4 * 360)])
    assert checked > 0  # every scene drawn assembles somewhere: a pass compared something


def _check_at(scene, poly, labels, angles):
    """How many hand-drawn positions of P (at ``angles``, on each branch) the curve was checked at."""
    checked = 0
    for degrees in angles:
        for label in labels:
            points = trajectory(scene, degrees, label)
            if points is not None:
                assert relative_value(poly, points["P"]) < mpmath.mpf(10) ** -45, (degrees, label)
                checked += 1
    return checked
