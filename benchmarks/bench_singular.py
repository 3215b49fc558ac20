"""Singular points of four-bar coupler curves: their cost per design, beside a Gröbner baseline.

For random four-bars (rational dimensions, a seed), the coupler curve of P comes from
``algkin.curve`` (timed on its own, no verification samples); then its singular points come from
``singular_points`` (resultants and gcds over number fields in python-flint) and, as the
baseline on the same curve, from sympy's lex Gröbner basis of ``(F, F_x, F_y)`` (to its
x-eliminant only). The run asserts they agree: the number of real singular points equals the
number of real roots of the eliminant's squarefree part, and all singular points, complex ones
too, its degree. It prints the median time per design of each, the ratio, and the share of the
whole (curve + singular points) the singular points take.

Run: ``python benchmarks/bench_singular.py [--designs N] [--seed S]``.
"""

import argparse
import random
import statistics
import time
from fractions import Fraction

import sympy

import algkin
from algkin.errors import SceneError
from algkin.analyses.singular import singular_points


def designs(seed):
    """Random four-bars: bars in [1/2, 6] (eighths), the coupler point in [-2, 2]² (quarters)."""
    draw = random.Random(seed)
    bar = lambda: str(Fraction(draw.randint(4, 48), 8))  # noqa: E731
    point = lambda: str(Fraction(draw.randint(-8, 8), 4))  # noqa: E731
    while True:
        yield {"a": bar(), "d": bar(), "l": bar(), "m": bar(), "p": point(), "q": point()}


def coupler_curves(count, seed):
    """``count`` coupler curves with their time, skipping the designs that cannot assemble."""
    skipped = 0
    for values in designs(seed):
        start = time.perf_counter()
        try:
            curve = algkin.curve("fourbar", "P", set=values, samples=0)
        except SceneError:
            skipped += 1
            continue
        yield values, curve, time.perf_counter() - start, skipped
        count -= 1
        if not count:
            return


def groebner_baseline(polynomial):
    """(real roots, degree) of the squarefree x-eliminant of (F, F_x, F_y), by sympy's groebner."""
    px, py = sorted(polynomial.free_symbols, key=str)
    basis = sympy.groebner([polynomial, polynomial.diff(px), polynomial.diff(py)], py, px, order="lex")
    eliminant = sympy.Poly(basis.exprs[-1], px)
    if eliminant.is_ground:
        return 0, 0
    squarefree = sympy.Poly(sympy.quo(eliminant, sympy.gcd(eliminant, eliminant.diff(px))), px)
    return len(squarefree.real_roots()), squarefree.degree()


def shear_free(found):
    """Whether every singular point has its own x: then the x-eliminant has one root per point."""
    return all(p.representation["shear"] == 0 for p in found.points) and \
        all(c["representation"]["shear"] == 0 for c in found.complex)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--designs", type=int, default=60)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    curve_times, ours, theirs, kinds, skipped = [], [], [], {}, 0
    for values, curve, seconds, skipped in coupler_curves(args.designs, args.seed):
        curve_times.append(seconds)
        start = time.perf_counter()
        found = singular_points(curve)
        ours.append(time.perf_counter() - start)
        start = time.perf_counter()
        real, total = groebner_baseline(found.curve)
        theirs.append(time.perf_counter() - start)
        if shear_free(found):  # points sharing an x are one root of the eliminant: compare where they do not
            assert len(found.points) == real, (values, found.to_json())
            assert len(found.points) + sum(c["count"] for c in found.complex) == total, (values, found.to_json())
        for p in found.points:
            kinds[p.kind] = kinds.get(p.kind, 0) + 1
    ours_med, theirs_med, curve_med = (statistics.median(t) for t in (ours, theirs, curve_times))
    print(f"{args.designs} random four-bars (seed {args.seed}; {skipped} more drawn could not assemble), "
          "coupler curve of P:")
    print(f"  curve (algkin.curve, no samples)      median {curve_med * 1e3:8.2f} ms")
    print(f"  singular points (flint, number fields) median {ours_med * 1e3:8.2f} ms   max {max(ours) * 1e3:.2f} ms")
    print(f"  baseline: sympy lex Groebner basis    median {theirs_med * 1e3:8.2f} ms")
    print(f"  speed-up over the baseline: {theirs_med / ours_med:.1f}x; singular points are "
          f"{ours_med / (ours_med + curve_med):.0%} of curve + singular points")
    print(f"  real singular points found: {dict(sorted(kinds.items()))}")


if __name__ == "__main__":
    main()
