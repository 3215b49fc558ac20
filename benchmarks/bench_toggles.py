"""The toggles' artefacts: each eliminant's discriminant and its factors, python-flint against sympy.

``algkin toggles`` factors the discriminant of every eliminant of degree 2 or more in its unknown
(the dimensions put in) to report the factors that are not toggles. It did so with sympy's
``discriminant`` and ``factor_list``; ``analyses.toggles.discriminant_factors`` does it in
python-flint and gives sympy's factors in sympy's order. For each eliminant of the scene, this
times the two once each (sympy's takes most of a minute on a six-bar), checks that they give
the same factors, and prints the ratio.

Run: ``python benchmarks/bench_toggles.py [--scene NAME]`` (default ``stephenson-iii``).
"""

import argparse
import time

import sympy

import algkin
from algkin.analyses.toggles import discriminant_factors
from algkin.system import symbol


def sympys(polynomial, unknown, values):
    """The factors the way toggles found them before: sympy's discriminant, then its factor_list."""
    discriminant = sympy.expand(sympy.discriminant(polynomial, unknown).xreplace(values))
    return [factor for factor, _ in sympy.factor_list(discriminant)[1]]


def timed(function, *args):
    start = time.perf_counter()
    answer = function(*args)
    return time.perf_counter() - start, answer


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", default="stephenson-iii")
    scene = parser.parse_args().scene
    prepared = algkin.prepare(scene)
    compiled = prepared.compiled
    values = {symbol(n): compiled.parameter_values[n] for n in compiled.system.parameters}
    derived = algkin.derive(prepared, samples=0, certify=False)
    print(f"{scene}: each eliminant's discriminant factored, once each")
    print(f"{'eliminant':>10} {'degree':>6} {'factors':>7} {'sympy s':>9} {'flint s':>9} {'ratio':>8}")
    totals = [0.0, 0.0]
    for name, elimination in derived.eliminations.items():
        unknown = symbol(name)
        degree = int(sympy.degree(elimination.polynomial, unknown))
        if degree < 2:
            continue
        slow, expected = timed(sympys, elimination.polynomial, unknown, values)
        fast, found = timed(discriminant_factors, elimination.polynomial, unknown, values)
        assert [str(f) for f in found] == [str(f) for f in expected], name
        totals[0] += slow
        totals[1] += fast
        print(f"{name:>10} {degree:>6} {len(found):>7} {slow:>9.3f} {fast:>9.3f} {slow / fast:>7.0f}x")
    print(f"{'all':>10} {'':>6} {'':>7} {totals[0]:>9.3f} {totals[1]:>9.3f} {totals[0] / totals[1]:>7.0f}x")


if __name__ == "__main__":
    main()
