"""algkin.runtime.progress: one status line on a terminal, nothing elsewhere, nothing outside ``shown()``,
and a forked worker's progress shown by its parent."""

import io
import subprocess
import sys
import threading

from algkin.runtime import progress
from algkin.runtime.budget import Budget

from ..clocks import still, ticks
from ..processes import ENV


class Terminal(io.StringIO):
    """What a terminal would show, kept as written (tqdm draws on it as on stderr)."""

    def isatty(self):
        return True


def test_a_terminal_shows_the_stage_and_the_count_then_a_cleared_line():
    terminal = Terminal()
    # a second passes at each reading of the line's clock: every step is drawn (at most one each 0.1 s)
    with progress.shown(stream=terminal, clock=ticks()):
        progress.stage("compiling\nthe \x1b[31mscene")
        for _ in progress.counted(["uniform", "near-fold"], "cases"):
            pass
    shown = terminal.getvalue()
    assert "algkin: compiling the \\x1b[31mscene" in shown  # on one line, the escape not obeyed
    assert "2/2 cases" in shown
    assert "\n" not in shown and shown.endswith("\r")
    assert shown.rsplit("\r", 2)[1].strip() == ""  # the last thing drawn: a blank line


def test_nothing_shows_off_a_terminal_with_quiet_or_outside_the_block():
    log, terminal = io.StringIO(), Terminal()
    with progress.shown(stream=log):
        progress.stage("compiling")
    with progress.shown(quiet=True, stream=terminal):
        progress.stage("compiling")
    with progress.shown(stream=Terminal()):
        pass
    progress.stage("compiling")  # after a block: what it set is gone
    assert log.getvalue() == terminal.getvalue() == ""


def test_a_forked_worker_shows_through_its_parent():
    # The worker's copy of the terminal is not the parent's: what shows here was handed over.
    deadline = Budget(seconds=30, clock=still).start()  # a worker, and no deadline to come

    def work():
        deadline.note("compiling in the worker")
        Budget().start().note("a stage another budget notes")
        with progress.counting(3, "cases"):
            progress.step()
        return "done"

    terminal, threads = Terminal(), threading.active_count()
    with progress.shown(stream=terminal, clock=ticks()):
        assert threading.active_count() == threads  # no tqdm monitor: a process that forks keeps to one thread
        assert deadline.run(work) == "done"
    shown = terminal.getvalue()
    assert "algkin: compiling in the worker" in shown and "algkin: a stage another budget notes" in shown
    assert "1/3 cases" in shown


def test_importing_algkin_and_a_command_off_a_terminal_leave_tqdm_unloaded():
    code = ("import sys, algkin, algkin.runtime.budget; from algkin.ui.cli import main; main(['list']); "
            "print('tqdm' in sys.modules)")
    done = subprocess.run([sys.executable, "-c", code], env=ENV, capture_output=True, text=True, timeout=300,
                          check=False)  # a hang guard
    assert done.stdout.splitlines()[-1] == "False", done.stderr
