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
    (["--analyses", "grashof,wobble"], "--analyses='wobble': unknown (valid: curve, grashof, toggles, limits, transmission, singular, modes)"),
    (["--executor", "threads"], "--executor='threads': unknown (valid: dask, serial)"),
    (["--workers", "2"], "--workers=2: sizes the LocalCluster: only for the dask executor without a scheduler"),
    (["--workers", "0"], "expected a whole number from 1"),
    (["--budget", "-1"], "--budget=-1.0: must be a positive number of seconds"),
    (["--point", "Z"], "--point='Z': not a point of fourbar"),
    (["--random", "5"], "--grid='a=1:2:2': expected NAME=LO:HI, e.g. a=1:2 (for random draws)"),
    (["--chunk", "x"], "expected a whole number from 1"),
    (["--grid", "a=1:2:1000000000"], "--grid='a=1:2:1000000000': 1000000000 designs, more than 1000000"),
    (["--grid", "a=1:1:3"], "--grid='a=1:1:3': LO = HI is one value, not 3: give COUNT 1"),
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


@pytest.mark.parametrize("extra, says", [
    (["--grid", "a=1:3:2"], "--grid='a': given twice"),
    (["--random", "1000000000"], "--random=1000000000: expected a number of designs from 1 to 1000000"),
])
def test_a_name_twice_and_absurd_draws_are_refused(tmp_path, capsys, extra, says):
    grid = "a=1:2" if "--random" in extra else "a=1:2:2"
    argv = ["sweep", "fourbar", "--grid", grid, *extra, "--executor", "serial", "--out", str(tmp_path / "out")]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and says in err, err
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("grids, says", [
    (["a=1:1"], "--random=2: the ranges hold 1 distinct design at most (a=1:1: one value)"),
    (["a=1:1", "l=3:3"], "--random=2: the ranges hold 1 distinct design at most (a=1:1, l=3:3: one value each)"),
])
def test_random_draws_in_ranges_of_one_value_are_refused(tmp_path, capsys, grids, says):
    # Two draws where every range is one value are one design twice: refused, as a grid's LO = HI with a
    # COUNT above 1 is.
    argv = ["sweep", "fourbar", *(f"--grid={g}" for g in grids), "--random", "2", "--analyses", "grashof",
            "--executor", "serial", "--out", str(tmp_path / "out")]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and says in err, err
    assert not (tmp_path / "out").exists()


def test_a_run_longer_than_a_day_asks_for_yes(tmp_path, capsys):
    # 10^6 designs, each at least 0.001 s to assemble and 0.2 s of limits (the table's floors, not this
    # machine's speed), one at a time: 201000 s, 2.33 days
    argv = ["sweep", "fourbar", "--grid", "a=1:2:1000", "--grid", "d=1:2:1000", "--analyses", "limits",
            "--executor", "serial", "--out", str(tmp_path / "out")]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and not (tmp_path / "out").exists()
    assert ("--grid='a=1:2:1000 d=1:2:1000': 1000000 designs would take at least 2.33 days (0.2 s each, "
            "1 at once); confirm with yes to start anyway") in err


def test_yes_starts_it(tmp_path, capsys, monkeypatch):
    import dataclasses

    from algkin.sweep import ANALYSES

    # an injected cost: two designs of a day each, one at a time, are two days
    monkeypatch.setitem(ANALYSES, "grashof", dataclasses.replace(ANALYSES["grashof"], seconds=86400.0))
    argv = GOOD + ["--out", str(tmp_path / "out")]
    assert main(argv) == 2
    assert "2 designs would take at least 2 days" in capsys.readouterr().err
    assert main(argv + ["--yes"]) == 0
    assert capsys.readouterr().out.startswith("2 designs (2 computed now): ok 2")


def test_the_atlas_samples_have_a_cap(tmp_path, capsys):
    assert main(GOOD + ["--out", str(tmp_path / "out")]) == 0
    capsys.readouterr()
    argv = ["atlas", str(tmp_path / "out"), "--out", str(tmp_path / "atlas.html"), "--samples", "1000000000"]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--samples=1000000000: expected a number of inputs per thumbnail from 1 to 3601" in err
    assert not (tmp_path / "atlas.html").exists()


def test_the_atlas_is_written_under_an_html_name_only(tmp_path, capsys):
    # a page written as at.png was an HTML page under an image's name
    assert main(GOOD + ["--out", str(tmp_path / "out")]) == 0
    capsys.readouterr()
    assert main(["atlas", str(tmp_path / "out"), "--out", str(tmp_path / "at.png")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "the atlas is an HTML page: give a name ending in .html" in err
    assert not (tmp_path / "at.png").exists()


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


def test_a_structure_among_moving_designs_has_its_own_status(tmp_path, capsys):
    # a = 5/6 and d = 16/3, 19/3, 22/3 (coupler 3, rocker 7/2): |AD| runs from d - a to d + a, B needs
    # 1/2 <= |AD| <= 13/2. d = 16/3: 9/2 to 37/6, the whole turn; d = 19/3: from 11/2, part of it;
    # d = 22/3: from 13/2, reached at theta = 0 only: a structure, no curve, no thumbnail
    argv = ["sweep", "fourbar", "--grid", "a=5/6:5/6:1", "--grid", "d=16/3:22/3:3", "--analyses", "curve",
            "--executor", "serial", "--out", str(tmp_path / "out"), "--json"]
    assert main(argv) == 0
    assert json.loads(capsys.readouterr().out)["status"] == {"ok": 2, "structure": 1}
    from algkin.sweep import read_dataset

    table = read_dataset(tmp_path / "out")
    assert table.column("status").to_pylist() == ["ok", "ok", "structure"]
    assert table.column("curve_degree").to_pylist() == [6, 6, None]
    assert main(["atlas", str(tmp_path / "out"), "--out", str(tmp_path / "atlas.html")]) == 0
    assert capsys.readouterr().out.endswith(": 2 of 3 designs drawn\n")


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


def test_set_gives_the_dimensions_it_does_not_sweep_their_values(tmp_path, capsys):
    """SPEC section 3: every command that takes a scene takes ``--set``; ``sweep`` had none. With the
    ground set to 10 (coupler 3, rocker 7/2), a crank of 1 or 2 leaves |AD| >= 8 > 3 + 7/2: neither
    design assembles, where on the default ground of 4 both do (the test above)."""
    assert main(GOOD + ["--set", "d=10", "--out", str(tmp_path / "out"), "--json"]) == 0
    document = json.loads(capsys.readouterr().out)
    assert document["designs"] == 2 and document["status"] == {"does-not-assemble": 2}
    assert main(GOOD + ["--set", "d=4", "--out", str(tmp_path / "four"), "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["status"] == {"ok": 2}


@pytest.mark.parametrize("change, says", [
    (["--set", "a=3"], "--set='a=3': a is swept by --grid; set it or sweep it, not both"),
    (["--set", "zz=3"], "--set='zz=3': not a parameter of fourbar"),
    (["--set", "l=1/0"], "--set='l=1/0': division by zero"),
    # every design would fail alike (a coupler of length -1), where the file's own values compile
    (["--set", "l=-1"], "--set='l=-1': fourbar.toml: points.B: length must be positive, got -1"),
])
def test_a_set_that_cannot_hold_is_refused_in_one_line(tmp_path, capsys, change, says):
    assert main(GOOD + change + ["--out", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and says in err, err
    assert not (tmp_path / "out").exists()
