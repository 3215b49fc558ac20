"""One computation timed in a forked child process, within a time budget.

sympy and python-flint cannot be interrupted from inside a call, so each measurement runs
in a child (``algkin.runtime.child``) that is killed at the budget; its error is the row's note. The first run is a warm-up and is not counted
(caches, imports); then runs repeat until they add up to ``MIN_SECONDS`` over at least
``MIN_REPEATS`` runs, stopping when one more would pass half the budget. The median is
reported, with the child's peak resident memory (``getrusage``: it counts what the child
shares with the parent it was forked from, so it bounds the run's own peak from above).

>>> seconds, summary, note = measure(lambda: sum(range(1000)), lambda total: total, budget=10)
>>> summary, seconds < 0.01, note.startswith("median of")
(499500, True, True)
"""

from __future__ import annotations

import resource
import statistics
import time
from collections.abc import Callable
from typing import TypeVar

from ..runtime.child import TimeUp, forked

__all__ = ["measure", "MIN_SECONDS", "MIN_REPEATS"]

R = TypeVar("R")  # what a run returns
S = TypeVar("S")  # what the row keeps of it

MIN_SECONDS = 0.2
MIN_REPEATS = 5


def measure(run: Callable[[], R], summarize: Callable[[R], S],
            budget: float) -> tuple[float | None, S | None, str]:
    """``(median seconds or None, summarize(result), note)`` of ``run()`` within ``budget`` seconds."""
    end = time.monotonic() + budget
    with forked(lambda tell: _repeated(run, summarize, budget)) as child:  # its progress shown nowhere
        try:
            return child.answer(left=lambda: end - time.monotonic())
        except TimeUp:
            return None, None, f"over budget ({budget:g} s)"
        except Exception as error:  # noqa: BLE001 - the row says why, and the bench goes on
            return None, None, f"failed: {type(error).__name__}: {str(error)[:120]}"


def _peak() -> str:
    """The process's peak resident memory so far, as a note (Linux reports kilobytes)."""
    return f"peak RSS {resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024:.0f} MB"


def _repeated(run: Callable[[], R], summarize: Callable[[R], S], budget: float) -> tuple[float, S, str]:
    """In the child: a warm-up, then runs repeated while they fit in half the ``budget``."""
    start = time.perf_counter()
    result = run()
    warm_up = time.perf_counter() - start
    deadline = start + budget / 2
    times: list[float] = []
    while len(times) < MIN_REPEATS or sum(times) < MIN_SECONDS:
        if time.perf_counter() + (times[-1] if times else warm_up) > deadline:
            break
        mark = time.perf_counter()
        result = run()
        times.append(time.perf_counter() - mark)
    if times:
        return statistics.median(times), summarize(result), f"median of {len(times)} runs after a warm-up; {_peak()}"
    return warm_up, summarize(result), f"one run (no time left for repeats); {_peak()}"
