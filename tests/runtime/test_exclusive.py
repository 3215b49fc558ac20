"""Threads computing in one process take turns (``algkin.runtime.exclusive``): python-flint's
working precision belongs to the process, and a derivation in one thread ran at the precision
another thread's work had just put back (its verification "failed" at 53 bits in place of 192)."""

import threading

import flint

import algkin
from algkin.verify import check

# How long the first thread waits for the second to be inside its verification too. Taking turns,
# the second never is (it waits for the lock): the first goes on after this. Without the lock the
# second is there in milliseconds; a machine too slow for that could only let the old code pass.
OVERLAP_WAIT = 2.0


def test_a_thread_deriving_keeps_its_precision_while_another_derives(monkeypatch):
    original = check._check_batch
    first_in, second_in, first_done = threading.Event(), threading.Event(), threading.Event()
    seen = {}

    def check_batch(*args, **kwargs):  # called inside verify's flint.ctx.workprec(WORKING_BITS)
        if threading.current_thread().name == "first":
            first_in.set()
            second_in.wait(OVERLAP_WAIT)  # the second enters its own precision block on top of this one
        elif not seen:
            second_in.set()
            first_done.wait(60)  # the first leaves its block, putting back the precision it found
            seen["bits"] = flint.ctx.prec
        return original(*args, **kwargs)

    monkeypatch.setattr(check, "_check_batch", check_batch)
    results = {}

    def derive(name):
        results[name] = algkin.derive("chebyshev-lambda", outputs=["B"], samples=2)
        if name == "first":
            first_done.set()

    first = threading.Thread(target=derive, args=("first",), name="first")
    first.start()
    assert first_in.wait(60)
    second = threading.Thread(target=derive, args=("second",), name="second")
    second.start()
    first.join(120)
    second.join(120)
    assert seen["bits"] == check.WORKING_BITS  # was 53: the first thread's block put back the default
    assert results["first"].verification.passed and results["second"].verification.passed
