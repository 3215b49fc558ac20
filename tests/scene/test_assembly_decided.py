"""What compiling decides about assembly, exactly: a dyad whose bases coincide is refused; one
on two fixed bases out of its lengths' reach is said to never assemble (``Compiled.never_assembles``)."""

from fractions import Fraction

import pytest
from hypothesis import given, settings, strategies as st

from algkin.errors import SceneError
from algkin.scene import compile_scene, load_scene_text

DYAD = """
[points]
P = {{ fixed = ["{px}", "{py}"] }}
Q = {{ fixed = ["{qx}", "{qy}"] }}
C = {{ dyad = ["P", "Q"], lengths = ["{l1}", "{l2}"], branch = "left" }}
[outputs]
C = "C"
"""

coordinates = st.fractions(-6, 6, max_denominator=4)
lengths = st.fractions(Fraction(1, 4), 6, max_denominator=4)


@settings(max_examples=60, deadline=None)
@given(coordinates, coordinates, coordinates, coordinates, lengths, lengths)
def test_a_dyad_on_fixed_bases_never_assembles_exactly_out_of_reach(px, py, qx, qy, l1, l2):
    if (px, py) == (qx, qy):
        return  # refused: see below
    scene = load_scene_text(DYAD.format(px=px, py=py, qx=qx, qy=qy, l1=l1, l2=l2), "dyad.toml")
    squared = (qx - px) ** 2 + (qy - py) ** 2
    out_of_reach = squared > (l1 + l2) ** 2 or squared < (l1 - l2) ** 2  # |l1 - l2| <= |PQ| <= l1 + l2
    assert ("C" in compile_scene(scene).never_assembles) == out_of_reach


@pytest.mark.parametrize("q, l1, l2, never", [
    ("10", "1", "1", True),     # far apart
    ("2", "1", "1", False),     # tangent outside: one configuration
    ("1", "3", "2", False),     # tangent inside
    ("1", "3", "1", True),      # one circle inside the other
    ("10", "sqrt(26)", "sqrt(26)", False),  # irrational lengths, squared: 5.099 + 5.099 > 10
    ("109/10", "sqrt(30)", "sqrt(30)", False),  # 5.4772 + 5.4772 = 10.954 > 10.9
    ("109/10", "sqrt(29)", "sqrt(30)", True),   # 5.3852 + 5.4772 = 10.862 < 10.9
])
def test_the_edges_of_the_reach(q, l1, l2, never):
    scene = load_scene_text(DYAD.format(px=0, py=0, qx=q, qy=0, l1=l1, l2=l2), "dyad.toml")
    found = compile_scene(scene).never_assembles
    assert ("C" in found) == never
    if never:
        assert found["C"].startswith(f"its fixed bases P and Q are {q} apart")


def test_moving_bases_are_not_decided_here():
    text = DYAD.format(px=0, py=0, qx=10, qy=0, l1=1, l2=1).replace(
        'P = { fixed = ["0", "0"] }', 'O = { fixed = [0, 0] }\nP = { crank = "O", length = 1, input = "t" }')
    scene = load_scene_text("[inputs]\nt = { range = [0, 360] }\n" + text, "dyad.toml")
    assert compile_scene(scene).never_assembles == {}


@pytest.mark.parametrize("q", ["0", "4/2 - 2"])
def test_bases_at_one_place_are_refused(q):
    scene = load_scene_text(DYAD.format(px=0, py=0, qx=q, qy=0, l1=1, l2=1), "dyad.toml")
    with pytest.raises(SceneError, match=r"^dyad.toml: points.C: bases coincide: P and Q are one point at \(0, 0\)"):
        compile_scene(scene)
