"""A four-bar's check and defects, on positions computed here by hand (circle intersections in mpmath)."""

import flint
import mpmath
import pytest

from algkin.synthesis.check import check_design
from algkin.synthesis.fourbar import FourBar, Position

DIGITS = 60  # scoped (mpmath.workdps): another test may have set mpmath's global precision


def _position(theta: float, *, crank: float, coupler: float, rocker: float, ground: float, left: bool) -> Position:
    """The crank tip at theta degrees about (0, 0); B where the circles about A (coupler) and
    D = (ground, 0) (rocker) meet, left of the line from A to D when ``left``."""
    with mpmath.workdps(DIGITS):
        return _position_at(mpmath.radians(mpmath.mpf(theta)), crank=crank, coupler=coupler, rocker=rocker,
                            ground=ground, left=left)


def _position_at(t, *, crank, coupler, rocker, ground, left):
    ax, ay = crank * mpmath.cos(t), crank * mpmath.sin(t)
    dx, dy = ground - ax, -ay
    dist = mpmath.sqrt(dx**2 + dy**2)
    along = (coupler**2 - rocker**2 + dist**2) / (2 * dist)
    across = mpmath.sqrt(coupler**2 - along**2) * (1 if left else -1)
    bx = ax + (along * dx - across * dy) / dist
    by = ay + (along * dy + across * dx) / dist
    with flint.ctx.workprec(200):
        ball = lambda v: flint.arb(mpmath.nstr(v, 55))  # noqa: E731
        return Position((ball(ax), ball(ay)), (ball(bx), ball(by)))


def _design(thetas, lefts, *, crank=1, coupler=3, rocker=mpmath.mpf(7) / 2, ground=4):
    positions = tuple(_position(t, crank=crank, coupler=coupler, rocker=rocker, ground=ground, left=left)
                      for t, left in zip(thetas, lefts))
    return FourBar("hand", crank_pivot=(flint.arb(0), flint.arb(0)), rocker_pivot=(flint.arb(ground), flint.arb(0)),
                   positions=positions)


def _transmission_by_sampling(thetas, *, crank=1, coupler=3, rocker=mpmath.mpf(7) / 2, ground=4):
    """The angle at B between A and D, sampled every 0.01 degree between the first and last theta."""
    with mpmath.workdps(DIGITS):
        return _sampled(thetas, crank=crank, coupler=coupler, rocker=rocker, ground=ground)


def _sampled(thetas, *, crank, coupler, rocker, ground):
    values = []
    for k in range(int((thetas[-1] - thetas[0]) * 100) + 1):
        t = mpmath.radians(thetas[0] + mpmath.mpf(k) / 100)
        ad2 = crank**2 + ground**2 - 2 * crank * ground * mpmath.cos(t)
        values.append(mpmath.degrees(mpmath.acos((coupler**2 + rocker**2 - ad2) / (2 * coupler * rocker))))
    return float(min(values)), float(max(values))


def test_a_crank_rocker_through_five_positions_in_order_is_usable():
    thetas = [10, 60, 120, 200, 300]
    checked = check_design(_design(thetas, [True] * 5))
    assert checked.reached and checked.deviation < 1e-35
    assert checked.modes == ("left",) * 5 and checked.direction == 1
    assert checked.grashof == "crank-rocker" and checked.defects == () and checked.usable
    low, high = _transmission_by_sampling(thetas)
    assert checked.transmission_range == pytest.approx((low, high), abs=1e-6)


def test_positions_out_of_order_are_an_order_defect():
    checked = check_design(_design([10, 120, 60, 200, 300], [True] * 5))
    assert [kind for kind, _ in checked.defects] == ["order"] and not checked.usable


def test_a_crank_rocker_with_positions_on_both_modes_has_a_circuit_defect():
    checked = check_design(_design([10, 60, 120], [True, True, False]))
    assert checked.modes == ("left", "left", "right")
    assert [kind for kind, _ in checked.defects] == ["circuit"]


def test_a_triple_rocker_crossing_its_dead_centre_has_a_branch_defect():
    # crank 2, coupler 3, rocker 7/2, ground 5: dead centres where |AD| = 13/2, cos(theta) = -53/80 (131.49 deg)
    sizes = dict(crank=2, coupler=3, rocker=mpmath.mpf(7) / 2, ground=5)
    checked = check_design(_design([120, 125, -120], [True] * 3, **sizes))
    assert checked.grashof == "non-grashof (triple rocker)" and checked.direction == 1
    (kind, why), = checked.defects
    dead_centre = float(mpmath.degrees(mpmath.acos(mpmath.mpf(-53) / 80)))
    assert kind == "branch" and f"{dead_centre:.6g} degrees" in why


def test_a_transmission_angle_below_the_bound_is_a_defect():
    checked = check_design(_design([10, 60, 120, 200, 300], [True] * 5), min_transmission=60)
    (kind, why), = checked.defects
    assert kind == "transmission" and "60" in why


def test_a_position_the_scene_cannot_reach_is_not_reached():
    design = _design([10, 60, 120], [True] * 3)
    with flint.ctx.workprec(200):
        shifted = design.positions[2].rocker_tip[0] + flint.arb("1e-10")
    moved = Position(design.positions[2].crank_tip, (shifted,
                                                     design.positions[2].rocker_tip[1]))
    checked = check_design(FourBar("moved", crank_pivot=design.crank_pivot, rocker_pivot=design.rocker_pivot,
                                   positions=design.positions[:2] + (moved,)))
    assert not checked.reached and 1e-11 < checked.deviation < 1e-9 and not checked.usable
