"""A point that does not move with the input has no trajectory curve: refused in one line."""

import subprocess
import sys

import pytest

from algkin import curve
from algkin.errors import UsageError

STILL = """
name = "still"
[inputs]
t = { range = [0, 360], unit = "deg" }
[points]
O = { fixed = [0, 0] }
D = { fixed = [2, 0] }
F = { frame = ["O", "D"], at = ["1/2", 1] }
A = { crank = "O", length = 1, input = "t" }
[outputs]
F = "F"
A = "A"
"""


@pytest.mark.parametrize("scene, point, where", [
    ("chebyshev-lambda", "O", "(0, 0)"),
    ("chebyshev-lambda", "D", "(2, 0)"),
    ("still", "F", "(1, 2)"),  # O + (D - O)/2 + rot90(D - O), built from two pivots only
])
def test_a_still_point_is_refused_naming_where_it_stays(tmp_path, scene, point, where):
    if scene == "still":
        (tmp_path / "still.toml").write_text(STILL)
        scene = str(tmp_path / "still.toml")
    with pytest.raises(UsageError, match=rf"fixed at \({where[1:-1]}\).*a point, not a curve"):
        curve(scene, point, samples=0)


def test_the_command_says_it_in_one_line_with_exit_2():
    done = subprocess.run([sys.executable, "-m", "algkin", "curve", "chebyshev-lambda", "--point", "O"],
                          capture_output=True, text=True)
    assert done.returncode == 2 and done.stderr.strip().splitlines() == [
        "algkin: error: --point='O': is fixed at (0, 0): its trajectory is a point, not a curve"]


def test_a_symbolic_offset_shows_in_the_place():
    with pytest.raises(UsageError, match=r"fixed at \(0, e\)"):
        curve("slider-crank", "L", params=["e"], samples=0)
