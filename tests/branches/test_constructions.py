"""Each construction's branch algebra lives in the branches layer, picked by the spec's type; the
scene layer's specs describe geometry only (issue 31)."""

from dataclasses import dataclass

import pytest

import algkin.branches
from algkin.branches.constructions import DyadAlgebra, MirrorAlgebra, SliderAlgebra, algebra_of
from algkin.branches.stable import StableBranch
from algkin.scene import compile_scene, load_scene
from algkin.scene.implicit import DyadSpec, ImplicitSpec, MirrorSpec, SliderSpec


def test_each_construction_gets_its_own_algebra():
    # peaucellier-lipkin.toml: B a dyad, D and P the circles' other intersections (of B's, and at A)
    cell = compile_scene(load_scene("peaucellier-lipkin"))
    assert [(s.point, type(algebra_of(s))) for s in cell.implicit] == \
        [("B", DyadAlgebra), ("D", MirrorAlgebra), ("P", MirrorAlgebra)]
    (slider,) = compile_scene(load_scene("slider-crank"), ["B"]).implicit
    assert type(algebra_of(slider)) is SliderAlgebra


def test_a_spec_without_branch_algebra_is_refused_by_name():
    @dataclass(frozen=True)
    class Unheard(ImplicitSpec):
        labels = ()
        never_meets = ""

        def written(self):
            return []

        def start_parts(self):
            return ()

        @staticmethod
        def start(parts, sigma):
            return parts[0], parts[1]

    with pytest.raises(TypeError, match="no branch algebra for Unheard"):
        algebra_of(Unheard("X", ("X_x", "X_y"), "left"))


@pytest.mark.parametrize("spec", [ImplicitSpec, DyadSpec, SliderSpec, MirrorSpec])
def test_the_scene_layer_specs_hold_no_branch_algebra(spec):
    assert not {"closed_form", "toggle_conditions", "stable_evaluator"} & set(dir(spec))


def test_branches_exports_its_own_names_only():
    assert "reduce_on_circles" not in algkin.branches.__all__
    assert not hasattr(algkin.branches, "reduce_on_circles")


def test_a_compiled_scene_lists_its_implicit_points_once_and_a_stable_branch_its_evaluators():
    compiled = compile_scene(load_scene("peaucellier-lipkin"))
    assert not hasattr(compiled, "dyads")  # it duplicated ``implicit`` (the dyads among them)
    stable = StableBranch(compiled, algkin.branches.closed_forms(compiled)[0])
    assert [e.unknowns for e in stable.evaluators] == [("B_x", "B_y"), ("D_x", "D_y"), ("P_x", "P_y")]
    assert not hasattr(stable, "dyads")  # it held the sliders' and second intersections' too
