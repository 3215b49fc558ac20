"""The library names a bad argument by its Python parameter; the command line by the flag typed.

``algkin.ui.cli.flags.FLAGS`` maps the one to the other: every name an error below the command
line gives, and a command can reach, must be in it, and every flag in it must be one the
command line takes.
"""

import argparse
import json
import pathlib
import re

import pytest

import algkin
from algkin.errors import UsageError
from algkin.ui.cli import build_parser, main
from algkin.ui.cli.flags import FLAGS

PACKAGE = pathlib.Path(algkin.__file__).parent

# Names raised below the command line that no command can reach, each with why.
NOT_FROM_THE_COMMAND_LINE = {
    "analysis": "sweep.register: a Python extension point",
    "curve": "singular_points of a sympy curve; the command line passes a scene and a point",
    "variables": "singular_points' variables; the command line passes none",
    "engine": "evaluate's engine; no command takes one",
    "NUMBA_NUM_THREADS": "an environment variable, named as such",
    "sweep": "the sweep extra missing: its name is the package's, said as such",
    "poly": "system.roots of a zero polynomial; every command passes a nonzero one",
    "within": "system.roots' interval turned round; every command passes an ordered one",
    "equations": "eliminate.group's solve_group, from Python only: no command solves a group",
    "unknowns": "eliminate.group's solve_group, from Python only",
    "prefer": "eliminate.group's solve_group, from Python only",
    **dict.fromkeys(("poses", "pairs", "points", "ground", "crank_pivot", "rocker_pivot"),
                    "a synthesis file's data: algkin synthesize says it as the file's (FILE: poses: ...)"),
    **dict.fromkeys(("centre", "circle"), "synthesis.motion's matched points, from Python only"),
    "witnesses": "eliminate.eliminate_each's witness list, from Python only (a batch path no command takes)",
    "values": "extremum.family's design values, from Python only (the sweep passes the grid's, checked as --grid)",
    **dict.fromkeys(("mechanism", "text"), "a Quantity made by hand, from Python only (commands make their own)"),
    "clock": "a Budget's clock, from Python only (the command line's is time.monotonic)",
}

# A name given as the first argument of UsageError, or of the helpers that pass it on to one.
_NAMED = re.compile(r'\b(?:UsageError|names|count|check_directory|check_output)\(\s*"([^"]+)"'
                    r'|\b(?:time_budget|_lookup)\(\s*\w+,\s*"([^"]+)"|\bargument="([^"]+)"')


def _names_raised_below_the_command_line():
    names = {}
    for path in sorted(PACKAGE.rglob("*.py")):
        if path.relative_to(PACKAGE).parts[0] == "ui":
            continue
        code = "\n".join(line for line in path.read_text().splitlines() if not line.lstrip().startswith(">>>"))
        for match in _NAMED.finditer(code):  # the code, not its docstrings' examples
            name = next(group for group in match.groups() if group)
            names.setdefault(name, str(path.relative_to(PACKAGE)))
    return names


def _command_line_names():
    """Every option string and positional argument of every command."""
    parser = build_parser()
    commands = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    found = set()
    for command in commands.choices.values():
        for action in command._actions:
            found.update(action.option_strings or [action.dest, action.metavar])
    return found


@pytest.mark.parametrize("budget", [[], ["--max-seconds", "600"]], ids=["here", "in-a-child-process"])
def test_the_python_api_names_the_parameter_and_the_command_line_the_flag(capsys, budget):
    with pytest.raises(UsageError) as caught:
        algkin.curve("chebyshev-lambda", "Q")
    assert str(caught.value).startswith("point='Q': not a point of chebyshev-lambda")
    assert main(["curve", "chebyshev-lambda", "--point", "Q", *budget]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--point='Q': not a point of chebyshev-lambda" in err


@pytest.mark.parametrize("call, argv, python, flag", [
    (lambda: algkin.derive("arm-string", params=["zz"]), ["derive", "arm-string", "--param", "zz"],
     "params='zz'", "--param='zz'"),
    (lambda: algkin.derive("arm-string", outputs=["dist(A, Z)"]), ["derive", "arm-string", "--outputs", "dist(A, Z)"],
     "outputs='dist(A, Z)'", "--outputs='dist(A, Z)'"),
    (lambda: algkin.extremum("fourbar", "B"), ["extremum", "fourbar", "--of", "B"], "output='B'", "--of='B'"),
    (lambda: algkin.extremum("fourbar", "dist(O, B)", (10, 5)), ["extremum", "fourbar", "--of", "dist(O, B)",
                                                                 "--range", "10:5"], "angle_range=", "--range="),
])
def test_each_way_in_names_the_argument_its_own_way(capsys, call, argv, python, flag):
    with pytest.raises(UsageError) as caught:
        call()
    assert str(caught.value).startswith(python)
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and f"error: {flag}" in err


def test_every_name_raised_below_the_command_line_has_its_flag():
    raised = _names_raised_below_the_command_line()
    assert {"point", "outputs", "params", "set", "grid", "angle_range"} <= set(raised)  # the scan finds them
    flagged = {name: where for name, where in raised.items() if name.startswith("-")}
    assert not flagged, f"a flag named below the command line: {flagged}"
    missing = {name: where for name, where in raised.items()
               if name not in FLAGS and name not in NOT_FROM_THE_COMMAND_LINE}
    assert not missing, f"no flag in algkin.ui.cli.flags.FLAGS for {missing}"


def test_every_flag_in_the_table_is_one_the_command_line_takes():
    assert set(FLAGS.values()) <= _command_line_names()


@pytest.mark.parametrize("args, flag", [
    (["export", "chebyshev-lambda", "--to", "c", "--to", "js", "--out", "p.c"], "--to='js'"),
    (["curve", "chebyshev-lambda", "--point", "P", "--point", "B"], "--point='B'"),
    (["derive", "chebyshev-lambda", "--samples", "1", "--samples=2"], "--samples=2"),
])
def test_a_flag_of_one_value_given_twice_is_refused(tmp_path, monkeypatch, capsys, args, flag):
    # argparse kept the last without a word: JavaScript written into p.c, the curve of B for P's
    monkeypatch.chdir(tmp_path)
    assert main(args) == 2
    out, err = capsys.readouterr()
    assert out == "" and err == f"algkin: error: {flag}: given twice\n"
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("repeated, listed, dest, expected", [
    (["derive", "fourbar", "--outputs", "B.x", "--outputs", "A.y"], ["derive", "fourbar", "--outputs", "B.x", "A.y"],
     "outputs", ["B.x", "A.y"]),
    (["derive", "fourbar", "--param", "a", "--param", "l"], ["derive", "fourbar", "--param", "a", "l"],
     "param", ["a", "l"]),
    (["solve", "five-bar", "--at", "t1=30", "--at", "t2=100"], ["solve", "five-bar", "--at", "t1=30", "t2=100"],
     "at", ["t1=30", "t2=100"]),
    (["sweep", "fourbar", "--grid", "a=1:2:2", "--grid", "d=4:10:2", "--out", "x"],
     ["sweep", "fourbar", "--grid", "a=1:2:2", "d=4:10:2", "--out", "x"], "grid", ["a=1:2:2", "d=4:10:2"]),
])
def test_an_option_of_several_values_takes_them_repeated_or_listed_alike(repeated, listed, dest, expected):
    """SPEC section 3 writes ``[--outputs ...]``, ``[--param p ...]``, ``--at INPUT=VALUE ...``,
    ``--grid NAME=LO:HI:COUNT ...``: ``--outputs`` kept only its last repetition (the first dropped
    without a word), and ``--param``, ``--at``, ``--grid`` refused a second value after the flag."""
    assert getattr(build_parser().parse_args(repeated), dest) == expected
    assert getattr(build_parser().parse_args(listed), dest) == expected


def test_outputs_repeated_are_all_derived(capsys):
    assert main(["derive", "fourbar", "--outputs", "B.x", "--outputs", "A.y", "--samples", "0", "--json"]) == 0
    assert {"B_x", "A_y"} <= set(json.loads(capsys.readouterr().out)["eliminants"])


def test_a_scene_after_a_list_of_names_is_still_the_scene():
    parsed = build_parser().parse_args(["derive", "--param", "a", "l", "fourbar"])
    assert (parsed.scene, parsed.param) == ("fourbar", ["a", "l"])
