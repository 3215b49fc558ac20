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


ABOVE = SCENE.replace("[parameters]\n", "[parameters]\ng = 2\n")  # a's default may be written in g


@pytest.mark.parametrize("spec, value", [('{ default = "g/4", range = ["1/4", 1] }', sympy.Rational(1, 2)),
                                         ('{ default = "g**2 - 3", range = [1, 2] }', 1)])  # on the range's end
def test_a_default_in_other_parameters_inside_its_range_loads(spec, value):
    scene = load_scene_text(ABOVE.format(spec=spec), "r.toml")
    assert scene.parameters["a"].xreplace({sympy.Symbol("g", real=True): 2}) == value


@pytest.mark.parametrize("spec, said", [('{ default = "g/4", range = [1, 2] }', "g/4 = 1/2 is outside its range [1, 2]"),
                                        ('{ default = "g**3 + g", range = [0, 9] }', "= 10 is outside its range [0, 9]")])
def test_a_default_in_other_parameters_outside_its_range_is_refused(spec, said):
    with pytest.raises(SceneError, match=r"r.toml: parameters.a.default: ") as caught:
        load_scene_text(ABOVE.format(spec=spec), "r.toml")
    assert said in str(caught.value) and "\n" not in str(caught.value)


def test_a_default_in_a_default_is_left_to_the_bits_checks():
    # putting p1's value into p5 through p2..p4 would reach 65 * 64**4 bits: only p2, in p1 (a
    # number), is evaluated here
    text = """
[parameters]
p1 = "(2**64 + 1)/2**64"
p2 = { default = "p1**64", range = [1, 2] }
p3 = "p2**64"
p4 = "p3**64"
p5 = { default = "p4**64", range = [0, 1] }
[inputs]
t = { range = [0, 360] }
[points]
O = { fixed = [0, 0] }
A = { crank = "O", length = "p5", input = "t" }
[outputs]
A = "A"
"""
    assert set(load_scene_text(text, "chained.toml").parameter_ranges) == {"p2", "p5"}
