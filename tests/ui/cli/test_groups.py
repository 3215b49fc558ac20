"""derive, curve, verify and toggles on scenes with points solved together, from the command line."""

import json

import pytest

from algkin.ui.cli import main


@pytest.mark.parametrize("argv, says", [
    (["derive", "stephenson-iii-triad"], "modes at theta = 0°: 2 real of 6 complex"),
    (["curve", "stephenson-iii-triad", "--point", "P"], "degree 6, circularity 3"),
    (["verify", "stephenson-iii-triad"], "verification passed"),
    (["toggles", "stephenson-iii-triad"], "(certified)"),
    (["toggles", "3rpr"], "modes meet (P1, P2) at [7.92278018529"),
], ids=lambda a: " ".join(a) if isinstance(a, list) else "")
def test_the_triad_through_each_command(capsys, argv, says):
    assert main([*argv, "--samples", "6"] if argv[0] != "toggles" else argv) == 0
    assert says in capsys.readouterr().out


def test_derive_json_and_out(capsys, tmp_path):
    out = tmp_path / "triad.json"
    assert main(["derive", "stephenson-iii-triad", "--samples", "4", "--json", "--out", str(out)]) == 0
    document = json.loads(capsys.readouterr().out)
    assert json.loads(out.read_text()) == document
    assert document["groups"][0]["degree"] == 6 and document["verification"]["passed"]
    assert [b["label"] for b in document["branches"]] == ["-++", "+++"]


def test_curve_json(capsys):
    assert main(["curve", "stephenson-iii-triad", "--point", "P", "--samples", "4", "--json"]) == 0
    document = json.loads(capsys.readouterr().out)
    assert (document["degree"], document["circularity"], document["dropped_factors"]) == (6, 3, ["P_x + 2*P_y"])


@pytest.mark.parametrize("argv, flag", [
    (["derive", "3rpr", "--param", "r2"], "--param"),
    (["derive", "3rpr", "--latex"], "--latex"),
    (["derive", "3rpr", "--outputs", "P1"], "--outputs"),
    (["curve", "3rpr", "--point", "P3", "--method", "groebner"], "--method"),
    (["verify", "3rpr", "--backend", "sympy"], "--backend"),
], ids=lambda a: " ".join(a) if isinstance(a, list) else "")
def test_what_only_the_dyads_take_is_refused_in_one_line(capsys, argv, flag):
    assert main(argv) == 2
    captured = capsys.readouterr()
    assert captured.out == "" and captured.err.count("\n") == 1
    assert flag in captured.err and "points solved together" in captured.err


def test_a_point_of_no_scene_is_refused(capsys):
    assert main(["curve", "stephenson-iii-triad", "--point", "Z"]) == 2
    assert "not a point of stephenson-iii-triad" in capsys.readouterr().err


def test_derive_rates_on_a_group_scene(capsys):
    assert main(["derive", "3rpr", "--rates", "--samples", "3", "--json"]) == 0
    document = json.loads(capsys.readouterr().out)
    group, = document["rates"]["groups"]
    assert list(group["modes"]) == ["---", "+++"] and set(group["velocity"]) == {"P1_x", "P1_y", "P2_x", "P2_y"}
    assert document["rates_input"] == {"name": "r1", "per": "length"}
    assert document["rates_verification"]["passed"] and document["rates_verification"]["eliminant_compared"] > 0


def test_derive_rates_text_on_the_triad(capsys):
    assert main(["derive", "stephenson-iii-triad", "--rates", "--samples", "3"]) == 0
    out = capsys.readouterr().out
    assert "per radian" in out and "rates verification passed" in out and "[+++] A_x' = " in out


def test_show_gives_each_group_its_points_unknowns_constraints_and_equations(capsys):
    assert main(["show", "3rpr", "--json"]) == 0
    document = json.loads(capsys.readouterr().out)
    (group,) = document["groups"]
    assert group["points"] == ["P1", "P2"] and group["constraints"] == ["leg1", "leg2", "leg3", "side"]
    assert group["unknowns"] == ["P1_x", "P1_y", "P2_x", "P2_y"] and len(group["equations"]) == 4
    # leg1 by hand: |A1 P1| = r1 with A1 at the origin
    assert group["equations"][0] == "P1_x**2 + P1_y**2 - r1**2"
    assert main(["show", "3rpr"]) == 0
    assert "solved together: P1, P2" in capsys.readouterr().out


def test_show_says_a_length_input_as_a_length(capsys):
    # it raised KeyError 'cos' (a traceback) on every scene driven by a length
    assert main(["show", "arm-by-string"]) == 0
    assert "inputs: s (a length)" in capsys.readouterr().out
