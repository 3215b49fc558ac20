"""``algkin solve``: the JSON keys SPEC section 3 lists, the text report, bad input in one line, exit 2."""

import json

import pytest

from algkin.ui.cli import main


def test_json_of_the_fourbar(capsys):
    assert main(["solve", "fourbar", "--at", "theta=30", "--digits", "10", "--json"]) == 0
    document = json.loads(capsys.readouterr().out)
    assert document["scene"] == "fourbar" and document["at"] == {"theta": "30"}
    assert [c["mode"] for c in document["configurations"]] == ["left", "right"]
    assert document["configurations"][0]["points"]["B"] == ["2.368647265", "3.096560714"]
    assert document["configurations"][0]["radius"] < 1e-10


def test_nothing_assembles_is_said_and_exit_0(capsys):
    assert main(["solve", "fourbar-nongrashof", "--at", "theta=150"]) == 0
    assert "no configuration: nothing assembles there" in capsys.readouterr().out


def test_text_report_and_one_mode(capsys):
    assert main(["solve", "slider-crank", "--at", "theta=0", "--mode", "behind", "--digits", "8"]) == 0
    out = capsys.readouterr().out
    assert "slider-crank at theta = 0: 1 configuration" in out
    assert "behind: O = (0, 0), L = (0, 0.5), A = (1, 0), B = (-1.9580399, 0.5)" in out  # 1 - sqrt(35)/2


@pytest.mark.parametrize(("argv", "said"), [
    (["--at", "theta=400"], "--at='theta=400': expected a number of degrees in [0, 360]"),
    (["--at", "phi=3", "--at", "theta=3"], "--at='phi': not an input of fourbar"),
    ([], "--at='theta': no value given for theta"),
    (["--at", "theta=1", "--at", "theta=2"], "--at='theta=2': theta given twice"),
    (["--at", "theta"], "--at='theta': expected INPUT=VALUE"),
    (["--at", "theta=1", "--digits", "0"], "--digits=0: expected a whole number of digits"),
    (["--at", "theta=1", "--mode", "up"], "--mode='up': not a mode of fourbar (modes: left, right)"),
])
def test_bad_input_is_one_line_exit_2(capsys, argv, said):
    assert main(["solve", "fourbar", *argv]) == 2
    captured = capsys.readouterr()
    assert captured.out == ""
    assert captured.err.count("\n") == 1 and said in captured.err


@pytest.fixture
def platform(tmp_path):
    from tests.scene.test_groups import SPEC_3RPR

    path = tmp_path / "3rpr.toml"
    path.write_text(SPEC_3RPR)
    return str(path)


def test_solve_on_points_solved_together_gives_the_complex_count(capsys, platform):
    assert main(["solve", platform, "--at", "r1=6", "--json"]) == 0
    document = json.loads(capsys.readouterr().out)
    assert document["complex_count"] == 6 and len(document["configurations"]) == 2
    assert set(document["configurations"][0]["points"]) == {"A1", "A2", "A3", "P1", "P2", "P3"}
    assert main(["solve", platform, "--at", "r1=6"]) == 0
    assert "complex solutions of the group's eliminant: 6" in capsys.readouterr().out


@pytest.mark.parametrize("command", [
    ["extremum", "--of", "P1.x"],
    ["singular", "--point", "P3"],
], ids=lambda c: c[0])
def test_every_other_command_refuses_them_saying_which_command_works(capsys, platform, tmp_path, command):
    argv = [command[0], platform, *(a.format(tmp=tmp_path) for a in command[1:])]
    assert main(argv) == 2
    captured = capsys.readouterr()
    assert captured.out == "" and captured.err.count("\n") == 1
    assert ("has points solved together (P1, P2): show, solve, follow, derive, curve, verify, toggles, plot, export, "
            "sweep and accuracy take it, and in Python derive, curve, solve, follow, rates and load_quantities; "
            "extremum and singular do not yet, nor prepare and compile_scene") in captured.err
    assert not (tmp_path / "x.png").exists() and not (tmp_path / "sweep").exists()


def test_the_catalogs_six_mode_3rpr(capsys):
    """Gosselin's design (tests/analyses/test_solve.py checks it against the loop equations)."""
    assert main(["solve", "3rpr-six-modes", "--at", "r1=14.98", "--json", "--digits", "8"]) == 0
    document = json.loads(capsys.readouterr().out)
    assert document["at"] == {"r1": "749/50"} and document["complex_count"] == 6
    assert len({c["mode"] for c in document["configurations"]}) == 6


def test_a_mode_by_its_label_and_an_unknown_label(capsys):
    assert main(["solve", "3rpr", "--at", "r1=6", "--mode", "+++", "--json"]) == 0
    (configuration,) = json.loads(capsys.readouterr().out)["configurations"]
    assert configuration["mode"] == "+++"
    assert main(["solve", "3rpr", "--at", "r1=6", "--mode", "+-+"]) == 2
    assert "--mode='+-+': not a mode of 3rpr at r1 = 6 (modes: ---, +++)" in capsys.readouterr().err
