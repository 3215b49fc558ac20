"""``algkin follow``: the JSON document, the text report, the budget, bad input in one line with exit 2."""

import json

import pytest

from algkin.ui.cli import main
from tests.clocks import late_budgets


def test_json_of_a_mode_that_meets_another(capsys):
    argv = ["follow", "fourbar-nongrashof", "--mode", "left", "--from", "theta=0", "--to", "180", "--digits", "8"]
    assert main([*argv, "--json"]) == 0
    document = json.loads(capsys.readouterr().out)
    assert document["ended"] == "meets" and document["input"] == "theta" and document["from"] == "0"
    assert document["meeting"]["from"] <= "131.4908169" <= document["meeting"]["to"]  # its dead centre
    assert document["samples"][0]["points"]["A"] == ["2", "0"]
    assert main(argv) == 0
    out = capsys.readouterr().out
    assert out.startswith("fourbar-nongrashof, mode left, theta from 0 to 180: meets another mode for theta in [131.49")
    assert "(holds 0; the meeting point proved)" in out and "  theta = 0: O = (0, 0)" in out


def test_a_group_scene_along_a_length_with_a_largest_step(capsys):
    assert main(["follow", "3rpr", "--mode=---", "--from", "r1=6", "--to", "5", "--max-step", "1/4", "--json"]) == 0
    document = json.loads(capsys.readouterr().out)
    assert document["ended"] == "reached" and document["steps"] == 4
    assert [s["at"] for s in document["samples"]] == ["6", "5.75", "5.5", "5.25", "5"]


def test_a_scene_with_two_inputs_takes_the_other_with_at(capsys):
    assert main(["follow", "five-bar", "--mode", "left", "--from", "t1=90", "--to", "60", "--at", "t2=90"]) == 0
    assert "reached 60" in capsys.readouterr().out


def test_the_budget_stops_it_with_one_line_exit_1(monkeypatch, capsys):
    late_budgets(monkeypatch)
    assert main(["follow", "chebyshev-lambda", "--mode", "left", "--from", "angle=0", "--to", "360",
                 "--max-seconds", "5"]) == 1
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "max_seconds=5: stopped after 3600.00 s" in err


@pytest.mark.parametrize(("argv", "said"), [
    (["--mode", "up", "--from", "theta=0", "--to", "90"], "--mode='up': not a mode of fourbar (modes: left, right)"),
    (["--mode", "left", "--from", "theta=0", "--to", "400"], "--to='theta=400': expected a number of degrees in [0, 360]"),
    (["--mode", "left", "--from", "theta=-5", "--to", "90"], "--from='theta=-5': expected a number of degrees in [0, 360]"),
    (["--mode", "left", "--from", "phi=0", "--to", "90"], "--from='phi': not an input of fourbar (inputs: theta)"),
    (["--mode", "left", "--from", "0", "--to", "90"], "--from='0': expected INPUT=VALUE"),
    (["--mode", "left", "--from", "theta=0", "--to", "90", "--max-step", "-1"], "--max-step='-1': expected a positive"),
    (["--mode", "left", "--from", "theta=0", "--to", "90", "--at", "theta=3"], "--at='theta': is the input followed: give its value as the start only"),
    (["--mode", "left", "--from", "theta=0"], "the following arguments are required: --to"),
])
def test_bad_input_is_one_line_exit_2(capsys, argv, said):
    assert main(["follow", "fourbar", *argv]) == 2
    captured = capsys.readouterr()
    assert captured.out == ""
    assert captured.err.count("\n") == 1 and said in captured.err


def test_a_mode_that_does_not_assemble_at_the_start_is_one_line_exit_2(capsys):
    assert main(["follow", "fourbar-nongrashof", "--mode", "left", "--from", "theta=150", "--to", "0"]) == 2
    assert "--mode='left': does not assemble at theta = 150" in capsys.readouterr().err
