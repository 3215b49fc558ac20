"""Grid and random designs: exact values by hand, bad specs refused in one line."""

import re
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, strategies as st

from algkin.errors import UsageError
from algkin.sweep.grid import RANDOM_STEPS, first_repeat, grid_designs, parse_grid, parse_ranges, random_designs


def test_values_are_exact_and_include_both_ends():
    axes = parse_grid(["a=0.1:0.3:3", "m=3/2:2:2"])
    assert axes == {"a": [Fraction(1, 10), Fraction(2, 10), Fraction(3, 10)], "m": [Fraction(3, 2), Fraction(2)]}


def test_the_first_axis_varies_slowest():
    designs = grid_designs(parse_grid(["a=1:2:2", "l=5:7:3"]))
    assert [(int(d["a"]), int(d["l"])) for d in designs] == [(1, 5), (1, 6), (1, 7), (2, 5), (2, 6), (2, 7)]


@pytest.mark.parametrize("spec, says", [
    ("a=1:2", "expected NAME=LO:HI:COUNT"),
    ("a", "expected NAME=LO:HI:COUNT"),
    ("=1:2:3", "expected NAME=LO:HI:COUNT"),
    ("a=1:x:3", "'x' is not a number"),
    ("a=2:1:3", "LO must not exceed HI"),
    ("a=1:2:0", "COUNT must be a whole number from 1"),
    ("a=1:2:2.5", "COUNT must be a whole number from 1"),
    ("a=1:2:1", "COUNT 1 needs LO = HI"),
    ("a=1:1:3", "LO = HI is one value, not 3: give COUNT 1"),  # three identical designs
    ("a=1e200:1e201:2", "outside 1e-100 to 1e100"),
    ("a=1e-1000000000:1:2", "decimal exponent out of range"),  # Fraction would compute 10**1000000000 first
    ("a=1:2:" + "9" * 5000, "COUNT has 5000 digits: more than 1000000 designs"),  # int() refused it: an internal error
    ("a=1:2:" + "0" * 5000, "COUNT must be a whole number from 1"),
])
def test_bad_grids_are_refused(spec, says):
    with pytest.raises(UsageError, match=says) as raised:
        parse_grid([spec])
    assert "\n" not in str(raised.value)


def test_a_name_given_twice_is_refused():
    with pytest.raises(UsageError, match="given twice"):
        parse_grid(["a=1:2:2", "a=3:4:2"])


def test_too_many_designs_are_refused_before_any_is_made():
    with pytest.raises(UsageError, match="more than"):
        parse_grid([f"{n}=0:1:1000" for n in "abc"])


def test_a_billion_values_are_counted_not_made():
    import tracemalloc

    tracemalloc.start()
    try:
        with pytest.raises(UsageError, match="1000000000 designs, more than 1000000"):
            parse_grid(["a=1:2:1000000000"])
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert peak < 10**6  # bytes: not one value per design (a billion Fractions would be ~100 GB)


def test_the_cap_is_the_product_of_the_counts():
    assert len(grid_designs(parse_grid(["a=0:1:1000", "b=0:1:1000"]))) == 10**6  # at the cap: taken
    with pytest.raises(UsageError, match="1001000 designs"):
        parse_grid(["a=0:1:1000", "b=0:1:1001"])


@given(st.integers(0, 2**32), st.integers(1, 20))
def test_random_draws_repeat_with_the_seed_and_stay_in_range(seed, count):
    ranges = parse_ranges(["a=1/3:2", "l=-1:1"])
    drawn = random_designs(ranges, count, seed)
    assert drawn == random_designs(ranges, count, seed)
    for design in drawn:
        for name, (lo, hi) in ranges.items():
            assert lo <= design[name] <= hi
            # on the lattice: (value - lo) / (hi - lo) is k / RANDOM_STEPS for a whole k
            assert ((design[name] - lo) / (hi - lo) * RANDOM_STEPS).denominator == 1


@pytest.mark.parametrize("specs", [["a=0:1"], ["a=1:1", "l=0:1"]], ids=["one-range", "beside-one-value"])
def test_random_designs_are_distinct(specs):
    # 3000 draws on 10^6 + 1 steps repeat about 3000^2 / 2 / 10^6 = 4.5 times (the birthday bound): with
    # seed 0, 7 times; each repeat is drawn again.
    drawn = random_designs(parse_ranges(specs), 3000, 0)
    assert len(drawn) == 3000 and len({tuple(d.values()) for d in drawn}) == 3000
    if "a=1:1" in specs:
        assert {d["a"] for d in drawn} == {1}


def test_random_designs_keep_the_seeds_draws_up_to_its_first_repeat():
    # The seed's sequence, read from numpy directly: k in [0, 10^6] per design; the designs are those
    # draws, in order, until one repeats an earlier one.
    ks = np.random.Generator(np.random.PCG64(0)).integers(0, RANDOM_STEPS, size=(3000, 1), endpoint=True)[:, 0]
    first = next(i for i, k in enumerate(ks) if k in ks[:i])
    drawn = random_designs(parse_ranges(["a=0:1"]), 3000, 0)
    assert [d["a"] for d in drawn[:first]] == [Fraction(int(k), RANDOM_STEPS) for k in ks[:first]]



@pytest.mark.parametrize("count, seed", [(3000, 0), (8, 23365), (8, 0), (500, 3)])
def test_the_first_repeat_of_the_first_draw_scheme(count, seed):
    # Scheme 1 drew the seed's first rows as they came: read from numpy directly, the first index whose k
    # is among the earlier ones (none: the distinct draws are the same designs)
    ks = np.random.Generator(np.random.PCG64(seed)).integers(0, RANDOM_STEPS, size=(count, 1), endpoint=True)[:, 0]
    expected = next((i for i, k in enumerate(ks) if k in ks[:i]), None)
    assert first_repeat(parse_ranges(["a=0:1"]), count, seed) == expected
    if expected is None:
        assert [d["a"] for d in random_designs(parse_ranges(["a=0:1"]), count, seed)] == \
            [Fraction(int(k), RANDOM_STEPS) for k in ks]


@pytest.mark.parametrize("specs, count, says", [
    (["a=1:1"], 2, "the ranges hold 1 distinct design at most (a=1:1: one value)"),
    (["a=1:1", "l=3/2:3/2"], 5, "the ranges hold 1 distinct design at most (a=1:1, l=3/2:3/2: one value each)"),
])
def test_more_random_designs_than_the_ranges_hold_are_refused(specs, count, says):
    with pytest.raises(UsageError, match=re.escape(says)):
        random_designs(parse_ranges(specs), count, 0)
    assert random_designs(parse_ranges(specs), 1, 0)[0]["a"] == 1  # the one design they hold


def test_random_ranges_take_no_count():
    with pytest.raises(UsageError, match="expected NAME=LO:HI"):
        parse_ranges(["a=1:2:3"])


def test_a_run_refused_for_its_length_made_no_design(tmp_path, monkeypatch):
    from algkin.sweep import sweep
    from algkin.sweep.grid import Designs

    made = []
    get = Designs.__getitem__
    monkeypatch.setattr(Designs, "__getitem__", lambda self, k: made.append(k) or get(self, k))
    # 10^6 designs of limits, at least 0.22 s each one at a time: 2.5 days
    with pytest.raises(UsageError, match="confirm with yes"):
        sweep("fourbar", tmp_path / "out", grid=["a=1:2:1000", "d=1:2:1000"], analyses=["limits"], executor="serial")
    assert made == [0, 0]  # the first design's names, read by the plan; no other made
    assert not (tmp_path / "out").exists()


def test_the_sweep_takes_its_options_by_name(tmp_path):
    from algkin.sweep import plan, sweep

    # a grid passed where the designs' random count was meant is a TypeError, not a silent mix-up
    with pytest.raises(TypeError):
        sweep("fourbar", tmp_path / "out", ["a=1:2:2"])
    with pytest.raises(TypeError):
        plan("fourbar", ["a=1:2:2"])
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("point, analyses", [("O", ["curve"]), ("D", ["grashof", "singular"])])
def test_a_ground_pivot_for_the_curve_is_refused_before_any_design(point, analyses):
    # every design failed, one by one, on the same bad argument (exit 0): O = (0, 0) and D = (d, 0) never move
    from algkin.sweep import plan

    with pytest.raises(UsageError, match=f"point='{point}': is fixed at .*its trajectory is a point"):
        plan("fourbar", grid=["a=1:2:2", "d=3:4:2"], analyses=analyses, point=point)


def test_a_ground_pivot_is_no_matter_without_a_curve():
    from algkin.sweep import plan

    assert len(plan("fourbar", grid=["a=1:2:2"], analyses=["grashof"], point="O").designs) == 2
