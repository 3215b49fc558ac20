"""Rates of points solved together: the implicit function theorem on a group's own equations."""

import flint
import pytest

import algkin
from algkin.analyses.groups.check import check_group_rates
from algkin.analyses.groups.implicit import ImplicitRates
from algkin.analyses.groups.rates import group_rates, implicit_of
from algkin.analyses.groups.scene import prepare_groups
from algkin.verify.groups import BITS


def _rates_at_reference(found):
    """Each mode's configuration and rates (balls) at the reference input."""
    prepared, reference = found.derivation.prepared, found.derivation.reference
    forms = implicit_of(prepared, 0)
    with flint.ctx.workprec(BITS):
        for mode in prepared.modes(reference, bits=BITS)[0]:
            values = dict(mode.values, **reference.balls(BITS))
            yield values, forms.at(values)


def test_3rpr_legs_keep_their_lengths_along_the_motion():
    """Independent of the forms: |P1 - A1| = r1 and |P2 - A2| = 9 along the motion, so
    (P1 - A1).P1' = r1, |P1'|**2 + (P1 - A1).P1'' = 1, (P2 - A2).P2' = 0, |P2'|**2 + (P2 - A2).P2'' = 0."""
    found = group_rates("3rpr", samples=0)
    assert len(found.modes[0]) == 2
    for values, rates in _rates_at_reference(found):
        x1, y1, x2, y2 = (values[u] for u in ("P1_x", "P1_y", "P2_x", "P2_y"))
        (vx1, ax1), (vy1, ay1), (vx2, ax2), (vy2, ay2) = (rates[u] for u in ("P1_x", "P1_y", "P2_x", "P2_y"))
        identities = [x1 * vx1 + y1 * vy1 - values["r1"], vx1**2 + vy1**2 + x1 * ax1 + y1 * ay1 - 1,
                      (x2 - 10) * vx2 + y2 * vy2, vx2**2 + vy2**2 + (x2 - 10) * ax2 + y2 * ay2]
        assert all(abs(float(e.mid())) < 1e-40 for e in identities)


def test_triad_crank_joint_rate_is_an_angle_rate():
    """The triad's A stays on its circle |A| = 1 as theta turns: A.A' = 0 (per radian)."""
    for values, rates in _rates_at_reference(group_rates("stephenson-iii-triad", samples=0)):
        assert abs(float((values["A_x"] * rates["A_x"][0] + values["A_y"] * rates["A_y"][0]).mid())) < 1e-40


@pytest.mark.parametrize("scene", ["3rpr", "stephenson-iii-triad"])
def test_rates_pass_central_differences_and_the_eliminant(scene):
    check = group_rates(scene, samples=3).verification
    assert check.passed and check.compared >= 3 and check.eliminant_compared == check.compared
    assert check.max_rel_error < 1e-15


def test_wrong_forms_are_caught():
    prepared = prepare_groups("3rpr")
    right = implicit_of(prepared, 0)
    wrong = ImplicitRates(right.unknowns, right.variables, right.denominator,
                          {u: 2 * p if u == "P2_y" else p for u, p in right.velocity.items()}, right.acceleration)
    check = check_group_rates(prepared, [wrong], samples=2)
    assert not check.passed and any("velocity of P2_y" in f for f in check.failures)


def test_a_check_that_compared_nothing_fails():
    check = check_group_rates(prepare_groups("3rpr"), [implicit_of(prepare_groups("3rpr"), 0)], samples=0)
    assert (check.passed, check.compared) == (False, 0) and "no mode's rates compared" in check.failures[0]


def test_the_python_api_takes_group_scenes_and_refuses_dyad_options():
    found = algkin.rates("3rpr", samples=2)
    assert found.verification.passed and found.per == "length" and found.input == "r1"
    with pytest.raises(algkin.AlgkinError, match="outputs"):
        algkin.rates("3rpr", outputs=["P1"])
