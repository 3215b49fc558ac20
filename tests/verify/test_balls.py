"""The proof in balls: an enclosure holds the true root, and nothing is proved where it should not be.

The true roots come from the textbook construction of two circles' intersection, computed
in mpmath at 60 digits, independently of the Krawczyk test under test.
"""

import flint
import mpmath
import numpy as np
import pytest
import sympy
from hypothesis import given, settings, strategies as st

from algkin.system import System, symbol
from algkin.verify.balls import BlockCertifier
from algkin.verify.solve import STARTS, blocks_of, solve_floats

x, y, cx, cy = (symbol(n) for n in ("x", "y", "cx", "cy"))
CIRCLES = [x**2 + y**2 - 4, (x - cx)**2 + (y - cy)**2 - 9]  # radii 2 about 0 and 3 about (cx, cy)


def textbook(cx_, cy_):
    """The two intersections of the circles, by the foot of the chord and its half-length."""
    with mpmath.workdps(80):
        cx_, cy_ = mpmath.mpf(cx_), mpmath.mpf(cy_)
        d2 = cx_**2 + cy_**2
        along = (d2 + 4 - 9) / (2 * d2)
        half = mpmath.sqrt(4 / d2 - along**2)
        return [(along * cx_ - s * half * cy_, along * cy_ + s * half * cx_) for s in (1, -1)]


def prove(cx_, cy_, candidate):
    certify = BlockCertifier(["x", "y"], CIRCLES, ["cx", "cy"])
    with flint.ctx.workprec(192):
        return certify(candidate, [flint.arb(cx_), flint.arb(cy_)])


@settings(max_examples=40, deadline=None)
@given(st.floats(1.5, 4.5), st.floats(0, 6.283))
def test_each_intersection_is_enclosed_tightly(distance, angle):
    cx_, cy_ = distance * np.cos(angle), distance * np.sin(angle)
    for root in textbook(cx_, cy_):
        start = [float(v) * (1 + 1e-9) for v in root]  # a float candidate near the root
        enclosure = prove(cx_, cy_, start)
        assert enclosure is not None
        with flint.ctx.workprec(300):
            for ball, value in zip(enclosure, root):  # the 75-digit value: a ball of radius ~1e-75
                assert ball.overlaps(flint.arb(mpmath.nstr(value, 75)))
                assert ball.rad() < 1e-40


def test_a_block_of_no_two_circles_is_proved_by_krawczyk():
    # x^2 + y^2 = 4 and xy = 1: x^2 = 2 + sqrt(3), y = 1/x (by hand); no line combines them
    certify = BlockCertifier(["x", "y"], [x**2 + y**2 - 4, x * y - 1], [])
    assert certify.pencil is None
    with flint.ctx.workprec(192):
        root = certify([1.93, 0.52], [])
        exact = (2 + flint.arb(3).sqrt()).sqrt()
        assert root[0].overlaps(exact) and root[1].overlaps(1 / exact) and root[0].rad() < 1e-40


def test_a_circle_and_a_line_are_a_pencil():
    # x^2 + y^2 = 4 and y = x + 2 meet at (0, 2) and (-2, 0)
    certify = BlockCertifier(["x", "y"], [x**2 + y**2 - 4, y - x - 2], [])
    assert certify.pencil is not None
    with flint.ctx.workprec(192):
        for point in ([0.0, 2.0], [-2.0, 0.0]):
            root = certify([v + 1e-10 for v in point], [])
            assert all(b.overlaps(flint.arb(v)) and b.rad() < 1e-50 for b, v in zip(root, point))


def test_a_tangency_is_not_proved():
    # Distance 5 = 2 + 3: one double root at (2, 0); no box holds exactly one simple root there.
    assert prove(5, 0, [2.0, 1e-9]) is None


def test_a_point_far_from_any_root_is_not_proved():
    assert prove(3, 1, [-1.9, -3.0]) is None


@pytest.mark.parametrize("starts", [STARTS, 8 * STARTS], ids=["pencil of the circles", "Newton (a retry)"])
def test_the_solver_finds_both_intersections_for_every_sample(starts):
    system = System(("x", "y"), (), {"t": ("c", "s")},
                    (x**2 + y**2 - 4, (x - 3 * symbol("c"))**2 + (y - 3 * symbol("s"))**2 - 9))
    angles = np.linspace(0, 6, 25)
    found = solve_floats(blocks_of(system), {"c": np.cos(angles), "s": np.sin(angles)},
                         np.random.default_rng(1), starts)
    assert np.bincount(found.owner, minlength=25).tolist() == [2] * 25
    for k, angle in enumerate(angles):
        expected = sorted(tuple(float(v) for v in r) for r in textbook(3 * np.cos(angle), 3 * np.sin(angle)))
        got = sorted(zip(found.values["x"][found.owner == k], found.values["y"][found.owner == k]))
        assert np.allclose(got, expected, atol=1e-12)


@pytest.mark.parametrize("distance", ["11/2", "1/2"])
def test_circles_that_miss_give_no_candidate(distance):
    distance = sympy.Rational(distance)
    system = System(("x", "y"), (), {"t": ("c", "s")},
                    (x**2 + y**2 - 4, (x - distance * symbol("c"))**2 + (y - distance * symbol("s"))**2 - 9))
    found = solve_floats(blocks_of(system), {"c": np.array([1.0]), "s": np.array([0.0])},
                         np.random.default_rng(0))
    assert len(found.owner) == 0
