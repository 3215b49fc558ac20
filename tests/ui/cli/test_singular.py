"""``algkin singular``: the report, the JSON keys docs/cli/singular.md lists, bad input in one line."""

import json

import pytest

from algkin.ui.cli import main

from .test_usage import run_cli

POINT_KEYS = {"x", "y", "kind", "multiplicity", "a_k", "hessian_sign", "real_branches", "tangents", "enclosure",
              "exact", "minimal_polynomials", "representation", "certified"}


def test_json_lists_the_crossing_of_watts_figure_eight(capsys):
    """Watt's linkage's coupler curve (a figure eight) crosses itself at the origin, between two
    acnodes at ±(8, -2)·sqrt(34)/17 (tests/analyses/singular check them by a Gröbner basis)."""
    assert main(["singular", "watt-straight-line", "--point", "P", "--json", "--samples", "0"]) == 0
    document = json.loads(capsys.readouterr().out)
    assert {"scene", "point", "variables", "curve", "degree", "circularity", "counts", "singular_points",
            "complex_singular_points", "curve_verification", "timings"} <= set(document)
    assert (document["degree"], document["circularity"]) == (6, 3)
    points = document["singular_points"]
    assert all(set(p) == POINT_KEYS for p in points)
    assert [(p["kind"], p["exact"]["x"], p["exact"]["y"]) for p in points] == [
        ("acnode", "-8*sqrt(34)/17", "2*sqrt(34)/17"), ("crunode", "0", "0"),
        ("acnode", "8*sqrt(34)/17", "-2*sqrt(34)/17")]
    assert points[0]["minimal_polynomials"] == {"x": "17*P_x**2 - 128", "y": "17*P_y**2 - 8"}
    assert document["curve_verification"]["status"] == "skipped"
    assert document["counts"] == {"acnode": 2, "crunode": 1, "complex": 0}


def test_text_report_gives_each_point_its_class_and_enclosure(capsys):
    assert main(["singular", "fourbar", "--point", "P", "--samples", "5"]) == 0
    text = capsys.readouterr().out
    assert "degree 6, circularity 3" in text
    assert "acnode (A1, multiplicity 2, 0 real of 2 tangents) at (3.58312767793, -1.22217296458)" in text
    assert "x = CRootOf(512*P_x**3 - 1632*P_x**2 - 507*P_x - 784, 0) in [3.58312767793" in text
    assert "and 2 complex (not real) singular points of multiplicity 2" in text
    assert "verification passed" in text


def test_a_smooth_curve_has_none(capsys):
    """The crank tip A runs on a circle: smooth, degree 2, one circular point each."""
    assert main(["singular", "fourbar", "--point", "A", "--samples", "0"]) == 0
    text = capsys.readouterr().out
    assert "degree 2, circularity 1" in text and "no real singular point" in text


@pytest.mark.parametrize("args, words", [
    (["singular", "fourbar", "--point", "Q"], ["--point='Q'", "not a point of fourbar"]),
    (["singular", "fourbar"], ["--point"]),
    (["singular", "fourbar", "--point", "O"], ["--point='O'", "fixed"]),
    (["singular", "five-bar", "--point", "P"], ["--point='P'", "2 inputs"]),
    (["singular", "fourbar", "--point", "P", "--set", "a=-1"], ["a", "positive"]),
    (["singular", "fourbar", "--point", "P", "--samples", "-3"], ["samples=-3"]),
])
def test_bad_input_is_one_line_and_exit_2(capsys, args, words):
    assert main(args) == 2
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1
    assert all(word in err for word in words), err
    assert main([*args, "--json"]) == 2
    assert json.loads(capsys.readouterr().out)["error"]["kind"] in ("usage", "scene")


def test_bad_input_from_a_shell_too(tmp_path):
    result = run_cli(["singular", "fourbar", "--point", "Q"], tmp_path)
    assert (result.returncode, result.stdout, result.stderr.count("\n")) == (2, "", 1)
