"""Where a symbolic dimension makes a mechanism: the spans over which every length in it is positive
(``spans_lengths_positive``), by hand from the lengths written in the scene."""

import pytest

from algkin.scene import load_scene, load_scene_text
from algkin.scene.compile import spans_lengths_positive

SCENE = """
[parameters]
a = 4
[inputs]
t = { range = [0, 360] }
[points]
O = { fixed = [0, 0] }
D = { fixed = ["a + 6", 0] }
A = { crank = "O", length = "2*a - 1", input = "t" }
B = { dyad = ["A", "D"], lengths = ["5 - a", "(a - 1)*(a - 3)"], branch = "left" }
[outputs]
B = "B"
"""


def test_the_spans_are_where_each_length_is_positive():
    # 2a - 1 > 0: a > 1/2; 5 - a > 0: a < 5; (a - 1)(a - 3) > 0: a < 1 or a > 3
    assert spans_lengths_positive(load_scene_text(SCENE, "s.toml"), "a") == ((0.5, 1.0), (3.0, 5.0))


@pytest.mark.parametrize("scene, name, spans", [
    ("fourbar", "a", ((0.0, None),)),   # the crank
    ("fourbar", "m", ((0.0, None),)),   # the rocker, a dyad's length
    ("slider-crank", "l", ((0.0, None),)),  # the rod, a slider's distance
    ("fourbar", "d", None),             # the pivot D = (d, 0): a coordinate
    ("slider-crank", "e", None),        # the slider's line y = e
])
def test_a_length_is_positive_a_coordinate_anything(scene, name, spans):
    assert spans_lengths_positive(load_scene(scene), name) == spans
