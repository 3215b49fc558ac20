"""Clocks that move when a test says, not with the machine's time: for budgets (``Budget(clock=)``)
and progress lines (``progress.shown(clock=)``), so that no test depends on how fast the machine is.

>>> clock = Clock(late=2.5)  # the deadline set on its first reading has passed at the next
>>> clock(), clock(), clock()
(0.0, 2.5, 2.5)
>>> ticking = ticks()
>>> ticking(), ticking()
(0, 1)
"""

import itertools

import attrs

from algkin.runtime import budget as budget_module

LATE = 3600.0  # what a passed clock reads: an hour, past any budget a test gives


def still():
    """A clock that stands still: a deadline read on it never comes."""
    return 0.0


def ticks():
    """A clock that moves a second at each reading: a progress line redraws at every step."""
    return itertools.count().__next__


class Clock:
    """Reads 0 at its first reading (a budget's start, which sets the deadline), then 0 until
    ``passed()`` holds (asked at each reading), then ``late`` ever after."""

    def __init__(self, late=LATE, passed=lambda: True):
        self.late, self._passed = late, passed
        self._started = self._over = False

    def __call__(self):
        if self._started and (self._over or self._passed()):
            self._over = True
            return self.late
        self._started = True
        return 0.0


def late_budgets(monkeypatch, doing=""):
    """Every budget started from now on (in this process: the command line's) reads a ``Clock``
    that passes its deadline once the work has said it is doing something that starts with
    ``doing`` (at once, by default): the message then says ``stopped after 3600.00 s``."""
    start = budget_module.Budget.start

    def late(budget):
        deadline = None  # the clock asks the deadline it is read for what its work is doing
        deadline = start(attrs.evolve(budget, clock=Clock(passed=lambda: deadline.doing.startswith(doing))))
        return deadline

    monkeypatch.setattr(budget_module.Budget, "start", late)
