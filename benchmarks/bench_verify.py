"""What verification costs against the elimination it checks, in one process, warm.

For each command of the grid, the call is made once to warm the caches (the compiled scene,
its closed forms, the verification's compiled residuals), then three times; the figure is
the median over those three of the command's total time over its own elimination stage
(``timings["total"] / timings["eliminate"]``), beside the target of issue 16. Each run must
verify: every sampled configuration proved in balls, compared with its branch, passed.

Run: ``python benchmarks/bench_verify.py [--samples N]`` (exit 1 if a ratio misses its target).
"""

import argparse
import statistics
import sys

import algkin

FOURBAR_DIMENSIONS = ["a", "d", "l", "m", "p", "q"]

GRID = [  # (command, call, target ratio)
    ("derive chebyshev-lambda --outputs B", lambda n: algkin.derive("chebyshev-lambda", outputs=["B"], samples=n), 10),
    ("curve chebyshev-lambda --point P", lambda n: algkin.curve("chebyshev-lambda", "P", samples=n), 5),
    ("curve stephenson-iii --point P", lambda n: algkin.curve("stephenson-iii", "P", samples=n), 3),
    ("curve fourbar --point P --param a d l m p q",
     lambda n: algkin.curve("fourbar", "P", params=FOURBAR_DIMENSIONS, samples=n), 3),
]


def measure(call, samples, repeats=3):
    """Median seconds per stage over ``repeats`` warm runs; the runs must have verified."""
    call(samples)
    runs = []
    for _ in range(repeats):
        result = call(samples)
        verification = result.verification
        assert verification.passed and verification.compared, verification.failures
        runs.append(result.timings)
    return {stage: statistics.median(run[stage] for run in runs) for stage in runs[0]}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--samples", type=int, default=40, help="verification samples (the commands' default: 40)")
    samples = parser.parse_args().samples
    print(f"{'command':46} {'eliminate':>10} {'verify':>9} {'total':>9} {'ratio':>7} {'target':>7}")
    missed = 0
    for command, call, target in GRID:
        stages = measure(call, samples)
        ratio = stages["total"] / stages["eliminate"]
        missed += ratio > target
        print(f"{command:46} {stages['eliminate'] * 1e3:8.2f}ms {stages['verify'] * 1e3:7.2f}ms "
              f"{stages['total'] * 1e3:7.2f}ms {ratio:6.1f}x {target:6d}x{'  MISSED' if ratio > target else ''}")
    return 1 if missed else 0


if __name__ == "__main__":
    sys.exit(main())
