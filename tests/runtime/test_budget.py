"""algkin.runtime.budget: a command called from Python without a time budget does not load the child
process's machinery; a budget ``apart`` puts work that holds the GIL (a python-flint call) in a child that
a signal stops at once."""

import os
import signal
import subprocess
import sys

from ..processes import ENV, finish, kill_group, start

WAIT = 120  # seconds: only a hang takes this long


def test_a_command_without_a_time_budget_leaves_multiprocessing_unloaded():
    # multiprocessing (sockets, pickling, ctypes) is milliseconds of a cold command's imports that only a
    # forked child uses: a time budget's, or the program's (``algkin ...``, apart for Ctrl-C)
    code = ("import sys, io, contextlib; from algkin.ui.cli import main\n"
            "with contextlib.redirect_stdout(io.StringIO()):\n"
            "    main(['derive', 'chebyshev-lambda', '--outputs', 'B'])\n"
            "print('multiprocessing' in sys.modules)")
    done = subprocess.run([sys.executable, "-c", code], env=ENV, capture_output=True, text=True, timeout=300,
                          check=False)  # a hang guard
    assert done.stdout.splitlines()[-1] == "False", done.stderr


# python-flint factoring a polynomial of degree 30,000 modulo a prime: minutes of one C call that keeps the
# GIL (degree 8,000 took 32 s), so no Python handler runs until it returns
HOLDING = """
import sys
import flint
from algkin.runtime.budget import Budget
from algkin.runtime.stopping import Stopped
from algkin.ui.cli.signals import stopping_signals

def held():
    prime = 1000000007
    poly = flint.nmod_poly([(k * k * 7919 + 13) % prime for k in range(30000)] + [1], prime)
    print("holding", flush=True)
    poly.factor()

with stopping_signals():
    try:
        Budget(apart=APART).start().run(held)
    except Stopped as stop:
        sys.exit(128 + stop.signum)
"""


def test_a_budget_apart_is_stopped_by_a_signal_while_its_work_holds_the_gil():
    # in-process (apart=False) the signal waits for the 600 s call: the test would fail at WAIT
    process = start(["-c", HOLDING.replace("APART", "True")], stdin=subprocess.DEVNULL)
    try:
        assert process.stdout.readline() == "holding\n"  # in the child, now in the call
        os.kill(process.pid, signal.SIGINT)
        assert finish(process, timeout=WAIT)[0] == 130
    finally:
        kill_group(process)
