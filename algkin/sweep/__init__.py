"""Sweeps: named analyses over a grid (or seeded random draws) of a scene's dimensions, to Parquet.

One row per design (``algkin.sweep.design``), computed in chunks, in this process or on Dask
(``executor``), each chunk written as a part file when done (``store``): a run stopped
anywhere resumes where it stopped, and the merged ``designs.parquet`` is the same, its
timing columns aside, whatever the executor, the number of workers or the interruptions.

>>> import tempfile
>>> folder = tempfile.mkdtemp()
>>> done = sweep("fourbar", folder, grid=["a=1/2:1:2", "d=4:10:2"], analyses=["grashof"], executor="serial")
>>> done.counts, done.computed
({'ok': 2, 'does-not-assemble': 2}, 4)
>>> table = read_dataset(folder)
>>> table.column("grashof_class").to_pylist()
['crank-rocker', None, 'crank-rocker', None]
>>> sweep("fourbar", folder, grid=["a=1/2:1:2", "d=4:10:2"], analyses=["grashof"], executor="serial").computed
0
"""

from __future__ import annotations

import hashlib
import math
import os
import pathlib
import sys
from collections.abc import Iterable
from dataclasses import dataclass, field
from fractions import Fraction
from typing import TYPE_CHECKING, Any

from ..runtime import suggest
from ..errors import UsageError
from ..runtime.budget import time_budget
from .analyses import ANALYSES, Analysis, analyses_named, applicable, register
from .design import STATUSES, TIMING_PREFIX, Job, columns
from .executor import EXECUTORS, dask_modules, run_chunks
from .grid import DRAW_SCHEME, Designs, first_repeat, grid_designs, parse_grid, parse_ranges, random_designs
from .store import DATASET, MANIFEST, done_chunks, merge, open_directory, read_dataset, read_manifest, \
    without_timings, write_part

if TYPE_CHECKING:  # the scene layer loads when a sweep is planned
    from ..scene import Scene
    from ..scene.load import SceneLike

__all__ = ["sweep", "Sweep", "plan", "ANALYSES", "Analysis", "register", "read_dataset", "read_manifest",
           "without_timings", "TIMING_PREFIX", "DATASET", "MANIFEST", "EXECUTORS", "CHUNK", "DAY",
           "projected_seconds"]

CHUNK = 8  # designs per part file (and per Dask task), by default
DAY = 86400.0  # a run projected to take longer (seconds) starts only with --yes
ASSEMBLY_SECONDS = 0.001  # assembling one design at least (a four-bar's, as the analyses' ``seconds``)


@dataclass
class Sweep:
    """A sweep run: its directory and dataset, how many designs there are and were computed now, by status."""

    out: pathlib.Path
    dataset: pathlib.Path
    designs: int
    computed: int  # in this run (the others were found done)
    counts: dict[str, int] = field(default_factory=dict)

    def to_json(self) -> dict[str, Any]:
        return {"out": str(self.out), "dataset": str(self.dataset), "designs": self.designs,
                "computed": self.computed, "status": self.counts}


@dataclass
class Plan:
    """What a sweep will compute, checked before anything is written."""

    job: Job
    designs: Designs
    manifest: dict[str, Any]
    columns: dict[str, str]
    chunk: int


def _refuse_still(scene: Scene, point: str, swept: tuple[str, ...]) -> None:
    """UsageError if ``point`` stays put whatever the swept dimensions (a ground pivot): its curve, and
    every design's, would be a point; a compile that fails here is left to each design to say."""
    from ..branches import closed_forms
    from ..derivation.curves import refuse_still
    from ..errors import SceneError
    from ..scene import compile_scene

    try:
        compiled = compile_scene(scene, [point], swept)
    except SceneError:
        return
    refuse_still(compiled, closed_forms(compiled), point)


def plan(scene: SceneLike, *, grid: Iterable[str] = (), random: int | None = None, seed: int = 0,
         analyses: Iterable[str] = ("curve",), point: str | None = None, budget: float | None = None,
         chunk: int = CHUNK, share: bool = True) -> Plan:
    """The sweep's job, designs and manifest, every argument checked (UsageError, SceneError);
    ``share``: the work every design shares done once (False: each design computed alone)."""
    from ..scene.dump import dump_scene
    from ..scene.groups import compile_groups
    from ..scene.load import as_scene

    scene = as_scene(scene)
    if scene.unknown_points:
        compile_groups(scene)  # a SceneError for bad groups, whatever the analyses
    chosen = tuple(a.name for a in analyses_named(analyses))
    applicable(chosen, solved_together=bool(scene.unknown_points))
    grid = list(grid)
    space: dict[str, Any]
    if random is None:
        axes = parse_grid(grid)
        designs, space = grid_designs(axes), {"grid": {n: [_text(v) for v in vs] for n, vs in axes.items()}}
    else:
        ranges = parse_ranges(grid)
        designs = random_designs(ranges, random, seed)
        space = {"random": {"count": random, "seed": seed, "scheme": DRAW_SCHEME,
                            "ranges": {n: [_text(lo), _text(hi)] for n, (lo, hi) in ranges.items()}}}
    for name in designs[0]:
        if name not in scene.parameters:
            raise UsageError("grid", name, f"not a parameter of {scene.name}"
                             + suggest.known(name, scene.parameters, plural="parameters"))
    point = point or list(scene.points)[-1]
    if point not in scene.points:
        raise UsageError("point", point, f"not a point of {scene.name} (points: {', '.join(scene.points)})")
    if {"curve", "singular"} & set(chosen) and not scene.unknown_points:
        _refuse_still(scene, point, tuple(designs[0]))
    if budget is not None:
        time_budget(budget, "budget")
    if not isinstance(chunk, int) or chunk < 1:
        raise UsageError("chunk", chunk, "must be a whole number of designs from 1")
    toml = dump_scene(scene)
    # the package's version from the facade, loaded before any of its subpackages (importing it
    # here would be an import of the facade's lazy names, the layers above, for the linter)
    version = sys.modules["algkin"].__version__
    manifest = {"algkin": version, "scene": {"name": scene.name, "toml": toml,
                                                 "sha256": hashlib.sha256(toml.encode()).hexdigest()},
                "designs": space, "analyses": list(chosen), "point": point, "budget": budget, "chunk": chunk,
                "count": len(designs)}
    job = Job(scene, chosen, point, budget, share=share)
    return Plan(job, designs, manifest, columns(job, list(designs[0])), chunk)


def sweep(scene: SceneLike, out: str | pathlib.Path, *, grid: Iterable[str] = (), random: int | None = None, seed: int = 0,
          analyses: Iterable[str] = ("curve",), point: str | None = None, executor: str = "dask",
          workers: int | None = None, scheduler: str | None = None, budget: float | None = None,
          chunk: int = CHUNK, yes: bool = False, share: bool = True) -> Sweep:
    """Run (or resume) the sweep into the directory ``out``; its merged dataset is ``out/designs.parquet``.

    A run projected to take longer than ``DAY`` (``projected_seconds``) is refused before it starts,
    unless ``yes``. The designs share what they can, worked out once (``algkin.sweep.family``: the
    scene compiled with the swept dimensions symbolic, the generic curve specialised); with ``share``
    False each is computed alone, as a check: the dataset is the same, its timings aside."""
    from ..runtime import progress

    planned = plan(scene, grid=grid, random=random, seed=seed, analyses=analyses, point=point, budget=budget,
                   chunk=chunk, share=share)
    _check_executor(executor, workers, scheduler)
    manifest = _manifest_in(out, planned)
    open_directory(out, manifest, check_only=True)
    done = done_chunks(out)
    total = len(planned.designs)
    chunks = [k for k in range(math.ceil(total / chunk)) if k not in done]
    computed = sum(min((k + 1) * chunk, total) - k * chunk for k in chunks)
    if not yes:  # counted, not made: a run refused here has made no design
        _check_length(planned, computed, _parallel(executor, workers, scheduler))
    pending = [(k, [(d, planned.designs[d]) for d in range(k * chunk, min((k + 1) * chunk, total))]) for k in chunks]
    progress.stage(f"sweeping {total} designs, {total - computed} done before")
    with progress.counting(computed, "designs"):
        def written(index: int, rows: list) -> None:
            write_part(out, index, rows, planned.columns)
            for _ in rows:
                progress.step()

        run_chunks(planned.job, pending, written, executor, workers, scheduler,
                   ready=lambda: open_directory(out, manifest))
    dataset = merge(out, planned.columns)
    statuses = read_dataset(out).column("status").to_pylist()
    counts = {s: statuses.count(s) for s in STATUSES if s in statuses}
    return Sweep(pathlib.Path(out), dataset, total, computed, counts)


def _manifest_in(out: str | pathlib.Path, planned: Plan) -> dict[str, Any]:
    """The manifest the sweep in ``out`` must have to be resumed: the planned one, or the folder's own
    when it holds these random designs drawn by the first draw scheme, which are this one's where
    none repeats. Where one does, the designs differ from it on: resuming would mix the two draws,
    and is refused."""
    found = read_manifest(out, argument="out")
    drawn = found.get("designs") if found is not None else None
    older = drawn.get("random") if isinstance(drawn, dict) else None
    if found is None or not isinstance(older, dict) or "scheme" in older:
        return planned.manifest  # not a random sweep of the first scheme: compared as it is
    if dict(found, designs={"random": dict(older, scheme=DRAW_SCHEME)}) != planned.manifest:
        return planned.manifest  # another sweep anyway: said so as any other
    space = planned.manifest["designs"]["random"]
    ranges = {name: (Fraction(lo), Fraction(hi)) for name, (lo, hi) in space["ranges"].items()}
    repeat = first_repeat(ranges, space["count"], space["seed"])
    if repeat is not None:
        raise UsageError("out", str(out), f"holds a sweep begun by an older algkin, whose random designs repeat "
                                          f"(design {repeat} repeats an earlier one) where this one draws distinct "
                                          "designs: resuming it would mix the two draws; give a new directory")
    return found


def projected_seconds(analyses: Iterable[str], designs: int, budget: float | None = None, parallel: int = 1) -> float:
    """How long ``designs`` designs take at least: each its assembly and analyses' ``seconds`` (no more than
    its ``budget``), ``parallel`` at once.

    >>> projected_seconds(["curve", "limits"], 10**6, parallel=2) / DAY   # (0.001 + 0.005 + 0.2) s each
    1.1921296296296298
    >>> projected_seconds(["curve", "limits"], 10**6, budget=0.1, parallel=2) / DAY
    0.5787037037037037
    """
    each = ASSEMBLY_SECONDS + sum(ANALYSES[name].seconds for name in analyses)
    return designs * (each if budget is None else min(each, budget)) / parallel


def _parallel(executor: str, workers: int | None, scheduler: str | None) -> int:
    """Designs computed at once: the LocalCluster's workers (one a core by default); one in this process,
    and one on a scheduler's cluster, whose size is not known before connecting."""
    if executor != "dask" or scheduler is not None:
        return 1
    return workers or os.cpu_count() or 1


def _check_length(planned: Plan, count: int, parallel: int) -> None:
    seconds = projected_seconds(planned.job.analyses, count, planned.job.budget, parallel)
    if seconds <= DAY:
        return
    space = planned.manifest["designs"]
    argument, value = ("random", space["random"]["count"]) if "random" in space else \
        ("grid", " ".join(f"{n}={v[0]}:{v[-1]}:{len(v)}" for n, v in space["grid"].items()))
    raise UsageError(argument, value, f"{count} designs would take at least {_duration(seconds)} "
                                  f"({_duration(seconds * parallel / count)} each, {parallel} at once); "
                                  "confirm with yes to start anyway")


def _duration(seconds: float) -> str:
    """``2.5 days``, ``3.1 hours``, ``0.27 s``: a length of time, readable."""
    for unit, size in (("days", DAY), ("hours", 3600.0)):
        if seconds >= size:
            return f"{seconds / size:.3g} {unit}"
    return f"{seconds:.2g} s"


def _check_executor(executor: str, workers: int | None, scheduler: str | None) -> None:
    if executor not in EXECUTORS:
        raise UsageError("executor", executor, "unknown" + suggest.known(str(executor), EXECUTORS, plural="valid"))
    if workers is not None and (executor != "dask" or scheduler is not None):
        raise UsageError("workers", workers, "sizes the LocalCluster: only for the dask executor without a scheduler")
    if scheduler is not None and executor != "dask":
        raise UsageError("scheduler", scheduler, "is for the dask executor only")
    if workers is not None and not 1 <= workers <= 256:
        raise UsageError("workers", workers, "expected a number of worker processes from 1 to 256")
    if executor == "dask":
        dask_modules()  # missing, it is a usage error before anything is written


def _text(value: Fraction) -> str:
    return str(value.numerator) if value.denominator == 1 else f"{value.numerator}/{value.denominator}"
