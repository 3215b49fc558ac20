"""Messages that guide (issue 35, items 4-6): options and the scene in any order, the flag the user
typed named, and the close match of a mistyped name suggested wherever a name is looked up."""

import json

import pytest

from algkin.ui.cli import main


def run(capsys, *args):
    code = main(list(args))
    out, err = capsys.readouterr()
    return code, out, err


def one_error(capsys, *args):
    code, _, err = run(capsys, *args)
    assert code == 2
    assert err.count("\n") == 1 and err.startswith("algkin: error: ")
    return err


def test_a_list_option_before_the_scene_gives_the_scene_back(capsys):
    code, after, _ = run(capsys, "derive", "chebyshev-lambda", "--outputs", "B", "--samples", "0", "--json")
    assert code == 0
    code, before, _ = run(capsys, "derive", "--outputs", "B", "chebyshev-lambda", "--samples", "0", "--json")
    assert code == 0
    strip = lambda text: {k: v for k, v in json.loads(text).items() if k != "timings"}  # noqa: E731
    assert strip(before) == strip(after)
    assert json.loads(before)["scene"] == "chebyshev-lambda"


def test_two_outputs_before_the_scene(capsys):
    code, out, _ = run(capsys, "show", "--outputs", "B", "P", "chebyshev-lambda", "--json")
    assert code == 0, out
    assert json.loads(out)["scene"] == "chebyshev-lambda"


def test_a_missing_scene_is_still_said(capsys):
    assert "required: scene" in one_error(capsys, "derive", "--outputs", "B")


@pytest.mark.parametrize(("args", "words"), [
    (["dervie", "chebyshev-lambda"], ["command='dervie'", "did you mean 'derive'?"]),
    (["derive", "chebyshev-lambd"], ["chebyshev-lambd", "did you mean 'chebyshev-lambda'?"]),
    (["derive", "arm-string", "--param", "gg"], ["--param='gg'", "parameters: a, b, r, g", "did you mean 'g'?"]),
    (["derive", "arm-string", "--set", "rr=2"], ["--set='rr=2'", "did you mean 'r'?"]),
    (["derive", "chebyshev-lambda", "--method", "linaer"], ["--method='linaer'", "did you mean 'linear'?"]),
    (["curve", "fourbar", "--point", "b"], ["--point='b'", "did you mean 'B'?"]),
    (["solve", "fourbar", "--at", "thetaa=30"], ["--at='thetaa'", "did you mean 'theta'?"]),
    (["derive", "arm-string", "--outputs", "Bx"], ["--outputs='Bx'", "did you mean 'B'?"]),
])
def test_a_mistyped_name_gets_its_close_match(capsys, args, words):
    err = one_error(capsys, *args)
    for word in words:
        assert word in err, err


@pytest.mark.parametrize("command", [["show"], ["derive"], ["curve", "--point", "P"], ["extremum", "--of", "P.x"]],
                         ids=lambda command: command[0])
@pytest.mark.parametrize(("file", "name"), [("arm-string.toml", "arm-string"), ("3rpr.toml", "3rpr"),
                                            ("fourbr.toml", "fourbar")])
def test_a_missing_file_named_like_a_catalog_scene_suggests_the_scene(capsys, tmp_path, command, file, name):
    # only the whole path was matched against the names: a directory before it, or a short name
    # ('3rpr.toml' is too unlike '3rpr'), left the catalog listed with nothing suggested
    err = one_error(capsys, command[0], str(tmp_path / file), *command[1:])
    assert "no such file" in err and err.rstrip().endswith(f"did you mean {name!r}?"), err


def test_a_name_like_nothing_gets_no_suggestion(capsys):
    err = one_error(capsys, "derive", "arm-string", "--param", "zzzz")
    assert "did you mean" not in err and "parameters: a, b, r, g" in err


@pytest.mark.parametrize("command", ["extremum", "accuracy"])
def test_the_flag_typed_is_named_with_the_outputs_it_could_be(capsys, command):
    err = one_error(capsys, command, "arm-string", "--of", "|AB|")
    assert err.startswith("algkin: error: --of='|AB|'"), err
    assert "outputs: AB" in err and "did you mean 'AB'?" in err


def test_plot_of_names_its_flag(capsys, tmp_path):
    err = one_error(capsys, "plot", "arm-string", "--of", "|AB|", "--out", str(tmp_path / "x.svg"))
    assert err.startswith("algkin: error: --of='|AB|'"), err
    assert not (tmp_path / "x.svg").exists()


def test_a_curve_with_nothing_dropped_says_so_without_a_dangling_colon(capsys):
    code, out, _ = run(capsys, "curve", "slider-crank", "--point", "B", "--samples", "0")
    assert code == 0
    assert "no extraneous factor dropped" in out.splitlines()
    assert not any(line.endswith(":") for line in out.splitlines())


@pytest.mark.parametrize("command", [["derive"], ["curve", "--point", "P"], ["verify"]])
def test_an_empty_method_is_no_method_not_the_default(capsys, command):
    # `--method ""` (an unset shell variable) ran the default method as if the flag were absent
    err = one_error(capsys, command[0], "chebyshev-lambda", *command[1:], "--method", "", "--samples", "3")
    assert err.startswith("algkin: error: --method='': unknown elimination method"), err


def test_an_empty_method_with_points_solved_together_is_refused(capsys):
    err = one_error(capsys, "derive", "3rpr", "--method", "", "--samples", "3")
    assert err.startswith("algkin: error: --method='': is not taken with points solved together"), err


@pytest.mark.parametrize(("args", "said"), [
    (["extremum", "arm-string", "--of", "AB", "--range", "-1e-3:-2e-3"], "--range='-1e-3:-2e-3': lo must be below hi"),
    (["follow", "fourbar", "--mode", "left", "--from", "theta=0", "--to", "9", "--max-step", "-1e-3"],
     "--max-step='-1e-3': expected a positive number"),
])
def test_a_value_starting_with_a_minus_and_a_digit_is_a_value(capsys, args, said):
    # argparse took only -90 or -0.5 for a value: `--range -90:90` said "expected one argument"
    err = one_error(capsys, *args)
    assert err.startswith(f"algkin: error: {said}"), err


def test_a_value_a_hundred_thousand_characters_long_leaves_a_short_line_with_the_flag_and_the_reason(capsys):
    # the value stands in the message three times: 300 KB on one line before
    code, _, err = run(capsys, "derive", "fourbar", "--outputs", "Q" * 100_000)
    assert code == 2 and err.count("\n") == 1 and len(err) < 1200
    assert err.startswith("algkin: error: --outputs='QQQ") and "characters left out" in err
    assert err.endswith("(outputs: B, P; or a point, P.x, P.y, dist(P, Q), angle(P, Q, R))\n")


def test_an_output_named_with_spaces_about_it_is_the_output(capsys):
    # ' B.x' was taken and 'AB ' refused as "unknown point 'AB'; did you mean 'B'?" though AB is the output
    code, out, _ = run(capsys, "extremum", "arm-string", "--of", "AB ", "--json")
    assert code == 0 and json.loads(out)["of"] == "AB"
    # |AB| least where OA points along OB (hand: |OB| - |OA| = sqrt(400**2 + 80**2) - 350)
    assert json.loads(out)["minimum"]["value"] == pytest.approx((400**2 + 80**2) ** 0.5 - 350, rel=1e-12)
