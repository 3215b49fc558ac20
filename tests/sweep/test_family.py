"""A family (algkin.sweep.family): what the designs share, worked out once, gives each design the
row it gets computed alone, and leaves to each design's own path what it cannot answer for."""

import functools
from fractions import Fraction
from importlib import resources

import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

from algkin.scene import load_scene, load_scene_text
from algkin.sweep import sweep, without_timings, read_dataset
from algkin.sweep.design import Job, evaluate_design
from algkin.sweep.family import Family

FOURBAR = load_scene("fourbar")
FOURBAR_TEXT = resources.files("algkin.catalog").joinpath("fourbar.toml").read_text()
ANALYSES = ("curve", "grashof")


def without_seconds(row):
    return {k: v for k, v in row.items() if not k.startswith("seconds_")}


@functools.cache
def family_of(scene, names, point, analyses):
    """The family, made once for all the designs a test draws in its dimensions, as a sweep makes it once
    for all of its designs."""
    return Family.of(scene, names, point, analyses=analyses)


def shared_and_alone(scene, values, *, point="P", analyses=ANALYSES):
    """The row of one design of ``scene`` with the family of its dimensions, and alone."""
    job = Job(scene, analyses, point)
    family = family_of(scene, tuple(values), point, analyses)
    return (without_seconds(evaluate_design(job, 0, values, family=family)),
            without_seconds(evaluate_design(job, 0, values)))


small = st.fractions(min_value=Fraction(1, 4), max_value=6, max_denominator=4)


@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(a=small, l=small, m=small, d=small)
def test_a_design_of_the_family_has_the_row_it_has_alone(a, l, m, d):
    shared, alone = shared_and_alone(FOURBAR, {"a": a, "l": l, "m": m, "d": d})
    assert shared == alone


@pytest.mark.parametrize("values, status", [
    ({"a": Fraction(5, 6), "d": Fraction(22, 3)}, "structure"),          # |DA| = l + m at theta = 0 only
    ({"a": Fraction(1), "d": Fraction(10)}, "does-not-assemble"),        # |DA| >= 9 > l + m
    ({"a": Fraction(1, 2), "d": Fraction(6)}, "ok"),                     # a + d = l + m: a dead centre at 180
    ({"a": Fraction(2), "d": Fraction(5)}, "ok"),                        # non-Grashof: part of the turn
])
def test_the_hard_designs_get_their_own_rows(values, status):
    shared, alone = shared_and_alone(FOURBAR, values)
    assert shared == alone and shared["status"] == status


def test_the_designs_the_grid_does_not_decide_are_left_to_their_own_path():
    family = Family.of(FOURBAR, ("a", "d"), "P", analyses=ANALYSES)
    assert family.design({"a": Fraction(5, 6), "d": Fraction(22, 3)}) is None   # a structure
    assert family.design({"a": Fraction(1), "d": Fraction(10)}) is None          # never assembles
    assert family.design({"a": Fraction(1)}) is None                             # not the family's dimensions
    assert family.design({"a": Fraction(1, 2), "d": Fraction(4)}) is not None


@pytest.mark.parametrize("values", [
    {"a": Fraction(1, 2), "d": Fraction(6)},     # a + d = l + m: the discriminant 0.0 at 180 degrees in floats
    {"a": Fraction(2, 3), "d": Fraction(35, 6)},  # the same touch, 3e-13 from zero in floats
])
def test_a_dead_centre_at_a_grid_input_is_decided_whatever_its_rounding(values):
    """A change point's dead centre falls on the grid (180 degrees): the value there is within
    rounding of zero, but the design's own path decides the same (it assembles on the whole range)
    whichever sign rounding gives it, so the family answers for it, with the row it has alone."""
    family = Family.of(FOURBAR, ("a", "d"), "P", analyses=ANALYSES)
    assert family.design(values) is not None
    shared, alone = shared_and_alone(FOURBAR, values, analyses=("curve", "grashof", "transmission"))
    assert shared == alone and shared["status"] == "ok" and shared["grashof_class"] == "change-point"


def test_a_curve_of_lower_degree_than_the_familys_is_its_own():
    """With the coupler point on the crank tip (p = q = 0), P = A runs on the crank's circle x^2 + y^2 = a^2:
    the generic sextic drops degree there, so the design's own elimination answers."""
    family = Family.of(FOURBAR, ("a", "p", "q"), "P", analyses=("curve",))
    values = {"a": Fraction(1), "p": Fraction(0), "q": Fraction(0)}
    assert family.curve(family.design(values)) is None
    shared, alone = shared_and_alone(FOURBAR, values, analyses=("curve",))
    assert shared == alone
    assert (shared["curve_polynomial"], shared["curve_degree"]) == ("P_x**2 + P_y**2 - 1", 2)


def test_a_parallelogram_whose_curve_splits_is_its_own():
    """Crank = rocker and coupler = ground (a = m = 1, l = d = 4): the four-bar folds into a kite as
    well as moving as a parallelogram, and its coupler curve has more than one factor."""
    family = Family.of(FOURBAR, ("a", "l", "m"), "P", analyses=("curve",))
    values = {"a": Fraction(1), "l": Fraction(4), "m": Fraction(1)}
    design = family.design(values)
    assert design is None or family.curve(design) is None
    shared, alone = shared_and_alone(FOURBAR, values, analyses=("curve",))
    assert shared == alone


def test_a_scene_with_nothing_to_share_has_no_family():
    assert Family.of(FOURBAR, (), "P", analyses=ANALYSES) is None
    assert Family.of(load_scene("3rpr"), ("r2",), "P", analyses=("modes",)) is None


def test_a_shared_sweep_writes_the_dataset_of_each_design_alone(tmp_path):
    grid = ["a=1/2:3/2:3", "l=2:4:3", "d=4:10:3"]   # 27 four-bars: ok, never assembling and structures among them
    shared = sweep("fourbar", tmp_path / "shared", grid=grid, analyses=["curve", "grashof"], executor="serial")
    alone = sweep("fourbar", tmp_path / "alone", grid=grid, analyses=["curve", "grashof"], executor="serial",
                  share=False)
    assert shared.counts == alone.counts and len(shared.counts) > 1
    assert without_timings(read_dataset(tmp_path / "shared")).equals(without_timings(read_dataset(tmp_path / "alone")))


@pytest.mark.parametrize("scene, values, point, element", [
    (FOURBAR, {"a": Fraction(0)}, "P", "points.A"),                          # a crank of length 0
    (FOURBAR, {"a": Fraction(-1)}, "P", "points.A"),
    (FOURBAR, {"l": Fraction(-3), "m": Fraction(7, 2)}, "P", "points.B"),     # a dyad's negative length
    (load_scene("inverted-slider-crank"), {"k": Fraction(-1)}, "H", "points.H"),  # a slider's distance
])
def test_a_zero_or_negative_length_fails_as_it_does_alone(scene, values, point, element):
    """A length that is not positive breaks the scene (as a file with it would): the row says so,
    with no curve, whatever the family's grid of discriminants says."""
    shared, alone = shared_and_alone(scene, values, point=point, analyses=("curve",))
    assert shared == alone
    assert shared["status"] == "failed" and f"{element}: length must be positive" in shared["reason"]
    assert shared["curve_polynomial"] is None


@pytest.mark.parametrize("name, values, point, curve", [
    # arm-string's G, at g = 120 along the arm, runs on x^2 + y^2 = 120^2 wherever the string's
    # anchor B = (a, -b) is: the generic curve has no a or b in it
    ("arm-string", {"a": Fraction(300), "b": Fraction(50)}, "G", "G_x**2 + G_y**2 - 14400"),
    # whitworth-quick-return's ram D runs along its guide y = h = 6, whatever the crank and lever:
    # the generic curve has no D_x (nor r or c) in it
    ("whitworth-quick-return", {"r": Fraction(3), "c": Fraction(5)}, "D", "D_y - 6"),
])
def test_a_curve_free_of_a_swept_dimension_or_a_coordinate_is_specialised(name, values, point, curve):
    scene = load_scene(name)
    family = Family.of(scene, tuple(values), point, analyses=("curve",))
    assert family.curve(family.design(values)) is not None   # the family answers for it
    shared, alone = shared_and_alone(scene, values, point=point, analyses=("curve",))
    assert shared == alone
    assert (shared["status"], shared["curve_polynomial"]) == ("ok", curve)


def test_a_point_before_the_dyads_assembles_with_them():
    """Tracing the crank tip A of a four-bar whose dyad B never meets (|DA| >= 9 > l + m): the design
    does not assemble, as derive says of the scene, though A alone would turn."""
    shared, alone = shared_and_alone(FOURBAR, {"d": Fraction(10)}, point="A", analyses=("curve",))
    assert shared == alone and shared["status"] == "does-not-assemble"
    shared, alone = shared_and_alone(FOURBAR, {"d": Fraction(4)}, point="A", analyses=("curve",))
    assert shared == alone and shared["curve_polynomial"] == "A_x**2 + A_y**2 - 1"


def test_a_generic_curve_past_its_time_leaves_each_design_its_own(monkeypatch):
    """A family's generic curve that takes longer than GENERIC_SECONDS (here a microsecond: the
    child it runs in is stopped before it starts) is dropped; the rest is still shared."""
    monkeypatch.setattr("algkin.sweep.family.GENERIC_SECONDS", 1e-6)
    family = Family.of(FOURBAR, ("a", "l"), "P", analyses=ANALYSES)
    design = family.design({"a": Fraction(1, 2), "l": Fraction(3)})
    assert design is not None and family.curve(design) is None
    shared, alone = shared_and_alone(FOURBAR, {"a": Fraction(1, 2), "l": Fraction(3)})
    assert shared == alone


def test_a_mode_named_by_a_configuration_is_named_with_each_designs_values():
    """B's mode named near (2, 3) at theta = 0: with a = 1/2, d = 4, m = 5 its configurations there
    are (-1/28, +-3.0), 2 from (2, 3), further than a quarter of the 6 between them: no mode is named,
    as the design's own path says, though the defaults' mode is."""
    scene = load_scene_text(FOURBAR_TEXT.replace('branch = "left"', 'mode = { at = 0, near = [2, 3] }'))
    values = {"a": Fraction(1, 2), "d": Fraction(4), "m": Fraction(5)}
    shared, alone = shared_and_alone(scene, values, point="P", analyses=("curve",))
    assert shared == alone
    assert shared["status"] == "failed" and "mode.near: [2, 3] is not close to a configuration" in shared["reason"]


def test_a_transmission_free_of_a_swept_dimension_is_the_designs():
    """The transmission angle at B, between BA and BD, is the same wherever the coupler point (p, q)
    is: by the law of cosines cos = (l^2 + m^2 - |AD|^2) / (2 l m), least at theta = 0 (|AD| = d - a
    = 7/2: 3/7), greatest at 180 (|AD| = d + a = 9/2: 1/21), for a = 1/2, l = 3, m = 7/2, d = 4."""
    values = {"a": Fraction(1, 2), "p": Fraction(0), "q": Fraction(1)}
    shared, alone = shared_and_alone(FOURBAR, values, point="P", analyses=("transmission",))
    assert shared == alone
    assert (shared["status"], shared["transmission_min_exact"], shared["transmission_max_exact"]) == \
        ("ok", "180*acos(3/7)/pi", "180*acos(1/21)/pi")
    assert (shared["transmission_min_at_deg"], shared["transmission_max_at_deg"]) == (0.0, 180.0)


def test_a_scene_driven_by_a_length_sweeps_as_each_design_alone(tmp_path):
    """piston-driven-crank's piston B = (x, 0) is placed at its input's value x, in 2..4: a check of
    B's coordinates moves with the input, so no family checks it without compiling; the sweep runs
    (it stopped on a TypeError) and writes what each design alone gives: with r = 1 and l = 3,
    |OB| = x runs from l - r to l + r, the crank turning through its two dead centres."""
    grid = ["r=1:2:2", "l=3:4:2"]
    shared = sweep("piston-driven-crank", tmp_path / "shared", grid=grid, analyses=["curve"], executor="serial")
    alone = sweep("piston-driven-crank", tmp_path / "alone", grid=grid, analyses=["curve"], executor="serial",
                  share=False)
    assert shared.counts == alone.counts
    assert without_timings(read_dataset(tmp_path / "shared")).equals(without_timings(read_dataset(tmp_path / "alone")))
    assert read_dataset(tmp_path / "shared").column("status").to_pylist()[0] == "ok"


def test_a_family_that_cannot_be_made_leaves_each_design_its_own(monkeypatch, tmp_path):
    """Whatever stops a family being made (here an error of ours injected into its grid), the sweep
    computes each design alone: the family is a shortcut, never a reason for a sweep to stop."""
    def broken(*args, **kwargs):
        raise TypeError("injected")

    monkeypatch.setattr("algkin.sweep.family._Grid.of", broken)
    assert Family.of(FOURBAR, ("a",), "P", analyses=ANALYSES) is None
    done = sweep("fourbar", tmp_path / "out", grid=["a=1/2:1:2"], analyses=["curve"], executor="serial")
    assert done.counts == {"ok": 2}


def test_a_dimension_given_by_a_swept_one_moves_with_it():
    """The rocker given by the crank (m = a + 5/2): each design's own scene moves m with a; a family
    compiled with a symbolic would keep m at its default's 3 (found: every row's curve differed)."""
    scene = load_scene_text(FOURBAR_TEXT.replace('m = "7/2"', 'm = "a + 5/2"'))
    assert Family.of(scene, ("a",), "P", analyses=("curve",)) is None
    shared, alone = shared_and_alone(scene, {"a": Fraction(1)}, point="P", analyses=("curve", "grashof"))
    assert shared == alone and shared["grashof_margin"] == "3/2"   # s + L = 1 + 4, p + q = 3 + 7/2


def test_a_scene_with_points_placed_by_side_has_no_family():
    """Peaucellier-Lipkin's inversor places its points by side: the design's own path checks the side
    on each design's motion, so every design takes it."""
    scene = load_scene("peaucellier-lipkin")
    assert Family.of(scene, ("s",), "P", analyses=("curve",)) is None
