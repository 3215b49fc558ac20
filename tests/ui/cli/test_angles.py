"""Angle outputs through the command line: derive, verify, extremum and plot (exit codes, JSON, text)."""

import json

import pytest
import sympy

from .in_process import run_main

RUNS = {
    "derive-json": ["derive", "fourbar", "--outputs", "angle(D, B)", "--json"],
    "derive-text": ["derive", "fourbar", "--outputs", "angle(D, B)", "angle(A, B, D)"],
    "verify": ["verify", "fourbar", "--outputs", "angle(D, P)", "angle(A, B)", "--samples", "30"],
    "extremum-text": ["extremum", "fourbar", "--of", "angle(A, B, D)"],
    "extremum-json": ["extremum", "fourbar", "--of", "angle(A, B, D)", "--json"],
    "drag-link": ["extremum", "fourbar", "--of", "angle(A, B, D)", "--set", "a=5", "--set", "d=2", "--set", "l=6",
                  "--set", "m=4", "--json"],
    "rocker": ["extremum", "fourbar", "--of", "angle(D, B)", "--json"],
    "closed": ["extremum", "fourbar", "--of", "angle(A, B, D)", "--param", "a", "--json"],
    "plot": ["plot", "fourbar", "--of", "angle(D, B)", "--out", "rocker.png"],
}


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    # in this process: these check what each command computes and writes, not its process (test_usage does)
    dirs = {k: tmp_path_factory.mktemp(k) for k in RUNS}
    return {k: (run_main(a, dirs[k]), dirs[k]) for k, a in RUNS.items()}


def ok(runs, key):
    result, _ = runs[key]
    assert result.returncode == 0, result.stderr[-2000:]
    return result.stdout


def test_derive_json_gives_the_cosine_and_sine_per_branch_verified(runs):
    document = json.loads(ok(runs, "derive-json"))
    assert document["outputs"] == {"angle_D_B": ["cos_angle_D_B", "sin_angle_D_B"]}
    assert document["verification"]["passed"] and document["verification"]["compared"] > 0
    assert {"cos_angle_D_B", "sin_angle_D_B"} <= set(document["eliminants"]) <= set(document["system"]["unknowns"])
    for branch in document["branches"]:
        cos, sin = (sympy.parse_expr(branch["values"][u]) for u in ("cos_angle_D_B", "sin_angle_D_B"))
        at = {sympy.Symbol("c_theta"): sympy.Rational(3, 5), sympy.Symbol("s_theta"): sympy.Rational(4, 5)}
        assert abs(sympy.N((cos**2 + sin**2).xreplace(at), 40) - 1) < 1e-35


def test_derive_text_shows_each_angles_closed_forms(runs):
    text = ok(runs, "derive-text")
    assert "cos_angle_D_B = " in text and "sin_angle_D_B = " in text
    assert text.count("cos_angle_A_B_D = 8*c_theta/21 + 17/84") == 2  # both modes: the textbook's cosine
    assert "verification passed" in text


def test_verify_checks_angles_with_a_varying_side(runs):
    assert "verification passed" in ok(runs, "verify")


def test_extremum_text_reports_degrees_and_exact_values(runs):
    text = ok(runs, "extremum-text")
    assert "minimum: 54.3146652873 deg at 0 deg" in text
    assert "exactly 180*acos(7/12)/pi deg, where cos_angle_A_B_D = 7/12" in text
    assert "maximum: 100.286560611 deg at 180 deg" in text


def test_extremum_json_has_exact_algebraic_extremes(runs):
    document = json.loads(ok(runs, "extremum-json"))
    assert document["minimum"]["exact_via"] == "7/12" and document["maximum"]["exact_via"] == "-5/28"
    assert document["angle"] == {"unit": "deg", "via": "cos_angle_A_B_D", "degrees": "180*acos(cos_angle_A_B_D)/pi",
                                 "kind": "at a point"}
    drag = json.loads(ok(runs, "drag-link"))  # ground shortest: a double-crank
    assert (drag["minimum"]["exact_via"], drag["maximum"]["exact_via"]) == ("43/48", "1/16")


def test_rocker_extremum_and_closed_form(runs):
    rocker = json.loads(ok(runs, "rocker"))
    assert rocker["angle"]["kind"] == "direction"
    assert 115.9 < rocker["minimum"]["value"] < 116 and 150 < rocker["maximum"]["value"] < 150.01
    closed = json.loads(ok(runs, "closed"))["closed_form"]
    a = sympy.Symbol("a")
    assert sympy.simplify(sympy.parse_expr(closed["value"])
                          - 180 * sympy.acos((-4 * a**2 + 32 * a + 21) / 84) / sympy.pi) == 0
    assert closed["via_value"] == "(-4*a**2 + 32*a + 21)/84"


def test_plot_draws_an_angle_against_the_input(runs):
    result, workdir = runs["plot"]
    assert result.returncode == 0, result.stderr
    assert (workdir / "rocker.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
