"""Modes named by a configuration (``mode = { at, near }``), resolved and followed (algkin.derivation.modes).

Hart's inversor, where the label flips, is in tests/catalog/test_inversors.py; here the cases where
it must not, the scene format and the refusals. Expected configurations are by hand: the catalog
four-bar (a=1, d=4, l=3, m=7/2) at theta = 0 has A = (1, 0), and B on the circles of radius 3 about A
and 7/2 about D = (4, 0): B_x = 1 + (9 - 49/4 + 9) / 6 = 47/24, B_y = +-sqrt(9 - (23/24)**2) = +-2.8428...
(left of A -> D: B_y > 0).
"""

import os

import pytest

import algkin
from algkin.analyses.solve import solve
from algkin.derivation.modes import follow_modes, resolve_modes
from algkin.errors import SceneError
from algkin.scene import dump_scene, load_scene_text

def scene_with(name, *changes):
    """The catalog scene ``name`` with each (old, new) text of ``changes`` replaced."""
    with open(os.path.join(os.path.dirname(algkin.__file__), "catalog", f"{name}.toml")) as handle:
        source = handle.read()
    for old, new in zip(changes[::2], changes[1::2]):
        assert old in source
        source = source.replace(old, new)
    return load_scene_text(source, f"{name}.toml")


def fourbar(mode):
    return scene_with("fourbar", 'branch = "left" }', f"mode = {mode} }}")


@pytest.mark.parametrize("near, label", [("[2, 2.8]", "left"), ("[2, -2.8]", "right")])
def test_a_crank_rocker_mode_followed_through_a_full_turn_is_the_dyads_labelled_branch(near, label):
    scene = resolve_modes(fourbar(f"{{ at = 0, near = {near} }}"))
    assert scene.points["B"].branch == label
    (followed,) = follow_modes(scene)
    assert followed.factor is None  # B's curve is the circle about D: both modes trace it
    assert [(p.lo, p.hi, p.status, dict(p.labels)) for p in followed.pieces] == [(0.0, 360.0, "mode", {"B": label})]
    assert followed.change_points == ()
    derived = algkin.derive(scene, ["B"], samples=0, certify=False)
    assert next(b for b in derived.branches if b.selected).label == label
    assert [c.mode for c in solve(scene, at={"theta": 90}).configurations] == [label]


def test_a_slider_names_its_mode_too():
    scene = resolve_modes(scene_with("slider-crank", 'branch = "ahead" }', "mode = { at = 0, near = [-2, 0.5] } }"))
    assert scene.points["B"].branch == "behind"  # B = (1 - sqrt(9 - 1/4), 1/2) = (-1.958, 0.5) at theta = 0


def test_with_two_inputs_the_mode_is_named_at_both_and_kept_by_its_label():
    scene = scene_with("five-bar", 'branch = "left" }', "mode = { at = { t1 = 90, t2 = 90 }, near = [1, -0.8] } }")
    # A1 = (0, 2), A2 = (2, 2): P = (1, 2 -+ 2 sqrt(2)), the lower one right of A1 -> A2
    assert resolve_modes(scene).points["P"].branch == "right"
    found = solve(scene, at={"t1": 90, "t2": 90})
    assert [c.mode for c in found.configurations] == ["right"] and found.left_out == 1


def test_a_scene_with_modes_writes_back_as_it_reads():
    for scene in (fourbar("{ at = 0, near = [2, 2.8] }"),
                  scene_with("five-bar", 'branch = "left" }', "mode = { at = { t1 = 90, t2 = 45 }, near = [1, 4] } }"),
                  load_scene_text('[inputs]\nr = { range = [1, 2], unit = "length" }\n[points]\nA = { fixed = [0, 0] }\n'
                                  'P = { unknown = true, mode = { at = "3/2", near = [0, 1] } }\n'
                                  '[constraints]\nc = "dist(A, P) = r"\n')):
        assert load_scene_text(dump_scene(scene)) == scene


@pytest.mark.parametrize("mode, element, said", [
    ("{ at = 0, near = [1.958, 0] }", "points.B.mode.near",
     "is not close to a configuration of B at theta = 0°: the nearest is [1.95833, "),
    ("{ at = 0, near = [2, 2.8], extra = 1 }", "points.B.mode.extra", "unknown key (expected at, near)"),
    ("{ at = { theta = 0, phi = 1 }, near = [2, 2.8] }", "points.B.mode.at.phi", "expected a value for each input"),
    ("{ at = 0, near = [2, \"q\"] }", "points.B.mode.near", "unknown name 'q'"),
])
def test_bad_modes_are_refused_naming_the_element(mode, element, said):
    with pytest.raises(SceneError) as caught:
        resolve_modes(fourbar(mode))
    assert caught.value.element == element and said in caught.value.message, str(caught.value)


def test_a_mode_named_where_its_two_configurations_meet_is_refused():
    # d = 5, l = m = 3: at theta = 180, A = (-1, 0) and |AD| = 6 = l + m, B's circles touch at (2, 0)
    scene = scene_with("fourbar", "d = 4", "d = 5", 'm = "7/2"', "m = 3", 'branch = "left" }',
                       "mode = { at = 180, near = [2, 0] } }")
    with pytest.raises(SceneError, match=r"points\.B\.mode\.at: B is at a toggle"):
        resolve_modes(scene)


def test_several_inputs_need_a_table_for_at():
    with pytest.raises(SceneError, match=r"points\.P\.mode\.at: expected a table \{ t1 = \.\., t2 = \.\. \}"):
        scene_with("five-bar", 'branch = "left" }', "mode = { at = 90, near = [1, 4] } }")


def test_the_other_intersection_of_two_circles_has_no_mode_to_name():
    scene = scene_with("peaucellier-lipkin", 'lengths = ["s", "s"], branch = "left" }',
                       'lengths = ["s", "s"], mode = { at = 0, near = [3, 0] } }')
    with pytest.raises(SceneError, match=r"points\.P\.mode: P's circles pass through an earlier point"):
        resolve_modes(scene)
