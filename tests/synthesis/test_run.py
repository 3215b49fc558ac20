"""``synthesize``: each task solved completely, its four-bars written, re-derived and judged.

The example files are built from known four-bars (algkin/synthesis/examples/*.toml: the catalog four-bar
with crank 1, coupler 3, rocker 7/2, ground 4, computed independently in mpmath, and a four-bar
worked by hand): synthesis must find those mechanisms among its answers, and algkin's own solve
of each written scene must reach every position.
"""

import math
import pathlib

import flint
import pytest

import algkin.synthesis

from algkin.scene import load_scene_text
from algkin.synthesis import synthesize

EXAMPLES = pathlib.Path(algkin.synthesis.__file__).parent / "examples"


def _near(ball, value, tolerance):
    return abs(float(ball.mid()) - value) < tolerance


@pytest.fixture(scope="module")
def poses():
    return synthesize(EXAMPLES / "fourbar-poses.toml")


def test_the_four_bar_whose_poses_were_given_is_found_and_usable(poses):
    assert poses.result.complex_count == 4 and len(poses.result.pairs) == 4 and len(poses.mechanisms) == 6
    known = [m for m in poses.mechanisms
             if _near(m.design.crank_pivot[0], 0, 1e-40) and _near(m.design.rocker_pivot[0], 4, 1e-40)]
    (mechanism,) = known
    lengths = {k: float(v.mid()) for k, v in mechanism.design.lengths().items()}
    assert lengths == pytest.approx({"crank": 1, "coupler": 3, "rocker": 3.5, "ground": 4}, abs=1e-40)
    checked = mechanism.checked
    assert checked.reached and checked.deviation < 1e-30 and checked.usable
    assert checked.grashof == "crank-rocker" and checked.crank_angles == pytest.approx((0, 30, 60, 90, 120), abs=1e-40)
    # the transmission angle at B: cos(mu) = (3**2 + 3.5**2 - |AD|**2) / (2 * 3 * 3.5), |AD| growing
    # from 3 (crank at 0) to sqrt(21) (crank at 120)
    mu = lambda reach2: math.degrees(math.acos((9 + 12.25 - reach2) / 21))  # noqa: E731
    assert checked.transmission_range == pytest.approx((mu(9), mu(21)), abs=1e-9)


def test_another_solution_of_the_same_poses_has_a_branch_defect(poses):
    kinds = [[kind for kind, _ in m.checked.defects] for m in poses.mechanisms]
    assert ["branch"] in kinds and all(m.checked.reached for m in poses.mechanisms)


def test_every_scene_written_loads_and_reaches_its_positions(poses):
    for name, text in poses.scenes().items():
        scene = load_scene_text(text, name)
        assert scene.name == name[:-len(".toml")] and list(scene.points) == ["O", "D", "A", "B", "P"]


def test_three_pairs_give_the_hand_four_bar_exactly():
    found = synthesize(EXAMPLES / "three-pairs.toml")
    (solution,) = found.result.solutions
    assert (solution.crank, solution.rocker, solution.ground, solution.coupler_squared) == (2, 5, 6, 41)
    (mechanism,) = found.mechanisms
    assert mechanism.checked.reached and mechanism.checked.usable
    # at the first pair the crank is at 2 atan(-5/2) degrees (its tan_half), the rocker at 2 atan(-3/2)
    assert mechanism.checked.crank_angles[0] == pytest.approx(math.degrees(2 * math.atan(-2.5)) % 360, abs=1e-12)


@pytest.mark.slow
def test_five_pairs_with_unknown_starts_find_the_four_bar_they_came_from():
    found = synthesize(EXAMPLES / "fourbar-pairs.toml")
    known = [s for s in found.result.solutions
             if all(_near(flint.arb(getattr(s, k)), v, 1e-40) for k, v in (("crank", 1), ("coupler", 3), ("rocker", 3.5)))]
    (solution,) = known
    assert _near(flint.arb(solution.start_input[0]), math.cos(math.radians(30)), 1e-12)
    assert all(m.checked.reached for m in found.mechanisms)


def test_seven_points_give_the_four_bar_they_came_from_alone():
    """The example's seven points, built from a four-bar (crank 2 about (0, 0), rocker 5 about (3, -1),
    joints (0, -3) and (4, -2) from the coupler point in the coupler's frame): it alone, reached
    at all seven, its coupler sqrt(17); only its transmission angle (14 to 68 degrees) is a defect."""
    found = synthesize(EXAMPLES / "seven-points-path.toml")
    assert (found.result.complex_count, found.result.real_count) == (1, 1)
    (mechanism,) = found.mechanisms
    lengths = {k: float(v.mid()) for k, v in mechanism.design.lengths().items()}
    assert lengths == pytest.approx({"crank": 2, "coupler": math.sqrt(17), "rocker": 5, "ground": math.sqrt(10)},
                                    abs=1e-30)
    checked = mechanism.checked
    assert checked.reached and checked.deviation < 1e-30
    # the construction's crank angles: twice the angle of the half-angle tangents 0, 1/2, 13/11, 3, -3, -1, -1/3
    half = [0, 1 / 2, 13 / 11, 3, -3, -1, -1 / 3]
    turns = [(angle - math.degrees(2 * math.atan(t)) + 180) % 360 - 180 for angle, t in zip(checked.crank_angles, half)]
    assert len(turns) == 7 and max(map(abs, turns)) < 1e-12  # 0 degrees may be given as 360
    assert [kind for kind, _ in checked.defects] == ["transmission"]
    # seven points: six turns, each a cos and sin on their circle and one row per dyad, and the two
    # joints' z: 6 + 12 equations in 12 + 4 unknowns; the first five points general (Morgan and Wampler's 36)
    size = found.to_json()["size"]
    assert (size["points"], size["equations"], size["unknowns"], size["five_point_solutions"]) == (7, 18, 16, 36)


def test_arguments_are_checked():
    from algkin.errors import UsageError

    for kwargs in ({"bits": 10}, {"digits": 0}, {"digits": 500}, {"min_transmission": 95},
                   {"min_transmission": "30"}, {"min_transmission": float("nan")}, {"min_transmission": True}):
        with pytest.raises(UsageError) as caught:
            synthesize(EXAMPLES / "three-pairs.toml", **kwargs)
        assert caught.value.argument == next(iter(kwargs))


def test_the_time_budget_is_kept():
    """It was only told what the work did: a second's budget let the run take as long as it took."""
    from algkin.errors import BudgetExceeded
    from algkin.runtime.budget import Budget

    from ..clocks import Clock

    with pytest.raises(BudgetExceeded, match="max_seconds=1: stopped after"):
        synthesize(EXAMPLES / "seven-points-path.toml", budget=Budget(seconds=1, clock=Clock()))


def test_within_its_budget_it_gives_what_it_gives_without_one():
    from algkin.runtime.budget import Budget

    from ..clocks import still

    bounded = synthesize(EXAMPLES / "three-pairs.toml", budget=Budget(seconds=1, clock=still))
    assert bounded.scenes() == synthesize(EXAMPLES / "three-pairs.toml").scenes()
