"""``algkin derive --rates``: the velocity and acceleration closed forms per branch, their check,
in the text report and as JSON keys whose strings sympy reads back; bad input exits 2."""

import json

import sympy

from algkin.ui.cli import main


def _run(capsys, *args):
    code = main(["derive", *args, "--quiet"])
    out, err = capsys.readouterr()
    return code, out, err


def test_json_has_rates_per_branch_and_coordinate_and_their_check(capsys):
    code, out, err = _run(capsys, "chebyshev-lambda", "--outputs", "B", "P", "--rates", "--json", "--samples", "6")
    document = json.loads(out)
    assert code == 0 and not err
    assert list(document["rates"]) == ["left", "right"]
    assert list(document["rates"]["left"]) == ["B_x", "B_y", "P_x", "P_y"]
    check = document["rates_verification"]
    assert check["passed"] and check["status"] == "passed" and check["compared"] >= 6
    assert check["max_rel_error"] < 1e-30
    assert document["rates_input"] == {"name": "angle", "per": "radian"}
    assert {"rate_forms", "rate_check"} <= set(document["timings"]) and list(document["timings"])[-1] == "total"
    angle = {"c_angle": sympy.Rational(3, 5), "s_angle": sympy.Rational(4, 5)}
    for rates in document["rates"].values():
        for forms in rates.values():
            values = [sympy.parse_expr(forms[k]).subs(angle) for k in ("velocity", "acceleration")]
            assert all(v.is_real for v in values), forms
    # the branches and positions of a plain derive are all still there
    assert document["verification"]["passed"] and len(document["branches"]) == 2


def test_p_y_velocity_of_the_lambda_is_the_hand_derivative_of_its_position(capsys):
    _, out, _ = _run(capsys, "chebyshev-lambda", "--outputs", "P", "--rates", "--json", "--samples", "2")
    document = json.loads(out)
    c, s, t = sympy.symbols("c_angle s_angle t")
    position = sympy.parse_expr(document["branches"][0]["values"]["P_y"]).subs({c: sympy.cos(t), s: sympy.sin(t)})
    velocity = sympy.parse_expr(document["rates"]["left"]["P_y"]["velocity"]).subs({c: sympy.cos(t), s: sympy.sin(t)})
    for angle in ("3/10", "11/10", "2", "4"):  # exact angles: 30 digits of the difference are right
        assert abs(sympy.N((sympy.diff(position, t) - velocity).subs(t, sympy.Rational(angle)), 30)) < 1e-25


def test_text_report_shows_the_rates_and_their_check(capsys):
    code, out, _ = _run(capsys, "chebyshev-lambda", "--outputs", "P", "--rates", "--samples", "4")
    assert code == 0
    assert "rates in angle (x' = dx/dangle, x'' = d2x/dangle2, per radian" in out
    assert "      P_y' = c_angle*s_angle*(8*c_angle + 5)/" in out
    assert "      P_y'' = " in out
    assert "rates verification passed: " in out and "on 4 samples" in out
    assert out.index("verification passed") < out.index("rates in angle") < out.index("timings:")


def test_zero_samples_skip_the_rates_check(capsys):
    code, out, _ = _run(capsys, "arm-string", "--outputs", "AB", "--rates", "--samples", "0")
    assert code == 0 and "rates verification skipped (--samples 0)" in out


def test_rates_of_a_two_input_scene_is_a_usage_error(capsys):
    code, out, err = _run(capsys, "five-bar", "--rates")
    assert code == 2 and out == ""
    assert err.count("\n") == 1 and "--rates='five-bar'" in err and "2 (t1, t2)" in err


def test_without_the_flag_there_are_no_rates(capsys):
    _, out, _ = _run(capsys, "arm-string", "--outputs", "AB", "--json", "--samples", "2")
    assert "rates" not in json.loads(out)
