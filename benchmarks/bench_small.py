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

``--against DIR`` times the stage of another checkout's sources too (``git archive <commit> | tar
-x -C DIR``), in a child process running this script on them, the blocks of the two taken in
turn: a change's before and after from one run. It checks that both give the same eliminant and
the same kept factors.

Run: ``python benchmarks/bench_small.py [--problem NAME ...] [--against DIR]``.
"""

import argparse
import dataclasses
import json
import statistics
import subprocess
import sys
import time
from pathlib import Path

from checkouts import add_against, environment
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


def calibrated(function):
    """The number of calls of ``function`` that take ``BLOCK_SECONDS`` of CPU time, after a warm-up call."""
    function()
    start, count = time.process_time(), 0
    while time.process_time() - start < BLOCK_SECONDS:
        function()
        count += 1
    return count


def block(function, count):
    """CPU seconds per call over ``count`` calls of ``function``."""
    start = time.process_time()
    for _ in range(count):
        function()
    return (time.process_time() - start) / count


def per_call(function):
    """Median CPU seconds per call over ``BLOCKS`` blocks of calls, after a warm-up."""
    count = calibrated(function)
    return statistics.median(block(function, count) for _ in range(BLOCKS))


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


def answer(elimination):
    """An elimination's answer as text: the eliminant and its kept factors (what a change must keep)."""
    return [elimination.text, *(str(f) for f in elimination.exact[1])]


class Here:
    """The elimination stage of this checkout, timed in this process."""

    def __init__(self):
        self.stages = {}

    def start(self, name):
        """Calibrate ``name``'s stage: (calls a block, the answer)."""
        task = flint_task(build(name).task)
        self.stages[name] = lambda: task.run("linear", "flint")
        return calibrated(self.stages[name]), answer(self.stages[name]())

    def block(self, name, count):
        return block(self.stages[name], count)


class There:
    """The elimination stage of another checkout's sources, timed in a child process
    (``serve``) that imports them."""

    def __init__(self, root):
        self.root = root
        self.child = subprocess.Popen([sys.executable, str(Path(__file__).resolve()), "--serve"], cwd=self.root,
                                      env=environment(self.root), stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                      text=True)
        where = self._ask("where")
        if not Path(where).resolve().is_relative_to(self.root):
            raise SystemExit(f"--against {root}: the child imported algkin from {where}")

    def _ask(self, request):
        self.child.stdin.write(json.dumps(request) + "\n")
        self.child.stdin.flush()
        line = self.child.stdout.readline()
        if not line:  # its traceback is on stderr, above
            raise SystemExit(f"--against {self.root}: the child stopped at {request}")
        return json.loads(line)

    def start(self, name):
        return tuple(self._ask(["start", name]))

    def block(self, name, count):
        return self._ask(["block", name, count])

    def close(self):
        self.child.stdin.close()
        self.child.wait()


def serve():
    """The child's loop (``There``): a JSON request a line, a JSON answer a line."""
    import algkin

    here = Here()
    for line in sys.stdin:
        request = json.loads(line)
        if request == "where":
            reply = algkin.__file__
        else:
            reply = here.start(request[1]) if request[0] == "start" else here.block(request[1], request[2])
        print(json.dumps(reply), flush=True)


def stages(name, sides):
    """Per side, (median CPU seconds per call of ``name``'s stage, its answer): the sides' blocks in turn."""
    started = [side.start(name) for side in sides]
    times = [[] for _ in sides]
    for _ in range(BLOCKS):
        for side, (count, _), taken in zip(sides, started, times):
            taken.append(side.block(name, count))
    return [(statistics.median(taken), result) for taken, (_, result) in zip(times, started)]


def row(name, sides):
    """(per side (stage seconds, answer), PARI seconds or None, PARI's note, floor seconds) for the problem ``name``."""
    task = flint_task(build(name).task)
    stage = stages(name, sides)
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
    add_against(parser)
    parser.add_argument("--serve", action="store_true", help=argparse.SUPPRESS)  # the child of --against
    args = parser.parse_args()
    if args.serve:
        return serve()
    sides = [Here()] if args.against is None else [There(args.against), Here()]
    print("CPU time per call; ratio = time / PARI/GP's polresultant loop" +
          (f"; before = {args.against}, after = this checkout, their blocks in turn" if args.against else ""))
    before = f"{'before':>10} {'ratio':>7} " if args.against else ""
    speedup = f"{'speed-up':>8} {'same':>4} " if args.against else ""
    print(f"{'problem':15} {before}{'algkin stage':>12} {'ratio':>7} {speedup}{'PARI/GP':>10} {'flint floor':>12} "
          f"{'ratio':>7}  note")
    for name in args.problem:
        stage, pari, note, floor = row(name, sides)

        def ratio(seconds):
            return f"{seconds / pari:6.2f}x" if pari else "      -"
        shown = f"{pari * 1e6:7.1f} us" if pari else "         -"
        after, result = stage[-1]
        columns = [f"{name:15}"]
        if args.against:
            (old, old_result), _ = stage
            columns += [f"{old * 1e6:7.1f} us", f"{ratio(old):>7}"]
        columns += [f"{after * 1e6:9.1f} us", f"{ratio(after):>7}"]
        if args.against:
            columns += [f"{old / after:7.2f}x", f"{'yes' if old_result == result else 'NO':>4}"]
        columns += [f"{shown:>10}", f"{floor * 1e6:9.1f} us", f"{ratio(floor):>7}", f" {note}"]
        print(" ".join(columns))
    for side in sides:
        getattr(side, "close", lambda: None)()
    alone, batch = batch_rows()
    print(f"two-circles at {POSITIONS} crank positions, per position: one eliminate call each {alone * 1e6:.1f} us, "
          f"one eliminate_each call {batch * 1e6:.1f} us ({alone / batch:.2f}x)")


if __name__ == "__main__":
    main()
