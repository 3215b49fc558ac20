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

Run: ``python benchmarks/bench_sweep.py [--count-per-axis N] [--no-atlas]``.
"""

import argparse
import importlib
import math
import os
import tempfile
import time

import distributed

from algkin.sweep import read_dataset, sweep, without_timings

FOURBARS = "curve,grashof,transmission"
ATLAS = "curve,singular,grashof"


def canonical(folder):
    """The dataset without its timing columns."""
    return without_timings(read_dataset(folder))


def timed(folder, grid, analyses, **how):
    begun = time.perf_counter()
    done = sweep("fourbar", folder, grid=grid, analyses=analyses.split(","), yes=True, **how)
    return time.perf_counter() - begun, done


def on_cluster(folder, grid, analyses, workers, name=None):
    """The sweep on a LocalCluster of ``workers`` started, algkin imported in each, before the clock."""
    with distributed.LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, host="127.0.0.1",
                                  dashboard_address=None) as cluster, distributed.Client(cluster) as client:
        client.run(importlib.import_module, "algkin.sweep.family")
        return timed(os.path.join(folder, name or f"dask{workers}"), grid, analyses, scheduler=cluster.scheduler_address)


# 4 x 5 x 5 x 10 x 10 = 10,000 four-bars: crank, coupler, rocker, and the coupler point over a grid
ATLAS_GRID = ["a=1/2:2:4", "l=2:5:5", "m=2:5:5", "p=-1:2:10", "q=-1:1:10"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count-per-axis", type=int, default=10, help="values per axis (designs: its cube)")
    parser.add_argument("--no-atlas", action="store_true", help="skip the 10,000-design atlas")
    args = parser.parse_args()
    n = args.count_per_axis
    grid = [f"a=1/2:2:{n}", f"l=2:5:{n}", f"m=2:5:{n}"]
    load = os.getloadavg()[0]
    importlib.import_module("algkin.sweep.family")  # here as in each worker: imported before any clock starts
    with tempfile.TemporaryDirectory() as scratch:
        folder = lambda name: os.path.join(scratch, name)  # noqa: E731
        shared_s, shared = timed(folder("shared"), grid, FOURBARS, executor="serial")
        alone_s, alone = timed(folder("alone"), grid, FOURBARS, executor="serial", share=False)
        assert shared.counts == alone.counts, (shared.counts, alone.counts)
        assert canonical(folder("shared")).equals(canonical(folder("alone"))), "shared and alone rows differ"
        one_s, _ = on_cluster(scratch, grid, FOURBARS, 1)
        two_s, _ = on_cluster(scratch, grid, FOURBARS, 2)
        for workers in (1, 2):
            assert canonical(folder(f"dask{workers}")).equals(canonical(folder("shared"))), f"{workers} workers differ"
        atlas = None
        if not args.no_atlas:
            atlas_s, atlas_done = on_cluster(scratch, ATLAS_GRID, ATLAS, 2, name="atlas")
            atlas = (ATLAS_GRID, atlas_s, atlas_done)
    designs = n ** 3
    print(f"sweeps of four-bars (fourbar: {', '.join(grid)}), {os.cpu_count()} cores, "
          f"load average {load:.1f} before, {os.getloadavg()[0]:.1f} after")
    print(f"{designs} designs, {FOURBARS}; by status: {shared.counts}")
    rate = lambda seconds, count=designs: count / seconds  # noqa: E731
    print(f"  serial, each design alone      {alone_s:7.1f} s  {rate(alone_s):7.1f} designs/s")
    print(f"  serial, shared (the default)   {shared_s:7.1f} s  {rate(shared_s):7.1f} designs/s  "
          f"{alone_s / shared_s:5.2f}x   same rows apart from timings: yes")
    print(f"  dask, 1 worker (started)       {one_s:7.1f} s  {rate(one_s):7.1f} designs/s")
    print(f"  dask, 2 workers (started)      {two_s:7.1f} s  {rate(two_s):7.1f} designs/s  "
          f"{one_s / two_s:5.2f}x 1 worker   same rows: yes")
    if atlas:
        axes, seconds, done = atlas
        count = math.prod(int(a.rsplit(":", 1)[1]) for a in axes)
        print(f"atlas: {count} designs ({', '.join(axes)}), {ATLAS}, 2 workers: {seconds:.1f} s "
              f"({seconds / 60:.1f} min, {rate(seconds, count):.1f} designs/s); by status: {done.counts}")


if __name__ == "__main__":
    main()
