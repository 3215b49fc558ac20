"""Budgets for commands and eliminations: wall seconds and the size of every intermediate eliminant.

A python-flint resultant or Gröbner basis is one C call that no signal interrupts, so a
time budget runs the work in a forked child process that is killed at the deadline; the
result comes back pickled. The child reports what it is doing (``note``), so the message
says what was being eliminated when time ran out; the parent shows it as progress
(``algkin.runtime.progress``), since the child does not write to the terminal itself. A terms budget
is checked after every resultant and Gröbner basis. An elimination called without a budget,
inside a budget's ``run()``, counts against that budget (``current()``).

No child outlives its parent: the kernel kills it when the parent dies (Linux), and the
parent kills and joins it however ``run()`` ends, an exception raised by a signal included.
This module imports no algebra, so that a command's parent process stays light.

>>> budget = Budget(terms=3)
>>> budget.check_terms(4, "the resultant in B_x")
Traceback (most recent call last):
...
algkin.errors.BudgetExceeded: max_terms=3: the resultant in B_x has 4 terms, while computing

The deadline is read on a clock, ``time.monotonic`` unless one is given; tests give one that
moves when they say, so that nothing depends on how fast the machine is. Here one that stands
still (the deadline never comes), then one that reads 0 when the budget starts and 10.5 ever
after, against work that would never end:

>>> Budget(seconds=10, clock=lambda: 0.0).run(lambda: sum(range(10)))
45
>>> import threading
>>> readings = iter([0.0])
>>> Budget(seconds=10, clock=lambda: next(readings, 10.5)).run(threading.Event().wait)
Traceback (most recent call last):
...
algkin.errors.BudgetExceeded: max_seconds=10: stopped after 10.50 s while computing

A time budget is at most a week (``MAX_SECONDS``): more is a slip (a unit, a zero too many),
and the timers that keep it (a poll's timeout in milliseconds, a C int) go no further than 24 days.

>>> Budget(seconds=1e10)
Traceback (most recent call last):
...
algkin.errors.UsageError: max_seconds=10000000000.0: must be a positive number of seconds, at most a week (604800)
"""

import ctypes
import multiprocessing
import os
import pickle
import signal
import sys
import time

from ..errors import BudgetExceeded, ComputationError, UsageError
from . import progress

__all__ = ["Budget", "current", "bind_to_parent", "time_budget", "MAX_SECONDS"]

MAX_SECONDS = 7 * 24 * 3600  # a week

_ACTIVE = []  # the budgets whose run() is under way in this process, innermost last
_PR_SET_PDEATHSIG = 1  # <linux/prctl.h>
# Signals that stop a command: the parent turns them into an exception (algkin.ui.cli); the child,
# which would otherwise inherit that handler, just dies (Ctrl-C reaches the whole process group).
_STOPPING = (signal.SIGINT, signal.SIGTERM, signal.SIGHUP)


def current():
    """The budget of the ``run()`` under way, for eliminations called without one.

    >>> current().seconds is None
    True
    >>> Budget(terms=7).run(lambda: current().terms)
    7
    """
    return _ACTIVE[-1] if _ACTIVE else Budget()


class Budget:
    """At most ``seconds`` of wall time from ``start()`` and ``terms`` terms per eliminant.

    Either may be None (no limit). One budget covers everything run under it: the
    deadline is set once, by the first ``start()`` or ``run()``, on ``clock`` (seconds).
    """

    def __init__(self, seconds=None, terms=None, *, clock=time.monotonic):
        if seconds is not None:
            time_budget(seconds, "max_seconds")
        if terms is not None and (int(terms) != terms or not terms > 0):
            raise UsageError("max_terms", terms, "a terms budget must be a positive integer")
        self.seconds, self.terms = seconds, terms
        self.deadline = None
        self._clock = clock
        self.doing = "computing"
        self._report = None  # in a child process: the pipe to the parent

    def __repr__(self):
        return f"Budget(seconds={self.seconds!r}, terms={self.terms!r})"

    def start(self):
        """Set the deadline (once) and return the budget."""
        if self.seconds is not None and self.deadline is None:
            self.deadline = self._clock() + self.seconds
        return self

    def note(self, doing):
        """Say what is being computed now, for the message if the time runs out, and as progress."""
        self.doing = doing
        if self._report is not None:
            self._report.send(("doing", doing))  # the parent shows it
        else:
            progress.stage(doing)

    def check_terms(self, count, what):
        """Raise BudgetExceeded if ``what`` (an intermediate eliminant) has more than ``terms`` terms."""
        if self.terms is not None and count > self.terms:
            raise BudgetExceeded(f"max_terms={self.terms}: {what} has {count} terms, while {self.doing}")

    def run(self, function):
        """``function()``, stopped at the deadline when there is a time budget."""
        if self.seconds is None or self._report is not None:
            return self._within(function)  # no deadline, or already inside the child that has one
        self.start()
        context = multiprocessing.get_context("fork")
        parent, child = context.Pipe(duplex=False)
        process = context.Process(target=self._child, args=(function, child, os.getpid()), daemon=True)
        process.start()
        try:
            child.close()
            return self._wait(parent, process)
        finally:  # however the wait ended (answer, deadline, error, a signal's exception): no child left
            if process.is_alive():
                process.kill()
            process.join()
            parent.close()

    def _within(self, function):
        _ACTIVE.append(self)
        try:
            return function()
        finally:
            _ACTIVE.remove(self)

    def _child(self, function, report, parent_pid):
        bind_to_parent(parent_pid)
        self._report = report
        progress.hand_over(lambda event: report.send(("progress", event)))
        try:
            outcome = ("done", self._within(function))
        except BaseException as err:  # noqa: BLE001 - every failure goes back to the parent
            outcome = ("error", err)
        try:
            report.send(outcome)
        except (pickle.PicklingError, TypeError, AttributeError) as err:
            report.send(("error", ComputationError(f"the result could not be sent back: {err}")))

    def _wait(self, pipe, process):
        """The child's answer, taking its notes on the way, until the deadline."""
        while True:
            left = self.deadline - self._clock()
            if left <= 0:
                return self._overtime(pipe, process)
            if not pipe.poll(left):
                continue  # the clock says when the deadline has come (a poll may wake early)
            try:
                kind, value = pipe.recv()
            except (EOFError, OSError):  # OSError: the pipe closed in the middle of a message
                process.join()
                raise ComputationError(f"the process {self.doing} ended without an answer "
                                       f"(exit code {process.exitcode})") from None
            if not self._noted(kind, value):
                return self._outcome(kind, value)

    def _overtime(self, pipe, process):
        """Past the deadline: kill the child, then read only what it had sent already.

        Once the child is dead the pipe holds a bounded amount, so this cannot spin or wait:
        an answer that came in time is still taken, a late note only names what was cut short.
        """
        process.kill()
        process.join()
        for kind, value in _already_sent(pipe):
            if not self._noted(kind, value):
                return self._outcome(kind, value)
        elapsed = self.seconds - (self.deadline - self._clock())
        raise BudgetExceeded(f"max_seconds={self.seconds:g}: stopped after {elapsed:.2f} s while {self.doing}")

    def _noted(self, kind, value):
        """Take a note from the child, what it is doing or other progress, and show it: whether it was one."""
        if kind == "doing":
            self.doing = value
            progress.stage(value)
        elif kind == "progress":
            progress.replay(value)
        else:
            return False
        return True

    @staticmethod
    def _outcome(kind, value):
        if kind == "error":
            raise value
        return value


def time_budget(seconds, argument):
    """``seconds`` if it is a time budget that can be kept: a positive number, at most ``MAX_SECONDS``;
    else UsageError naming ``argument``.

    >>> time_budget(2.5, "budget")
    2.5
    >>> time_budget(float("nan"), "budget")
    Traceback (most recent call last):
    ...
    algkin.errors.UsageError: budget=nan: must be a positive number of seconds, at most a week (604800)
    """
    if not 0 < seconds <= MAX_SECONDS:  # nan and inf too
        raise UsageError(argument, seconds, f"must be a positive number of seconds, at most a week ({MAX_SECONDS})")
    return seconds


def _already_sent(pipe):
    """The messages in ``pipe`` now, up to the end of what was written or a message cut off."""
    try:
        while pipe.poll(0):
            yield pipe.recv()
    except (EOFError, OSError):
        return


def bind_to_parent(parent_pid):
    """In a worker just forked by ``parent_pid``: die with the parent, and of a stopping signal.

    On Linux the kernel kills the worker when its parent dies (elsewhere only the parent's own
    clean-up stops it). Strictly the kernel watches the parent's thread that forked, which
    waits for the worker, so it ends no sooner. A parent killed before the request took
    effect is caught by the check that follows it: the worker has then been re-parented, and
    leaves at once.
    """
    if sys.platform.startswith("linux"):
        ctypes.CDLL(None, use_errno=True).prctl(_PR_SET_PDEATHSIG, signal.SIGKILL)
    if os.getppid() != parent_pid:
        os._exit(1)
    for signum in _STOPPING:
        signal.signal(signum, signal.SIG_DFL)
