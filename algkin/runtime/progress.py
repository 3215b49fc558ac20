"""Progress on stderr: one status line saying the stage (what ``Budget.note`` says) and, while a
loop counts its steps, how far it is.

Shown only inside ``shown()``, which the command line enters unless ``--quiet``, and which shows
nothing unless stderr is a terminal: a pipe or a log gets no progress, and neither does a call
from Python (``algkin.derive(...)``) outside it. The choice lives in a context variable, so it
ends with the block, and tqdm is imported only when something is shown.

A forked worker never writes to the terminal: ``hand_over`` sends what it would show to its
parent, which shows it (``replay``), or drops it.

>>> stage("compiling")  # not shown: no shown() block
>>> [n for n in counted(range(3))]
[0, 1, 2]
"""

import contextlib
import contextvars
import sys
import time
from collections.abc import Callable, Collection, Iterator
from typing import Literal, TextIO, TypeAlias, TypeVar

__all__ = ["shown", "stage", "counting", "step", "counted", "hand_over", "replay"]

# What a display is told: a stage's text, a count begun (its total and unit) or ended (None), a step done.
Event: TypeAlias = tuple[Literal["stage"], str] | tuple[Literal["count"], int | None, str] | tuple[Literal["step"]]
Show: TypeAlias = Callable[[Event], None]
_T = TypeVar("_T")

# What shows an event: a status line's ``apply``, a worker's ``send`` to its parent, or None (silent).
_DISPLAY: contextvars.ContextVar[Show | None] = contextvars.ContextVar("algkin_progress", default=None)
_STAGE = "{desc}"  # the status line between counts: the stage alone
_COUNT = "{desc}: {n_fmt}/{total_fmt} {unit} |{bar}| [{elapsed}<{remaining}]"


@contextlib.contextmanager
def shown(quiet: bool = False, stream: TextIO | None = None, *,
          clock: Callable[[], float] = time.monotonic) -> Iterator[None]:
    """Within the block, show progress on ``stream`` (stderr) if it is a terminal and not ``quiet``;
    the line is cleared when the block ends, so that what is written next starts clean. A count is
    redrawn at most every 0.1 s of ``clock`` (seconds; tests give one that moves when they say)."""
    stream = sys.stderr if stream is None else stream
    if quiet or stream is None or not stream.isatty():  # None: stderr closed (``2>&-``)
        yield
        return
    line = _Line(stream, clock)
    token = _DISPLAY.set(line.apply)
    try:
        yield
    finally:
        _DISPLAY.reset(token)
        with contextlib.suppress(OSError):  # the terminal is gone (hung up): nothing left to clear
            line.close()


def stage(text: str) -> None:
    """Say the stage the work is at (shown in place of the one before)."""
    _apply(("stage", text))


@contextlib.contextmanager
def counting(total: int, unit: str = "steps") -> Iterator[None]:
    """Within the block, count ``total`` steps (``step()`` after each) under the stages said meanwhile;
    one count at a time."""
    _apply(("count", total, unit))
    try:
        yield
    finally:
        _apply(("count", None, unit))


def step() -> None:
    """One more step of the count under way done."""
    _apply(("step",))


def counted(iterable: Collection[_T], unit: str = "steps") -> Iterator[_T]:
    """The items of ``iterable`` (a collection: its length is the total), each counted once done."""
    with counting(len(iterable), unit):
        for item in iterable:
            yield item
            step()


def hand_over(send: Show | None) -> None:
    """In a worker just forked: the terminal is its parent's. What it would show goes to
    ``send(event)``, for the parent to ``replay``, or with ``send=None`` nowhere."""
    _DISPLAY.set(send if _DISPLAY.get() is not None else None)


def replay(event: Event) -> None:
    """Show an event a worker handed over."""
    _apply(event)


def _apply(event: Event) -> None:
    show = _DISPLAY.get()
    if show is not None:
        with contextlib.suppress(OSError):  # progress is a courtesy: a lost terminal or parent stops no command
            show(event)


class _Line:
    """The status line on a terminal: one tqdm bar, its text the stage, with a count while there is one."""

    def __init__(self, stream: TextIO, clock: Callable[[], float]) -> None:
        # here, and not at the top: only a shown line pays for the import
        from tqdm import tqdm

        class Bar(tqdm):  # type: ignore[type-arg, unused-ignore]  # generic in its stubs only (--strict asks for its argument): not subscriptable at run time
            # No monitor thread: it only tunes how often a fast loop redraws, and a process that
            # forks workers (budgets) had better have no other thread, which could hold a lock.
            monitor_interval = 0
            _time: Callable[[], float]  # tqdm's clock: an attribute its stubs leave out

        self._bar = Bar(file=stream, total=None, bar_format=_STAGE, desc="algkin", leave=False, dynamic_ncols=True)
        # tqdm's clock (time.time) is no parameter: set after the fact, with the times read on it
        self._bar._time = clock
        self._bar.start_t = self._bar.last_print_t = clock()

    def apply(self, event: Event) -> None:
        match event:
            case ("stage", text):
                self._stage(text)
            case ("count", total, unit):
                self._count(total, unit)
            case ("step",):
                self._bar.update()

    def _stage(self, text: str) -> None:
        # one line: a newline would leave a line behind that the next update cannot clear
        self._bar.set_description_str(f"algkin: {_one_line(text)}")

    def _count(self, total: int | None, unit: str) -> None:
        self._bar.unit = unit
        self._bar.bar_format = _STAGE if total is None else _COUNT
        self._bar.reset(float("inf") if total is None else total)  # tqdm's way to say "no total"

    def close(self) -> None:
        self._bar.close()


def _one_line(text: str) -> str:
    """``text`` on one line, its control and bidi characters escaped (as the reports do)."""
    from .terminal import terminal_safe

    return terminal_safe(" ".join(str(text).split()))
