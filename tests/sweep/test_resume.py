"""A sweep stopped anywhere resumes where it stopped: killed by SIGKILL after some parts, or
interrupted while writing a part; restarted, it computes only the missing chunks and its dataset
is the uninterrupted one, byte for byte once the timing columns are dropped."""

import io
import json
import signal

import pyarrow.parquet as pq
import pytest

from algkin.sweep import read_dataset, store, sweep, without_timings
from algkin.ui.cli import main

from ..processes import run

GRID = ["a=1/2:3/2:4", "m=3:4:2"]  # 8 four-bars
ANALYSES = ["curve", "grashof"]


def canonical(folder):
    buffer = io.BytesIO()
    pq.write_table(without_timings(read_dataset(folder)), buffer)
    return buffer.getvalue()


@pytest.fixture(scope="module")
def uninterrupted(tmp_path_factory):
    folder = tmp_path_factory.mktemp("whole")
    done = sweep("fourbar", folder, grid=GRID, analyses=ANALYSES, executor="serial", chunk=1)
    assert done.computed == 8 and done.counts == {"ok": 8}
    return folder


def parts(folder):
    return {p.name: (p.stat().st_ino, p.stat().st_mtime_ns) for p in (folder / "parts").iterdir()}


# The sweep's process kills itself (SIGKILL: no clean-up) once it has written its third part:
# killed at the same point however fast the machine, and never too late to test a resumption.
KILLED_AFTER_THREE = """
import os, signal, sys
import algkin.sweep
from algkin.ui.cli import main

real = algkin.sweep.write_part
written = []

def write_part(folder, index, rows, columns):
    real(folder, index, rows, columns)
    written.append(index)
    if len(written) == 3:
        os.kill(os.getpid(), signal.SIGKILL)

algkin.sweep.write_part = write_part
main(sys.argv[1:])
"""


def test_killed_by_sigkill_and_restarted(tmp_path, uninterrupted):
    argv = ["sweep", "fourbar", *(f"--grid={g}" for g in GRID), "--analyses", ",".join(ANALYSES),
            "--out", tmp_path, "--executor", "serial", "--chunk", "1"]
    code, _, err, _ = run(["-c", KILLED_AFTER_THREE, *argv], timeout=300)  # a hang guard
    assert code == -signal.SIGKILL, err
    before = parts(tmp_path)
    assert len(before) == 3 and len(store.done_chunks(tmp_path)) == 3
    assert all(not n.startswith(".") for n in before), "a partial part file was left"
    code = main([*map(str, argv), "--json", "--quiet"])
    assert code == 0
    after = parts(tmp_path)
    # the parts of the killed run are the same files, untouched; only the missing ones were computed
    assert {n: after[n] for n in before} == before and len(after) == 8
    assert canonical(tmp_path) == canonical(uninterrupted)


def test_interrupted_while_writing_a_part(tmp_path, uninterrupted, monkeypatch):
    written = []
    real = store.write_part

    def interrupted(folder, index, rows, columns):
        if len(written) == 2:
            raise KeyboardInterrupt  # as Ctrl-C, in the middle of the third part
        written.append(index)
        real(folder, index, rows, columns)

    monkeypatch.setattr("algkin.sweep.write_part", interrupted)
    with pytest.raises(KeyboardInterrupt):
        sweep("fourbar", tmp_path, grid=GRID, analyses=ANALYSES, executor="serial", chunk=1)
    assert sorted(store.done_chunks(tmp_path)) == written and not (tmp_path / "designs.parquet").exists()
    monkeypatch.undo()
    # what a SIGKILL in the middle of a write leaves: the part's hidden temporary file, half written
    (tmp_path / "parts" / ".part-000002.x1y2.tmp.parquet").write_bytes(b"PAR1 half")
    done = sweep("fourbar", tmp_path, grid=GRID, analyses=ANALYSES, executor="serial", chunk=1)
    assert done.computed == 6 and done.designs == 8
    assert canonical(tmp_path) == canonical(uninterrupted)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["designs.parquet", "manifest.json", "parts"]
    assert sorted(p.name for p in (tmp_path / "parts").iterdir()) == [f"part-{k:06d}.parquet" for k in range(8)]


def test_a_finished_sweep_run_again_computes_nothing(tmp_path, uninterrupted):
    import shutil

    shutil.copytree(uninterrupted, tmp_path, dirs_exist_ok=True)
    done = sweep("fourbar", tmp_path, grid=GRID, analyses=ANALYSES, executor="serial", chunk=1)
    assert done.computed == 0 and canonical(tmp_path) == canonical(uninterrupted)


@pytest.mark.parametrize("change", [["--grid", "a=1/2:3/2:3"], ["--analyses", "curve"], ["--chunk", "2"],
                                    ["--point", "B"]])
def test_resuming_with_other_arguments_is_refused(tmp_path, uninterrupted, capsys, change):
    import shutil

    shutil.copytree(uninterrupted, tmp_path, dirs_exist_ok=True)
    argv = {"--grid": GRID[0], "--analyses": ",".join(ANALYSES), "--chunk": "1", "--point": "P"}
    argv[change[0]] = change[1]
    files = {p: p.read_bytes() for p in tmp_path.rglob("*") if p.is_file()}
    code = main(["sweep", "fourbar", "--grid", argv["--grid"], *([] if change[0] == "--grid" else ["--grid", GRID[1]]),
                 *(x for k in ("--analyses", "--chunk", "--point") for x in (k, argv[k])),
                 "--out", str(tmp_path), "--executor", "serial"])
    err = capsys.readouterr().err
    assert code == 2 and err.count("\n") == 1 and "holds a different sweep" in err
    assert {p: p.read_bytes() for p in tmp_path.rglob("*") if p.is_file()} == files


def test_the_manifest_says_what_the_sweep_is(uninterrupted):
    manifest = json.loads((uninterrupted / "manifest.json").read_text())
    assert manifest["scene"]["name"] == "fourbar" and "[points]" in manifest["scene"]["toml"]
    assert manifest["designs"] == {"grid": {"a": ["1/2", "5/6", "7/6", "3/2"], "m": ["3", "4"]}}
    assert manifest["analyses"] == ANALYSES and manifest["count"] == 8 and manifest["algkin"]


@pytest.mark.parametrize("damage", ["manifest", "part"])
def test_a_damaged_sweep_directory_is_refused_in_one_line_and_left_as_it_is(tmp_path, uninterrupted, capsys,
                                                                            damage):
    """A manifest edited into a list, a part file overwritten: each was a traceback (AttributeError, ArrowInvalid)."""
    import shutil

    shutil.copytree(uninterrupted, tmp_path, dirs_exist_ok=True)
    (tmp_path / "designs.parquet").unlink()  # the parts are merged again
    damaged = tmp_path / ("manifest.json" if damage == "manifest" else "parts/part-000001.parquet")
    damaged.write_text("[]")
    files = {p: p.read_bytes() for p in tmp_path.rglob("*") if p.is_file()}
    code = main(["sweep", "fourbar", *(x for g in GRID for x in ("--grid", g)), "--analyses", ",".join(ANALYSES),
                 "--chunk", "1", "--out", str(tmp_path), "--executor", "serial"])
    err = capsys.readouterr().err
    assert code == 2 and err.count("\n") == 1 and "Traceback" not in err, err
    assert ("is not a sweep's" if damage == "manifest" else "part-000001.parquet': cannot be read") in err
    assert {p: p.read_bytes() for p in tmp_path.rglob("*") if p.is_file()} == files


# Eight random four-bars, a in [1, 2]: drawn with this seed, the generator's eighth row repeats an earlier
# one (found by trying seeds; checked in the test, by numpy directly).
RANDOM = ["--random", "8", "--seed", "23365", "--grid", "a=1:2", "--analyses", "grashof", "--chunk", "4",
          "--executor", "serial"]


def first_scheme_designs(ranges, count, seed):
    """The random designs as algkin drew them before distinct designs (draw scheme 1): the generator's
    first ``count`` rows of steps, repeats kept."""
    from fractions import Fraction

    import numpy as np

    from algkin.sweep.grid import RANDOM_STEPS, Designs

    steps = np.random.Generator(np.random.PCG64(seed)).integers(0, RANDOM_STEPS, size=(count, len(ranges)),
                                                                endpoint=True)
    bounds = list(ranges.values())
    return Designs(list(ranges), count, lambda k: [lo + (hi - lo) * Fraction(int(step), RANDOM_STEPS)
                                                   for (lo, hi), step in zip(bounds, steps[k])])


def stopped_first_scheme_sweep(folder, monkeypatch, argv, *, keep):
    """``folder`` as ``algkin sweep argv`` of the first draw scheme leaves it, stopped with only the parts
    ``keep``: its designs drawn so, its manifest without the scheme's number."""
    with monkeypatch.context() as patched:
        patched.setattr("algkin.sweep.random_designs", first_scheme_designs)
        assert main([*argv, "--out", str(folder), "--quiet"]) == 0
    manifest = json.loads((folder / "manifest.json").read_text())
    manifest["designs"]["random"].pop("scheme", None)
    (folder / "manifest.json").write_text(json.dumps(manifest, indent=2, sort_keys=True) + "\n")
    (folder / "designs.parquet").unlink()
    for part in (folder / "parts").iterdir():
        if part.name not in keep:
            part.unlink()


def test_a_random_sweep_begun_with_repeated_designs_is_not_resumed(tmp_path, monkeypatch, capsys):
    # It was resumed: its second chunk's designs (the eighth a repeat) joined the first chunk of the
    # distinct draws, a set of designs neither run draws.
    from algkin.sweep.grid import parse_ranges

    draws = [d["a"] for d in first_scheme_designs(parse_ranges(["a=1:2"]), 8, 23365)]
    assert len(set(draws[:7])) == 7 and draws[7] in draws[:7]  # the premise: the eighth design repeats
    stopped_first_scheme_sweep(tmp_path, monkeypatch, ["sweep", "fourbar", *RANDOM], keep={"part-000001.parquet"})
    capsys.readouterr()
    files = {p: p.read_bytes() for p in tmp_path.rglob("*") if p.is_file()}
    code = main(["sweep", "fourbar", *RANDOM, "--out", str(tmp_path)])
    err = capsys.readouterr().err
    assert code == 2 and err.count("\n") == 1, err
    assert err.startswith(f"algkin: error: --out='{tmp_path}': holds a sweep begun by an older algkin") and \
        "design 7 repeats an earlier one" in err and "give a new directory" in err
    assert {p: p.read_bytes() for p in tmp_path.rglob("*") if p.is_file()} == files


def test_a_random_sweep_begun_without_a_repeat_is_resumed_as_the_same_designs(tmp_path, monkeypatch):
    # Drawn by the first scheme, eight designs with seed 0 repeat none: they are the distinct draws too.
    from algkin.sweep.grid import parse_ranges

    assert len({d["a"] for d in first_scheme_designs(parse_ranges(["a=1:2"]), 8, 0)}) == 8
    whole, stopped = tmp_path / "whole", tmp_path / "stopped"
    argv = ["sweep", "fourbar", *RANDOM[:2], "--seed", "0", *RANDOM[4:]]
    assert main([*argv, "--out", str(whole), "--quiet"]) == 0
    stopped_first_scheme_sweep(stopped, monkeypatch, argv, keep={"part-000000.parquet"})
    done = sweep("fourbar", stopped, grid=["a=1:2"], random=8, seed=0, analyses=["grashof"], chunk=4,
                 executor="serial")
    assert done.computed == 4 and canonical(stopped) == canonical(whole)
