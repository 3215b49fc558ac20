"""Elimination ideas measured one at a time: early factoring, and where the linear method's
multipliers may hold kept coordinates.

- early factoring: every intermediate resultant factored and cut to the factors the
  witnesses satisfy (algkin's way), against only made squarefree;
- coordinate multipliers: the ``linear`` method with multipliers allowed to hold kept
  coordinates only in the closing Cramer step (algkin's way), against at every step
  ("without" is then the variant that allows them everywhere).

Both variants are swapped in for the run only; each time is CPU time per elimination
(the median of repeats after a warm-up), and every variant's eliminant is asserted equal
to algkin's.

Run: ``python benchmarks/bench_ideas.py [--problems ...]``.
"""

import argparse
import statistics
import time
from contextlib import contextmanager

import algkin.eliminate as eliminate
import algkin.eliminate.methods as methods
from algkin.bench.problems import build
from algkin.eliminate.linear import linear_elimination

PROBLEMS = ("fourbar-symbolic", "watt-i", "stephenson-iii")


def _squarefree_only(backend, poly, witnesses, dropped):
    _, factors = poly.factor_squarefree()
    product = factors[0][0]
    for factor, _ in factors[1:]:
        product = product * factor
    return product


def _coordinates_always(backend, polys, eliminate, witnesses, dropped, log, parameters=(), budget=None,
                        multipliers=None):
    # every kept variable counts as a dimension: multipliers may hold coordinates at every step
    kept = tuple(n for n in backend.names if n not in eliminate)
    return linear_elimination(backend, polys, eliminate, witnesses, dropped, log, kept, budget, multipliers)


IDEAS = {  # the idea -> how to run without it
    "early factoring": lambda: swapped(methods, "_squarefree_kept", _squarefree_only),
    "coordinate multipliers": lambda: swapped(eliminate, "METHODS", {**eliminate.METHODS,
                                                                      "linear": _coordinates_always}),
}


@contextmanager
def swapped(module, name, replacement):
    original = getattr(module, name)
    setattr(module, name, replacement)
    try:
        yield
    finally:
        setattr(module, name, original)


def cpu_time(run, repeats=5):
    run()
    times = []
    for _ in range(repeats):
        start = time.process_time()
        result = run()
        times.append(time.process_time() - start)
    return statistics.median(times), result


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--problems", nargs="+", default=list(PROBLEMS))
    args = parser.parse_args()
    print(f"{'problem':18} {'idea':22} {'with (algkin)':>14} {'without':>12} {'ratio':>8}")
    for name in args.problems:
        task = build(name).task
        with_seconds, reference = cpu_time(lambda: task.run("linear", "flint"))
        for idea, without in IDEAS.items():
            with without():
                without_seconds, result = cpu_time(lambda: task.run("linear", "flint"), repeats=1)
            same = result.raw * reference.raw.leading_coefficient() == reference.raw * result.raw.leading_coefficient()
            assert same, (name, idea)
            print(f"{name:18} {idea:22} {with_seconds * 1e3:11.1f} ms {without_seconds * 1e3:9.1f} ms "
                  f"{without_seconds / with_seconds:7.1f}x")


if __name__ == "__main__":
    main()
