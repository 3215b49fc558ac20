"""Budgets for commands and eliminations: wall seconds and the size of every intermediate eliminant.

A ``Budget`` is a value, what a caller allows: at most ``seconds`` of wall time, at most
``terms`` terms per eliminant. ``start()`` makes a ``Deadline``, the budget running from now,
which is passed to the work that keeps to it (``budget=`` of ``derive``, ``eliminate``...):
one budget starts any number of deadlines.

A python-flint resultant or Gröbner basis is one C call that no signal interrupts (it holds
the GIL: no Python handler runs until it returns), so a deadline's ``run()`` computes in a
forked child process killed at the deadline (``algkin.runtime.child``); a budget ``apart``
does so with no time limit too, so that a signal to the parent (Ctrl-C) stops the work at
once. The work says what it is doing (``note``), so the message says
what was being computed when time ran out; the parent shows it as progress
(``algkin.runtime.progress``). A terms budget is checked after every resultant and Gröbner basis.
This module imports no algebra, so that a command's parent process stays light.

>>> deadline = Budget(terms=3).start()
>>> deadline.check_terms(4, "the resultant in B_x")
Traceback (most recent call last):
...
algkin.errors.BudgetExceeded: max_terms=3: the resultant in B_x has 4 terms, while computing

The deadline is read on a clock, ``time.monotonic`` unless one is given; tests give one that
moves when they say, so that nothing depends on how fast the machine is. Here one that stands
still (the deadline never comes), then one that reads 0 when the budget starts and 10.5 ever
after, against work that would never end:

>>> Budget(seconds=10, clock=lambda: 0.0).start().run(lambda: sum(range(10)))
45
>>> import threading
>>> readings = iter([0.0])
>>> Budget(seconds=10, clock=lambda: next(readings, 10.5)).start().run(threading.Event().wait)
Traceback (most recent call last):
...
algkin.errors.BudgetExceeded: max_seconds=10: stopped after 10.50 s while computing

A time budget is at most a week (``MAX_SECONDS``): more is a slip (a unit, a zero too many),
and the timers that keep it (a poll's timeout in milliseconds, a C int) go no further than 24 days.

>>> Budget(seconds=1e10)
Traceback (most recent call last):
...
algkin.errors.UsageError: seconds=10000000000.0: must be a positive number of seconds, at most a week (604800)
"""

import numbers
import time
from collections.abc import Callable
from typing import TYPE_CHECKING, Any, TypeVar

import attrs

from ..errors import BudgetExceeded, UsageError
from . import progress

if TYPE_CHECKING:  # the child (multiprocessing: milliseconds of imports) is loaded by a timed run only
    from .child import Tell

__all__ = ["Budget", "Deadline", "started", "time_budget", "MAX_SECONDS"]

MAX_SECONDS = 7 * 24 * 3600  # a week

T = TypeVar("T")


def time_budget(seconds: float, argument: str) -> float:
    """``seconds`` if it is a time budget that can be kept: a positive number, at most ``MAX_SECONDS``;
    else UsageError naming ``argument``.

    >>> time_budget(2.5, "budget")
    2.5
    >>> time_budget(float("nan"), "budget")
    Traceback (most recent call last):
    ...
    algkin.errors.UsageError: budget=nan: must be a positive number of seconds, at most a week (604800)
    """
    if isinstance(seconds, bool) or not isinstance(seconds, numbers.Real) or not 0 < seconds <= MAX_SECONDS:  # nan, inf
        raise UsageError(argument, seconds, f"must be a positive number of seconds, at most a week ({MAX_SECONDS})")
    return seconds


def _seconds(_: Any, __: Any, seconds: float | None) -> None:
    if seconds is not None:
        time_budget(seconds, "seconds")


def _terms(_: Any, __: Any, terms: int | None) -> None:
    if terms is None:
        return
    try:
        whole = int(terms) == terms
    except (TypeError, ValueError, OverflowError):  # not a number, nan, inf
        whole = False
    if not whole or not terms > 0:
        raise UsageError("terms", terms, "a terms budget must be a positive integer")


def _clock(_: Any, __: Any, clock: object) -> None:
    if not callable(clock):
        raise UsageError("clock", clock, "expected a function giving seconds, such as time.monotonic")


@attrs.frozen
class Budget:
    """At most ``seconds`` of wall time from ``start()`` and ``terms`` terms per eliminant.

    Either may be None (no limit); the time is read on ``clock`` (seconds). A value: equal
    budgets are interchangeable, and starting one changes nothing in it.

    >>> Budget(seconds=10) == Budget(10) and len({Budget(10), Budget(10)}) == 1
    True
    """

    seconds: float | None = attrs.field(default=None, validator=_seconds)
    terms: int | None = attrs.field(default=None, validator=_terms)
    clock: Callable[[], float] = attrs.field(default=time.monotonic, kw_only=True, repr=False, validator=_clock)
    # the work in a forked child even without ``seconds`` (where the platform forks): the command line's
    # own way of running, not a limit, so not in the repr users read
    apart: bool = attrs.field(default=False, kw_only=True, repr=False)

    def start(self) -> "Deadline":
        """This budget running from now: its deadline ``seconds`` on from the clock's reading."""
        reading = self.clock()
        if isinstance(reading, bool) or not isinstance(reading, numbers.Real):  # else a TypeError at its next reading
            raise UsageError("clock", reading, "a clock's reading must be a number of seconds")
        return Deadline(self, reading)


@attrs.define(eq=False)
class Deadline:
    """A budget started when its clock read ``begun``, and what its work is doing now.

    The work's notes (``note``) say what it is doing, for the message if the time runs out and
    as progress. Compared by identity: two deadlines of one budget are two runs of it.

    >>> readings = iter([100.0, 104.0])
    >>> deadline = Budget(seconds=10, clock=lambda: next(readings)).start()
    >>> deadline.begun, deadline.left()
    (100.0, 6.0)
    """

    budget: Budget = attrs.field(on_setattr=attrs.setters.frozen)
    begun: float = attrs.field(on_setattr=attrs.setters.frozen)
    doing: str = "computing"
    _tell: "Tell | None" = attrs.field(default=None, init=False)  # in its child process: to the parent

    def left(self) -> float | None:
        """The seconds left before the deadline (None: no time budget); zero or less once it has passed."""
        seconds = self.budget.seconds
        return None if seconds is None else self.begun + seconds - self.budget.clock()

    def note(self, doing: str) -> None:
        """Say what is being computed now, for the message if the time runs out, and as progress."""
        self.doing = doing
        if self._tell is not None:
            self._tell(doing)  # the parent shows it
        else:
            progress.stage(doing)

    def check_terms(self, count: int, what: str) -> None:
        """Raise BudgetExceeded if ``what`` (an intermediate eliminant) has more than ``terms`` terms."""
        terms = self.budget.terms
        if terms is not None and count > terms:
            raise BudgetExceeded(f"max_terms={terms}: {what} has {count} terms, while {self.doing}")

    def run(self, function: Callable[[], T]) -> T:
        """``function()``, stopped at the deadline when there is a time budget: in a forked
        child (where the budget is ``apart``, with no time budget too), unless this is already
        the child keeping this deadline."""
        seconds, clock = self.budget.seconds, self.budget.clock
        if self._tell is not None or (seconds is None and not (self.budget.apart and _can_fork())):
            return function()
        from .child import TimeUp, forked

        left = None if seconds is None else (lambda: self.begun + seconds - clock())
        with forked(lambda tell: self._within(function, tell), shows_progress=True) as child:
            try:
                return child.answer(left=left, heard=self._heard)
            except TimeUp:
                elapsed = clock() - self.begun
                raise BudgetExceeded(f"max_seconds={seconds:g}: stopped after {elapsed:.2f} s "
                                     f"while {self.doing}") from None

    def _within(self, function: Callable[[], T], tell: "Tell") -> T:
        """In the child: ``function()``, this deadline's notes told to the parent."""
        self._tell = tell
        return function()

    def _heard(self, doing: str) -> None:
        """A note from the child, kept and shown."""
        self.doing = doing
        progress.stage(doing)


def _can_fork() -> bool:
    from .child import can_fork

    return can_fork()


def started(budget: "Budget | Deadline | None" = None) -> Deadline:
    """The deadline work keeps to: ``budget`` started now, a deadline already running, or none (no limit).

    >>> started().left() is None
    True
    >>> deadline = Budget(terms=7).start()
    >>> started(deadline) is deadline
    True
    >>> started(10)
    Traceback (most recent call last):
    ...
    algkin.errors.UsageError: budget=10: expected an algkin.Budget, e.g. Budget(seconds=10)
    """
    if isinstance(budget, Deadline):
        return budget
    if budget is None:
        return Budget().start()
    if not isinstance(budget, Budget):
        raise UsageError("budget", budget, "expected an algkin.Budget, e.g. Budget(seconds=10)")
    return budget.start()
