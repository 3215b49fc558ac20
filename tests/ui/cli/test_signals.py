"""The command line under budgets, signals and closed pipes (exit codes: docs/cli/index.md): a budget covers the
whole command and stops it near its deadline whatever it is doing; a signal or an error says
one line on stderr (and, with --json, one JSON document on stdout); no process outlives it.

Each command runs in a session of its own (``tests/processes.py``): a hang fails its test. No
test here depends on how fast the machine is: a signal is sent once the worker has used some
processor time (it is at work, however loaded the machine), and a deadline is passed by a
clock the test moves (``tests/clocks.py``); the two tests of how soon a budget stops a command
on the machine's own clock are in the slow set, with generous bounds, and run alone (marked alone).
"""

import json
import os
import signal
import statistics

import pytest
from hypothesis import given, settings, strategies as st

from algkin.runtime.budget import MAX_SECONDS
from algkin.ui.cli import main

from ...clocks import late_budgets
from ...processes import algkin, alive, busy_children, finish, kill_group, run, start

# Real commands, some done within the largest budget drawn (show), most not.
COMMANDS = [("derive", "chebyshev-lambda"), ("curve", "watt-i", "--point", "P"),
            ("show", "chebyshev-lambda", "--outputs", "B"), ("derive", "stephenson-iii")]
# What a budgeted command does besides start-up (parse, fork the worker, kill it) takes about
# 20 ms against 350 ms of start-up (measured), and slows down as much on a loaded machine.
OVERHEAD = 0.5  # of start-up: generous, for a loaded machine
ATTEMPTS = 5  # the machine is shared: a time bound must hold on the best of these runs
WEEK = str(MAX_SECONDS)  # the longest budget: a worker, and no deadline that could come
# About 10 s of processor time in its worker (10,000 samples solved and proved), of which a
# signal comes after BUSY: the worker is at work, and far from done, however loaded the machine.
SLOW = ("derive", "stephenson-iii", "--samples", "10000", "--max-seconds", WEEK, "--json")
BUSY = 1.5  # seconds of the worker's processor time: past its imports (about 0.8 s), into the algebra

# Parameter defaults that chain powers: each is the one before to the 64th.
CHAINED_POWERS = """
name = "chained-powers"
description = "Parameter defaults that chain powers."

[parameters]
p1 = "2**64"
p2 = "p1**64"
p3 = "p2**64"
p4 = "p3**64"
p5 = "p4**64"

[inputs]
theta = { range = [0, 180], unit = "deg" }

[points]
O = { fixed = [0, 0] }
B = { fixed = ["p5", 0] }
A = { crank = "O", length = 1, input = "theta" }

[outputs]
AB = "dist(A, B)"
"""


@pytest.fixture(scope="module")
def startup():
    """Seconds of python's start and algkin's imports, as `algkin list` takes them (the median of
    five: as loaded a machine as the runs it bounds, which keep the best of their attempts)."""
    return statistics.median(run(algkin("list"), timeout=60)[3] for _ in range(5))


def one_line(err):
    """Whether stderr is one line, and no traceback."""
    return err.count("\n") == 1 and err.endswith("\n") and "Traceback" not in err


@pytest.mark.slow
@pytest.mark.alone
@settings(max_examples=12)
@given(command=st.sampled_from(COMMANDS), milliseconds=st.integers(10, 300))
def test_a_small_budget_stops_the_command_near_it(startup, command, milliseconds):
    seconds = milliseconds / 1000
    bound = (1 + OVERHEAD) * startup + 2 * seconds
    walls = []
    while len(walls) < ATTEMPTS and min(walls, default=bound + 1) > bound:
        code, out, err, wall = run(algkin(*command, "--max-seconds", seconds), timeout=bound + 20)
        assert code in (0, 1), err
        if code == 0:
            assert err == ""
        else:
            assert one_line(err) and f"max_seconds={seconds:g}: stopped after" in err, err
        walls.append(wall)
    assert min(walls) <= bound, (walls, bound)


@pytest.mark.slow
@pytest.mark.alone
@pytest.mark.parametrize("command", ["derive", "show"])
def test_a_scene_slow_to_load_stops_at_the_budget(tmp_path, startup, command):
    # Before the budget covered loading, derive took 30 s here (and 1.7 GB); a size guard on
    # parameter values may refuse the scene instead (exit 2). On the machine's clock: slow set.
    scene = tmp_path / "chained-powers.toml"
    scene.write_text(CHAINED_POWERS)
    code, out, err, wall = run(algkin(command, scene, "--max-seconds", 2), timeout=60)
    assert out == "" and one_line(err), err
    said = f"algkin: error: {scene}: " if code == 2 else "algkin: failed: max_seconds=2: stopped after"
    assert err.startswith(said), err
    assert wall <= 2 * startup + 2 * 2, wall


STOPS = {signal.SIGINT: (130, "interrupted"), signal.SIGTERM: (143, "terminated (SIGTERM)"),
         signal.SIGHUP: (129, "hung up (SIGHUP)")}


@pytest.mark.parametrize("signum,group", [(signal.SIGINT, False), (signal.SIGINT, True),
                                          (signal.SIGTERM, False), (signal.SIGHUP, False)],
                         ids=["SIGINT", "SIGINT-to-the-group", "SIGTERM", "SIGHUP"])
def test_a_signal_stops_the_command_with_one_line_and_no_worker_left(signum, group):
    # To the group: as Ctrl-C in a terminal, which reaches the worker too.
    code, message = STOPS[signum]
    process = start(algkin(*SLOW))
    try:
        workers = busy_children(process.pid, BUSY)
        (os.killpg if group else os.kill)(process.pid, signum)
        returncode, out, err, _ = finish(process, timeout=60)  # a hang guard
        assert (returncode, err) == (code, f"algkin: {message}\n")
        assert json.loads(out) == {"error": {"kind": "interrupted", "message": message},
                                   "command": "derive", "scene": "stephenson-iii"}
        assert not alive(workers, within=30)
    finally:
        kill_group(process)


def test_the_worker_dies_with_its_parent():
    # SIGKILL leaves the parent no clean-up: the kernel must end the worker (PR_SET_PDEATHSIG).
    process = start(algkin(*SLOW))
    try:
        workers = busy_children(process.pid, BUSY)
        process.kill()
        assert finish(process, timeout=60)[0] == -signal.SIGKILL
        assert not alive(workers, within=30)  # returns as soon as they are gone
    finally:
        kill_group(process)


# main() called in a process that goes on after it: SIGTERM stops the command, not the caller.
# A thread sends it once the worker is at work.
IN_PROCESS = """
import os, signal, sys, threading
from algkin.ui.cli import main
from tests.processes import busy_children

def stop_when_busy():
    busy_children(os.getpid(), float(sys.argv[1]))
    os.kill(os.getpid(), signal.SIGTERM)

before = {s: signal.getsignal(s) for s in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP)}
threading.Thread(target=stop_when_busy, daemon=True).start()
code = main(sys.argv[2:])
try:
    os.waitpid(-1, os.WNOHANG)
    children = "a child left"
except ChildProcessError:
    children = "no-child"
print(code, before == {s: signal.getsignal(s) for s in before}, children)
"""


def test_main_in_process_puts_the_signal_handlers_back():
    code, out, err, _ = run(["-c", IN_PROCESS, BUSY, *SLOW[:-1]], timeout=120)  # a hang guard
    assert (code, err) == (0, "algkin: terminated (SIGTERM)\n")
    assert out.split() == ["143", "True", "no-child"]  # the command's code, the handlers back, its worker reaped


@pytest.mark.parametrize("args", [("list", "--json"),
                                  ("derive", "chebyshev-lambda", "--outputs", "B", "--samples", "3", "--json",
                                   "--max-seconds", WEEK)])
def test_a_closed_stdout_ends_quietly(args):
    read, write = os.pipe()
    os.close(read)  # the reader has gone before the first line: `algkin list --json | true`
    try:
        process = start(algkin(*args), stdout=write)
    finally:
        os.close(write)
    code, _, err, _ = finish(process, timeout=120)  # a hang guard
    assert (code, err) == (128 + signal.SIGPIPE, "")


def test_json_past_the_budget_is_one_error_document(monkeypatch, capsys):
    late_budgets(monkeypatch, doing="eliminating")  # the deadline passes while the worker eliminates
    assert main(["derive", "stephenson-iii", "--max-seconds", "0.5", "--json"]) == 1
    out, err = capsys.readouterr()
    assert one_line(err) and err.startswith("algkin: failed: max_seconds=0.5: stopped after 3600.00 s while "
                                            "eliminating "), err
    assert json.loads(out) == {"error": {"kind": "budget", "message": err[len("algkin: failed: "):-1]},
                               "command": "derive", "scene": "stephenson-iii"}


@pytest.mark.parametrize("args,kind,scene", [
    (["derive", "no-such-scene", "--json"], "scene", "no-such-scene"),
    (["curve", "chebyshev-lambda", "--point", "Q", "--json", "--max-seconds", WEEK], "usage", "chebyshev-lambda"),
    (["derive", "chebyshev-lambda", "--samples", "many", "--json"], "usage", None),  # refused by the parser
])
def test_json_bad_input_is_one_error_document(args, kind, scene, capsys):
    assert main(args) == 2
    captured = capsys.readouterr()
    assert one_line(captured.err) and captured.err.startswith("algkin: error: ")
    assert json.loads(captured.out) == {"error": {"kind": kind, "message": captured.err[len("algkin: error: "):-1]},
                                        "command": args[0], "scene": scene}
