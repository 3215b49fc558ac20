"""One design of a sweep evaluated: its row (status, the analyses' columns, timings).

A row never depends on where or when it was computed, but for its ``seconds_`` columns: the
status is ``ok``, ``does-not-assemble`` (the scene's branch cannot assemble anywhere in the
input range: ``algkin.branches.check_assembly``, the same test as ``derive``'s),
``structure`` (it assembles at isolated inputs only: no motion, no curve;
``algkin.derivation.assembles``) or ``failed`` with the one-line reason (the first analysis
that failed, named).

>>> from fractions import Fraction
>>> job = Job(load_scene("fourbar"), ("grashof",), "P")
>>> row = evaluate_design(job, 0, {"d": Fraction(10)})   # |DA| >= 9 > l + m = 6.5: B never meets
>>> row["status"], row["param_d"], row["grashof_class"]
('does-not-assemble', '10', None)
>>> evaluate_design(job, 1, {"a": Fraction(1, 2)})["grashof_class"]
'crank-rocker'
>>> evaluate_design(job, 2, {"a": Fraction(5, 6), "d": Fraction(22, 3)})["status"]  # |DA| = l + m at 0 only
'structure'
"""

from __future__ import annotations

import contextvars
import time
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from fractions import Fraction
from typing import TYPE_CHECKING, Any

from ..errors import BudgetExceeded, SceneError
from ..runtime import progress
from ..runtime.cache import BoundedCache
from ..scene import Scene, load_scene
from .analyses import ANALYSES, Analysis, Design
from .family import Family

if TYPE_CHECKING:
    from ..runtime.budget import Deadline

__all__ = ["Job", "evaluate_design", "evaluate_chunk", "columns", "TIMING_PREFIX", "REASON_CHARS", "STATUSES"]

TIMING_PREFIX = "seconds_"  # the only columns that may differ between two runs of the same sweep
STATUSES = ("ok", "does-not-assemble", "structure", "failed")  # a row's status, in the order they are counted
REASON_CHARS = 400  # a failure's reason is one line, at most this long


@dataclass(frozen=True)
class Job:
    """What every design of a sweep shares: the scene, the analyses by name, the traced point, the budget.

    The analyses themselves (``table``) are looked up where the job is made and travel with it: a
    Dask worker process has the built-in table only, not what ``register`` added in this one."""

    scene: Scene
    analyses: tuple[str, ...]
    point: str
    budget: float | None = None  # seconds per design
    # the designs' shared work done once (``algkin.sweep.family``); False: each design computed alone,
    # the reference the shared path is checked against (the same rows, timings aside)
    share: bool = True
    table: Mapping[str, Analysis] = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "table", {name: ANALYSES[name] for name in self.analyses})


def columns(job: Job, names: Sequence[str]) -> dict[str, str]:
    """Every column of a row, in order, with its Arrow type; ``names``: the swept parameters."""
    found = {"design": "int64"}
    for name in names:
        found.update({f"param_{name}": "string", f"param_{name}_float": "float64"})
    found.update({"status": "string", "reason": "string"})
    for name in job.analyses:
        found.update(job.table[name].columns)
    found.update({f"{TIMING_PREFIX}{stage}": "float64" for stage in ("assembly", *job.analyses, "total")})
    return found


def evaluate_chunk(job: Job, index: int, designs: Sequence[tuple[int, Mapping[str, Fraction]]],
                   families: BoundedCache[Family | None] | None = None) -> tuple[int, list]:
    """``(index, rows)`` of the designs ``(id, values)`` of one chunk (what a worker runs).

    ``families`` keeps, across the chunks this process evaluates, the work every design of the
    job shares (``algkin.sweep.family``); without it each design is computed alone. The analyses'
    own progress (stages, counts of samples) is shown nowhere: in this process it would replace
    the sweep's count of designs."""
    def quietly() -> tuple[int, list]:
        progress.hand_over(None)
        family = _family(job, designs, families)
        return index, [evaluate_design(job, design, values, family=family) for design, values in designs]

    return contextvars.copy_context().run(quietly)


def _family(job: Job, designs: Sequence[tuple[int, Mapping[str, Fraction]]],
            families: BoundedCache[Family | None] | None) -> Family | None:
    """The job's family in the dimensions the designs set, from ``families`` (made there the first time)."""
    if families is None or not designs or not job.share:
        return None
    names = tuple(designs[0][1])
    return families.get((job, names), lambda: Family.of(job.scene, names, job.point, analyses=job.analyses))


def evaluate_design(job: Job, design: int, values: Mapping[str, Fraction], *,
                    family: Family | None = None) -> dict[str, Any]:
    """The row of one design: its values, status, each analysis's columns and the timings; the
    same row with the ``family`` of the job's designs (what they share worked out once) or without."""
    row: dict[str, Any] = dict.fromkeys(columns(job, list(values)))
    row["design"] = design
    for name, value in values.items():
        row[f"param_{name}"], row[f"param_{name}_float"] = _exact_text(value), float(value)
    begun = time.perf_counter()
    if job.budget is None:
        found = _analyse(job, values, family=family)
    else:
        from ..runtime.budget import Budget

        deadline = Budget(seconds=job.budget).start()
        try:
            found = deadline.run(lambda: _analyse(job, values, deadline, family=family))
        except BudgetExceeded as err:
            found = {"status": "failed", "reason": _one_line(f"budget: {err}")}
    row.update(found)
    row[f"{TIMING_PREFIX}total"] = time.perf_counter() - begun
    return row


def _analyse(job: Job, values: Mapping[str, Fraction], deadline: Deadline | None = None, *,
             family: Family | None = None) -> dict[str, Any]:
    """The status, reason, analyses' columns and timings of one design (no design id, no values);
    each analysis noted on ``deadline``, if any, for the message if its time runs out."""
    begun = time.perf_counter()
    try:
        design = _assembled(job, values, family)
        found: dict[str, Any] = {"status": "ok"}
    except SceneError as err:
        found = {"status": _status_of(err), "reason": _one_line(str(err))}
    except Exception as err:  # noqa: BLE001 - a bad design is a row that says why, not a stopped sweep
        found = {"status": "failed", "reason": _one_line(f"scene: {err}")}
    found[f"{TIMING_PREFIX}assembly"] = time.perf_counter() - begun
    if found["status"] != "ok":
        return found
    for name in job.analyses:
        if deadline is not None:
            deadline.note(f"running the {name} analysis")
        begun = time.perf_counter()
        try:
            found.update(job.table[name](design))
        except Exception as err:  # noqa: BLE001 - the other analyses still run; the first failure is said
            if found["status"] == "ok":
                found.update(status="failed", reason=_one_line(f"{name}: {type(err).__name__}: {err}"))
        found[f"{TIMING_PREFIX}{name}"] = time.perf_counter() - begun
    return found


def _status_of(err: SceneError) -> str:
    """``does-not-assemble``, ``structure`` (it assembles at isolated inputs only) or ``failed``."""
    from ..derivation.assembles import STRUCTURE

    if "never assemble" in str(err):
        return "does-not-assemble"
    return "structure" if STRUCTURE in str(err) else "failed"


def _assembled(job: Job, values: Mapping[str, Fraction], family: Family | None = None) -> Design:
    """The design's scene, compiled with its dyads and sliders (SceneError if its branch never
    assembles), or with its groups of points solved together solved; from the ``family``'s
    compiled scene where it answers for the design."""
    from ..branches import check_assembly, closed_forms
    from ..derivation.assembles import where_assembled
    from ..scene import compile_scene
    from ..scene.settings import with_values

    shared = family.design(values) if family is not None else None
    if shared is not None:
        return Design(shared.scene, shared.compiled, job.point, family=family, shared=shared)

    scene = with_values(job.scene if not isinstance(job.scene, str) else load_scene(job.scene), dict(values))
    if scene.unknown_points:  # its groups solved once, for every analysis
        from ..analyses.groups.scene import prepare_groups

        return Design(scene, None, job.point, groups=prepare_groups(scene, command="sweep"))
    implicit = [n for n, p in scene.points.items() if p.labels]
    compiled = compile_scene(scene, implicit or [job.point])
    if implicit:
        branches = closed_forms(compiled)
        check_assembly(compiled, branches)
        where_assembled(compiled, branches)  # SceneError for a structure
    return Design(scene, compiled, job.point)


def _exact_text(value: Fraction) -> str:
    return str(value.numerator) if value.denominator == 1 else f"{value.numerator}/{value.denominator}"


def _one_line(text: str) -> str:
    line = " ".join(str(text).split())
    return line if len(line) <= REASON_CHARS else line[:REASON_CHARS - 3] + "..."
