"""Text reports are summaries a person reads; --json, --out and --latex give the whole forms."""

import json
import subprocess
import sys

import sympy

import algkin
from algkin.ui.cli.reports import _report_toggles

from .test_usage import ROOT, run_cli


def test_derive_text_summarises_long_forms_and_out_keeps_them_whole(tmp_path):
    out = tmp_path / "stephenson.json"
    command = [sys.executable, "-m", "algkin", "derive", "stephenson-iii", "--out", str(out)]
    with subprocess.Popen(command, cwd=tmp_path, env={"PYTHONPATH": str(ROOT)}, stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE, text=True) as cli:
        expected = algkin.derive("stephenson-iii").to_json()  # meanwhile, the same through the Python API
        text, errors = cli.communicate(timeout=300)
    assert cli.returncode == 0, errors
    assert len(text.encode()) < 8000 and max(len(line) for line in text.splitlines()) <= 250
    assert "full forms: --json or --out FILE" in text
    assert f"wrote the full JSON document to {out}" in text
    document = json.loads(out.read_text())
    assert document["eliminants"] == expected["eliminants"]
    assert [b["values"] for b in document["branches"]] == [b["values"] for b in expected["branches"]]
    assert max(len(p) for p in document["eliminants"].values()) > 10000  # whole, not summarised


def test_short_forms_stay_whole_with_no_hint(tmp_path):
    result = run_cli(["derive", "arm-string", "--samples", "0"], tmp_path)
    assert result.returncode == 0, result.stderr
    document = algkin.derive("arm-string", samples=0).to_json()
    for form in [*document["eliminants"].values(), *document["branches"][0]["values"].values()]:
        assert f": {form}\n" in result.stdout or f" = {form}\n" in result.stdout
    assert "full forms" not in result.stdout


def test_toggles_text_puts_each_dropped_factor_on_one_short_line():
    long_factor = " + ".join(f"{k}*c_t**{k}" for k in range(1, 80))
    document = {"scene": "s", "input": "t", "range": [0, 360], "toggles": [], "grashof": None,
                "artefacts": [{"eliminant": "B_x", "factor": long_factor, "why": "no real root\n  (certified)"}]}
    lines = _report_toggles(document).splitlines()
    assert all(len(line) <= 250 for line in lines), lines
    assert lines[-2].startswith("dropped from disc(B_x): 1*c_t**1 + ") and "(certified)" in lines[-2]
    assert lines[-1] == "full factors: --json"


def test_latex_of_derive_curve_and_extremum(tmp_path):
    derived = run_cli(["derive", "chebyshev-lambda", "--outputs", "B", "--samples", "0", "--latex"], tmp_path)
    assert derived.returncode == 0, derived.stderr
    result = algkin.derive("chebyshev-lambda", ["B"], samples=0)
    for elimination in result.eliminations.values():
        assert sympy.latex(elimination.polynomial) + " = 0" in derived.stdout
    assert "\\sqrt" in derived.stdout and "\\frac" in derived.stdout
    curve = run_cli(["curve", "chebyshev-lambda", "--point", "P", "--samples", "0", "--latex"], tmp_path)
    assert curve.returncode == 0, curve.stderr
    assert sympy.latex(algkin.curve("chebyshev-lambda", "P", samples=0).elimination.polynomial) in curve.stdout
    minimum = run_cli(["extremum", "arm-string", "--of", "AB", "--param", "b", "--latex"], tmp_path)
    assert minimum.returncode == 0, minimum.stderr
    assert "\\sqrt{b^{2} + 160000} - 350" in minimum.stdout


def test_latex_with_json_is_refused(tmp_path):
    for args in (["derive", "chebyshev-lambda"], ["curve", "chebyshev-lambda", "--point", "P"],
                 ["extremum", "arm-string", "--of", "AB"]):
        result = run_cli([*args, "--latex", "--json"], tmp_path)
        assert result.returncode == 2
        assert "--latex" in result.stderr and len(result.stderr.splitlines()) == 1
        assert json.loads(result.stdout)["error"]["kind"] == "usage"
