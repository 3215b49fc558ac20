"""``algkin.verify.groups``: the real solutions of a group's equations, found and proved without its eliminant."""

import flint
import mpmath
import numpy as np

from algkin.system import symbol
from algkin.verify.groups import real_solutions


def test_two_circles_meet_where_the_textbook_says():
    x, y, r = symbol("x"), symbol("y"), symbol("r")
    found, = real_solutions(("x", "y"), (x**2 + y**2 - r**2, (x - 4)**2 + y**2 - 9), {"r": ("r",)},
                            [{"r": flint.fmpq(3)}], np.random.default_rng(0))
    # x = (r**2 - 9 + 16)/8 = 2, y = ±sqrt(9 - 4)
    assert len(found) == 2
    for root in found:
        assert root["x"].overlaps(flint.arb(2)) and root["x"].rad() < 1e-40
        assert abs(abs(mpmath.mpf(root["y"].mid().str(50, radius=False))) - mpmath.sqrt(5)) < 1e-40


def test_no_real_solution_no_root_with_several_samples_at_once():
    x, y, r = symbol("x"), symbol("y"), symbol("r")
    found = real_solutions(("x", "y"), (x**2 + y**2 - r**2, (x - 10)**2 + y**2 - 1), {"r": ("r",)},
                           [{"r": flint.fmpq(1)}, {"r": flint.fmpq(10)}], np.random.default_rng(0))
    assert [len(f) for f in found] == [0, 2]
