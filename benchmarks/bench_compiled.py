"""ns per sample of a branch's closed form from input angles: lambdify, the stabilised numpy form and
the compiled (numba) form, same run, same angles; and each one's error against the certified reference.

For the lambda's B and P and the four-bar's P, at 10**6 uniform angles (best of repeats, warm):
the seeds' way (``sympy.solve`` of the eliminants, ``lambdify`` in the angle, the root credited
that is nearest the truth), ``StableBranch``'s numpy form (``engine="numpy"``) and its fused
kernel (``engine="compiled"``) on one thread (as with ``NUMBA_NUM_THREADS=1``) and on every core,
and on one thread from the half-angle tangents given (``kernel(tangents=True)``: no ``tan`` to take).
Ratios are to the numpy form of the same run. Errors: on a subset of the angles, against the
root of the original equations certified in balls (``algkin.bench.reference``), relative to the
point's size, in units of 2**-53 (median, max). The run asserts that the compiled values are the
numpy form's to a few ulps and no less accurate; the target (at most 10 ns a sample on one core
for the lambda's B and the four-bar's P) is printed as met or missed.

Then what ``engine="auto"`` rests on: the cost of a kernel in a fresh process (importing numba,
loading the kernel from the disk cache) against numpy's time for a few sample counts.

Run: ``make bench`` (or ``python benchmarks/bench_compiled.py [--samples N] [--repeats R]``).
"""

import argparse
import os
import subprocess
import sys
import time

import numpy as np

from algkin.bench.reference import Reference
from algkin.branches import closed_forms
from algkin.branches.stable import StableBranch, output_forms
from algkin.derivation.pipeline import derive
from algkin.evaluate.fused import numba_available
from algkin.scene import compile_scene, load_scene
from bench_evaluation import seeds_way

SUBJECTS = [("chebyshev-lambda", "B", True), ("fourbar", "P", True), ("chebyshev-lambda", "P", False)]
TARGET_NS = 10.0
EPS = 2.0**-53
ULPS = 4
CHECKED = 2000  # samples certified in balls for the errors


def timed(run, repeats):
    """The result and the best of ``repeats`` warm runs: on a shared machine, the others' load only adds."""
    run()
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        result = run()
        times.append(time.perf_counter() - start)
    return result, min(times)


def subject(name, point):
    scene = load_scene(name)
    compiled = compile_scene(scene, [point])
    branch = next(b for b in closed_forms(compiled) if b.selected)
    stable = StableBranch(compiled, branch)
    unknowns, forms = output_forms(stable, [point])
    return scene, compiled, branch, unknowns, stable.kernel(forms), stable.kernel(forms, tangents=True)


def errors(estimate, truth):
    """Per sample, the largest coordinate error over the point's size, in units of 2**-53."""
    return np.abs(estimate - truth).max(axis=0) / np.abs(truth).max(axis=0) / EPS


def bench(name, point, samples, repeats, cores):
    scene, compiled, branch, unknowns, kernel, from_tangents = subject(name, point)
    theta = np.sort(np.random.default_rng(0).uniform(0, 2 * np.pi, samples))
    check = theta[:: max(1, samples // CHECKED)]
    certified = Reference(compiled, branch, unknowns).certify(check)
    check, truth = check[certified.ok], certified.points[:, certified.ok]
    functions = seeds_way(derive(scene, [point], samples=0), unknowns, theta)
    picks = [min(range(len(fs)), key=lambda k: np.nanmax(np.abs(fs[k](check) - truth[i])))
             for i, fs in enumerate(functions)]
    runs = {"lambdify": lambda t: np.array([functions[i][k](t) for i, k in enumerate(picks)]),
            "stabilised numpy": lambda t: np.array(kernel(t, engine="numpy")),
            "compiled, 1 thread": lambda t: np.array(kernel(t, engine="compiled", threads=1)),
            f"compiled, {cores} threads": lambda t: np.array(kernel(t, engine="compiled", threads=cores))}
    tangents = {"check": np.tan(0.5 * check), "all": np.tan(0.5 * theta)}  # given, not timed
    rows, values = [], {}
    for label, run in runs.items():
        values[label], seconds = timed(lambda: run(theta), repeats)
        error = errors(run(check), truth)
        rows.append((label, seconds / samples * 1e9, float(np.median(error)), float(error.max())))
    half = lambda which: np.array(from_tangents(tangents[which], engine="compiled", threads=1))  # noqa: E731
    values["compiled from tan(theta/2)"], seconds = timed(lambda: half("all"), repeats)
    error = errors(half("check"), truth)
    rows.append(("compiled from tan/2", seconds / samples * 1e9, float(np.median(error)), float(error.max())))
    baseline = values["stabilised numpy"]
    for label in values:
        if label.startswith("compiled"):
            same = np.abs(values[label] - baseline) <= ULPS * np.spacing(np.abs(baseline))
            assert same.all(), f"{name} {point} {label}: not the numpy form's values"
    numpy_max = rows[1][3]
    assert all(r[3] <= numpy_max + ULPS for r in rows[2:]), (name, point, rows)
    return rows


def cold_costs(name, point):
    """Seconds, each in a fresh process: importing numba; then loading the kernel from the disk cache
    and evaluating one sample (the kernel compiled by this run already)."""
    code = ("import time, numpy as np; t0 = time.perf_counter(); import numba; t1 = time.perf_counter(); "
            "import sys; sys.path.insert(0, 'benchmarks'); from bench_compiled import subject; "
            f"k = subject({name!r}, {point!r})[-2]; t2 = time.perf_counter(); "
            "k(np.zeros(1), engine='compiled'); t3 = time.perf_counter(); print(t1 - t0, t3 - t2)")
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([root, os.environ.get("PYTHONPATH", "")]))
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True, cwd=root, env=env)
    return [float(v) for v in out.stdout.split()]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--samples", type=int, default=10**6)
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args()
    if not numba_available():
        sys.exit("bench_compiled: numba is not installed (pip install 'algkin[fast]')")
    cores = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count()
    print(f"{args.samples} samples from angles, best of {args.repeats}; errors against the certified reference "
          f"on {CHECKED}, in units of 2**-53")
    print(f"{'subject':22} {'strategy':20} {'ns/sample':>10} {'vs numpy':>9} {'err median':>11} {'err max':>8}")
    for name, point, targeted in SUBJECTS:
        rows = bench(name, point, args.samples, args.repeats, cores)
        base = rows[1][1]
        for label, ns, median, worst in rows:
            print(f"{name + ' ' + point:22} {label:20} {ns:10.1f} {base / ns:8.2f}x {median:11.2f} {worst:8.2f}")
        if targeted:
            one = rows[2][1]
            print(f"{'':22} target <= {TARGET_NS:.0f} ns/sample on one thread: "
                  f"{'met' if one <= TARGET_NS else 'missed'} ({one:.1f})")
    import_seconds, load_seconds = cold_costs("chebyshev-lambda", "B")
    kernel = subject("chebyshev-lambda", "B")[-2]
    print(f"fresh process: import numba {import_seconds * 1e3:.0f} ms, load the cached kernel and run it "
          f"{load_seconds * 1e3:.0f} ms; numpy's form of chebyshev-lambda B, for comparison:")
    for n in (200, 10**4, 10**5, 10**6):
        theta = np.random.default_rng(1).uniform(0, 2 * np.pi, n)
        _, seconds = timed(lambda: kernel(theta, engine="numpy"), 3)
        _, fast = timed(lambda: kernel(theta, engine="compiled"), 3)
        print(f"  {n:>8} samples: numpy {seconds * 1e3:8.2f} ms, compiled (loaded) {fast * 1e3:8.2f} ms")


if __name__ == "__main__":
    main()
