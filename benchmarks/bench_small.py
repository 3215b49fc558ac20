"""The four small problems against PARI/GP's bare resultant loop, and python-flint's floor, in one run.

On ``two-circles``, ``arm-extremum``, ``slider-crank`` and ``lambda-coupler`` (``algkin bench``'s
problems), it times

- algkin's elimination stage: ``eliminate`` with the default method, from the equations as
  python-flint polynomials (as a compiled system holds them; the arm's are converted from sympy
  once, before timing) to the kept factor, proved irreducible or chosen at the witnesses;
- PARI/GP's ``polresultant`` chain (``algkin.bench.engines``), timed by its own clock inside its
  own loop, when ``gp`` is installed;
- the python-flint floor: the same chain of ``resultant`` calls as PARI's (the same pivots), on
  polynomials already in python-flint's ring, and nothing else;
- the batch path: the seed's two circles at ``POSITIONS`` rational crank positions, each
  ``eliminate``'d alone, then all in one ``eliminate_each`` call (no witnesses for either: the
  task's are at one position), per position.

Every time is CPU time per call (PARI's ``getabstime`` is CPU time too, so a loaded machine
slows both alike), the median of repeated blocks after a warm-up. Ratios are against PARI/GP's
loop: 2.00x is twice its time.

Run: ``python benchmarks/bench_small.py [--problem NAME ...]``.
"""

import argparse
import dataclasses
import statistics
import time

from flint import fmpq

from algkin.bench.engines import PEERS
from algkin.bench.peers import PeerProblem
from algkin.bench.problems import build
from algkin.eliminate import eliminate, eliminate_each
from algkin.eliminate.backends import FlintBackend
from algkin.system.convert import flint_context, to_flint

SMALL = ("two-circles", "arm-extremum", "slider-crank", "lambda-coupler")
BLOCK_SECONDS = 0.05
BLOCKS = 9
POSITIONS = 50


def per_call(function):
    """Median CPU seconds per call over ``BLOCKS`` blocks of calls, after a warm-up."""
    function()
    start, count = time.process_time(), 0
    while time.process_time() - start < BLOCK_SECONDS:
        function()
        count += 1
    blocks = []
    for _ in range(BLOCKS):
        start = time.process_time()
        for _ in range(count):
            function()
        blocks.append((time.process_time() - start) / count)
    return statistics.median(blocks)


def flint_task(task):
    """``task`` with its equations as python-flint polynomials (converted once, here, if it has none)."""
    if task.polynomials:
        return task
    ctx = flint_context(task.eliminate + task.keep)
    return dataclasses.replace(task, polynomials=tuple(to_flint(e, ctx) for e in task.equations))


def pari_chain(polys, eliminate):
    """PARI's loop (``algkin.bench.engines``) in python-flint: for each variable in turn, the
    resultants of its holders against the one of least degree in it. Only resultant calls."""
    for var in eliminate:
        holders = [p for p in polys if p.degrees()[p.context().variable_to_index(var)]]
        if len(holders) < 2:
            continue
        pivot = min(holders, key=lambda p: p.degrees()[p.context().variable_to_index(var)])
        polys = [p for p in polys if p not in holders] + [pivot.resultant(p, var) for p in holders if p is not pivot]
    return polys


def row(name):
    """(stage seconds, PARI seconds or None, PARI's note, floor seconds) for the problem ``name``."""
    task = flint_task(build(name).task)
    stage = per_call(lambda: task.run("linear", "flint"))
    engine = FlintBackend(task.eliminate + task.keep)
    polys = [engine.from_flint(p) for p in task.polynomials]
    floor = per_call(lambda: pari_chain(polys, task.eliminate))
    peer = PEERS["PARI/GP resultant"](PeerProblem(name, tuple(str(e) for e in task.equations), task.eliminate,
                                                  task.keep))
    return stage, peer.seconds_per_run, peer.note, floor


def batch_rows():
    """(seconds per position one call each, seconds per position in one ``eliminate_each`` call)."""
    task = build("two-circles").task
    half = [fmpq(1, k) for k in range(2, POSITIONS + 2)]  # tan of half the crank angle: rational cos and sin
    at = [{"c_angle": (1 - t * t) / (1 + t * t), "s_angle": 2 * t / (1 + t * t)} for t in half]

    def one_by_one():
        for values in at:
            eliminate([p.subs(values) for p in task.polynomials], task.eliminate, task.keep)

    def in_one_call():
        eliminate_each(task.polynomials, task.eliminate, task.keep, at=at)

    return per_call(one_by_one) / POSITIONS, per_call(in_one_call) / POSITIONS


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--problem", nargs="*", default=SMALL, choices=SMALL)
    args = parser.parse_args()
    print("CPU time per call; ratio = time / PARI/GP's polresultant loop")
    print(f"{'problem':15} {'algkin stage':>12} {'PARI/GP':>10} {'ratio':>7} {'flint floor':>12} {'ratio':>7}  note")
    for name in args.problem:
        stage, pari, note, floor = row(name)

        def ratio(seconds):
            return f"{seconds / pari:6.2f}x" if pari else "      -"
        shown = f"{pari * 1e6:7.1f} us" if pari else "         -"
        print(f"{name:15} {stage * 1e6:9.1f} us {shown:>10} {ratio(stage):>7} {floor * 1e6:9.1f} us "
              f"{ratio(floor):>7}  {note}")
    alone, batch = batch_rows()
    print(f"two-circles at {POSITIONS} crank positions, per position: one eliminate call each {alone * 1e6:.1f} us, "
          f"one eliminate_each call {batch * 1e6:.1f} us ({alone / batch:.2f}x)")


if __name__ == "__main__":
    main()
