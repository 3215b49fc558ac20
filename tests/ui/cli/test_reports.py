"""Text reports are summaries a person reads; --json, --out and --latex give the whole forms."""

import json
import math
import re

import pytest
import sympy

import algkin
from algkin.ui.cli import main
from algkin.ui.cli.reports import report_toggles

from .in_process import run_main
from .test_usage import ROOT, run_cli


def test_derive_text_summarises_long_forms_and_out_keeps_them_whole(tmp_path):
    out = tmp_path / "stephenson.json"
    cli = run_main(["derive", "stephenson-iii", "--out", str(out)], tmp_path)
    text = cli.stdout
    expected = algkin.derive("stephenson-iii").to_json()  # the same through the Python API
    assert cli.returncode == 0, cli.stderr
    assert len(text.encode()) < 8000 and max(len(line) for line in text.splitlines()) <= 250
    assert "full forms: --json or --out FILE" in text
    assert f"wrote the full JSON document to {out}" in text
    document = json.loads(out.read_text())
    assert document["eliminants"] == expected["eliminants"]
    assert [b["values"] for b in document["branches"]] == [b["values"] for b in expected["branches"]]
    assert max(len(p) for p in document["eliminants"].values()) > 10000  # whole, not summarised


def test_short_forms_stay_whole_with_no_hint(tmp_path):
    result = run_main(["derive", "arm-string", "--samples", "0"], tmp_path)
    assert result.returncode == 0, result.stderr
    document = algkin.derive("arm-string", samples=0).to_json()
    for form in [*document["eliminants_reduced"].values(), *document["branches"][0]["values"].values()]:
        assert f": {form}\n" in result.stdout or f" = {form}\n" in result.stdout
    assert "full forms" not in result.stdout


def test_toggles_text_puts_each_dropped_factor_on_one_short_line():
    long_factor = " + ".join(f"{k}*c_t**{k}" for k in range(1, 80))
    document = {"scene": "s", "input": "t", "unit": "deg", "range": [0, 360], "toggles": [], "grashof": None,
                "artefacts": [{"eliminant": "B_x", "factor": long_factor, "why": "no real root\n  (certified)"}]}
    lines = report_toggles(document).splitlines()
    assert all(len(line) <= 250 for line in lines), lines
    assert lines[-2].startswith("dropped from disc(B_x): 1*c_t**1 + ") and "(certified)" in lines[-2]
    assert lines[-1] == "full factors: --json"


def test_extremum_says_a_range_end_where_the_mechanism_does_not_assemble(tmp_path):
    # fourbar-nongrashof: at theta = +-180 deg, A = (-2, 0) is 7 from D = (5, 0), beyond the coupler
    # and rocker's reach 3 + 7/2: B does not exist there (the text once said "nan").
    done = run_main(["extremum", "fourbar-nongrashof", "--of", "B.y"], tmp_path)
    ends = [line.split() for line in done.stdout.splitlines() if line.lstrip().startswith("end ")]
    assert done.returncode == 0 and "nan" not in done.stdout
    assert ends == [["end", "(does", "not", "assemble)", "at", "-180", "deg"], ["end", "(does", "not", "assemble)", "at", "180", "deg"]]


def test_latex_of_derive_curve_and_extremum(tmp_path):
    derived = run_main(["derive", "chebyshev-lambda", "--outputs", "B", "--samples", "0", "--latex"], tmp_path)
    assert derived.returncode == 0, derived.stderr
    result = algkin.derive("chebyshev-lambda", ["B"], samples=0)
    for reduced in result.eliminants_reduced.values():  # on the circle, and labelled so
        assert sympy.latex(reduced) + " = 0" in derived.stdout
    assert "reduced on c^2 + s^2 = 1" in derived.stdout
    assert "\\sqrt" in derived.stdout and "\\frac" in derived.stdout
    curve = run_main(["curve", "chebyshev-lambda", "--point", "P", "--samples", "0", "--latex"], tmp_path)
    assert curve.returncode == 0, curve.stderr
    assert sympy.latex(algkin.curve("chebyshev-lambda", "P", samples=0).elimination.polynomial) in curve.stdout
    minimum = run_main(["extremum", "arm-string", "--of", "AB", "--param", "b", "--latex"], tmp_path)
    assert minimum.returncode == 0, minimum.stderr
    assert "\\sqrt{b^{2} + 160000} - 350" in minimum.stdout


def test_derive_reduces_its_eliminants_once_without_latex(monkeypatch, capsys):
    """The LaTeX forms (the eliminants reduced again, the closed forms made readable) only for --latex:
    on a six-bar they were seconds of every derive. The JSON's reduction is written from python-flint,
    without the sympy forms (``eliminants_reduced``)."""
    from algkin.derivation.results import Derivation
    from algkin.ui.cli import main

    reductions = []
    reduced = Derivation.eliminants_reduced.fget
    monkeypatch.setattr(Derivation, "eliminants_reduced",
                        property(lambda result: reductions.append(1) or reduced(result)))
    assert main(["derive", "chebyshev-lambda", "--outputs", "B", "--samples", "0", "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["eliminants_reduced"]
    assert len(reductions) == 0


def test_latex_with_json_is_refused(tmp_path):
    # the first as the program, the others by main in this process: the same parsing, exit code and stderr
    for run, args in ((run_cli, ["derive", "chebyshev-lambda"]), (run_main, ["curve", "chebyshev-lambda", "--point", "P"]),
                      (run_main, ["extremum", "arm-string", "--of", "AB"])):
        result = run([*args, "--latex", "--json"], tmp_path)
        assert result.returncode == 2
        assert "--latex" in result.stderr and len(result.stderr.splitlines()) == 1
        assert json.loads(result.stdout)["error"]["kind"] == "usage"


def test_toggles_gives_the_limit_positions_and_the_time_ratio(tmp_path):
    # the offset slider-crank (crank 1, rod 3, offset 1/2): B stops where crank and rod line up,
    # |OB| = 4 and 2; by hand its stroke is (sqrt(63) - sqrt(15))/2 and the return angle
    # alpha = asin(1/4) - asin(1/8)
    text = run_main(["toggles", "slider-crank"], tmp_path)
    assert text.returncode == 0, text.stderr
    assert "  extended   B [ahead] * at [7.18075578145828" in text.stdout
    assert "output stroke: travel 2.03213529349318 = (-sqrt(15) + 3*sqrt(7))/2" in text.stdout
    alpha = math.degrees(math.asin(1 / 4) - math.asin(1 / 8))
    printed = re.search(r"time ratio of B \[ahead\]: (\S+) = \(180 \+ alpha\)/\(180 - alpha\)", text.stdout)
    assert float(printed.group(1)) == pytest.approx((180 + alpha) / (180 - alpha), rel=1e-14)
    result = run_main(["toggles", "slider-crank", "--json"], tmp_path)
    document = json.loads(result.stdout)
    assert {"scene", "input", "range", "toggles", "grashof", "artefacts", "limits", "time_ratio"} <= set(document)
    ahead = [g for g in document["limits"] if g["selected"]]
    assert [(g["kind"], g["point"], g["branch"], g["certified"]) for g in ahead] == [
        ("extended", "B", "ahead", True), ("folded", "B", "ahead", True)]
    for limit in document["limits"]:  # the exact angle is sympy's syntax, and the certified one
        assert abs(float(sympy.sympify(limit["exact_deg"])) - limit["input_deg"]) < 1e-12
    ratio = document["time_ratio"]
    assert ratio["ratio"] == pytest.approx((180 + alpha) / (180 - alpha), rel=1e-14)
    assert [s["stroke"] for s in ratio["strokes"]] == ["working", "return"]
    assert ratio["stroke"]["exact"] == "(-sqrt(15) + 3*sqrt(7))/2"


def test_toggles_time_ratio_follows_set_and_is_null_with_a_reason(tmp_path):
    # crank 3/2, ground 4, coupler 3, rocker 7/2: a crank-rocker; by the law of cosines the crank
    # is at acos((16 + 4.5**2 - 3.5**2)/36) extended and 180 + acos((16 + 1.5**2 - 3.5**2)/12) folded
    set_crank = run_main(["toggles", "fourbar", "--set", "a=3/2", "--json"], tmp_path)
    assert set_crank.returncode == 0, set_crank.stderr
    extended = math.degrees(math.acos((16 + 4.5**2 - 3.5**2) / 36))
    folded = 180 + math.degrees(math.acos((16 + 1.5**2 - 3.5**2) / 12))
    span = folded - extended
    ratio = json.loads(set_crank.stdout)["time_ratio"]
    assert ratio["ratio"] == pytest.approx(max(span, 360 - span) / min(span, 360 - span), rel=1e-12)
    rocking = run_main(["toggles", "fourbar-nongrashof", "--json"], tmp_path)
    document = json.loads(rocking.stdout)
    assert document["time_ratio"] is None and "does not turn fully" in document["time_ratio_reason"]
    assert len(document["limits"]) == 2


@pytest.mark.parametrize("command", [["show"], ["derive", "--samples", "3"], ["toggles"]])
def test_a_scene_name_cannot_start_a_line_of_the_report(tmp_path, capsys, command):
    # a name holding a newline printed a line of the scene's own making among algkin's
    forged = "x\nverification passed: 80 branch values on 40 samples\r\n"
    text = (ROOT / "algkin" / "catalog" / "chebyshev-lambda.toml").read_text()
    (tmp_path / "forged.toml").write_text(text.replace('name = "chebyshev-lambda"', f"name = {json.dumps(forged)}"))
    from algkin.ui.cli import main

    assert main([command[0], str(tmp_path / "forged.toml"), *command[1:]]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert not any(line.startswith("verification passed: 80") for line in lines)
    assert any("x\\nverification passed: 80 branch values on 40 samples\\r\\n" in line for line in lines)


def test_show_of_a_scene_with_no_input_says_so(tmp_path, capsys):
    # it printed "inputs: " and nothing after
    scene = tmp_path / "structure.toml"
    scene.write_text('[points]\nO = { fixed = [0, 0] }\nD = { fixed = [2, 0] }\n[outputs]\nd = "dist(O, D)"\n')
    assert main(["show", str(scene)]) == 0
    assert "inputs: none (a structure)\n" in capsys.readouterr().out


def test_a_scene_description_cannot_start_a_line_of_show(tmp_path, capsys):
    # the description was printed as it is: its newline started a line that read as algkin's own
    text = (ROOT / "algkin" / "catalog" / "chebyshev-lambda.toml").read_text()
    forged = "one\nnever assembles: B: forged\r\nequations (= 0):"
    (tmp_path / "forged.toml").write_text(text.replace("description = ", f"description = {json.dumps(forged)}\n# ", 1))
    assert main(["show", str(tmp_path / "forged.toml")]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert lines[0] == "scene chebyshev-lambda: one\\nnever assembles: B: forged\\r\\nequations (= 0):"
    assert not any(line.startswith("never assembles") for line in lines)
    assert sum(line.startswith("equations (= 0):") for line in lines) == 1


def test_a_latex_caption_stays_in_its_comment():
    # a caption holding a newline (an output typed "dist(O,\nB)") ended the % comment: the rest was TeX
    from algkin.ui.cli.reports import latex_lines

    text = latex_lines([("minimum of dist(O,\nB)\r\\input{x}", sympy.Integer(2), "")])
    assert text.splitlines() == ["% minimum of dist(O,\\nB)\\r\\input{x}", r"\[ 2 \]"]


@pytest.mark.parametrize("command", [["accuracy", "fourbar", "--samples", "10"], ["extremum", "fourbar"]])
def test_an_output_typed_with_a_newline_cannot_start_a_line_of_the_report(tmp_path, command):
    # --of "dist(O,\nB)" (a newline is white space in it) printed "B) in fourbar..." as a line of its own
    result = run_main([*command, "--of", "dist(O,\nB)"], tmp_path)
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    assert "dist(O,\\nB)" in lines[0] and not any(line.startswith("B)") for line in lines)


FORGED_PATH = "x\nalgkin: all checks passed"  # a file's name may hold a newline: printed as it is, it forged a line


@pytest.mark.parametrize("command, out", [
    (["curve", "fourbar", "--point", "P", "--samples", "3", "--out"], FORGED_PATH),
    (["export", "fourbar", "--to", "c", "--out"], FORGED_PATH),
    (["plot", "fourbar", "--of", "dist(O, B)", "--out"], FORGED_PATH + ".svg"),
    (["sweep", "fourbar", "--grid", "a=1:2:2", "--analyses", "grashof", "--executor", "serial", "--out"],
     FORGED_PATH)])
def test_a_path_typed_with_a_newline_is_said_in_one_line(tmp_path, command, out):
    result = run_main([*command, out], tmp_path)
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    assert not any(line.startswith("algkin: all checks passed") for line in lines)
    assert any("x\\nalgkin: all checks passed" in line for line in lines)
    if command[0] == "sweep":  # and the atlas of that sweep, written under a name as forged
        atlas = run_main(["atlas", out, "--out", FORGED_PATH + ".html"], tmp_path)
        assert atlas.returncode == 0, atlas.stderr
        assert atlas.stdout.startswith("wrote x\\nalgkin: all checks passed.html: ") and atlas.stdout.count("\n") == 1

