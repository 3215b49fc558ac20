"""The strategies draw what they promise: the Grashof class by the rule, scenes that assemble."""

import collections
import importlib.metadata
import os
import subprocess
import sys
from pathlib import Path

import pytest
import sympy
from hypothesis import given, settings, strategies as st

from algkin.branches import check_assembly, closed_forms
from algkin.scene import compile_scene
from algkin.scene.constructions import Slider
from algkin.scene.implicit import MirrorSpec
from algkin.testing import strategies
from algkin.analyses.toggles import grashof

ROOT = Path(__file__).resolve().parents[2]
# algkin.analyses.toggles names the classes in words; the strategies' kinds are identifiers.
WORDS = {"crank-rocker": "crank-rocker", "double-crank": "double crank", "double-rocker": "double rocker",
         "rocker-crank": "rocker-crank", "change-point": "change point",
         "non-grashof": "non-grashof (triple rocker)"}


def by_the_rule(bars):
    """Grashof's rule, from the textbook: shortest + longest against the other two."""
    s, u, v, w = sorted(bars.values())
    if s + w > u + v:
        return "non-grashof"
    if s + w == u + v:
        return "change-point"
    shortest = min(bars, key=bars.get)
    return {"crank": "crank-rocker", "ground": "double-crank", "coupler": "double-rocker",
            "rocker": "rocker-crank"}[shortest]


@settings(max_examples=300)
@given(st.data())
def test_lengths_are_of_the_asked_class(data):
    kind = data.draw(st.sampled_from(strategies.GRASHOF_KINDS))
    bars = data.draw(strategies.four_bar_lengths(kind))
    assert by_the_rule(bars) == kind
    s, u, v, w = sorted(bars.values())
    assert w < s + u + v and s > 0  # closes: some configuration exists


@settings(max_examples=100)
@given(st.data())
def test_scenes_are_of_the_asked_class_and_assemble(data):
    kind = data.draw(st.sampled_from(strategies.GRASHOF_KINDS))
    compiled = compile_scene(data.draw(strategies.four_bars(kind)), ["B"])
    assert grashof(compiled)["class"] == WORDS[kind]
    check_assembly(compiled, closed_forms(compiled))  # raises SceneError if it never assembles


@settings(max_examples=60)
@given(strategies.near_toggle_four_bars(digits=(3, 8)))
def test_near_toggle_four_bars_are_crank_rockers_just_short_of_the_change_point(scene):
    bars = [scene.parameters[n] for n in "aglm"]
    margin = sorted(bars)[1] + sorted(bars)[2] - min(bars) - max(bars)
    assert min(bars) == bars[0] and margin in {sympy.Rational(1, 10**k) for k in range(3, 9)}


def test_scenes_draw_every_construction():
    # Over a sample of draws: sliders on a fixed and on a moving line, inversor kites and cells
    # (compiled with a mirrored point: the twin E, and the cell's P), and angle outputs.
    seen = collections.Counter()

    @settings(max_examples=300, database=None)
    @given(strategies.scenes())
    def draw(scene):
        b = scene.points["B"]
        seen["fixed line"] += isinstance(b, Slider) and b.direction is not None
        seen["moving line"] += isinstance(b, Slider) and b.toward is not None
        if isinstance(b, Slider) and b.toward is not None:
            seen[f"moving line {b.through} to {b.to}"] += 1
        seen[scene.name] += scene.name.startswith("inversor")
        if "E" in scene.points:
            mirrored = [s.point for s in compile_scene(scene, ["B", "P"]).implicit if isinstance(s, MirrorSpec)]
            seen["mirrored E"] += "E" in mirrored
            seen["mirrored P"] += "P" in mirrored
        seen["angle output"] += "phi" in scene.outputs

    draw()
    kinds = ["fixed line", "moving line", "inversor-kite", "inversor-cell", "mirrored E", "mirrored P", "angle output"]
    assert all(seen[kind] >= 5 for kind in kinds), str(sorted(seen.items()))
    # every line (through L toward A, or through A toward L) at a distance from each point (L, A, Q)
    assert all(seen[f"moving line {through} to {to}"] for through in "LA" for to in "LAQ"), str(sorted(seen.items()))
    assert seen["mirrored E"] == seen["inversor-kite"] + seen["inversor-cell"]  # B and P built: E is B's twin
    assert seen["mirrored P"] == seen["inversor-cell"]


@settings(max_examples=40)
@given(st.one_of(strategies.moving_sliders(), strategies.inversors()))
def test_moving_sliders_and_inversors_assemble(scene):
    compiled = compile_scene(scene, ["B", "P"])
    check_assembly(compiled, closed_forms(compiled))  # raises SceneError if never, or a mirror on the wrong side


def run(code, **env):
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          env=dict(os.environ, PYTHONPATH=str(ROOT), **env))


def test_import_algkin_does_not_import_hypothesis():
    result = run("import sys, algkin; algkin.derive; print('hypothesis' in sys.modules)")
    assert result.returncode == 0 and result.stdout.strip() == "False", result.stderr


def test_without_hypothesis_the_message_says_what_to_install():
    # None in sys.modules makes the import fail as if hypothesis were not installed.
    result = run("import sys; sys.modules['hypothesis'] = None; import algkin.testing")
    assert result.returncode != 0
    assert "ModuleNotFoundError: algkin.testing needs hypothesis" in result.stderr
    assert "pip install 'algkin[test]'" in result.stderr


def test_hypothesis_knows_the_scene_type_through_the_entry_point():
    hooks = [e.value for e in importlib.metadata.entry_points(group="hypothesis") if e.name == "algkin"]
    assert hooks == ["algkin.testing.hook:setup"]
    # A fresh process: nothing but hypothesis's own import registers the strategy.
    result = run("from hypothesis import given, settings, strategies as st\n"
                 "from algkin.scene import Scene\n"
                 "seen = []\n"
                 "@settings(max_examples=3, database=None)\n"
                 "@given(st.from_type(Scene))\n"
                 "def draw(scene): seen.append(sorted(scene.points))\n"
                 "draw(); print(len(seen), all(('A' in p and 'B' in p) or 'P1' in p for p in seen))")
    assert result.returncode == 0 and result.stdout.split() == ["3", "True"], result.stderr


@pytest.mark.parametrize("kind", ["crank rocker", "grashof"])
def test_unknown_kind_is_refused(kind):
    with pytest.raises(ValueError, match="valid: crank-rocker"):
        strategies.four_bars(kind)


@settings(max_examples=10, deadline=None)
@given(strategies.group_scenes())
def test_group_scenes_are_one_group_of_two_points_solved_together(scene):
    from algkin.scene.groups import compile_groups

    (group,) = compile_groups(scene).groups
    assert scene.name in ("3rpr-drawn", "triad-drawn") and len(group.unknowns) == len(group.equations) == 4
    name, value = strategies.design_input(scene)
    assert scene.inputs[name].lo < value < scene.inputs[name].hi


def test_the_scene_type_draws_points_solved_together_too():
    from hypothesis import Phase, find

    from algkin.scene import Scene

    # the first one found is enough: shrinking it assembled scene after scene (25 s of the suite)
    found = find(st.from_type(Scene), lambda scene: bool(scene.unknown_points),
                 settings=settings(database=None, phases=[Phase.generate]))
    assert found.name in ("3rpr-drawn", "triad-drawn")
