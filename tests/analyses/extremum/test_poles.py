"""An output whose closed form has a pole in the range is unbounded there; a 0/0 point is read by its limit.

The instant centre of ``fourbar-instant-centre`` (crank 1 about O = (0, 0), ground 4, coupler 3,
rocker 7/2 about D = (4, 0), B left of A -> D) is where the lines OA and DB meet. They turn parallel
where DB = mu (cos, sin) with mu = +-7/2; then |B - A| = 3 gives, by hand,
``16 + 8 (mu - 1) cos + (mu - 1)**2 = 9``: cos = -53/80 (mu = 7/2: at +-131.49 deg) and
cos = 109/144 (mu = -7/2: at +-40.80 deg). On the left branch the lines are parallel at
acos(-53/80) and 360 - acos(109/144) deg (the other two are the right branch's); the centre runs
off to infinity there, on each side towards an opposite end of the line.
"""

import json
import math

import mpmath
import pytest
import sympy

from algkin.analyses.extremum import extremum
from algkin.analyses.extremum.critical import Problem, critical_points, extreme, pole_factors
from algkin.errors import UsageError
from algkin.system import symbol
from algkin.system.angles import Parametrisation
from algkin.ui.cli import main

POLES = (math.degrees(math.acos(-53 / 80)), 360 - math.degrees(math.acos(109 / 144)))
C, S, T, U = (symbol(n) for n in ("c", "s", "t", "u"))
LINE = Parametrisation((C, S), T)


def _instant_centre(degrees: float) -> tuple[float, float]:
    """I from the scene's geometry alone (floats): the dyad B left of A -> D, then OA meet DB."""
    theta = math.radians(degrees)
    ax, ay = math.cos(theta), math.sin(theta)
    ex, ey = 4 - ax, -ay
    dist = math.hypot(ex, ey)
    along = (9 - 49 / 4 + dist**2) / (2 * dist)
    height = math.sqrt(9 - along**2)
    bx, by = ax + (along * ex - height * ey) / dist, ay + (along * ey + height * ex) / dist
    # s A = D + r (B - D): Cramer's rule for s
    det = -(ax * by - ay * (bx - 4))
    s = (4 * -by) / det
    return s * ax, s * ay


def _runs_off(degrees: float, side: int, axis: int) -> float:
    """The sign of I's coordinate just beside a pole (1e-7 deg), where it is some 1e8 long."""
    value = _instant_centre(degrees + side * 1e-7)[axis]
    assert abs(value) > 1e6
    return math.copysign(math.inf, value)


@pytest.mark.parametrize("axis", [0, 1])
def test_the_instant_centre_is_unbounded_where_crank_and_rocker_turn_parallel(axis):
    """It reported minimum = maximum = 4 at the range's ends (I.x; 0 for I.y): no point where
    the closed form's denominator vanishes was looked at."""
    found = extremum("fourbar-instant-centre", f"I.{'xy'[axis]}")
    poles = [p for p in found.critical_points if p.kind == "pole"]
    assert [(round(float(p.input_deg), 9), p.side) for p in poles] == \
        [(round(degrees, 9), side) for degrees in POLES for side in (-1, 1)]
    for p in poles:
        assert float(p.input_deg) == pytest.approx(POLES[0] if p.input_deg < 200 else POLES[1], abs=1e-12)
        assert p.value == _runs_off(float(p.input_deg), p.side, axis)
    assert (found.minimum.value, found.maximum.value) == (-math.inf, math.inf)
    assert {found.minimum.kind, found.maximum.kind} == {"pole"}
    assert float(found.minimum.input_deg) == pytest.approx(POLES[0], abs=1e-12)
    ends = [p for p in found.critical_points if p.kind == "endpoint"]
    assert [float(p.value) for p in ends] == pytest.approx([_instant_centre(0)[axis], _instant_centre(360)[axis]],
                                                          abs=1e-12)


def test_an_unbounded_output_says_so_in_its_json_and_text(capsys):
    assert main(["extremum", "fourbar-instant-centre", "--of", "I.x", "--json"]) == 0
    document = json.loads(capsys.readouterr().out)
    minimum, maximum = document["minimum"], document["maximum"]
    assert (minimum["value"], minimum["limit"], minimum["kind"], minimum["side"]) == (None, "-inf", "pole", "below")
    assert (maximum["value"], maximum["limit"], maximum["side"]) == (None, "+inf", "above")
    assert minimum["input_deg"] == pytest.approx(POLES[0], abs=1e-12)
    assert len([p for p in document["critical_points"] if p["kind"] == "pole"]) == 4
    assert main(["extremum", "fourbar-instant-centre", "--of", "I.x"]) == 0
    text = capsys.readouterr().out
    assert f"minimum: -inf: unbounded near theta = {POLES[0]:.12g} deg" in text
    assert f"maximum: +inf: unbounded near theta = {POLES[0]:.12g} deg" in text


def test_a_closed_form_of_an_unbounded_minimum_is_refused():
    """With --param it gave the closed form 4 (the range end's), valid for a small a."""
    with pytest.raises(UsageError, match="unbounded near 131.49"):
        extremum("fourbar-instant-centre", "I.x", params=["a"])


def test_range_ends_on_dead_centres_have_their_values():
    """Peaucellier's P runs on the line x = (L^2 - s^2) / (2 r) = 5/2 along the ray OA, A on the
    circle of radius 1 about (1, 0): at the range's ends, +-120 deg, the arms reach no further,
    and OA points at +-60 deg (the angle at the circle's rim is half the one at its centre), so
    P.y = 5/2 tan(+-60 deg) = +-5 sqrt(3) / 2. The ends read nan (the closed form's root of a
    rounding below zero)."""
    found = extremum("peaucellier-lipkin", "P.y")
    ends = [p for p in found.critical_points if p.kind == "endpoint"]
    assert [float(p.input_deg) for p in ends] == [-120, 120]
    assert [float(p.value) for p in ends] == pytest.approx([-5 * math.sqrt(3) / 2, 5 * math.sqrt(3) / 2], abs=1e-12)
    assert found.minimum.kind == "dead centre"  # the tie goes to the point found inside


# u c**2 - 2 u + s = 0 (by hand): u = (1 -+ sqrt(1 - c s)) / c; the "-" root is s / (1 + sqrt(1 - c s)),
# bounded (s/2 at c = 0: 1/2 at 90 deg), the "+" root 2/c and more: +inf as theta rises to 90 deg.
def _problem(sign: int) -> Problem:
    return Problem(C * U**2 - 2 * U + S, (1 + sign * sympy.sqrt(1 - C * S)) / C, U, LINE, ())


def test_a_pole_of_a_root_is_unbounded_with_the_sign_of_each_side():
    points = critical_points(_problem(1), None, 0, 180)
    poles = [(float(p.input_deg), p.side, p.value) for p in points if p.kind == "pole"]
    assert poles == [(90.0, -1, math.inf), (90.0, 1, -math.inf)]
    assert (extreme(points).value, extreme(points, True).value) == (-math.inf, math.inf)
    (lowest,) = [p for p in points if p.kind == "minimum"]  # from 2 at 0 deg it falls, then rises to the pole

    def plus(degrees):
        c, s = mpmath.cos(mpmath.radians(degrees)), mpmath.sin(mpmath.radians(degrees))
        return (1 + mpmath.sqrt(1 - c * s)) / c

    with mpmath.workdps(30):
        where = mpmath.findroot(lambda x: mpmath.diff(plus, x), 10)  # its slope's zero, by mpmath
        assert float(lowest.input_deg) == pytest.approx(float(where), abs=1e-12)
        assert float(lowest.value) == pytest.approx(float(plus(where)), abs=1e-12)


def test_a_range_end_on_a_removable_zero_over_zero_has_the_limit():
    """At 90 deg the "-" root's closed form is 0/0 to rounding: the end read 0.0 (the cancellation's)."""
    points = critical_points(_problem(-1), None, 0, 90)
    assert [float(p.value) for p in points if p.kind == "endpoint"] == pytest.approx([0, 0.5], abs=1e-15)
    assert not any(p.kind == "pole" for p in points)
    up_to = critical_points(_problem(1), None, 0, 90)  # the "+" root there runs off
    assert [p.value for p in up_to if p.kind == "endpoint"][1] == math.inf


def test_a_stationary_point_at_a_removable_zero_over_zero_is_read_by_its_limit():
    """u c**2 - 2 u + s - c/4 = 0: its "-" root k / (1 + sqrt(1 - c k)), k = s - c/4, is k/2 + c k**2/8 + ...
    near c = 0, of slope k'/2 - k**2/8 = 1/8 - 1/8 = 0 at 90 deg, where its value is 1/2. Over
    [60, 120] that is the greatest value (the rationalised form sampled in mpmath); it read
    0.49999... there, a "minimum" (the 0/0 of its closed form's cancellation)."""
    problem = Problem(C * U**2 - 2 * U + S - C / 4, (1 - sympy.sqrt(1 - C * (S - C / 4))) / C, U, LINE, ())
    points = critical_points(problem, None, 60, 120)
    best = extreme(points, True)
    assert (float(best.input_deg), best.kind) == (90.0, "maximum")
    assert float(best.value) == pytest.approx(0.5, abs=1e-15)

    def rationalised(degrees):
        c, s = mpmath.cos(mpmath.radians(degrees)), mpmath.sin(mpmath.radians(degrees))
        k = s - c / 4
        return k / (1 + mpmath.sqrt(1 - c * k))

    with mpmath.workdps(30):
        assert max(rationalised(60 + mpmath.mpf(k) / 100) for k in range(6001)) == pytest.approx(0.5, abs=1e-20)


def test_a_leading_coefficient_that_is_a_number_has_no_poles():
    """A length input's ``B_x - x`` (piston-driven-crank's B.x): the coefficient of ``u`` is 1, nowhere
    zero (it was taken as a Python int, and the extremum failed on it)."""
    x = symbol("x")
    assert pole_factors(Problem(U - x, x, U, Parametrisation((x,), x), ())) == []
    assert pole_factors(Problem(x * U**2 - 1, 1 / sympy.sqrt(x), U, Parametrisation((x,), x), ())) == [x]
