"""Range ends an extremum meets: an input in radians (its ends irrational in degrees), and ends whose
exact tan(end/2) is of high degree, which the closed form in symbolic dimensions cannot take."""

import mpmath
import pytest

from algkin.analyses.extremum import extremum
from algkin.errors import UsageError
from algkin.scene import load_scene_text

# The arm of arm-string turned without its phase, its input in radians: A = 350 (cos t, sin t), B = (400, -80)
ARM_IN_RADIANS = """
name = "arm-radians"
[inputs]
theta = { range = [0, 3], unit = "rad" }
[parameters]
b = 80
[points]
O = { fixed = [0, 0] }
B = { fixed = [400, "-b"] }
A = { crank = "O", length = 350, input = "theta" }
[outputs]
AB = "dist(A, B)"
"""


def test_an_input_in_radians_has_its_extremes_by_hand():
    found = extremum(load_scene_text(ARM_IN_RADIANS, "arm.toml"), "AB")
    # |AB| is greatest with A opposite B seen from O: 350 + |OB|, at the direction of -B
    far = 350 + mpmath.sqrt(400**2 + 80**2)
    assert float(found.maximum.value) == pytest.approx(float(far), rel=1e-12)
    assert float(found.maximum.input_deg) == pytest.approx(float(mpmath.degrees(mpmath.atan2(80, -400))), abs=1e-9)
    # nearest on [0, 3] rad at 0: |(350, 0) - (400, -80)| = sqrt(8900); the other end at 3 rad = 171.887 deg
    assert float(found.minimum.value) == pytest.approx(float(mpmath.sqrt(8900)), rel=1e-12)
    assert found.range == pytest.approx((0.0, float(mpmath.degrees(3))))


def test_a_symbolic_dimension_over_a_range_in_radians_is_refused_in_one_line():
    with pytest.raises(UsageError, match=r"tan\(end/2\) is algebraic of degree at most 12.*171\.887"):
        extremum(load_scene_text(ARM_IN_RADIANS, "arm.toml"), "AB", params=["b"])


@pytest.mark.parametrize("ends", [(91, 180), (0, "90.0000000001")])
def test_a_symbolic_dimension_over_an_end_of_high_degree_is_refused_at_once(ends):
    # tan(91/2 deg) is of degree 48: its conditions on b ran past ten minutes, 90.0000000001 deg's for ever
    with pytest.raises(UsageError, match=r"at most 12 \(any multiple of 5 degrees"):
        extremum("arm-string", "AB", ends, params=["b"])


def test_an_angle_output_at_an_end_of_high_degree_is_still_exact():
    # with no dimension symbolic, the end 91.0000001 deg (which ran for minutes) is the extremum, exactly
    found = extremum("fourbar", "angle(A, B, D)", (0, "91.0000001"))
    assert found.maximum.kind == "endpoint"
    # law of cosines on the four-bar's defaults (crank a = 1, ground d = 4, coupler l = 3, rocker m = 7/2):
    # cos mu = (l**2 + m**2 - a**2 - d**2 + 2 a d cos theta) / (2 l m)
    theta = mpmath.radians(mpmath.mpf("91.0000001"))
    m = mpmath.mpf(7) / 2
    mu = mpmath.degrees(mpmath.acos((3**2 + m**2 - 1 - 4**2 + 2 * 4 * mpmath.cos(theta)) / (2 * 3 * m)))
    assert float(found.maximum.value) == pytest.approx(float(mu), rel=1e-12)
