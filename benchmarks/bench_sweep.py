"""A sweep of 1,000 four-bars, serial against a 2-worker Dask LocalCluster on this machine.

The grid: the catalog ``fourbar``'s crank ``a``, coupler ``l`` and rocker ``m`` over 10 exact
values each (the ground ``d`` and the coupler point at their defaults), with the analyses
``curve`` (the coupler curve, eliminated and verified), ``grashof`` and ``transmission`` (the
transmission angle's extremes). Both runs write their own directory; the two datasets are
asserted equal apart from the timing columns (byte for byte once those are dropped), and the
wall times and their ratio are printed. The LocalCluster's start-up (worker processes,
algkin imported in each) is inside the timed run, as a user would pay it.

Beside the wall times: the designs' own seconds summed (the ``seconds_total`` column) over
the wall time, how many designs were being computed at once on average (1 at most serially,
2 at most on two workers, less by the cluster's start-up and idle ends), and the machine's
load average before and after: on a machine shared with other work the two workers get less
than two cores (Linux shares the CPU between sessions first), and the speed-up with them.

Run: ``python benchmarks/bench_sweep.py [--count-per-axis N] [--workers W] [--analyses A,B]``.
"""

import argparse
import io
import os
import tempfile
import time

import pyarrow.parquet as pq

from algkin.sweep import read_dataset, sweep, without_timings


def canonical(folder):
    """The dataset without its timing columns, as Parquet bytes."""
    buffer = io.BytesIO()
    pq.write_table(without_timings(read_dataset(folder)), buffer)
    return buffer.getvalue()


def timed(folder, grid, analyses, **executor):
    begun = time.perf_counter()
    done = sweep("fourbar", folder, grid=grid, analyses=analyses, **executor)
    return time.perf_counter() - begun, done


def busy(folder, wall):
    """The designs' own seconds summed, over the wall time: designs computed at once, on average."""
    return sum(read_dataset(folder).column("seconds_total").to_pylist()) / wall


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count-per-axis", type=int, default=10, help="values per axis (designs: its cube)")
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--analyses", default="curve,grashof,transmission")
    args = parser.parse_args()
    n = args.count_per_axis
    grid = [f"a=1/2:2:{n}", f"l=2:5:{n}", f"m=2:5:{n}"]
    analyses = args.analyses.split(",")
    load = os.getloadavg()[0]
    with tempfile.TemporaryDirectory() as scratch:
        serial_dir, dask_dir = os.path.join(scratch, "serial"), os.path.join(scratch, "dask")
        serial_s, serial = timed(serial_dir, grid, analyses, executor="serial")
        dask_s, distributed = timed(dask_dir, grid, analyses, executor="dask", workers=args.workers)
        assert serial.counts == distributed.counts, (serial.counts, distributed.counts)
        assert canonical(serial_dir) == canonical(dask_dir), "the two datasets differ beyond their timings"
        assert serial.designs == n ** 3 and serial.computed == distributed.computed == n ** 3
        at_once = busy(serial_dir, serial_s), busy(dask_dir, dask_s)
    print(f"sweep of {n ** 3} four-bars (fourbar: {', '.join(grid)}; analyses {', '.join(analyses)}), "
          f"{os.cpu_count()} cores, load average {load:.1f} before, {os.getloadavg()[0]:.1f} after")
    print(f"designs by status: {serial.counts}")
    print(f"serial                        {serial_s:8.1f} s  ({1000 * serial_s / n ** 3:.0f} ms/design, "
          f"{at_once[0]:.2f} designs at once)")
    print(f"dask LocalCluster, {args.workers} workers   {dask_s:8.1f} s  (start-up included, "
          f"{at_once[1]:.2f} designs at once)")
    print(f"speed-up                      {serial_s / dask_s:8.2f}x   same dataset apart from timings: yes")


if __name__ == "__main__":
    main()
