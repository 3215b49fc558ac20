"""Certified labels: intervals agree with hand toggles; inside them the label never flips."""

import random
from fractions import Fraction

import mpmath
from hypothesis import assume, given, settings, strategies as st

from algkin.branches import closed_forms
from algkin.evaluate import MPMATH, evaluate
from algkin.derivation.assembles import certify_labels
from algkin.scene import compile_scene

from ..analyses.test_toggles import four_bar, law_of_cosines


def certified(scene):
    compiled = compile_scene(scene, ["B"])
    branches = closed_forms(compiled)
    return compiled, branches, certify_labels(compiled, branches)


def test_non_grashof_intervals_are_cut_at_the_hand_dead_centres():
    _, _, per_branch = certified(four_bar(3, 4, 2, "5/2"))
    (first, _), (second, _) = law_of_cosines(3, 4, 2, 2.5)
    for intervals in per_branch:
        assert [i["status"] for i in intervals] == ["certified", "undecided", "no-assembly", "undecided", "certified"]
        undecided = [i for i in intervals if i["status"] == "undecided"]
        for interval, toggle in zip(undecided, (first, second)):
            assert interval["from_deg"] <= toggle <= interval["to_deg"]
            assert interval["to_deg"] - interval["from_deg"] < 1e-6


def _label_at(branch, degrees, crank, ground):
    """Side of B from the directed line A -> D = (ground, 0), at 30 digits; None if B is not real."""
    with mpmath.workdps(30):
        angle = mpmath.radians(degrees)
        values = {"c_angle": mpmath.cos(angle), "s_angle": mpmath.sin(angle)}
        bx, by = (evaluate(branch.values[u], values, MPMATH) for u in ("B_x", "B_y"))
        if not isinstance(bx, mpmath.mpf):
            return None
        crank, ground = (mpmath.mpf(v.numerator) / v.denominator for v in (crank, ground))
        ax, ay = values["c_angle"] * crank, values["s_angle"] * crank
        cross = (ground - ax) * (by - ay) - (0 - ay) * (bx - ax)
        return "left" if cross > 0 else "right"


lengths = st.fractions(min_value=Fraction(1, 2), max_value=6, max_denominator=8)


@settings(max_examples=15)
@given(lengths, lengths, lengths, lengths, st.integers(0, 2**32 - 1))
def test_labels_never_flip_inside_a_certified_interval(crank, ground, coupler, rocker, seed):
    bars = sorted([crank, ground, coupler, rocker])
    assume(bars[3] < bars[0] + bars[1] + bars[2])  # a quadrilateral: it assembles somewhere
    compiled, branches, per_branch = certified(four_bar(crank, ground, coupler, rocker))
    rng = random.Random(seed)
    for branch, intervals in zip(branches, per_branch):
        assert any(i["status"] == "certified" for i in intervals)  # something to check
        for interval in intervals:
            if interval["status"] != "certified":
                continue
            for _ in range(5):
                degrees = rng.uniform(interval["from_deg"], interval["to_deg"])
                assert _label_at(branch, degrees, crank, ground) == branch.label
