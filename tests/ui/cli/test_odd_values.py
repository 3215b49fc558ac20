"""Odd values through the real command (docs/cli/index.md: exit 2, one line): each is either computed or refused in one
line with exit 2 (bad input), never a traceback."""

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from .in_process import first_apart, run_main

ROOT = Path(__file__).resolve().parents[3]
FIVE_BAR = (ROOT / "algkin" / "catalog" / "five-bar.toml").read_text()


def algkin(*args, cwd, timeout=300):
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    return subprocess.run([sys.executable, "-m", "algkin", *args], cwd=cwd, env=env, capture_output=True,
                          text=True, timeout=timeout)


def refusal(*args, apart, cwd):
    """``algkin args...`` as the program (``apart``: ``algkin``) or in this process (``run_main``)."""
    return algkin(*args, cwd=cwd) if apart else run_main(args, cwd)


def refused(done, *words):
    """``done`` exited 2 with one line on stderr holding ``words``, and said nothing on stdout."""
    assert done.returncode == 2, (done.returncode, done.stderr[-2000:])
    assert "Traceback" not in done.stderr and done.stdout == ""
    lines = done.stderr.splitlines()
    assert len(lines) == 1, done.stderr[-2000:]
    for word in words:
        assert word in lines[0], (word, lines[0][:500])
    return lines[0]


def test_a_five_bar_whose_second_input_turns_about_a_half_turn(tmp_path):
    """Its witnesses were indexed by the first input's count of samples: those of an input
    around 180 degrees (half-angle tangents near infinity) were all dropped."""
    text = FIVE_BAR.replace('t2 = { range = [0, 180]', 't2 = { range = [179, 181]')
    assert text != FIVE_BAR
    (tmp_path / "five.toml").write_text(text)
    done = algkin("derive", "five.toml", "--json", cwd=tmp_path)
    assert done.returncode == 0, done.stderr[-2000:]
    document = json.loads(done.stdout)
    assert document["verification"]["passed"] and document["verification"]["samples"] > 0


def huge_over_huge(value, digits=90):
    """``value + 10**-digits`` written as the quotient of two integers of about ``digits`` digits."""
    return f"{value * 10**digits + 1}/{10**digits}"


def test_a_dimension_of_huge_numerator_and_denominator_gives_the_curve(tmp_path):
    """d = 4.000...1: the curve's integer coefficients pass a float's range (they overflowed in
    the verification's float magnitudes); its residuals are scaled by a power of two."""
    done = algkin("curve", "fourbar", "--point", "P", "--set", f"d={huge_over_huge(4)}", "--json", cwd=tmp_path)
    assert done.returncode == 0, done.stderr[-2000:]
    document = json.loads(done.stdout)
    assert document["verification"]["passed"] and document["verification"]["evaluated"] > 0
    assert document["degree"] == 6 and document["circularity"] == 3  # a four-bar's coupler curve


def test_a_dimension_just_past_reach_written_huge_is_refused_as_its_round_value_is(tmp_path):
    """d = 10.000...1 (as d = 10): |AD| >= 9 > l + m = 13/2, so B never assembles; a factor 1/10**357
    of its discriminant was 0.0 in floats, and the check took it for assembling."""
    refused(algkin("curve", "fourbar", "--point", "P", "--set", "d=10", cwd=tmp_path), "points.B", "never assemble")
    refused(run_main(["curve", "fourbar", "--point", "P", "--set", f"d={huge_over_huge(10, 89)}"], tmp_path),
            "points.B", "never assemble")  # the process tested on the line above


@pytest.mark.parametrize("args, words, apart", first_apart([
    (["derive", "fourbar", "--outputs", "B", "--param", "a", "--param", "a"], ["--param='a'", "given twice"]),
    (["derive", "fourbar", "--outputs", "B", "B"], ["--outputs='B'", "given twice"]),
    (["show", "fourbar", "--param", "d", "--param", "d"], ["--param='d'", "given twice"]),
    (["show", "fourbar", "--set", "a=2", "--set", "a=3"], ["--set='a=3'", "a is set twice"]),
    (["show", "fourbar", "--set", "a=2", "--set", "a=2"], ["--set='a=2'", "a is set twice"]),
], ids=["param", "outputs", "show-param", "set-two-values", "set-same-value"]))
def test_a_name_given_twice_is_refused(tmp_path, args, words, apart):
    refused(refusal(*args, apart=apart, cwd=tmp_path), *words)


def test_ten_thousand_copies_of_a_param_are_refused_at_the_second(tmp_path):
    """sympy refused the repeated generator after 37 s of work, in a traceback."""
    done = algkin("derive", "fourbar", "--outputs", "B", *["--param", "a"] * 10_000, cwd=tmp_path)
    assert len(refused(done, "--param='a'", "given twice")) < 100


def test_a_value_of_100000_digits_is_refused_in_a_short_line(tmp_path):
    line = refused(algkin("derive", "fourbar", "--outputs", "B", "--set", "a=" + "7" * 100_000, cwd=tmp_path),
                   "--set='a=777", "(100002 characters)", "longer than 500 characters")
    assert len(line) < 200


@pytest.mark.parametrize("args, words, apart", first_apart([
    (["show", "fourbar", "--set", "a=\u0661"], ["--set=", "ASCII"]),             # Arabic-Indic one
    (["show", "fourbar", "--set", "a=\uff12"], ["--set=", "ASCII"]),             # fullwidth two
    (["show", "fourbar", "--set", "a=2\u00a0"], ["--set=", "ASCII"]),            # a trailing no-break space
    (["derive", "fourbar", "--samples", "\uff14"], ["--samples", "ASCII"]),
    (["derive", "fourbar", "--seed", "\u0661"], ["--seed", "ASCII"]),
    (["derive", "fourbar", "--max-seconds", "\u0665"], ["--max-seconds"]),
    (["derive", "fourbar", "--max-terms", "\u0665"], ["--max-terms"]),
    (["extremum", "arm-string", "--of", "AB", "--range", "0:\u0661\u0668\u0660"], ["--range"]),
    (["sweep", "fourbar", "--grid", "a=\u0661:2:3", "--out", "sweep"], ["--grid", "is not a number"]),
    (["sweep", "fourbar", "--grid", "a=1:2:\uff13", "--out", "sweep"], ["--grid", "COUNT"]),
    (["sweep", "fourbar", "--grid", "a=1:2\u00a0:3", "--out", "sweep"], ["--grid", "is not a number"]),
    (["plot", "fourbar", "--out", "f.html", "--range-of", "a=0.5:\uff12"], ["--range-of"]),
    (["plot", "fourbar", "--out", "f.png", "--input", "\uff13\uff10"], ["--input"]),
], ids=["set-arabic-indic", "set-fullwidth", "set-no-break-space", "samples", "seed", "max-seconds", "max-terms",
        "range", "grid-value", "grid-count", "grid-no-break-space", "range-of", "input"]))
def test_numbers_in_other_scripts_are_refused(tmp_path, args, words, apart):
    """Python's int(), float() and Fraction() read them; the tiny language (docs/scene-format.md) is ASCII."""
    refused(refusal(*args, apart=apart, cwd=tmp_path), *words)
    assert os.listdir(tmp_path) == []


def test_a_scene_expression_in_other_digits_is_refused(tmp_path):
    text = FIVE_BAR.replace('lengths = [3, 3]', 'lengths = ["\u0663", 3]')
    assert text != FIVE_BAR
    (tmp_path / "five.toml").write_text(text, encoding="utf-8")
    refused(algkin("show", "five.toml", cwd=tmp_path), "five.toml", "points.P.lengths", "ASCII")


def test_an_irrational_value_set_is_refused_saying_what_is_allowed(tmp_path):
    refused(algkin("derive", "fourbar", "--outputs", "B", "--set", "a=sqrt(2)", cwd=tmp_path),
            "--set='a=sqrt(2)'", "not rational", "sqrt(9/4)")
    done = run_main(["show", "fourbar", "--set", "a=sqrt(9/4)", "--json"], tmp_path)  # a rational, written with sqrt
    assert done.returncode == 0, done.stderr


FAR = """
[points]
O = { fixed = [0, 0] }
D = { fixed = [10, 0] }
C = { dyad = ["O", "D"], lengths = [1, 1], branch = "left" }
[outputs]
C = "C"
"""


def test_show_says_a_dyad_on_fixed_bases_never_assembles(tmp_path):
    """|OD| = 10 > 1 + 1: no configuration; ``show`` compiled it without a word."""
    (tmp_path / "far.toml").write_text(FAR)
    text = algkin("show", "far.toml", cwd=tmp_path)
    assert text.returncode == 0, text.stderr
    assert "never assembles: C: its fixed bases O and D are 10 apart" in text.stdout
    document = json.loads(run_main(["show", "far.toml", "--json"], tmp_path).stdout)  # the document: in this process
    assert list(document["never_assembles"]) == ["C"]
    (tmp_path / "near.toml").write_text(FAR.replace("[10, 0]", "[2, 0]"))  # tangent circles: one configuration
    assert json.loads(run_main(["show", "near.toml", "--json"], tmp_path).stdout)["never_assembles"] == {}
    refused(algkin("derive", "far.toml", cwd=tmp_path), "far.toml", "points.C", "never assemble")


def test_a_dyad_on_two_fixed_points_at_one_place_is_bad_input(tmp_path):
    """It was exit 1, "resultant vanished"."""
    (tmp_path / "same.toml").write_text(FAR.replace('D = { fixed = [10, 0] }', 'D = { fixed = ["0.0", "0/7"] }'))
    for command, apart in (("show", True), ("derive", False)):
        refused(refusal(command, "same.toml", apart=apart, cwd=tmp_path), "same.toml", "points.C", "bases coincide",
                "O and D")


def test_a_float_overflow_in_the_verification_says_no_second_line(tmp_path):
    # a coupler point 1e99 along the coupler: the curve's coefficients pass float range where it is
    # checked; numpy's overflow warnings were six lines on stderr beside the report's failed check
    done = algkin("curve", "fourbar", "--point", "P", "--set", "p=1e99", "--samples", "3", cwd=tmp_path)
    assert done.returncode in (0, 1) and done.stderr == "", done.stderr[-2000:]


@pytest.mark.parametrize("flag, apart", first_apart(["--seed", "--samples", "--max-terms"], ["seed", "samples", "max-terms"]))
def test_a_whole_number_of_5000_digits_is_refused_as_too_long_in_a_short_line(tmp_path, flag, apart):
    # Python reads at most 4300 digits: the line said "expected a whole number (ASCII digits 0-9)" of
    # one (--max-terms: "invalid _terms value") and repeated the command line whole, 10,000 characters
    line = refused(refusal("derive", "fourbar", flag, "9" * 5000, apart=apart, cwd=tmp_path), flag, "5000 digits")
    assert "ASCII" not in line and "_terms" not in line and len(line) < 400, line[:500]
