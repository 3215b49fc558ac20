"""Motion: every point by closed forms, checked against hand geometry on both branches."""

import numpy as np
import pytest

from algkin.errors import UsageError
from algkin.analyses.motion import Motion
from algkin.scene import load_scene_text

from ..hand_linkages import CHEBYSHEV, FOURBAR, fourbar


@pytest.mark.parametrize("branch", ["left", "right"])
@pytest.mark.parametrize("theta", [0, 37.3, 90, 163, 270.5, 359])
def test_chebyshev_points_are_the_hand_construction(theta, branch):
    pose = Motion("chebyshev-lambda").at({"angle": theta}, branch=branch)
    hand = fourbar(theta, **CHEBYSHEV, branch=branch)
    for name, (x, y) in hand.items():
        assert pose.points[name] == pytest.approx((x, y), abs=1e-12)


def test_dimensions_stay_symbolic_and_move_the_points():
    motion = Motion("fourbar")
    assert motion.params == ("a", "d", "l", "m", "p", "q")
    dims = dict(FOURBAR, l=2.5, m=3.2, q=-0.3)
    pose = motion.at({"theta": 123.4}, {"l": 2.5, "m": 3.2, "q": -0.3}, "right")
    for name, xy in fourbar(123.4, **dims, branch="right").items():
        assert pose.points[name] == pytest.approx(xy, abs=1e-12)


def test_cannot_assemble_where_the_circles_do_not_meet():
    motion = Motion("fourbar")
    # Crank at 180 deg: |DA| = 5 > l + m = 0.75 + 3.5, so no B exists.
    assert fourbar(180, **dict(FOURBAR, l=0.75)) is None
    pose = motion.at({"theta": 180}, {"l": 0.75})
    assert not pose.assembles and pose.blocked == ("B",) and set(pose.points.values()) == {None}
    assert motion.at({"theta": 0}, {"l": 0.75}).assembles  # |DA| = 3 is within [2.75, 4.25]


def test_sweep_is_nan_exactly_where_hand_geometry_fails():
    angles, points = Motion("fourbar").sweep({"l": 0.75}, samples=181)
    for theta, x in zip(angles, points["P"][0]):
        assert np.isnan(x) == (fourbar(theta, **dict(FOURBAR, l=0.75)) is None)


SCALED = """
name = "scaled"
description = "A crank whose coupler point sits at 1/k along the bar: k under a division."
[parameters]
r = 2
k = 4
[inputs]
t = { range = [0, 360] }
[points]
O = { fixed = [0, 0] }
A = { crank = "O", length = "r", input = "t" }
G = { frame = ["O", "A"], at = ["1/k", 0] }
"""


def test_a_dimension_under_a_division_keeps_its_default():
    scene = load_scene_text(SCALED)
    motion = Motion(scene)
    assert motion.params == ("r",)
    assert motion.at({"t": 90}, {"r": 3}).points["G"] == pytest.approx((0, 0.75), abs=1e-15)
    with pytest.raises(UsageError, match="not polynomial"):
        Motion(scene, ["k"])


def test_poses_loop_a_full_turn():
    poses = Motion("chebyshev-lambda").poses(samples=8)
    assert [p.inputs["angle"] for p in poses] == [0, 45, 90, 135, 180, 225, 270, 315]
