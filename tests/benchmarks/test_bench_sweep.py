"""benchmarks/bench_sweep.py's options (its sweeps are timed by running it, never here)."""

import json
import types

import pytest


@pytest.fixture
def bench(benchmark_module):
    return benchmark_module("bench_sweep")


def chosen(bench, *argv):
    arguments = bench.parse(list(argv))
    return list(bench.sweeps(["a=1:2:2"], alone=not arguments.quick,
                             atlas=not (arguments.quick or arguments.no_atlas)))


def test_by_default_this_checkout_alone_every_sweep_once(bench):
    arguments = bench.parse([])
    assert (arguments.against, arguments.repeats) == (None, 1)
    assert chosen(bench) == ["shared", "alone", "dask1", "dask2", "atlas"]
    assert chosen(bench, "--no-atlas") == ["shared", "alone", "dask1", "dask2"]


def test_quick_against_a_checkout_times_the_shared_serial_sweep_and_the_workers(bench, other_checkout):
    arguments = bench.parse(["--against", str(other_checkout), "--quick", "--repeats", "3"])
    assert (arguments.against, arguments.repeats) == (other_checkout, 3)
    assert chosen(bench, "--quick") == ["shared", "dask1", "dask2"]


def test_against_a_directory_without_algkin_is_refused_before_any_sweep(bench, tmp_path, capsys):
    with pytest.raises(SystemExit) as refused:
        bench.parse(["--against", str(tmp_path)])
    assert refused.value.code == 2
    assert "--against" in capsys.readouterr().err.splitlines()[-1]


def test_a_sweep_that_imported_another_algkin_than_the_checkouts_is_refused(bench, other_checkout, monkeypatch):
    result = {"seconds": 1.0, "counts": {"ok": 8}, "algkin": [str(other_checkout / "algkin" / "sweep" / "family.py"),
                                                              "/elsewhere/algkin/sweep/family.py"]}
    monkeypatch.setattr(bench, "run_python", lambda root, arguments: types.SimpleNamespace(stdout=json.dumps(result)))
    with pytest.raises(RuntimeError, match="/elsewhere/algkin"):
        bench.timed(other_checkout, "out", (["a=1:2:2"], "grashof", 2, False))
    result["algkin"].pop()
    assert bench.timed(other_checkout, "out", (["a=1:2:2"], "grashof", 2, False)) == (1.0, {"ok": 8})
