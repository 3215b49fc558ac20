"""Running algkin in processes of its own, for tests of budgets and signals.

Every process is started in a new session, so that a test that finds it hanging (or its
worker orphaned) can kill the whole group and fail instead of hanging itself.
"""

import fcntl
import os
import pty
import signal
import struct
import subprocess
import sys
import termios
import threading
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
ENV = dict(os.environ, PYTHONPATH=str(ROOT))


def start(argv, **options):
    """``python argv...``, started in a session of its own, its output piped."""
    options = {"stdout": subprocess.PIPE, "stderr": subprocess.PIPE, **options}
    begun = time.perf_counter()
    process = subprocess.Popen([sys.executable, *map(str, argv)], env=ENV, text=True, start_new_session=True,
                               **options)
    process.begun = begun  # for the wall time that finish() reports
    return process


def algkin(*args):
    """The argv of ``python -m algkin args...``."""
    return ["-m", "algkin", *args]


def finish(process, timeout):
    """``(exit code, stdout, stderr, wall seconds since it started)``; past ``timeout`` seconds from
    now, its process group is killed and AssertionError raised (a hang fails, not hangs, a test)."""
    try:
        out, err = process.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        kill_group(process)
        process.communicate()
        raise AssertionError(f"still running after {timeout:.1f} s: {' '.join(process.args)}") from None
    return process.returncode, out, err, time.perf_counter() - process.begun


def run(argv, timeout):
    """``(exit code, stdout, stderr, wall seconds)`` of ``python argv...``, within ``timeout``;
    nothing of it is left running after."""
    process = start(argv)
    try:
        return finish(process, timeout)
    finally:
        kill_group(process)


def run_on_terminal(argv, timeout, columns=200):
    """``(exit code, stdout, what was written to stderr, wall seconds)`` of ``python argv...``, its
    stdout a pipe and its stderr a terminal ``columns`` wide (a pseudo-terminal, which writes a
    newline as ``\r\n``); as ``run``, within ``timeout`` and nothing left running."""
    screen, terminal = pty.openpty()
    fcntl.ioctl(terminal, termios.TIOCSWINSZ, struct.pack("HHHH", 24, columns, 0, 0))
    try:
        process = start(argv, stderr=terminal)
    finally:
        os.close(terminal)  # the process has its own: once it (and its workers) end, reading ends
    written = []
    reader = threading.Thread(target=_read_all, args=(screen, written), daemon=True)
    reader.start()  # read as it writes: a full terminal would block the process
    try:
        code, out, _, wall = finish(process, timeout)
    finally:
        kill_group(process)
        reader.join(timeout=10)
        os.close(screen)
    return code, out, b"".join(written).decode(), wall


def _read_all(fd, written):
    """Read ``fd`` into the list ``written`` until the other end is closed (EIO, on Linux)."""
    while True:
        try:
            data = os.read(fd, 4096)
        except OSError:
            return
        if not data:
            return
        written.append(data)


def kill_group(process):
    """Kill whatever is left of the process's group (a worker orphaned, before a fix), so that
    it does not load the machine for the tests after."""
    try:
        os.killpg(process.pid, signal.SIGKILL)
    except ProcessLookupError:
        pass


def children(pid):
    """The living child processes of ``pid``, each as (pid, start time): the start time tells
    a pid reused later apart."""
    return {(child, started) for child, parent, started in _processes() if parent == pid}


def busy_children(pid, cpu, within=120):
    """The living children of ``pid`` (as ``children``) once they have used ``cpu`` seconds of
    processor time between them: at work, however loaded the machine. Past ``within`` seconds
    (a hang guard), AssertionError."""
    deadline = time.monotonic() + within
    while True:
        found = children(pid)
        if found and sum(cpu_seconds(child) for child, _ in found) >= cpu:
            return found
        assert time.monotonic() < deadline, f"no child of {pid} at work after {within} s"
        time.sleep(0.05)


def cpu_seconds(pid):
    """The processor time (user and system) the process ``pid`` has used, 0 once it has ended."""
    try:
        stat = (Path("/proc") / str(pid) / "stat").read_text()
    except OSError:
        return 0.0
    fields = stat[stat.rindex(")") + 2:].split()  # as in _processes: fields 14 and 15, utime and stime
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def alive(processes, within):
    """Those of ``processes`` still alive (zombies count as dead) after waiting up to ``within`` seconds."""
    deadline = time.monotonic() + within
    while True:
        left = processes & {(pid, started) for pid, _, started in _processes()}
        if not left or time.monotonic() > deadline:
            return left
        time.sleep(0.05)


def _processes():
    """(pid, parent pid, start time) of every living process, from /proc."""
    found = []
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            stat = (entry / "stat").read_text()
        except OSError:  # it ended while we looked
            continue
        fields = stat[stat.rindex(")") + 2:].split()  # after "pid (command) ": the command may hold spaces
        if fields[0] != "Z":
            found.append((int(entry.name), int(fields[1]), int(fields[19])))
    return found
