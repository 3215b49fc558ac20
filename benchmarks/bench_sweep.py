"""Sweeps of four-bars: designs a second, the shared path against each design alone, 1 and 2 workers, an atlas.

Three measurements, each from this one run:

1. **Shared against alone.** 1,000 designs of the catalog ``fourbar`` (crank ``a``, coupler
   ``l`` and rocker ``m`` over 10 exact values each) with the analyses ``curve``, ``grashof``
   and ``transmission``, serially: once as a sweep runs by default (the scene compiled once
   with the swept dimensions symbolic, the generic curve specialised: ``algkin.sweep.family``)
   and once with each design computed alone (``share=False``, the path before it). The two
   datasets are asserted equal apart from their timing columns, and the designs a second of
   each and their ratio printed.
2. **Workers.** The same sweep on a Dask LocalCluster of 1 worker and of 2, each cluster
   started and algkin imported in each worker before its clock starts (as in this process before
   the serial runs; each worker still works out the family itself, as on a cluster): designs a
   second and the ratio of 2 workers to 1.
   Both datasets equal the serial one.
3. **An atlas** of 10,000 four-bars (``--no-atlas`` skips it): coupler curves with their real
   singular points (``curve,singular,grashof``) over ``a``, ``l``, ``m`` and the coupler point
   ``p``, ``q``, on 2 workers: its wall time and designs a second.

The machine's load average is printed before and after: on a machine shared with other work
two workers get less than two cores (Linux shares the CPU between sessions first), and the
speed-up with them.

Each sweep runs in a fresh process (``timed_sweep.py``), its clock started after algkin is
imported there and in its workers. ``--against DIR`` runs each from another checkout's sources
too (``git archive <commit> | tar -x -C DIR``; any checkout whose ``algkin.sweep.sweep`` takes
``share``), in the same rounds, the two one after the other: it prints each checkout's table, then
this one's designs a second against the other's and the two datasets' rows compared, a change's
before and after from one run. ``--repeats N`` runs each sweep N times, in turn, and prints the
medians; ``--quick`` leaves out the sweep of each design alone and the atlas (minutes each).

Run: ``python benchmarks/bench_sweep.py [--count-per-axis N] [--no-atlas] [--quick] [--repeats N]
[--against DIR]``.
"""


import argparse
import json
import math
import os
import statistics
import tempfile
from pathlib import Path

from checkouts import add_against, describe, measured, run_python

from algkin.sweep import read_dataset, without_timings

FOURBARS = "curve,grashof,transmission"
ATLAS = "curve,singular,grashof"
# 4 x 5 x 5 x 10 x 10 = 10,000 four-bars: crank, coupler, rocker, and the coupler point over a grid
ATLAS_GRID = ["a=1/2:2:4", "l=2:5:5", "m=2:5:5", "p=-1:2:10", "q=-1:1:10"]
TIMED = Path(__file__).resolve().parent / "timed_sweep.py"
LABELS = {"alone": "serial, each design alone", "shared": "serial, shared (the default)",
          "dask1": "dask, 1 worker (started)", "dask2": "dask, 2 workers (started)", "atlas": "atlas, 2 workers"}


def canonical(folder):
    """The dataset without its timing columns."""
    return without_timings(read_dataset(folder))


def sweeps(grid, *, alone, atlas):
    """The sweeps measured, by name, in the order each round runs them: (grid, analyses, workers, alone)."""
    chosen = {"shared": (grid, FOURBARS, 0, False)}
    if alone:
        chosen["alone"] = (grid, FOURBARS, 0, True)
    chosen.update(dask1=(grid, FOURBARS, 1, False), dask2=(grid, FOURBARS, 2, False))
    if atlas:
        chosen["atlas"] = (ATLAS_GRID, ATLAS, 2, False)
    return chosen


def timed(root, out, sweep):
    """One sweep timed in a fresh process from ``root``'s sources: its seconds and its designs by status."""
    grid, analyses, workers, alone = sweep
    arguments = [TIMED, out, "--analyses", analyses, "--workers", workers, *(["--alone"] if alone else []),
                 "--grid", *grid]
    result = json.loads(run_python(root, arguments).stdout.splitlines()[-1])
    strays = [source for source in result["algkin"] if not Path(source).is_relative_to(root)]
    if strays:  # an installed algkin found before root's sources would measure the wrong checkout
        raise RuntimeError(f"algkin imported from {strays[0]}, not from {root}")
    return result["seconds"], result["counts"]


def measure(roots, chosen, *, repeats, scratch):
    """Per (root, sweep name), the seconds of its runs and its counts; the roots in turn, sweep by sweep."""
    seconds = {(root, name): [] for root in roots for name in chosen}
    counts = {}
    for round_ in range(repeats):
        for name, sweep in chosen.items():
            for index, root in enumerate(roots):
                spent, counts[root, name] = timed(root, folder(scratch, index, name, round_), sweep)
                seconds[root, name].append(spent)
    return seconds, counts


def folder(scratch, index, name, round_=0):
    """Where the root numbered ``index`` writes the sweep ``name`` in round ``round_`` (a new directory each)."""
    return os.path.join(scratch, f"{index}-{name}-{round_}")


def check_rows(scratch, index, chosen, counts):
    """Assert what each design alone and each cluster wrote equal to the serial shared dataset, timings aside."""
    shared = canonical(folder(scratch, index, "shared"))
    for name in ("alone", "dask1", "dask2"):
        if name in chosen:
            assert counts[name] == counts["shared"], (name, counts[name], counts["shared"])
            assert canonical(folder(scratch, index, name)).equals(shared), f"{name} and shared rows differ"


def print_table(seconds, counts, designs):
    """One checkout's designs a second, as the bench has always printed them."""
    rate = lambda spent, count=designs: count / spent  # noqa: E731
    line = lambda name: f"  {LABELS[name]:30} {seconds[name]:7.1f} s  {rate(seconds[name]):7.1f} designs/s"  # noqa: E731
    print(f"{designs} designs, {FOURBARS}; by status: {counts['shared']}")
    if "alone" in seconds:
        print(line("alone"))
        print(f"{line('shared')}  {seconds['alone'] / seconds['shared']:5.2f}x   same rows apart from timings: yes")
    else:
        print(line("shared"))
    print(line("dask1"))
    print(f"{line('dask2')}  {seconds['dask1'] / seconds['dask2']:5.2f}x 1 worker   same rows: yes")
    if "atlas" in seconds:
        spent, count = seconds["atlas"], math.prod(int(axis.rsplit(":", 1)[1]) for axis in ATLAS_GRID)
        print(f"atlas: {count} designs ({', '.join(ATLAS_GRID)}), {ATLAS}, 2 workers: {spent:.1f} s "
              f"({spent / 60:.1f} min, {rate(spent, count):.1f} designs/s); by status: {counts['atlas']}")


def print_against(before, after, *, same_rows):
    """This checkout's designs a second over the other's, per sweep (the ratio of the median seconds; with
    several rounds, the range of each round's ratio beside it), and its rows compared."""
    print("  (designs a second: this checkout's over the other's" +
          (", the range of each round's ratio beside it)" if len(after["shared"]) > 1 else ")"))
    for name in before:
        ratios = [earlier / later for earlier, later in zip(before[name], after[name])]
        spread = f" ({min(ratios):.2f}-{max(ratios):.2f})" if len(ratios) > 1 else ""
        note = f"   same rows apart from timings: {'yes' if same_rows else 'NO'}" if name == "shared" else ""
        print(f"  {LABELS[name]:30} {median(before, name) / median(after, name):5.2f}x{spread}{note}")
    speedups = [median(runs, "dask1") / median(runs, "dask2") for runs in (before, after)]
    print(f"  {'2 workers over 1':30} {speedups[0]:.2f}x before, {speedups[1]:.2f}x after")


def median(runs, name):
    """The median seconds of the sweep ``name``'s runs."""
    return statistics.median(runs[name])


def parse(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count-per-axis", type=int, default=10, help="values per axis (designs: its cube)")
    parser.add_argument("--no-atlas", action="store_true", help="skip the 10,000-design atlas")
    parser.add_argument("--quick", action="store_true", help="skip the atlas and the sweep of each design alone")
    parser.add_argument("--repeats", type=int, default=1, help="runs of each sweep, in turn; medians printed")
    add_against(parser)
    return parser.parse_args(argv)


def main(argv=None):
    arguments = parse(argv)
    n = arguments.count_per_axis
    grid = [f"a=1/2:2:{n}", f"l=2:5:{n}", f"m=2:5:{n}"]
    chosen = sweeps(grid, alone=not arguments.quick, atlas=not (arguments.quick or arguments.no_atlas))
    roots = measured(arguments.against)
    load = os.getloadavg()[0]
    with tempfile.TemporaryDirectory() as scratch:
        seconds, counts = measure(roots, chosen, repeats=arguments.repeats, scratch=scratch)
        tables = [({name: seconds[root, name] for name in chosen}, {name: counts[root, name] for name in chosen})
                  for root in roots]
        for index, (_, root_counts) in enumerate(tables):
            check_rows(scratch, index, chosen, root_counts)
        same_rows = canonical(folder(scratch, 0, "shared")).equals(canonical(folder(scratch, len(roots) - 1, "shared")))
    repeated = f"; the median of {arguments.repeats} runs of each, taken in turn" if arguments.repeats > 1 else ""
    print(f"sweeps of four-bars (fourbar: {', '.join(grid)}), {os.cpu_count()} cores, "
          f"load average {load:.1f} before, {os.getloadavg()[0]:.1f} after{repeated}")
    for root, (root_seconds, root_counts) in zip(roots, tables):
        if arguments.against:
            print(f"\nalgkin from {describe(root)}:")
        print_table({name: median(root_seconds, name) for name in chosen}, root_counts, n ** 3)
    if arguments.against:
        print(f"\nthis checkout against {arguments.against}:")
        print_against(tables[0][0], tables[1][0], same_rows=same_rows)


if __name__ == "__main__":
    main()
