"""``algkin sweep`` and ``algkin atlas`` on the command line: bad input is one line, exit 2,
and nothing written; a good run reports its counts."""

import json

import pytest

from algkin.ui.cli import main

GOOD = ["sweep", "fourbar", "--grid", "a=1:2:2", "--analyses", "grashof", "--executor", "serial"]


@pytest.mark.parametrize("change, says", [
    (["--grid", "a=1:2"], "--grid='a=1:2': expected NAME=LO:HI:COUNT"),
    (["--grid", "zz=1:2:3"], "--grid='zz': not a parameter of fourbar"),
    (["--grid", "a=2:1:3"], "LO must not exceed HI"),
    (["--analyses", "grashof,wobble"], "--analyses='wobble': unknown; valid: curve, grashof, toggles, limits"),
    (["--executor", "threads"], "--executor='threads': unknown; valid: dask, serial"),
    (["--workers", "2"], "--workers=2: sizes the LocalCluster: goes with --executor dask"),
    (["--workers", "0"], "expected a whole number from 1"),
    (["--budget", "-1"], "--budget=-1.0: must be a positive number of seconds"),
    (["--point", "Z"], "--point='Z': not a point of fourbar"),
    (["--random", "5"], "--grid='a=1:2:2': expected NAME=LO:HI, e.g. a=1:2 (with --random)"),
    (["--chunk", "x"], "expected a whole number from 1"),
])
def test_bad_input_is_one_line_and_nothing_is_written(tmp_path, capsys, change, says):
    argv = GOOD + ["--out", str(tmp_path / "out")]
    for k in range(0, len(change), 2):
        if change[k] in argv and change[k] != "--grid":
            argv[argv.index(change[k]) + 1] = change[k + 1]
        elif change[k] == "--grid":
            argv[argv.index("--grid") + 1] = change[k + 1]
        else:
            argv += change[k:k + 2]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and says in err, err
    assert not (tmp_path / "out").exists()


def test_a_directory_holding_other_files_is_refused(tmp_path, capsys):
    (tmp_path / "notes.txt").write_text("mine")
    assert main(GOOD + ["--out", str(tmp_path)]) == 2
    assert "is not empty and holds no sweep" in capsys.readouterr().err
    assert [p.name for p in tmp_path.iterdir()] == ["notes.txt"]


def test_a_sweep_and_its_atlas(tmp_path, capsys):
    assert main(GOOD + ["--grid", "d=4:10:2", "--out", str(tmp_path / "out"), "--json"]) == 0
    document = json.loads(capsys.readouterr().out)
    # a = 1 or 2 on a ground of 4 (coupler 3, rocker 7/2) assembles; on a ground of 10 it cannot
    assert document["designs"] == document["computed"] == 4
    assert document["status"] == {"ok": 2, "does-not-assemble": 2}
    assert main(["atlas", str(tmp_path / "out"), "--out", str(tmp_path / "atlas.html")]) == 0
    assert capsys.readouterr().out == f"wrote {tmp_path / 'atlas.html'}: 2 of 4 designs drawn\n"


def test_the_atlas_of_a_directory_without_a_sweep(tmp_path, capsys):
    (tmp_path / "empty").mkdir()  # the page beside it: never inside the directory read
    assert main(["atlas", str(tmp_path / "empty"), "--out", str(tmp_path / "atlas.html")]) == 2
    assert "holds no sweep" in capsys.readouterr().err and not (tmp_path / "atlas.html").exists()


def test_a_terminal_sees_the_count_of_designs(tmp_path):
    from ...processes import algkin, run_on_terminal

    code, out, err, _ = run_on_terminal(algkin(*GOOD, "--grid", "d=4:5:2", "--out", tmp_path / "out", "--chunk", "1"),
                                        120)
    assert code == 0 and out.startswith("4 designs (4 computed now)")
    # the sweep's own count, not replaced by the analyses' stages
    assert "sweeping 4 designs, 0 done before: 0/4 designs" in err and err.endswith("\r")


def test_a_design_past_its_budget_fails_saying_so(tmp_path, capsys):
    argv = ["sweep", "fourbar", "--grid", "a=1:2:2", "--analyses", "curve", "--executor", "serial",
            "--budget", "0.001", "--out", str(tmp_path / "out"), "--json"]
    assert main(argv) == 0
    assert json.loads(capsys.readouterr().out)["status"] == {"failed": 2}
    from algkin.sweep import read_dataset

    reasons = read_dataset(tmp_path / "out").column("reason").to_pylist()
    assert all(r.startswith("budget: max_seconds=0.001: stopped after") for r in reasons), reasons
