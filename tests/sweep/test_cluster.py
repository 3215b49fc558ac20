"""The sweep on a Dask cluster started as on several machines: a scheduler (``dask scheduler``)
and two workers (``dask worker ADDRESS``), each a process of its own that algkin did not start,
reached by ``--scheduler ADDRESS``. Its dataset is the serial run's, the timing columns aside;
the command writes every file (the workers only compute rows); a budget per design, an analysis
registered in the command's process alone and a worker with another algkin all work, or fail in
one line. No process of the cluster outlives the tests."""

import json
import os
import subprocess
import time
from dataclasses import dataclass

import pytest

import algkin
from algkin.sweep import ANALYSES, Analysis, read_dataset, register, sweep
from algkin.ui.cli import main

from ..processes import algkin as algkin_argv, children, finish, kill_group, start
from .test_executors import canonical

# A scheduler, two workers and the command, each importing dask and algkin: about 10 s.
pytestmark = pytest.mark.slow

GRID = ["a=1/2:3/2:3", "d=4:10:2"]  # 6 four-bars; with d = 10, |AD| >= 9 > l + m: 3 never assemble
SWEEP = ["sweep", "fourbar", *(f"--grid={g}" for g in GRID), "--analyses", "curve,grashof", "--chunk", "1"]
STARTING = 120  # seconds the cluster may take to start, a hang guard: it fails, never hangs, the tests
ENDING = 60  # seconds a killed process group may take to be gone


@dataclass
class Cluster:
    address: str  # the scheduler's
    workers: list  # the `dask worker` processes (each a nanny, its worker process a child of it)


@pytest.fixture(scope="module")
def cluster(tmp_path_factory):
    """A scheduler with two workers, each started as ``dask ...`` in a session of its
    own (its log in a file: a pipe nobody reads would fill), every one killed when the tests end."""
    logs = tmp_path_factory.mktemp("cluster")
    started = []
    try:
        _dask(started, logs, "scheduler", "--host", "127.0.0.1", "--port", "0", "--no-dashboard",
              "--dashboard-address", "127.0.0.1:0", "--scheduler-file", logs / "scheduler.json")
        address = _address(logs / "scheduler.json", started[0], time.monotonic() + STARTING)
        for name in ("worker-1", "worker-2"):
            _dask(started, logs, "worker", address, "--name", name, "--nthreads", "1", "--host", "127.0.0.1",
                  "--no-dashboard")
        _wait_for_workers(address, 2, started, STARTING)
        yield Cluster(address, started[1:])
    finally:
        for process in started:
            _stop(process)


def _dask(started, logs, command, *args):
    """``python -m dask COMMAND ARGS...`` (the ``dask`` command line) started, and added to ``started``."""
    path = logs / f"{command}-{len(started)}.log"
    with path.open("w") as log:  # the process has its own copy
        started.append(start(["-m", "dask", command, *args], stdout=log, stderr=subprocess.STDOUT))
    started[-1].log = path


def _address(scheduler_file, process, deadline):
    """The scheduler's address from the file it writes once it listens; AssertionError past ``deadline``."""
    while True:
        try:
            return json.loads(scheduler_file.read_text())["address"]
        except (OSError, ValueError, KeyError):  # not written yet, or half written
            pass
        assert process.poll() is None, f"dask scheduler ended (exit {process.returncode}):\n{process.log.read_text()}"
        assert time.monotonic() < deadline, f"no {scheduler_file.name} after {STARTING} s:\n{process.log.read_text()}"
        time.sleep(0.05)


def _wait_for_workers(address, count, started, within):
    from distributed import Client

    with Client(address, timeout=within) as client:
        try:
            client.wait_for_workers(count, timeout=within)
        except TimeoutError:
            logs = "\n".join(p.log.read_text() for p in started)
            raise AssertionError(f"{count} workers did not join {address} within {within} s:\n{logs}") from None


def _stop(process):
    """The process and everything it started (its session's group) killed, waited for, gone."""
    kill_group(process)
    process.wait(timeout=ENDING)
    deadline = time.monotonic() + ENDING
    while True:
        try:
            os.killpg(process.pid, 0)  # a member of the group still there?
        except ProcessLookupError:
            return
        assert time.monotonic() < deadline, f"processes of {' '.join(process.args)} left after {ENDING} s"
        time.sleep(0.05)


def run_cli(*args):
    """``algkin ARGS...`` in a process of its own: ``(exit code, stdout, stderr)``."""
    code, out, err, _ = finish(start(algkin_argv(*args)), 300)  # a hang guard
    return code, out, err


def test_a_cluster_of_processes_of_its_own_gives_the_serial_dataset(cluster, tmp_path):
    code, out, err = run_cli(*SWEEP, "--out", tmp_path / "dask", "--scheduler", cluster.address)
    assert (code, err) == (0, ""), err
    assert out == f"6 designs (6 computed now): ok 3, does-not-assemble 3\nwrote {tmp_path / 'dask' / 'designs.parquet'}\n"
    assert main([*SWEEP, "--out", str(tmp_path / "serial"), "--executor", "serial", "--quiet"]) == 0
    assert canonical(tmp_path / "dask") == canonical(tmp_path / "serial")
    # written by the command, where it runs: the workers only computed the rows
    assert sorted(p.name for p in (tmp_path / "dask").iterdir()) == ["designs.parquet", "manifest.json", "parts"]
    assert len(list((tmp_path / "dask" / "parts").iterdir())) == 6


def test_a_budget_per_design_runs_on_the_clusters_workers(cluster, tmp_path):
    # `dask worker` starts daemonic worker processes by default, and a budget's design runs in a
    # forked child (multiprocessing refuses a daemonic process children): it was a traceback.
    # 600 s is a hang guard: no design comes near it.
    code, _, err = run_cli(*SWEEP, "--budget", "600", "--out", tmp_path / "dask", "--scheduler", cluster.address)
    assert (code, err) == (0, ""), err
    assert main([*SWEEP, "--budget", "600", "--out", str(tmp_path / "serial"), "--executor", "serial",
                 "--quiet"]) == 0
    assert canonical(tmp_path / "dask") == canonical(tmp_path / "serial")


def test_an_analysis_registered_in_this_process_alone_runs_on_the_workers(cluster, tmp_path):
    # The workers' table of analyses is the built-in one: register() ran in this process only.
    def crank(design):
        return {"crank_length": str(design.scene.parameters["a"]), "crank_process": os.getpid()}

    register(Analysis("crank", {"crank_length": "string", "crank_process": "int64"}, crank))
    try:
        done = sweep("fourbar", tmp_path, grid=["a=1/2:3/2:3"], analyses=["crank"], scheduler=cluster.address,
                     chunk=1)
    finally:
        del ANALYSES["crank"]
    assert done.counts == {"ok": 3}
    table = read_dataset(tmp_path)
    assert table.column("crank_length").to_pylist() == ["1/2", "1", "3/2"]
    # computed by the workers' processes, not by this one
    workers = {pid for nanny in cluster.workers for pid, _ in children(nanny.pid)}
    assert set(table.column("crank_process").to_pylist()) <= workers


def test_a_worker_with_another_algkin_fails_the_command_in_one_line(cluster, tmp_path, monkeypatch, capsys):
    installed = algkin.__version__  # the workers'
    monkeypatch.setattr(algkin, "__version__", "0.0.1-other")  # this process's
    assert main([*SWEEP, "--out", str(tmp_path), "--scheduler", cluster.address]) == 1
    err = capsys.readouterr().err
    assert err.startswith("algkin: failed: ") and err.count("\n") == 1, err
    assert f"has algkin {installed}, this command 0.0.1-other" in err, err
    assert not (tmp_path / "designs.parquet").exists()


def test_an_analysis_the_workers_cannot_import_fails_the_command_in_one_line(cluster, tmp_path, monkeypatch,
                                                                              capsys):
    # A module on this process's path alone: its function travels by name, and neither the scheduler
    # (which unpickles the tasks) nor a worker finds it.
    (tmp_path / "mine").mkdir()
    (tmp_path / "mine" / "only_here.py").write_text("def crank(design):\n    return {'crank_length': '1'}\n")
    monkeypatch.syspath_prepend(str(tmp_path / "mine"))
    from only_here import crank

    register(Analysis("crank", {"crank_length": "string"}, crank))
    try:
        code = main(["sweep", "fourbar", "--grid", "a=1/2:3/2:3", "--analyses", "crank", "--out", str(tmp_path / "out"),
                     "--scheduler", cluster.address])
    finally:
        del ANALYSES["crank"]
    err = capsys.readouterr().err
    assert code == 1 and err.count("\n") == 1, err
    assert err.startswith("algkin: failed: chunk 0 failed on the Dask cluster: RuntimeError: "), err
    assert "different environments" in err, err  # Dask's words
