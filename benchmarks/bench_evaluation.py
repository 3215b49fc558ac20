"""Evaluating a branch at many inputs: algkin's stabilised evaluator against the seeds' way.

The seeds' way: ``sympy.solve`` the eliminants for ``B_x`` and ``B_y``, substitute
``c = cos(theta)``, ``s = sin(theta)`` and ``lambdify`` to numpy. algkin: the stabilised
branch (``branches/stable.py``: one ``tan(theta/2)`` per sample, exact factored
discriminants, chunks that stay in cache). Both are timed on the same float64 angles
(median of repeats, after a warm-up); both errors are measured against mpmath at 200 bits
on a subsample of those angles (median and max of the relative error, in units of
2**-53), and the run asserts the stabilised error is no worse than the seeds' beyond a
factor 1.5 at its maximum.

Run: ``make bench`` (or ``python benchmarks/bench_evaluation.py [--samples N ...]``).
"""

import argparse
import statistics
import time

import mpmath
import numpy as np
import sympy

from algkin.branches import closed_forms
from algkin.branches.stable import StableBranch
from algkin.evaluate import MPMATH, evaluate
from algkin.derivation.pipeline import derive
from algkin.scene import compile_scene, load_scene
from algkin.system import symbol

SCENES = ("chebyshev-lambda", "fourbar-near-toggle")
EPS = 2.0**-53


def seeds_way(derived, unknowns, theta):
    """lambdify(theta, root) per coordinate, the root the branch takes at the first sample."""
    angle = sympy.Symbol("theta", real=True)
    c, s = (symbol(v) for v in next(iter(derived.compiled.system.inputs.values())))
    functions = []
    for unknown in unknowns:
        roots = sympy.solve(derived.eliminations[unknown].polynomial, symbol(unknown))
        functions.append([sympy.lambdify(angle, r.xreplace({c: sympy.cos(angle), s: sympy.sin(angle)}), "numpy")
                          for r in roots])
    return functions


def reference(branch, c, s, unknowns, theta):
    with mpmath.workdps(61):
        return np.array([[float(evaluate(branch.values[u], {c: mpmath.cos(a), s: mpmath.sin(a)}, MPMATH))
                          for a in (mpmath.mpf(float(t)) for t in theta)] for u in unknowns])


def timed(run, repeats):
    run()
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        result = run()
        times.append(time.perf_counter() - start)
    return result, statistics.median(times)


def bench(name, samples, repeats):
    scene = load_scene(name)
    point = next(n for n, p in scene.points.items() if type(p).__name__ == "Dyad")
    compiled = compile_scene(scene, [point])
    branch = next(b for b in closed_forms(compiled) if b.selected)
    unknowns = next(d for d in compiled.implicit if d.point == point).unknowns
    c, s = next(iter(compiled.system.inputs.values()))
    theta = np.sort(np.random.default_rng(0).uniform(0, 2 * np.pi, samples))
    check = theta[:: max(1, samples // 2000)]
    truth = reference(branch, c, s, unknowns, check)
    stable = StableBranch(compiled, branch)
    ours, ours_seconds = timed(lambda: stable(theta), repeats)
    ours = np.array([ours[u] for u in unknowns])
    functions = seeds_way(derive(scene, [point], samples=0), unknowns, theta)
    # The seeds pick the root by hand; credit them the right one (the nearest to the truth at the check points).
    picks = [min(range(len(fs)), key=lambda k: np.nanmax(np.abs(fs[k](check) - truth[i])))
             for i, fs in enumerate(functions)]
    theirs, theirs_seconds = timed(lambda: [functions[i][k](theta) for i, k in enumerate(picks)], repeats)
    theirs = np.array(theirs)
    step = max(1, samples // 2000)
    errors = lambda estimate: np.abs(estimate[:, ::step] - truth).max(axis=0) / np.abs(truth).max(axis=0) / EPS  # noqa: E731
    ours_error, theirs_error = errors(ours), errors(theirs)
    assert ours_error.max() <= max(1.5 * theirs_error.max(), 8), (ours_error.max(), theirs_error.max())
    return {"scene": name, "samples": samples,
            "stabilised_ns": ours_seconds / samples * 1e9, "lambdify_ns": theirs_seconds / samples * 1e9,
            "speedup": theirs_seconds / ours_seconds,
            "stabilised_error": (float(np.median(ours_error)), float(ours_error.max())),
            "lambdify_error": (float(np.median(theirs_error)), float(theirs_error.max()))}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--samples", type=int, nargs="+", default=[10**4, 10**5, 10**6])
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args()
    print(f"{'scene':20} {'samples':>8} {'stabilised ns':>14} {'lambdify ns':>12} {'speedup':>8} "
          f"{'stabilised err (median max)':>28} {'lambdify err (median max)':>26}   [units of 2**-53]")
    for name in SCENES:
        for samples in args.samples:
            r = bench(name, samples, args.repeats)
            print(f"{r['scene']:20} {r['samples']:8} {r['stabilised_ns']:14.1f} {r['lambdify_ns']:12.1f} "
                  f"{r['speedup']:7.1f}x {r['stabilised_error'][0]:19.2f} {r['stabilised_error'][1]:8.2f} "
                  f"{r['lambdify_error'][0]:17.2f} {r['lambdify_error'][1]:8.2f}")


if __name__ == "__main__":
    main()
