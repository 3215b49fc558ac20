"""Angle outputs (docs/scene-format.md: ``angle(P, Q)``, the direction of PQ; here also ``angle(P, Q, R)``, the
angle at Q): parsing, the names they bring, and the equations they compile to."""

import pytest
import sympy

from algkin.errors import SceneError, UsageError
from algkin.scene import compile_scene, dump_scene, load_scene, load_scene_text
from algkin.scene.builder import SceneBuilder
from algkin.scene.load import parse_output

POINTS = {"O", "A", "B", "D"}

FOURBAR = """
[parameters]
a = 1
d = 4
l = 3
m = "7/2"

[inputs]
theta = { range = [0, 360] }

[points]
O = { fixed = [0, 0] }
D = { fixed = ["d", 0] }
A = { crank = "O", length = "a", input = "theta" }
B = { dyad = ["A", "D"], lengths = ["l", "m"], branch = "left" }
P = { frame = ["A", "B"], at = ["1/2", "1/2"] }

[outputs]
"""


@pytest.mark.parametrize("text, points", [
    ("angle(D, B)", ("D", "B")),
    ("angle(A,B,D)", ("A", "B", "D")),
    ("  angle ( A ,  B , D ) ", ("A", "B", "D")),
])
def test_angle_forms_parse(text, points):
    output = parse_output("phi", text, POINTS)
    assert (output.kind, output.points, output.text) == ("angle", points, text)


@pytest.mark.parametrize("text, words", [
    ("angle(A)", ["angle(P, Q)", "angle(P, Q, R)"]),
    ("angle()", ["angle(P, Q)"]),
    ("angle(A, B, D, O)", ["angle(P, Q, R)"]),
    ("angle(A; B)", ["angle(P, Q)"]),
    ("angle(A, A)", ["no direction", "same point"]),
    ("angle(A, B, B)", ["no angle at B"]),
    ("angle(B, B, D)", ["no angle at B"]),
    ("angle(A, B, A)", ["always 0"]),
    ("angle(A, Z)", ["unknown point 'Z'"]),
    ("angle(Z, B, D)", ["unknown point 'Z'"]),
])
def test_bad_angle_forms_are_one_line_scene_errors(text, words):
    with pytest.raises(SceneError) as caught:
        parse_output("phi", text, POINTS, source="s.toml")
    message = str(caught.value)
    assert "\n" not in message and message.startswith("s.toml: outputs.phi: ")
    for word in words:
        assert word in message


def test_scene_angle_outputs_load_dump_and_build_alike():
    scene = load_scene_text(FOURBAR + 'rocker = "angle(D, B)"\nmu = "angle(A, B, D)"\n', "f.toml")
    assert {n: (o.kind, o.points) for n, o in scene.outputs.items()} == {
        "rocker": ("angle", ("D", "B")), "mu": ("angle", ("A", "B", "D"))}
    assert load_scene_text(dump_scene(scene), "f.toml") == scene
    b = SceneBuilder("f")
    for name, value in (("a", 1), ("d", 4), ("l", 3), ("m", "7/2")):
        b.parameter(name, value)
    b.input("theta", range=(0, 360))
    b.fixed("O", (0, 0))
    b.fixed("D", ("d", 0))
    b.crank("A", "O", length="a", input="theta")
    b.dyad("B", ("A", "D"), lengths=("l", "m"), branch="left")
    b.frame("P", ("A", "B"), at=("1/2", "1/2"))
    b.output("rocker", "angle(D, B)")
    b.output("mu", "angle(A, B, D)")
    assert b.build().outputs == scene.outputs


@pytest.mark.parametrize("parameter, outputs, words", [
    ("cos_phi = 2", 'phi = "angle(D, B)"', ["outputs.phi", "'cos_phi'", "parameter"]),
    ("", 'phi = "angle(D, B)"\ncos_phi = "dist(O, B)"', ["outputs.cos_phi", "'cos_phi'", "output 'phi'"]),
    ("", 'mu = "angle(A, B, D)"\nlen_mu = "dist(O, B)"', ["outputs.len_mu", "'len_mu'", "output 'mu'"]),
])
def test_angle_unknowns_never_merge_with_scene_names(parameter, outputs, words):
    text = FOURBAR.replace("[parameters]\n", f"[parameters]\n{parameter}\n", 1) + outputs + "\n"
    with pytest.raises(SceneError) as caught:
        load_scene_text(text, "f.toml")
    for word in words:
        assert word in str(caught.value)


def test_command_line_angle_unknowns_never_merge_with_parameters():
    scene = load_scene_text(FOURBAR.replace("m = \"7/2\"", "m = \"7/2\"\ncos_angle_D_B = 1") + 'B = "B"\n', "f.toml")
    with pytest.raises(UsageError) as caught:
        compile_scene(scene, ["angle(D, B)"])
    assert str(caught.value).startswith("outputs='angle(D, B)'") and "'cos_angle_D_B'" in str(caught.value)
    assert "parameter" in str(caught.value)


def symbols(*names):
    return [sympy.Symbol(n, real=True) for n in names]


def test_a_bar_divides_a_direction_polynomially():
    # DB is the rocker, of the declared length m: m*cos - (B_x - d) = 0, no helper unknown.
    compiled = compile_scene(load_scene("fourbar"), ["angle(D, B)"], params=["a", "d", "l", "m"])
    d, m, bx, by, cos, sin = symbols("d", "m", "B_x", "B_y", "cos_angle_D_B", "sin_angle_D_B")
    assert compiled.system.unknowns == ("B_x", "B_y", "cos_angle_D_B", "sin_angle_D_B")
    equations = set(compiled.system.equations)
    assert sympy.expand(m * cos - bx + d) in equations and sympy.expand(m * sin - by) in equations
    angle = compiled.angles["angle_D_B"]
    assert (angle.cos, angle.sin, angle.length, angle.helper) == ("cos_angle_D_B", "sin_angle_D_B", m, None)
    assert compiled.outputs["angle_D_B"] == ("cos_angle_D_B", "sin_angle_D_B")


def test_transmission_angle_is_the_law_of_cosines_free_of_the_coupler_point():
    compiled = compile_scene(load_scene("fourbar"), ["angle(A, B, D)"], params=["a", "d", "l", "m"])
    a, d, l, m, c, cos = symbols("a", "d", "l", "m", "c_theta", "cos_angle_A_B_D")
    textbook = sympy.expand(l * m * cos - (l**2 + m**2 - a**2 - d**2 + 2 * a * d * c) / 2)
    assert textbook in set(compiled.system.equations)
    assert compiled.angles["angle_A_B_D"].sin is None


def test_a_side_of_varying_length_brings_a_nonnegative_helper():
    # D -> P: the coupler point's distance from the ground pivot varies.
    compiled = compile_scene(load_scene("fourbar"), ["angle(D, P)"])
    assert compiled.angles["angle_D_P"].helper == "len_angle_D_P"
    assert compiled.system.nonnegative == ("len_angle_D_P",)
    assert "len_angle_D_P" in compiled.system.unknowns


def test_a_coordinate_is_no_length_so_its_sign_is_not_assumed():
    # |OD| = |d|: d is a coordinate, not a declared length, so it stays under the helper's root.
    compiled = compile_scene(load_scene("fourbar"), ["angle(O, D)"], params=["d"])
    assert compiled.angles["angle_O_D"].helper == "len_angle_O_D"


def test_coincident_points_have_no_angle():
    text = FOURBAR.replace('P = {', 'E = { fixed = [0, 0] }\nP = {') + 'phi = "angle(O, E)"\n'
    with pytest.raises(SceneError, match="coincide"):
        compile_scene(load_scene_text(text, "f.toml"))


def test_asking_twice_compiles_once():
    compiled = compile_scene(load_scene("fourbar"), ["angle(D, B)", "angle(D, B)"])
    assert compiled.system.unknowns.count("cos_angle_D_B") == 1
