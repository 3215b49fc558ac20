"""Misuse of the Python API raises algkin's own errors, naming the argument (issue: hostile input)."""

from fractions import Fraction

import attrs
import pytest
import sympy

import algkin
from algkin.errors import AlgkinError, SceneError, UsageError
from algkin.scene import load_scene
from algkin.scene.constructions import Dyad


def test_extremum_stays_a_function_after_its_first_call():
    first = algkin.extremum("arm-string", "AB", (0, 180))
    second = algkin.extremum("arm-string", "AB", (0, 180))  # was the submodule: "'module' object is not callable"
    assert callable(algkin.extremum)
    assert first.minimum.value == second.minimum.value


@pytest.mark.parametrize("argument, value", [("outputs", "PB"), ("params", "ad")])
def test_a_string_for_a_list_of_names_is_refused(argument, value):
    # "PB" used to be split into the outputs P and B.
    with pytest.raises(UsageError, match=f"{argument}='{value}'"):
        algkin.derive("fourbar", **{argument: value}, samples=0)


@pytest.mark.parametrize("argument, value", [
    ("samples", "3"), ("samples", 2.5), ("samples", -1), ("samples", True), ("samples", 10**9),
    ("seed", -1), ("seed", "0"), ("seed", 2**64), ("budget", 5),
])
def test_bad_numbers_and_budgets_name_the_argument(argument, value):
    with pytest.raises(UsageError, match=f"^{argument}="):
        algkin.derive("chebyshev-lambda", outputs=["B"], **{argument: value})


@pytest.mark.parametrize("call, said", [
    (lambda: algkin.derive("chebyshev-lambda", outputs=["B"], samples=0, certify="no"),  # was taken as True
     "certify='no': expected True or False"),
    (lambda: algkin.extremum("arm-string", "AB", largest="no"), "largest='no': expected True or False"),
    (lambda: algkin.derive("chebyshev-lambda", outputs=["B"], samples=10**5000),  # past 4300 digits: a ValueError
     "samples=<an int of 16610 bits>: expected a whole number"),
    (lambda: algkin.prepare("fourbar", deadline=10), "deadline=10: expected an algkin.Budget"),  # was named budget=
], ids=["certify", "largest", "huge-samples", "prepare-deadline"])
def test_a_flag_or_number_that_is_not_one_is_refused_naming_it(call, said):
    with pytest.raises(UsageError) as caught:
        call()
    assert str(caught.value).startswith(said)


def test_a_numpy_bool_is_a_flag():
    import numpy as np

    assert algkin.derive("chebyshev-lambda", outputs=["B"], samples=0, certify=np.bool_(False)).certified == (None, None)


def test_curve_of_a_point_that_is_not_a_name():
    with pytest.raises(UsageError, match="^point=3: not a point"):
        algkin.curve("chebyshev-lambda", 3)


def test_a_scene_that_is_not_a_scene():
    with pytest.raises(UsageError, match="scene=3.5"):
        algkin.derive(3.5)


def test_hand_built_scene_with_an_unknown_point_is_a_scene_error():
    scene = load_scene("chebyshev-lambda")
    broken = attrs.evolve(scene, points={**scene.points, "B": Dyad(("A", "Z"), (1, 1), "left")})
    with pytest.raises(SceneError, match="unknown point 'Z'"):
        algkin.derive(broken, outputs=["B"], samples=0)


def test_hand_built_scene_with_int_parameters_works():
    scene = load_scene("fourbar")
    changed = attrs.evolve(scene, parameters={**scene.parameters, "a": 3})
    result = algkin.derive(changed, outputs=["B"], samples=2, certify=False)
    assert result.compiled.parameter_values["a"] == 3
    assert result.verification.passed


def test_load_with_a_mapping_of_params_is_refused():
    # {"a": 1.5} silently made a symbolic and ignored 1.5.
    with pytest.raises(UsageError, match="params="):
        algkin.load_quantities("fourbar", params={"a": 1.5})


def test_every_error_is_an_algkin_error():
    for call in (lambda: algkin.derive("chebyshev-lambda", outputs="B"),
                 lambda: algkin.load_quantities(None),
                 lambda: algkin.extremum("arm-string", "AB", ("a", "b"))):
        with pytest.raises(AlgkinError):
            call()


def test_symbolic_outputs_read_back_through_parse_expr():
    # The JSON's expression strings read back with sympy.parse_expr to the same expression (docs/cli/derive.md).
    result = algkin.derive("fourbar", outputs=["B"], params=["a", "l"], samples=0)
    document = result.to_json()
    expressions = [(document["eliminants"][u], e.polynomial) for u, e in result.eliminations.items()]
    expressions += [(text, eq) for text, eq in zip(document["system"]["equations"], result.compiled.system.equations)]
    for branch, written in zip(result.branches, document["branches"]):
        expressions += [(written["values"][u], v) for u, v in branch.values.items()]
    assert len(expressions) > 6
    for text, expr in expressions:
        plain = expr.xreplace({s: sympy.Symbol(s.name) for s in expr.free_symbols})  # parse_expr's symbols
        assert sympy.simplify(sympy.parse_expr(text) - plain) == 0, text


@pytest.mark.parametrize("argument", ["outputs", "params"])
def test_a_name_given_twice_is_refused_before_any_work(argument):
    """sympy refused the repeated generator only after the work before it (37 s for 10,000 copies)."""
    names = ["B"] * 10_000 if argument == "outputs" else ["a"] * 10_000
    with pytest.raises(UsageError, match=rf"{argument}='{names[0]}': given twice"):
        algkin.derive("fourbar", **{argument: names}, samples=0)


def test_a_huge_integer_set_is_refused_in_one_line_by_its_size():
    """2**100000 has more digits than Python writes (a bare ValueError before)."""
    with pytest.raises(UsageError, match=r"^set='a=<an integer of 100001 bits>': number too large") as caught:
        algkin.derive("fourbar", outputs=["B"], set={"a": sympy.Integer(2) ** 100000})
    assert len(str(caught.value)) < 200


@pytest.mark.parametrize("value", [2**100000, sympy.Rational(1, 3**70000)], ids=["integer", "fraction"])
def test_a_huge_value_for_an_unknown_name_is_shown_by_its_size(value):
    with pytest.raises(UsageError, match=r"^set='zz=<an? \w+ of \d+ bits>': not a parameter"):
        algkin.derive("fourbar", outputs=["B"], set={"zz": value}, samples=0)


def test_a_bound_size_value_set_exactly_still_does():
    """Within the scene language's bounds (numbers of 1024 bits, 500 characters), a value of
    numerator and denominator of 600 bits each is still exact."""
    big = 2**600 + 1
    result = algkin.derive("fourbar", outputs=["B"], set={"d": sympy.Rational(4 * big + 1, big)}, samples=0)
    assert result.compiled.parameter_values["d"] == sympy.Rational(4 * big + 1, big)


@pytest.mark.parametrize("text, says", [
    ("1e-1000000000", "decimal exponent out of range"),  # Fraction would compute 10**1000000000 first
    ("1e5000", "decimal exponent out of range"),
    ("1e-400", "more than 1024 bits"),
    ("0." + "0" * 400 + "1", "more than 1024 bits"),
    (str(2**1024), "more than 1024 bits"),
])
def test_an_exact_number_past_the_sizes_read_is_refused_before_it_is_made(text, says):
    from algkin.runtime.validation import NumberTooLarge, rational

    with pytest.raises(NumberTooLarge, match=says):
        rational(text)


def test_an_exact_number_within_the_sizes_is_read_exactly():
    from algkin.runtime.validation import rational

    assert rational("1e-300") == Fraction(1, 10**300)
    assert rational(str(2**1024 - 1)) == 2**1024 - 1
    assert rational(" 2.5e-1 ") == Fraction(1, 4)


@pytest.mark.parametrize("argument, value", [("method", ["linear"]), ("backend", {"flint": 1}), ("method", None)])
def test_a_method_or_backend_that_is_not_a_name_is_refused_by_name(argument, value):
    # a list or a dict was a TypeError (unhashable) from the table's lookup
    with pytest.raises(UsageError, match=f"^{argument}=.*unknown elimination {argument}"):
        algkin.derive("chebyshev-lambda", outputs=["B"], samples=0, **{argument: value})


@pytest.mark.parametrize("angle_range", [5, (), (0,), (0, 90, 180), "0:90", (0, "1e999999999"), (0, 2**2000)],
                         ids=["number", "empty", "one", "three", "text", "huge-exponent", "huge-integer"])
def test_an_extremum_range_that_is_not_two_numbers_of_a_readable_size_is_refused(angle_range):
    # a number or a pair too short or long was a TypeError or ValueError from unpacking it; "1e999999999"
    # was read exactly as 10**999999999, minutes of work before any answer
    with pytest.raises(UsageError, match="^angle_range="):
        algkin.extremum("arm-string", "AB", angle_range)


def test_compile_scene_takes_a_catalog_name_and_refuses_what_is_not_a_scene():
    # algkin.compile_scene("fourbar") was an AttributeError ('str' object has no attribute 'unknown_points')
    compiled = algkin.compile_scene("chebyshev-lambda", ["B"])
    assert [str(u) for u in compiled.system.unknowns] == ["B_x", "B_y"]
    with pytest.raises(UsageError, match="^scene=42: expected a catalog name"):
        algkin.compile_scene(42)


@pytest.mark.parametrize("seconds", ["5", None, [5]], ids=["text", "none", "list"])
def test_a_budget_of_seconds_that_is_not_a_number_is_refused_by_name(seconds):
    # Budget(seconds="5") was a TypeError from comparing it with 0; None there means no time budget
    if seconds is None:
        assert algkin.Budget(seconds=None).seconds is None
        return
    with pytest.raises(UsageError, match="^seconds="):  # its own name, as the other arguments' (was max_seconds=)
        algkin.Budget(seconds=seconds)


@pytest.mark.parametrize("clock, said", [
    ("x", "clock='x': expected a function giving seconds"),  # a TypeError when started
    (None, "clock=None: expected a function giving seconds"),
    (lambda: "x", "clock='x': a clock's reading must be a number of seconds"),  # a TypeError at its next reading
], ids=["text", "none", "reading-text"])
def test_a_budget_clock_that_is_no_clock_is_refused_naming_it(clock, said):
    with pytest.raises(UsageError) as caught:
        algkin.derive("chebyshev-lambda", outputs=["B"], samples=0, budget=algkin.Budget(seconds=5, clock=clock))
    assert str(caught.value).startswith(said)


def test_a_terms_budget_that_is_not_one_is_refused_by_its_name():
    with pytest.raises(UsageError, match="^terms=0: a terms budget must be a positive integer"):  # was max_terms=
        algkin.Budget(terms=0)
