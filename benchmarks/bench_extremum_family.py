"""The four-bar's transmission angle extremes per design: ``extremum`` against a family's ``at``.

A sweep's ``transmission`` analysis asks ``extremum(scene, "angle(A, B, D)")`` of every design
(the catalog ``fourbar`` with the design's exact dimensions): it prepares, derives and
eliminates with sympy each time. ``extremum_family`` derives the scene once with ``a, d, l, m``
symbolic; ``at`` instantiates a design from python-flint forms. Both are timed here on the
same designs in one run (the scenes with the values built before the clock starts), their
answers asserted equal: every critical point's kind, input and value (to 1e-12 degrees),
and the ``exact`` forms as text. The grid mixes Grashof crank-rockers and double cranks with
non-Grashof designs whose extremes lie at dead centres; designs that never assemble are
left out, as a sweep leaves them out.

Printed: the family's one-time cost, the milliseconds a design for each way (median and
mean), their ratio, and how many designs the family computed the old way (``fell_back``).

Run: ``python benchmarks/bench_extremum_family.py [--designs N]``.
"""

import argparse
import itertools
import statistics
import time
from fractions import Fraction

from algkin.analyses.extremum import extremum
from algkin.analyses.extremum.family import extremum_family
from algkin.errors import AlgkinError
from algkin.scene.load import load_scene
from algkin.scene.settings import with_values

OUTPUT = "angle(A, B, D)"
PARAMS = ["a", "d", "l", "m"]


def grid(count):
    """``count`` designs (a, d, l, m) that assemble somewhere, in a fixed order."""
    steps = [Fraction(k, 4) for k in range(2, 19)]
    designs = []
    for a, d, l, m in itertools.product(steps[:6], steps[8:14:2], steps[4:12:3], steps[6:14:3]):
        longest, others = max(a, d, l, m), a + d + l + m - max(a, d, l, m)
        if longest < others and abs(d - a) < l + m:  # a quadrilateral; |AD| <= l + m at theta = 0 or 180
            designs.append(dict(zip(PARAMS, (a, d, l, m))))
    return designs[:: max(1, len(designs) // count)][:count]


def same(found, expected):
    assert len(found.critical_points) == len(expected.critical_points)
    for got, want in zip(found.critical_points, expected.critical_points):
        assert got.kind == want.kind
        assert abs(float(got.input_deg) - float(want.input_deg)) <= 1e-12
        assert (got.value != got.value and want.value != want.value) or abs(float(got.value - want.value)) <= 1e-12
    assert {k: tuple(map(str, v)) for k, v in found.exact.items()} == \
        {k: tuple(map(str, v)) for k, v in expected.exact.items()}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--designs", type=int, default=50)
    args = parser.parse_args()
    scene = load_scene("fourbar")
    begun = time.perf_counter()
    family = extremum_family("fourbar", OUTPUT, PARAMS)
    setup = time.perf_counter() - begun
    before, after, kept = [], [], 0
    for values in grid(args.designs):
        fixed = with_values(scene, values)
        begun = time.perf_counter()
        try:
            expected = extremum(fixed, OUTPUT)
        except AlgkinError:
            continue  # it does not assemble on the range: a sweep skips it
        before.append(time.perf_counter() - begun)
        begun = time.perf_counter()
        found = family.at(values)
        after.append(time.perf_counter() - begun)
        same(found, expected)
        kept += 1
    ms = lambda xs: (1000 * statistics.median(xs), 1000 * statistics.mean(xs))  # noqa: E731
    print(f"designs: {kept} (all answers equal); family derived once in {1000 * setup:.1f} ms; "
          f"{family.fell_back} computed the old way")
    print(f"extremum(...)   median {ms(before)[0]:7.2f} ms, mean {ms(before)[1]:7.2f} ms a design")
    print(f"family.at(...)  median {ms(after)[0]:7.2f} ms, mean {ms(after)[1]:7.2f} ms a design")
    print(f"speed-up: {ms(before)[1] / ms(after)[1]:.1f}x (means)")


if __name__ == "__main__":
    main()
