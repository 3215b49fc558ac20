"""SceneBuilder: the same Scene as the TOML, a round trip through dump_scene, the same errors."""

import re
from fractions import Fraction
from pathlib import Path

import pytest
import sympy
from hypothesis import given, settings, strategies as st

try:
    import tomllib
except ModuleNotFoundError:  # Python 3.10
    import tomli as tomllib

import algkin
from algkin.errors import SceneError
from algkin.scene import Scene, SceneBuilder, catalog_names, dump_scene, load_scene, load_scene_text
from algkin.scene.constructions import CONSTRUCTIONS, Crank, Dyad, Fixed, Frame, Slider
from algkin.testing import strategies

ROOT = Path(__file__).resolve().parents[2]
CATALOG = ROOT / "algkin" / "catalog"


# -- by hand: each TOML table of the catalog file is one call --------------------------------------

def chebyshev_lambda():
    b = SceneBuilder("chebyshev-lambda", "Chebyshev lambda linkage: crank 1, ground 2, rocker 5/2, coupler 5.",
                     unit="mm")
    b.input("angle", range=(0, 360), unit="deg")
    b.fixed("O", (0, 0))
    b.fixed("D", (2, 0))
    b.crank("A", "O", length=1, input="angle")
    b.dyad("B", ("A", "D"), lengths=("5/2", Fraction(5, 2)), branch="left")
    b.frame("P", ("A", "B"), at=(2, 0))
    b.output("P")
    return b.build()


def fourbar():
    b = SceneBuilder("fourbar", "General four-bar: crank a, ground d, coupler l, rocker m, coupler point (p, q) "
                                "in the frame of AB; defaults a Grashof crank-rocker.")
    for name, value in dict(a=1, d=4, l=3, m="7/2", p=sympy.Rational(1, 2), q=0.5).items():
        b.parameter(name, value)
    b.input("theta", range=[0, 360], unit="deg")
    b.fixed("O", [0, 0])
    b.fixed("D", ["d", 0])
    b.crank("A", "O", length="a", input="theta")
    b.dyad("B", ["A", "D"], lengths=["l", "m"], branch="left")
    b.point("P", frame=["A", "B"], at=["p", "q"])  # the generic form of the same table
    b.output("B")
    b.output("P")
    return b.build()


def slider_crank():
    b = SceneBuilder("slider-crank", "Offset slider-crank: crank r about O, connecting rod l, slider B on the "
                                     "line y = e.")
    b.parameter("r", 1)
    b.parameter("l", 3)
    b.parameter("e", "1/2")
    b.input("theta")  # range [0, 360] and degrees: the file's defaults
    b.fixed("O", (0, 0))
    b.fixed("L", (0, "e"))
    b.crank("A", "O", length="r", input="theta")
    b.slider("B", dict(through="L", direction=(1, 0)), distance=dict(to="A", length="l"), branch="ahead")
    b.frame("M", ("A", "B"), at=("1/2", 0))
    b.output("x", "B.x")
    return b.build()


def watt_i():
    b = SceneBuilder("watt-i", "Watt I six-bar: a crank-rocker four-bar whose ternary crank and coupler are "
                               "joined by a dyad; P on the dyad's link EF.")
    b.input("theta", range=(0, 360), unit="deg")
    b.fixed("O", (0, 0))
    b.fixed("D", (4, 0))
    b.crank("A", "O", length=1, input="theta")
    b.frame("E", ("O", "A"), at=(1, -1))
    b.dyad("B", ("A", "D"), lengths=(3, "7/2"), branch="left")
    b.frame("C", ("A", "B"), at=("1/2", "1/2"))
    b.dyad("F", ("E", "C"), lengths=(2, "3/2"), branch="left")
    b.frame("P", ("E", "F"), at=("1/2", "1/4"))
    b.output("P")
    return b.build()


def arm_string():
    b = SceneBuilder("arm-string", "Arm OA about O pulled by a string from A around the fixed point B.", unit="mm")
    for name, value in dict(a=400, b=80, r=350, g=120).items():
        b.parameter(name, value)
    b.input("theta", range=(0, 180), unit="deg")
    b.fixed("O", (0, 0))
    b.fixed("B", ("a", "-b"))
    b.crank("A", "O", length="r", input="theta", phase=-90)
    b.frame("G", ("O", "A"), at=("g/r", 0))
    b.output("AB", "dist(A, B)")
    return b.build()


def inverted_slider_crank():
    b = SceneBuilder("inverted-slider-crank", load_scene("inverted-slider-crank").description)
    for name, value in dict(r=2, c=5, k=2).items():
        b.parameter(name, value)
    b.input("theta", range=(0, 360), unit="deg")
    b.fixed("O", (0, 0))
    b.fixed("C", ("c", 0))
    b.crank("A", "O", length="r", input="theta")
    b.slider("H", dict(through="C", toward="A"), distance=dict(to="C", length="k"), branch="ahead")
    b.output("H")
    b.output("stroke", "dist(A, C)")
    b.output("swing", "angle(C, A)")
    return b.build()


BY_HAND = {"chebyshev-lambda": chebyshev_lambda, "fourbar": fourbar, "slider-crank": slider_crank,
           "watt-i": watt_i, "arm-string": arm_string, "inverted-slider-crank": inverted_slider_crank}


@pytest.mark.parametrize("name", sorted(BY_HAND))
def test_a_scene_built_by_hand_is_the_catalog_scene(name):
    built = BY_HAND[name]()
    assert isinstance(built, Scene)
    assert built == load_scene(name)
    assert dump_scene(built) == dump_scene(load_scene(name))


# -- from data: every table of a parsed file, one call each ----------------------------------------

def rebuild(data, source="<scene>"):
    """A builder call per table of ``data`` (a scene file as ``tomllib`` parses it)."""
    b = SceneBuilder(data["name"], data.get("description", ""), source=source, unit=data.get("unit", ""))
    for name, value in data.get("parameters", {}).items():
        if isinstance(value, dict):
            b.parameter(name, **value)
        else:
            b.parameter(name, value)
    for name, spec in data.get("inputs", {}).items():
        b.input(name, **spec)
    for name, spec in data.get("points", {}).items():
        kind = next(key for key in spec if key in CONSTRUCTIONS)
        getattr(b, kind)(name, **spec)  # the construction's key names its first argument
    for name, text in data.get("constraints", {}).items():
        b.constraint(name, text)
    for name, text in data.get("outputs", {}).items():
        b.output(name, text)
    return b


@pytest.mark.parametrize("name", catalog_names())
def test_every_catalog_scene_rebuilt_from_its_tables_is_the_catalog_scene(name):
    text = (CATALOG / f"{name}.toml").read_text(encoding="utf-8")
    built = rebuild(tomllib.loads(text)).build()
    assert built == load_scene(name)
    assert load_scene_text(dump_scene(built)) == built  # (b) the round trip


@pytest.mark.parametrize("name", sorted(BY_HAND))
def test_a_built_scene_round_trips_through_dump_scene(name):
    built = BY_HAND[name]()
    assert load_scene_text(dump_scene(built)) == built


def test_the_builder_gives_the_data_a_parsed_file_gives():
    text = (CATALOG / "slider-crank.toml").read_text(encoding="utf-8")
    data = tomllib.loads(text)
    b = rebuild(data)
    assert b.data() == data
    assert b.data() is not b.data()  # a copy: changing it changes nothing built later


# -- (c) properties: random scenes, dumped and rebuilt --------------------------------------------

@settings(max_examples=40, database=None)
@given(st.from_type(Scene))
def test_a_drawn_scene_rebuilt_from_its_dumped_tables_is_equal(scene):
    built = rebuild(tomllib.loads(dump_scene(scene))).build()
    assert built == scene
    assert dump_scene(built) == dump_scene(scene)


def from_scene(scene):
    """A builder call per element of a Scene, with its sympy values as they are."""
    b = SceneBuilder(scene.name, scene.description)
    for name, value in scene.parameters.items():
        b.parameter(name, value, range=scene.parameter_ranges.get(name))
    for name, i in scene.inputs.items():
        b.input(name, range=(i.lo, i.hi), unit=i.unit)
    for name, c in scene.points.items():
        if isinstance(c, Fixed):
            b.fixed(name, (c.x, c.y))
        elif isinstance(c, Crank):
            b.crank(name, c.center, length=c.length, input=c.input, phase=90 * c.quarter_turns)
        elif isinstance(c, Dyad):
            b.dyad(name, c.bases, lengths=c.lengths, branch=c.branch)
        elif isinstance(c, Frame):
            b.frame(name, c.bases, at=c.at)
        else:
            assert isinstance(c, Slider)
            b.slider(name, dict(through=c.through, direction=c.direction, toward=c.toward),
                     distance=dict(to=c.to, length=c.length), branch=c.branch)
    for name, output in scene.outputs.items():
        b.output(name, output.text)
    return b


@settings(max_examples=40, database=None)
@given(strategies.with_ranges())
def test_a_drawn_scene_rebuilt_from_its_sympy_values_is_equal(scene):
    assert from_scene(scene).build() == scene


# -- (d) bad input: the file's error, word for word -------------------------------------------------

SOURCE = "bad"
HEAD = {"parameters": ['l = 2'], "inputs": ['t = { range = [0, 360] }'],
        "points": ['O = { fixed = [0, 0] }', 'A = { crank = "O", length = 1, input = "t" }'], "outputs": ['A = "A"']}


def base():
    b = SceneBuilder(SOURCE, source=SOURCE)
    b.parameter("l", 2)
    b.input("t", range=(0, 360))
    b.fixed("O", (0, 0))
    b.crank("A", "O", length=1, input="t")
    b.output("A")
    return b


def toml(**more):
    lines = [f'name = "{SOURCE}"']
    for table in ("parameters", "inputs", "points", "outputs"):
        lines += [f"[{table}]", *HEAD[table], *more.get(table, [])]
    return "\n".join(lines) + "\n"


# (id, the lines added to the file's tables, the same mistake as builder calls)
MISTAKES = [
    ("unknown point", {"points": ['B = { dyad = ["A", "X"], lengths = [1, 1] }']},
     lambda b: b.dyad("B", ("A", "X"), lengths=(1, 1))),
    ("unknown point in an output", {"outputs": ['Q = "Q.x"']}, lambda b: b.output("Q", "Q.x")),
    ("unknown slider point", {"points": ['B = { slider = { through = "Z", direction = [1, 0] }, '
                                         'distance = { to = "A", length = 3 } }']},
     lambda b: b.slider("B", dict(through="Z", direction=(1, 0)), distance=dict(to="A", length=3))),
    ("bad length expression", {"points": ['B = { dyad = ["A", "O"], lengths = ["l +", 1] }']},
     lambda b: b.dyad("B", ("A", "O"), lengths=("l +", 1))),
    ("negative length", {"points": ['B = { dyad = ["A", "O"], lengths = [-1, 1] }']},
     lambda b: b.dyad("B", ("A", "O"), lengths=(-1, 1))),
    ("a call in an expression", {"points": ['B = { fixed = ["__import__(1)", 0] }']},
     lambda b: b.fixed("B", ("__import__(1)", 0))),
    ("unknown name in an expression", {"points": ['B = { fixed = ["q", 0] }']}, lambda b: b.fixed("B", ("q", 0))),
    ("an infinite float", {"points": ['B = { fixed = [inf, 0] }']}, lambda b: b.fixed("B", (float("inf"), 0))),
    ("a boolean", {"points": ['B = { fixed = [true, 0] }']}, lambda b: b.fixed("B", (True, 0))),
    ("cycle", {"points": ['B = { frame = ["A", "C"], at = [1, 0] }', 'C = { frame = ["B", "O"], at = [1, 0] }']},
     lambda b: (b.frame("B", ("A", "C"), at=(1, 0)), b.frame("C", ("B", "O"), at=(1, 0)))),
    ("unknown construction field", {"points": ['B = { frame = ["A", "O"], at = [1, 0], foo = 1 }']},
     lambda b: b.frame("B", ("A", "O"), at=(1, 0), foo=1)),
    ("unknown field, generic call", {"points": ['B = { frame = ["A", "O"], at = [1, 0], foo = 1 }']},
     lambda b: b.point("B", frame=("A", "O"), at=(1, 0), foo=1)),
    ("no construction", {"points": ['B = { hinge = ["A", "O"] }']}, lambda b: b.point("B", hinge=("A", "O"))),
    ("two constructions", {"points": ['B = { fixed = [0, 1], frame = ["A", "O"] }']},
     lambda b: b.fixed("B", (0, 1), frame=("A", "O"))),
    ("unknown slider field", {"points": ['B = { slider = { through = "O", direction = [1, 0], up = 1 }, '
                                         'distance = { to = "A", length = 3 } }']},
     lambda b: b.slider("B", dict(through="O", direction=(1, 0), up=1), distance=dict(to="A", length=3))),
    ("missing slider distance", {"points": ['B = { slider = { through = "O", direction = [1, 0] } }']},
     lambda b: b.slider("B", dict(through="O", direction=(1, 0)))),
    ("missing crank length", {"points": ['B = { crank = "O", input = "t" }']}, lambda b: b.crank("B", "O", input="t")),
    ("missing input", {"points": ['B = { crank = "O", length = 1, input = "u" }']},
     lambda b: b.crank("B", "O", length=1, input="u")),
    ("phase off the quarter turns", {"points": ['B = { crank = "O", length = 1, input = "t", phase = 45 }']},
     lambda b: b.crank("B", "O", length=1, input="t", phase=45)),
    ("bad branch", {"points": ['B = { dyad = ["A", "O"], lengths = [1, 1], branch = "up" }']},
     lambda b: b.dyad("B", ("A", "O"), lengths=(1, 1), branch="up")),
    ("not an identifier", {"points": ['"2B" = { fixed = [0, 0] }']}, lambda b: b.fixed("2B", (0, 0))),
    ("an input named like a parameter", {"inputs": ['l = {}']}, lambda b: b.input("l")),
    ("unknown input field", {"inputs": ['u = { range = [0, 90], speed = 2 }']},
     lambda b: b.input("u", range=(0, 90), speed=2)),
    ("empty input range", {"inputs": ['u = { range = [90, 0] }']}, lambda b: b.input("u", range=(90, 0))),
    ("unknown parameter field", {"parameters": ['k = { default = 1, range = [0, 2], step = 1 }']},
     lambda b: b.parameter("k", 1, range=(0, 2), step=1)),
    ("a parameter named like a coordinate", {"parameters": ['A_x = 1']}, lambda b: b.parameter("A_x", 1)),
    ("a parameter named E", {"parameters": ['E = 1']}, lambda b: b.parameter("E", 1)),
]


@pytest.mark.parametrize("lines, calls", [m[1:] for m in MISTAKES], ids=[m[0] for m in MISTAKES])
def test_a_mistake_gives_the_error_the_file_gives(lines, calls):
    with pytest.raises(SceneError) as from_file:
        load_scene_text(toml(**lines), SOURCE)
    b = base()
    with pytest.raises(SceneError) as from_builder:
        calls(b)
        b.build()
    assert str(from_builder.value) == str(from_file.value)
    assert "\n" not in str(from_builder.value)


@pytest.mark.parametrize("table, calls", [
    ("points", lambda b: b.fixed("O", (1, 1))),
    ("parameters", lambda b: b.parameter("l", 3)),
    ("inputs", lambda b: b.input("t")),
    ("outputs", lambda b: b.output("A", "A.x")),  # each the first name of its table
])
def test_a_name_given_twice_is_refused_by_the_call_that_repeats_it(table, calls):
    # In a file the TOML parser refuses the repeated key (with its line and column).
    first = HEAD[table][0]
    with pytest.raises(SceneError, match="TOML syntax error"):
        load_scene_text(toml(**{table: [first]}), SOURCE)
    with pytest.raises(SceneError) as err:
        calls(base())
    name = first.split(" =")[0]
    assert str(err.value) == f"bad: {table}.{name}: given twice (a table names each entry once)"


def test_a_forward_reference_is_allowed_as_in_a_file():
    b = SceneBuilder("forward", source="forward")
    b.input("t")
    b.crank("A", "O", length=1, input="t")  # O is defined below, as a file may do
    b.fixed("O", (0, 0))
    b.output("A")
    text = 'name = "forward"\n[inputs]\nt = {}\n[points]\nA = { crank = "O", length = 1, input = "t" }\n' \
           'O = { fixed = [0, 0] }\n[outputs]\nA = "A"\n'
    assert b.build() == load_scene_text(text)


def test_a_name_that_is_not_a_string_is_refused_in_one_line():
    with pytest.raises(SceneError, match=r"^bad: points.3: a name is a string, got int$"):
        base().fixed(3, (0, 0))


# -- (2, e) a built scene is a scene everywhere ------------------------------------------------------

def comparable(derivation):
    report = derivation.to_json()
    report.pop("timings")
    return report


def test_derive_on_a_built_scene_is_derive_on_the_catalog_scene():
    built = comparable(algkin.derive(chebyshev_lambda(), outputs=["B"]))
    assert built == comparable(algkin.derive("chebyshev-lambda", outputs=["B"]))
    assert built["verification"]["passed"]


def test_curve_and_load_take_a_built_scene():
    assert (algkin.curve(chebyshev_lambda(), "P").to_json()["curve"]
            == algkin.curve("chebyshev-lambda", "P").to_json()["curve"])
    built = algkin.load_quantities(arm_string(), params=["b"]).dist("A", "B")
    assert built.relation == algkin.load_quantities("arm-string", params=["b"]).dist("A", "B").relation


# -- (4) the docs' example runs ---------------------------------------------------------------------

def test_the_example_in_the_scene_format_docs_runs():
    text = (ROOT / "docs" / "scene-format.md").read_text(encoding="utf-8")
    section = text.split("## From Python", 1)[1]
    code = re.search(r"```python\n(.*?)```", section, re.S).group(1)
    exec(compile(code, "scene-format.md", "exec"), {})


def test_numpy_arrays_and_decimals_build_the_scene_their_numbers_spell():
    """A numpy array was "expected a list of two", a Decimal "expected a number or expression"."""
    import numpy as np
    from decimal import Decimal

    built = SceneBuilder("lambda")
    built.input("angle", range=np.array([0, 360]))
    built.fixed("O", np.array([0.0, 0.0]))
    built.fixed("D", (Decimal("2"), Decimal("0")))
    built.crank("A", "O", length=np.float64(1), input="angle")
    built.dyad("B", ("A", "D"), lengths=np.array([2.5, 2.5]), branch="left")
    built.frame("P", ("A", "B"), at=(Decimal("2.0"), Decimal("0E+3")))
    built.output("P")
    by_hand = SceneBuilder("lambda")
    by_hand.input("angle", range=(0, 360))
    by_hand.fixed("O", (0, 0))
    by_hand.fixed("D", (2, 0))
    by_hand.crank("A", "O", length=1, input="angle")
    by_hand.dyad("B", ("A", "D"), lengths=("5/2", "5/2"), branch="left")
    by_hand.frame("P", ("A", "B"), at=(2, 0))
    by_hand.output("P")
    assert built.build() == by_hand.build()
