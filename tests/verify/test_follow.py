"""``algkin.verify.follow``: certified continuation against closed forms computed apart, at every sample."""

from fractions import Fraction

import flint
import pytest

from algkin.errors import BudgetExceeded, ComputationError
from algkin.runtime.budget import Budget
from algkin.system import symbol
from algkin.verify.follow import Follower
from tests.clocks import Clock, still

x, y, c, s = (symbol(n) for n in ("x", "y", "c", "s"))


def _near_tangent_circles(gap):
    """The unit circle about O and the unit circle about (2 - gap)(cos t, sin t): two intersections
    2 sqrt(gap) apart at every t, each a mode; ``mode(t, side)`` its closed form (side +1: left of O->centre)."""
    d = 2 - gap
    follower = Follower(["x", "y"], [x**2 + y**2 - 1, (x - d * c)**2 + (y - d * s)**2 - 1], ("c", "s"))

    def mode(t, side):
        radians = flint.arb.pi() * flint.fmpq(t.numerator, t.denominator) / 180
        cos, sin = radians.cos(), radians.sin()
        half = flint.arb(flint.fmpq(d.numerator, d.denominator)) / 2
        height = (1 - half * half).sqrt()
        return half * cos - side * height * sin, half * sin + side * height * cos

    return follower, mode


@pytest.mark.parametrize("side", [1, -1])
def test_two_modes_a_hair_apart_followed_with_a_huge_first_step_never_jump(side):
    follower, mode = _near_tangent_circles(Fraction(1, 10**5))  # the two modes 6e-3 apart, 1e-5 from tangent
    with flint.ctx.workprec(128):
        start = [float(v.mid()) for v in mode(Fraction(0), side)]
    path = follower.follow(start, Fraction(0), Fraction(360), max_step=Fraction(360))
    assert path.meeting is None and path.samples[-1].t == 360
    with flint.ctx.workprec(128):
        for sample in path.samples:
            own, other = mode(sample.t, side), mode(sample.t, -side)
            assert all(sample.values[n].overlaps(v) for n, v in zip("xy", own)), sample.t
            assert not all(sample.values[n].overlaps(v) for n, v in zip("xy", other)), sample.t


def test_a_fold_is_met_reported_with_its_interval_and_a_singular_jacobian_never_crossed():
    """x = sqrt(cos t) meets x = -sqrt(cos t) at 90 degrees, where 2x = 0."""
    path = Follower(["x"], [x**2 - c], ("c", "s")).follow([1.0], Fraction(0), Fraction(180))
    meeting = path.meeting
    assert meeting is not None and meeting.fold and meeting.lo <= 90 <= meeting.hi
    assert meeting.hi - meeting.lo < Fraction(1, 10**6) and meeting.determinant.contains(0)
    assert all(sample.t < 90 for sample in path.samples) and path.steps == len(path.samples) - 1
    with flint.ctx.workprec(128):
        for sample in path.samples:  # the positive root all the way
            radians = flint.arb.pi() * flint.fmpq(sample.t.numerator, sample.t.denominator) / 180
            assert sample.values["x"].overlaps(radians.cos().sqrt())


def test_a_length_input_is_followed_in_its_own_unit():
    """x**2 = t: x = sqrt(t) from t = 4 to 1/4, then down toward the fold at 0."""
    t = symbol("t")
    follower = Follower(["x"], [x**2 - t], ("t",))
    path = follower.follow([2.0], Fraction(4), Fraction(1, 4))
    assert path.meeting is None and path.samples[-1].values["x"].overlaps(flint.arb(1) / 2)
    meeting = follower.follow([2.0], Fraction(4), Fraction(-1)).meeting
    assert meeting is not None and meeting.lo <= 0 <= meeting.hi


def test_a_start_that_is_no_solution_is_refused():
    with pytest.raises(ComputationError, match="not proved"):
        Follower(["x"], [x**2 + 1 + c], ("c", "s")).follow([0.5], Fraction(0), Fraction(10))


def test_the_deadline_is_kept_between_steps():
    follower = Follower(["x"], [x**2 - 2 - c], ("c", "s"))
    with pytest.raises(BudgetExceeded, match="max_seconds=10: stopped after 3600.00 s while following"):
        follower.follow([3**0.5], Fraction(0), Fraction(360), deadline=Budget(seconds=10, clock=Clock()).start())
    kept = follower.follow([3**0.5], Fraction(0), Fraction(360), deadline=Budget(seconds=10, clock=still).start())
    assert kept.meeting is None
