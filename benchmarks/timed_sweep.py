"""One sweep of the catalog ``fourbar``, timed: what bench_sweep.py runs, in a fresh process, from each checkout it measures.

Started with the checkout's sources first on ``sys.path`` (``checkouts.run_python``), it drives
algkin only through its public ``algkin.sweep.sweep`` (with ``share=False`` only for each design
alone: ``--alone``), so that an older checkout runs it as well as this one, down to one whose
designs shared nothing. The family's
modules are imported before the clock starts, here and, on a Dask LocalCluster started before the
clock too, in each worker (each worker still works out the family itself, as on a cluster). It
prints one JSON line: the seconds, the designs by status, and the files algkin was imported from
here and in each worker (for the caller to check that they are the checkout's).

Run: ``python benchmarks/timed_sweep.py OUT --analyses A,B --workers N [--alone] --grid AXIS...``
(``--workers 0``: serially, in this process; ``--alone``: each design computed alone).
"""

import argparse
import importlib
import json
import time


def family_imported():
    """The file of the algkin the family's modules were imported from (in this process or a worker); a
    checkout older than the family, where each design is computed alone, has its design's module instead."""
    try:
        return importlib.import_module("algkin.sweep.family").__file__
    except ModuleNotFoundError:
        return importlib.import_module("algkin.sweep.design").__file__


def timed(out, *, grid, analyses, **how):
    """The seconds and the finished sweep of ``fourbar`` over ``grid`` into ``out``."""
    from algkin.sweep import sweep

    begun = time.perf_counter()
    done = sweep("fourbar", out, grid=grid, analyses=analyses.split(","), yes=True, **how)
    return time.perf_counter() - begun, done


def run(out, *, grid, analyses, workers, alone):
    """The sweep, serially (``workers`` 0) or on a LocalCluster of ``workers``: its seconds, counts and algkin files."""
    how = {"share": False} if alone else {}
    sources = [family_imported()]  # here as in each worker: imported before any clock starts
    if not workers:
        seconds, done = timed(out, grid=grid, analyses=analyses, executor="serial", **how)
        return {"seconds": seconds, "counts": done.counts, "algkin": sources}
    import distributed

    with distributed.LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, host="127.0.0.1",
                                  dashboard_address=None) as cluster, distributed.Client(cluster) as client:
        sources += client.run(family_imported).values()
        seconds, done = timed(out, grid=grid, analyses=analyses, scheduler=cluster.scheduler_address, **how)
    return {"seconds": seconds, "counts": done.counts, "algkin": sources}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out", help="the sweep's directory (new: a sweep into a finished one computes nothing)")
    parser.add_argument("--grid", nargs="+", required=True, help="the axes, as `algkin sweep --grid`")
    parser.add_argument("--analyses", required=True, help="comma-separated, as `algkin sweep --analyses`")
    parser.add_argument("--workers", type=int, default=0, help="Dask workers (0: serially, in this process)")
    parser.add_argument("--alone", action="store_true", help="each design computed alone (share=False)")
    arguments = parser.parse_args()
    print(json.dumps(run(arguments.out, grid=arguments.grid, analyses=arguments.analyses,
                         workers=arguments.workers, alone=arguments.alone)))


if __name__ == "__main__":
    main()
