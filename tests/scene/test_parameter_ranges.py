"""A parameter may declare its slider range: ``a = { default = 1, range = [lo, hi] }``."""

import pytest
import sympy

from algkin.errors import SceneError
from algkin.scene import dump_scene, load_scene_text

SCENE = """
[parameters]
a = {spec}
[inputs]
t = {{ range = [0, 360] }}
[points]
O = {{ fixed = [0, 0] }}
A = {{ crank = "O", length = "a", input = "t" }}
[outputs]
A = "A"
"""


def test_a_declared_range_loads_and_dumps_back():
    scene = load_scene_text(SCENE.format(spec='{ default = 1, range = ["1/2", 2] }'), "r.toml")
    assert scene.parameters == {"a": 1} and scene.parameter_ranges == {"a": (sympy.Rational(1, 2), 2)}
    assert load_scene_text(dump_scene(scene), "again.toml") == scene
    assert load_scene_text(SCENE.format(spec="1"), "plain.toml").parameter_ranges == {}


@pytest.mark.parametrize("spec, element", [
    ("{ default = 1, range = [2, 1] }", "parameters.a.range"),
    ("{ default = 1, range = [1] }", "parameters.a.range"),
    ('{ default = 1, range = ["sqrt(2)", 3] }', "parameters.a.range"),
    ("{ range = [1, 2] }", "parameters.a.default"),
    ("{ default = 1, span = [1, 2] }", "parameters.a.span"),
])
def test_a_bad_range_is_one_line_naming_it(spec, element):
    with pytest.raises(SceneError, match=rf"r.toml: {element}: ") as caught:
        load_scene_text(SCENE.format(spec=spec), "r.toml")
    assert "\n" not in str(caught.value)
