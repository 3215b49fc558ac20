"""Time derive and curve on both seed scenes, per method x backend, and print flint/sympy.

Each cell is the median of repeated runs after a warm-up, timing the pipeline without
numeric verification (which does not depend on the method or backend), and separately
its elimination stage. Every result is asserted to agree with the others.

    python benchmarks/bench_pipeline.py [--repeats N]
"""

import argparse
import statistics
import time

import sympy

import algkin
from algkin.eliminate import BACKENDS, METHODS

PROBLEMS = {
    "lambda connector B (derive)": lambda m, b: algkin.derive("chebyshev-lambda", ["B"], m, b, samples=0),
    "lambda coupler P (curve)": lambda m, b: algkin.curve("chebyshev-lambda", "P", m, b, samples=0),
    "arm |AB| with symbolic b (derive)": lambda m, b: algkin.derive("arm-string", ["AB"], m, b, ["b"], samples=0),
}


def answer(result):
    """The polynomials a run produced, for the agreement check."""
    if hasattr(result, "eliminations"):
        return {u: e.polynomial for u, e in result.eliminations.items()}
    return {"curve": result.elimination.polynomial}


def agree(a, b):
    return a.keys() == b.keys() and all(
        sympy.cancel(sympy.sympify(a[k]) / sympy.sympify(b[k])).is_number for k in a)


def measure(run, repeats):
    run()  # warm-up: imports, caches
    totals, stages = [], []
    for _ in range(repeats):
        start = time.perf_counter()
        result = run()
        totals.append(time.perf_counter() - start)
        stages.append(result.timings["eliminate"])
    return statistics.median(totals), statistics.median(stages), result


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args()
    print(f"{'problem':36} {'method':10} {'backend':8} {'total ms':>10} {'eliminate ms':>13} {'degree':>7}")
    for problem, make in PROBLEMS.items():
        reference, rows = None, {}
        for method in sorted(METHODS):
            for backend in sorted(BACKENDS):
                total, stage, result = measure(lambda: make(method, backend), args.repeats)
                polys = answer(result)
                reference = reference or polys
                assert agree(polys, reference), f"{problem}: {method}/{backend} disagrees"
                rows[method, backend] = (total, stage)
                degree = max(sympy.Poly(p).total_degree() for p in polys.values())
                print(f"{problem:36} {method:10} {backend:8} {total * 1e3:10.2f} {stage * 1e3:13.2f} {degree:7d}")
        for method in sorted(METHODS):
            flint_total, flint_stage = rows[method, "flint"]
            sympy_total, sympy_stage = rows[method, "sympy"]
            print(f"{'':36} {method:10} sympy/flint: total x{sympy_total / flint_total:.1f}, "
                  f"eliminate x{sympy_stage / flint_stage:.1f}")
    print("all results agree across methods and backends")


if __name__ == "__main__":
    main()
