"""A new user's first hour: bare ``algkin``, ``--version``, ``--help`` everywhere, ``--set``."""

import argparse
import json

import pytest
import sympy

import algkin
from algkin.ui.cli import build_parser, main
from algkin.errors import SceneError, UsageError

from .in_process import run_main
from .test_usage import run_cli


def test_bare_algkin_prints_the_commands_and_exits_0(tmp_path):
    result = run_cli([], tmp_path)
    assert result.returncode == 0, result.stderr
    assert result.stderr == ""
    assert "usage: algkin" in result.stdout
    for command in ("list", "derive", "curve", "toggles", "plot"):
        assert f"\n    {command} " in result.stdout


def test_version(tmp_path):
    result = run_cli(["--version"], tmp_path)
    assert (result.returncode, result.stdout, result.stderr) == (0, f"algkin {algkin.__version__}\n", "")


def _subcommands():
    parser = build_parser()
    (commands,) = [a for a in parser._actions if isinstance(a, argparse._SubParsersAction)]
    return [(None, parser)] + list(commands.choices.items())


@pytest.mark.parametrize("name, parser", _subcommands(), ids=lambda v: v if isinstance(v, str) else "")
def test_every_argument_has_help_and_its_default(name, parser):
    help_text = parser.format_help()
    for action in parser._actions:
        assert action.help and action.help.strip(), (name, action.dest)
        if action.option_strings and action.default not in (None, False, [], argparse.SUPPRESS):
            assert f"(default: {action.default})" in " ".join(help_text.split()), (name, action.dest)


def test_help_shows_defaults_of_zero_too(capsys):
    assert main(["verify", "--help"]) == 0  # written by main, as any output (a failed write is exit 1)
    assert "(default: 0)" in " ".join(capsys.readouterr().out.split())


def test_set_on_the_command_line_is_exact(tmp_path):
    result = run_main(["show", "arm-string", "--outputs", "AB", "--set", "b=0.1", "--set", "a=3/2", "--json"],
                      tmp_path)  # in this process: the document is the question
    assert result.returncode == 0, result.stderr
    equations = json.loads(result.stdout)["system"]["equations"]
    from algkin.scene import with_values

    expected = algkin.compile_scene(with_values(
        algkin.load_scene("arm-string"), {"a": sympy.Rational(3, 2), "b": sympy.Rational(1, 10)}), ["AB"])
    assert [sympy.parse_expr(e) for e in equations] == [sympy.parse_expr(str(e))
                                                      for e in expected.system.equations]
    assert " 70*c_theta" in equations[0] and "." not in "".join(equations)  # 700*b with b = 1/10 exactly


def test_set_in_the_python_api():
    arm = algkin.load_quantities("arm-string", params=["b"], set={"r": "1/2"})
    assert arm.scene.parameters["r"] == sympy.Rational(1, 2)
    b, theta = sympy.symbols("b theta", real=True)
    # |AB| with A = (1/2)(sin, -cos), B = (400, -b), by hand
    assert sympy.simplify(arm.dist("A", "B").expr ** 2
                          - ((400 - sympy.sin(theta) / 2) ** 2 + (-b + sympy.cos(theta) / 2) ** 2)) == 0
    derived = algkin.derive("arm-string", set={"b": 3, "r": 0.5}, samples=0)
    assert derived.compiled.scene.parameters["r"] == sympy.Rational(1, 2)
    assert derived.compiled.scene.parameters["b"] == 3
    bent = algkin.curve("chebyshev-lambda", "P", set={}, samples=0)
    assert bent.degree == 6


@pytest.mark.parametrize("values, message", [
    ({"zz": 1}, "not a parameter of arm-string"),
    ({"b": "2**"}, "set='b=2**'"),
    ({"b": "os.system"}, "set="),
    ({"b": 1.0j}, "set="),
])
def test_set_refuses_bad_values_in_one_line(values, message):
    with pytest.raises(UsageError) as err:
        algkin.load_quantities("arm-string", set=values)
    assert message in str(err.value) and "\n" not in str(err.value)
    assert str(err.value).startswith("set=")  # the Python argument, not the command line's --set


def test_set_and_param_together_are_refused():
    with pytest.raises(UsageError, match="kept symbolic"):
        algkin.derive("arm-string", params=["b"], set={"b": 1})


def test_set_value_is_checked_as_a_scene_file_would_be(tmp_path):
    with pytest.raises(SceneError, match="points.A: length must be positive, got -1"):
        algkin.derive("fourbar", set={"a": "-1"}, samples=0)
    result = run_cli(["show", "fourbar", "--set", "a=-1"], tmp_path)
    assert result.returncode == 2 and "length must be positive, got -1" in result.stderr
