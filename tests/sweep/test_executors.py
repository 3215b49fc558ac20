"""The same sweep in this process and on a 2-worker Dask LocalCluster: the same dataset apart
from the timing columns. A Dask sweep stopped by Ctrl-C leaves no worker process and no
partial part file."""

import io
import signal
import time
from pathlib import Path

import pyarrow.parquet as pq
import pytest

from algkin.errors import UsageError
from algkin.sweep import read_dataset, store, sweep, without_timings

from ..processes import algkin, alive, children, finish, kill_group, start

GRID = ["a=1/2:3:2", "l=2:3:2", "d=4:10:2"]  # 8 four-bars; with d = 10, |AD| >= 7 > l + m: 4 never assemble
ANALYSES = ["curve", "grashof", "transmission"]


def canonical(folder):
    buffer = io.BytesIO()
    pq.write_table(without_timings(read_dataset(folder)), buffer)
    return buffer.getvalue()


def test_serial_and_two_dask_workers_give_the_same_dataset(tmp_path):
    serial = sweep("fourbar", tmp_path / "serial", grid=GRID, analyses=ANALYSES, executor="serial", chunk=3)
    dask = sweep("fourbar", tmp_path / "dask", grid=GRID, analyses=ANALYSES, executor="dask", workers=2, chunk=2)
    assert serial.counts == dask.counts == {"ok": 4, "does-not-assemble": 4}
    assert canonical(tmp_path / "serial") == canonical(tmp_path / "dask")
    table = read_dataset(tmp_path / "dask")
    assert table.column("design").to_pylist() == list(range(8))
    timings = [n for n in table.column_names if n.startswith("seconds_")]
    assert timings == ["seconds_assembly", "seconds_curve", "seconds_grashof", "seconds_transmission",
                       "seconds_total"]


def test_a_scheduler_that_is_not_there_is_a_usage_error(tmp_path, monkeypatch):
    monkeypatch.setattr("algkin.sweep.executor.CONNECT_SECONDS", 1)
    with pytest.raises(UsageError, match="^scheduler='tcp://127.0.0.1:9': cannot connect"):
        sweep("fourbar", tmp_path, grid=["a=1:2:2"], analyses=["grashof"], scheduler="tcp://127.0.0.1:9")
    assert not any(tmp_path.iterdir())  # nothing written


@pytest.mark.parametrize("address", ["tls://127.0.0.1:9", "ucx://127.0.0.1:9"])
def test_a_scheduler_whose_protocol_cannot_be_used_is_a_usage_error(tmp_path, address):
    # TLS without its context, UCX without its package: Dask raises TypeError, which was a traceback
    with pytest.raises(UsageError, match=f"^scheduler='{address}': cannot connect: "):
        sweep("fourbar", tmp_path, grid=["a=1:2:2"], analyses=["grashof"], scheduler=address)
    assert not any(tmp_path.iterdir())


def test_ctrl_c_stops_the_cluster_and_leaves_no_process(tmp_path):
    argv = ["sweep", "fourbar", "--grid", "a=1/2:3/2:30", "--grid", "m=3:4:2", "--analyses", "curve,transmission",
            "--out", tmp_path, "--workers", "2", "--chunk", "1"]
    process = start(algkin(*argv))
    try:
        deadline = time.monotonic() + 120
        while not store.done_chunks(tmp_path) and process.poll() is None and time.monotonic() < deadline:
            time.sleep(0.05)
        assert process.poll() is None, "the sweep ended before it could be interrupted"
        workers = children(process.pid)
        assert len(workers) >= 2  # the LocalCluster's worker processes
        process.send_signal(signal.SIGINT)  # to the command alone: it must stop its workers itself
        code, out, err, _ = finish(process, 60)
        left = alive(workers, within=60)  # returns as soon as they are gone: a hang guard
    finally:
        kill_group(process)
    assert code == 130 and err == "algkin: interrupted\n", err
    assert not left, f"worker processes left behind: {left}"
    names = [p.name for p in (tmp_path / "parts").iterdir()]
    assert names and all(n.startswith("part-") and n.endswith(".parquet") for n in names), names
    for name in names:  # every part there is whole
        assert pq.read_table(tmp_path / "parts" / name).num_rows == 1
    assert not (tmp_path / "designs.parquet").exists()


def test_an_existing_cluster_by_its_address_is_used_and_left_running(tmp_path):
    from distributed import Client, LocalCluster

    with LocalCluster(n_workers=1, threads_per_worker=1, processes=True, dashboard_address=None,
                      scheduler_kwargs={"dashboard": False, "dashboard_address": "127.0.0.1:0"}) as cluster:
        code, out, err, _ = finish(start(algkin("sweep", "fourbar", "--grid", "a=1/2:1:2", "--analyses", "grashof",
                                                "--out", tmp_path, "--scheduler", cluster.scheduler_address)), 120)
        assert (code, err) == (0, ""), err
        assert out == f"2 designs (2 computed now): ok 2\nwrote {tmp_path / 'designs.parquet'}\n"
        with Client(cluster) as client:  # still there for its owner
            assert client.submit(sum, [1, 2]).result() == 3


def test_the_resource_tracker_removes_semaphores_left_behind_without_a_word():
    """Workers ended by a SIGTERM to the group leave their semaphores to the tracker, which removed them
    and printed two lines of warning after the command's one (as this process, ended at once, does)."""
    import subprocess
    import sys

    code = ("import os, multiprocessing\n"
            "from algkin.sweep.executor import _start_resource_tracker\n"
            "_start_resource_tracker()\n"
            "kept = multiprocessing.get_context('spawn').Semaphore()\n"
            "name = kept._semlock.name\n"
            "print(name, flush=True)\n"
            "os._exit(0)\n")  # no finaliser runs: the semaphore is left registered, as a killed worker's
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0 and done.stdout.strip(), done.stderr
    assert done.stderr == "", done.stderr
    assert not (Path("/dev/shm") / f"sem.{done.stdout.strip().lstrip('/')}").exists()  # removed all the same
