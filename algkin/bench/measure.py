"""One computation timed in a forked child process, within a time budget.

sympy and python-flint cannot be interrupted from inside a call, so each measurement runs
in a child that is killed at the budget. The first run is a warm-up and is not counted
(caches, imports); then runs repeat until they add up to ``MIN_SECONDS`` over at least
``MIN_REPEATS`` runs, stopping when one more would pass half the budget. The median is
reported, with the child's peak resident memory (``getrusage``: it counts what the child
shares with the parent it was forked from, so it bounds the run's own peak from above).

>>> seconds, summary, note = measure(lambda: sum(range(1000)), lambda total: total, budget=10)
>>> summary, seconds < 0.01, note.startswith("median of")
(499500, True, True)
"""

import multiprocessing
import os
import resource
import statistics
import time

from ..runtime import progress
from ..runtime.budget import bind_to_parent

__all__ = ["measure", "MIN_SECONDS", "MIN_REPEATS"]

MIN_SECONDS = 0.2
MIN_REPEATS = 5


def measure(run, summarize, budget):
    """``(median seconds or None, summarize(result), note)`` of ``run()`` within ``budget`` seconds."""
    receive, send = multiprocessing.Pipe(duplex=False)
    child = multiprocessing.get_context("fork").Process(target=_child, daemon=True,
                                                         args=(run, summarize, send, budget, os.getpid()))
    child.start()
    try:
        if not receive.poll(budget):
            return None, None, f"over budget ({budget:g} s)"
        return receive.recv()
    finally:  # over budget, done, or unwound by a signal's exception (algkin.ui.cli): no child left
        child.kill()
        child.join()


def _peak():
    """The process's peak resident memory so far, as a note (Linux reports kilobytes)."""
    return f"peak RSS {resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024:.0f} MB"


def _child(run, summarize, pipe, budget, parent_pid):
    bind_to_parent(parent_pid)
    progress.hand_over(None)  # the stages of every run repeated would only flicker: the parent says the row
    try:
        start = time.perf_counter()
        result = run()
        warm_up = time.perf_counter() - start
        deadline = start + budget / 2
        times = []
        while len(times) < MIN_REPEATS or sum(times) < MIN_SECONDS:
            if time.perf_counter() + (times[-1] if times else warm_up) > deadline:
                break
            mark = time.perf_counter()
            result = run()
            times.append(time.perf_counter() - mark)
        if times:
            pipe.send((statistics.median(times), summarize(result),
                       f"median of {len(times)} runs after a warm-up; {_peak()}"))
        else:
            pipe.send((warm_up, summarize(result), f"one run (no time left for repeats); {_peak()}"))
    except Exception as error:  # the parent reports it in the row and goes on
        pipe.send((None, None, f"failed: {type(error).__name__}: {str(error)[:120]}"))
