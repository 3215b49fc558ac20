"""Ctrl-C at any moment (exit 130, docs/cli/index.md): while Python imports algkin and sympy, or while Dask workers
compute a sweep, the command says one line, ``algkin: interrupted``, exits 130 and leaves no
process behind.

Robust on a loaded machine: a signal is sent once the process is seen at a given point (a
module imported, as ``python -X importtime`` reports it; a sweep's directory made), never after
a fixed sleep, and the only bounds on time are generous timeouts on waiting.
"""

import os
import queue
import signal
import sys
import threading
import time
from pathlib import Path

import pytest

from ...processes import algkin, finish, kill_group, start

WAIT = 120  # seconds: only a hang takes this long
# Work after its imports that a signal stops at once, and that lasts however late a loaded machine
# lets the test read the import it waits for: a serial sweep of 100,000 designs (some 15 minutes),
# each design milliseconds of python-flint calls. Not one long C call: a Gröbner basis of the six-bar
# family (a single python-flint call of minutes, which holds off every handler) once left a starved
# test waiting for an answer to its Ctrl-C for 120 s; with seconds of work, a starved test once
# signalled a process that had already finished (exit 0).
def _slow(tmp_path):
    return ("sweep", "fourbar", "--grid", "a=1:3:100000", "--analyses", "curve", "--out", str(tmp_path / "sweep"))


def _lines(stream):
    """The lines of ``stream`` as a reader thread gets them (a queue; None at its end)."""
    got = queue.Queue()

    def read():
        for line in stream:
            got.put(line)
        got.put(None)

    threading.Thread(target=read, daemon=True).start()
    return got


def _await_import(lines, module):
    """Read ``python -X importtime``'s lines until ``module`` is imported; the lines that are not its."""
    said, deadline = [], time.monotonic() + WAIT
    while True:
        line = lines.get(timeout=max(0.0, deadline - time.monotonic()))
        assert line is not None, f"ended before importing {module}: {''.join(said)}"
        if not line.startswith("import time:"):
            said.append(line)
        elif line.rstrip().rsplit("|", 1)[-1].strip() == module:
            return said


def _rest(lines):
    """What the process said on stderr after, without importtime's lines."""
    said = []
    while (line := lines.get(timeout=WAIT)) is not None:
        if not line.startswith("import time:"):
            said.append(line)
    return said


# What the `algkin` console script runs (pyproject.toml's entry point), beside `python -m algkin`.
CONSOLE_SCRIPT = ("-c", "import sys; from algkin.ui.cli import main; sys.exit(main())")


# Each a module imported after main() set its handlers: the first it imports, one of sympy's (the
# longest import: half a second), the scene layer's (after sympy). Before main(), Python's own
# start-up (site, the venv's .pth files) and ``import algkin.ui.cli`` (some 20 ms: no sympy) run
# with Python's handler, which no code of algkin's can replace sooner.
@pytest.mark.parametrize("module", ["algkin.ui.cli.sweep", "sympy.core.numbers", "algkin.scene"])
@pytest.mark.parametrize("entry", [algkin(), CONSOLE_SCRIPT], ids=["python-m", "console-script"])
def test_ctrl_c_while_importing_is_one_line_and_exit_130(module, entry, tmp_path):
    process = start(["-X", "importtime", *entry, *_slow(tmp_path)])
    try:
        lines = _lines(process.stderr)
        said = _await_import(lines, module)
        os.kill(process.pid, signal.SIGINT)
        said += _rest(lines)
        assert process.wait(timeout=WAIT) == 130
        assert said == ["algkin: interrupted\n"]
    finally:
        kill_group(process)


def _group(pgid):
    """The living processes (zombies are dead) of the process group ``pgid``."""
    found = set()
    for entry in Path("/proc").iterdir():
        try:
            stat = (entry / "stat").read_text() if entry.name.isdigit() else ""
        except OSError:  # it ended while we looked
            continue
        fields = stat[stat.rindex(")") + 2:].split() if stat else []
        if fields and fields[0] != "Z" and int(fields[2]) == pgid:
            found.add(int(entry.name))
    return found


def _await(condition, what):
    deadline = time.monotonic() + WAIT
    while not condition():
        assert time.monotonic() < deadline, what
        time.sleep(0.05)


@pytest.mark.slow
@pytest.mark.skipif(not Path("/proc").is_dir(), reason="reads the process group from /proc")
@pytest.mark.parametrize("signum,code,said", [(signal.SIGINT, 130, "interrupted"), (signal.SIGHUP, 129, "hung up (SIGHUP)"),
                                              (signal.SIGTERM, 143, "terminated (SIGTERM)")],
                         ids=["SIGINT", "SIGHUP", "SIGTERM"])
def test_a_signal_to_a_sweeps_group_stops_its_dask_workers_quietly(tmp_path, signum, code, said):
    pytest.importorskip("distributed")
    out = tmp_path / "sweep"
    # far more designs than can be done before the signal (40,000: minutes), however late a loaded machine
    # lets the test send it: the sweep is still running
    process = start(algkin("sweep", "fourbar", "--grid", "a=1:3:4000", "--grid", "d=2:3:10", "--analyses", "curve",
                           "--workers", "2", "--chunk", "2", "--out", out))
    try:
        # the manifest is written once the cluster and its workers are up (sweep's ``ready``)
        _await(lambda: (out / "manifest.json").exists() or process.poll() is not None, "no sweep started")
        assert process.poll() is None, process.communicate()
        os.killpg(process.pid, signum)  # as Ctrl-C (or a hang-up) in a terminal: the whole group
        assert finish(process, timeout=WAIT)[::2] == (code, f"algkin: {said}\n")
        _await(lambda: not _group(process.pid), "a process of the group outlived the command")
    finally:
        kill_group(process)


def _starting_workers(pgid):
    """The processes of the group ``pgid`` that multiprocessing spawned (a Dask worker, from its first import)."""
    found = set()
    for pid in _group(pgid):
        try:
            if b"spawn_main" in (Path("/proc") / str(pid) / "cmdline").read_bytes():
                found.add(pid)
        except OSError:  # it ended while we looked
            continue
    return found


@pytest.mark.slow
@pytest.mark.skipif(not Path("/proc").is_dir(), reason="reads the process group from /proc")
def test_ctrl_c_while_the_dask_workers_start_is_one_line(tmp_path):
    """Ctrl-C reaches the group while a worker is still importing distributed (a second or more), before
    it could ignore SIGINT: it printed its KeyboardInterrupt traceback, and another traceback per queue."""
    pytest.importorskip("distributed")
    out = tmp_path / "sweep"
    process = start(algkin("sweep", "fourbar", "--grid", "a=1:3:4000", "--analyses", "curve", "--workers", "2",
                           "--out", out))
    try:
        _await(lambda: _starting_workers(process.pid) or process.poll() is not None, "no Dask worker started")
        assert not (out / "manifest.json").exists(), "the workers were up already"
        os.killpg(process.pid, signal.SIGINT)
        assert finish(process, timeout=WAIT)[::2] == (130, "algkin: interrupted\n")
        _await(lambda: not _group(process.pid), "a process of the group outlived the command")
    finally:
        kill_group(process)


class _SignalledWhenCollected:
    """Sends this process SIGINT from its finaliser: the handler's exception is raised there, where
    Python prints it and drops it (as in a library's ``__del__`` during a sweep on Dask)."""

    def __del__(self):
        os.kill(os.getpid(), signal.SIGINT)


def test_a_signal_whose_exception_a_finaliser_dropped_still_stops_the_sweep(tmp_path, monkeypatch, capsys):
    import algkin.sweep.executor as executor
    from algkin.ui.cli import main

    evaluate = executor.evaluate_chunk

    def signalled_then_evaluated(*args):
        _SignalledWhenCollected()  # collected at once
        return evaluate(*args)

    monkeypatch.setattr(executor, "evaluate_chunk", signalled_then_evaluated)
    monkeypatch.setattr(sys, "unraisablehook", sys.__unraisablehook__)  # Python's, which prints (not pytest's)
    argv = ["sweep", "fourbar", "--grid", "a=1:2:40", "--executor", "serial", "--chunk", "4", "--out", str(tmp_path / "s")]
    assert main(argv) == 130  # it ran all 40 designs and said nothing, exit 0
    # one line: the dropped exception is not printed (it was, as "Exception ignored in: ..." and a traceback)
    assert capsys.readouterr().err == "algkin: interrupted\n"
