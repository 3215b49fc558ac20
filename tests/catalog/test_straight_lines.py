"""Straight-line linkages in their classical proportions: exact points by hand geometry, the
straightness of the stroke measured with an independent evaluation (law of cosines, mpmath),
and their coupler curves, tricircular sextics like every four-bar coupler curve (Watt's curve
is the classical example: a tricircular sextic)."""

import mpmath
import pytest
import sympy

from .geometry import at_angle, branch, circles, curve_at, exact_at, on_circle, rigid, run, same

R = sympy.Rational


def hoekens(theta):
    """Crank 1 about (0, 0), ground 2, coupler = rocker = 5/2, B right of A -> D, P = A + 2(B - A)."""
    a = on_circle((0, 0), 1, theta)
    b = circles(a, mpmath.mpf(5) / 2, (2, 0), mpmath.mpf(5) / 2, -1)
    return rigid(a, b, 2, 0)


def chebyshev(theta):
    """Rocker 5 about (0, 0), ground 4, coupler 2, other rocker 5 crossed; P the coupler's midpoint."""
    a = on_circle((0, 0), 5, theta)
    b = circles(a, 2, (4, 0), 5, -1)
    return rigid(a, b, mpmath.mpf(1) / 2, 0)


def watt(phi):
    """Arms 2 about (-2, 1/2) and (2, -1/2), coupler 1, P its midpoint."""
    a = on_circle((-2, mpmath.mpf(1) / 2), 2, phi)
    b = circles(a, 1, (2, -mpmath.mpf(1) / 2), 2, -1)
    return rigid(a, b, mpmath.mpf(1) / 2, 0)


CASES = {
    # scene: (hand function, input name, stroke angles, axis held, value held, largest deviation)
    "hoekens-straight-line": (hoekens, "theta", range(90, 271, 15), 1, -4, 0.0095),
    "chebyshev-straight-line": (chebyshev, "theta", range(40, 91, 5), 1, 4, 0.0099),
    "watt-straight-line": (watt, "phi", range(-10, 11, 2), 0, 0, 0.0002),
}


@pytest.fixture(scope="module", params=sorted(CASES))
def case(request):
    return request.param, run("derive", request.param, "--samples", "12")


def test_closed_form_is_the_hand_geometry_and_the_stroke_is_straight(case):
    name, document = case
    hand, input_name, stroke, axis, held, deviation = CASES[name]
    assert document["verification"]["passed"]
    chosen = next(b for b in document["branches"] if b["selected"])["values"]
    with mpmath.workdps(40):
        worst = 0
        for angle in stroke:
            p = hand(angle)
            for k, coordinate in enumerate(("P_x", "P_y")):
                assert abs(at_angle(chosen[coordinate], angle, input_name) - p[k]) < 1e-30
            worst = max(worst, abs(p[axis] - held))
    assert worst < deviation
    # ... while the stroke itself is long: the other coordinate sweeps over more than 1.
    ends = [hand(stroke[0])[1 - axis], hand(stroke[-1])[1 - axis]]
    assert abs(ends[1] - ends[0]) > 0.69


def test_hoekens_passes_exactly_through_three_points():
    # theta = 180: A = (-1, 0), |AD| = 3, B = (1/2, -2) (isosceles, height sqrt(25/4 - 9/4) = 2).
    # theta = 90: A = (0, 1), |AD| = sqrt(5), B = (1, 1/2) + (-1, -2) = (0, -3/2).
    # theta = 270: A = (0, -1), |AD| = sqrt(5), B = (1, -1/2) + (1, -2) = (2, -5/2), P = (4, -4).
    values = branch(run("derive", "hoekens-straight-line", "--samples", "0"), "right")["values"]
    for (c, s), point in (((-1, 0), (2, -4)), ((0, 1), (0, -4)), ((0, -1), (4, -4))):
        assert same(exact_at(values["P_x"], c, s), point[0]) and same(exact_at(values["P_y"], c, s), point[1])


def test_chebyshev_passes_exactly_through_three_points():
    # A = (3, 4): B = (1, 4), P = (2, 4).  A = (0, 5): B = (0, 3), P = (0, 4).
    # A = (4, 3): |AD| = 3 = 5 - 2, a dead centre: B = (4, 5) on the line DA, P = (4, 4).
    values = branch(run("derive", "chebyshev-straight-line", "--samples", "0"), "right")["values"]
    for (c, s), point in (((R(3, 5), R(4, 5)), (2, 4)), ((0, 1), (0, 4)), ((R(4, 5), R(3, 5)), (4, 4))):
        assert same(exact_at(values["P_x"], c, s), point[0]) and same(exact_at(values["P_y"], c, s), point[1])


def test_watt_middle_position():
    # phi = 0: both arms horizontal, the coupler from A = (0, 1/2) to B = (0, -1/2): P = (0, 0).
    values = branch(run("derive", "watt-straight-line", "--samples", "0"), "right")["values"]
    assert exact_at(values["P_x"], 1, 0, "phi") == 0 and exact_at(values["P_y"], 1, 0, "phi") == 0


@pytest.mark.parametrize("name", sorted(CASES))
def test_coupler_curve_is_a_tricircular_sextic_through_the_hand_points(name):
    document = run("curve", name, "--point", "P", "--samples", "8")
    assert (document["degree"], document["circularity"]) == (6, 3)
    assert document["verification"]["passed"]
    hand, _, stroke, *_ = CASES[name]
    with mpmath.workdps(40):
        for angle in stroke:
            assert abs(curve_at(document, hand(angle))) < 1e-30
