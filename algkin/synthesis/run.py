"""``synthesize``: a task solved completely, each real solution made a four-bar and checked.

Motion generation with five poses makes a four-bar of every two real Burmester pairs; function
and path generation one of each real solution. Each four-bar is written as a scene, solved by
algkin at every precision position and its defects certified (``check``). Four poses give the
centre-point and circle-point curves (a one-parameter family of dyads), and no four-bar.
"""

from __future__ import annotations

import functools
import itertools
import numbers
import os
import time
from collections.abc import Callable, Sequence
from typing import Any, Union

import attrs
import flint

from ..errors import UsageError
from ..runtime import validation
from ..runtime.budget import Budget, Deadline, started
from ..runtime.frozen import FrozenDict, frozen
from ..runtime.exclusive import one_at_a_time
from .check import MIN_TRANSMISSION, Checked, check_design
from .data import Angle, Point, Pose
from .files import Task, read_task
from .fourbar import BITS, FourBar, Position, safe_name
from .function import FreudensteinSolution, FunctionSynthesis, freudenstein
from .motion import BurmesterPair, FivePoses, FourPoses, burmester, curves
from .path import PathSolution, PathSynthesis, path_synthesis

__all__ = ["synthesize", "Synthesis", "SynthesizedMechanism", "DIGITS"]

DIGITS = 30
"""Significant digits of the numbers a synthesis reports, by default."""
Result = Union[FourPoses, FivePoses, FunctionSynthesis, PathSynthesis]
Ball2 = tuple[flint.arb, flint.arb]


@attrs.frozen
class SynthesizedMechanism:
    """A four-bar made of the kind's real ``solutions`` (their indexes: two Burmester pairs, or
    one solution), its ``design`` and how it ``checked``."""

    solutions: tuple[int, ...]
    design: FourBar
    checked: Checked

    def to_json(self, *, digits: int) -> dict[str, Any]:
        lengths = {k: _text(v, digits) for k, v in self.design.lengths().items()}
        return {"solutions": list(self.solutions), "scene": self.design.name + ".toml", "lengths": lengths,
                **self.checked.to_json()}


@attrs.frozen
class Synthesis:
    """A task's answer: the ``result`` of its kind, the ``mechanisms`` made of it, the seconds each
    stage took (``timings``), and the digits numbers are shown to."""

    task: Task
    result: Result
    mechanisms: tuple[SynthesizedMechanism, ...]
    timings: FrozenDict[str, float] = attrs.field(converter=frozen)
    digits: int = DIGITS

    def scenes(self) -> dict[str, str]:
        """Each mechanism's scene file: its name -> its TOML text."""
        return {m.design.name + ".toml": m.checked.scene for m in self.mechanisms}

    def to_json(self) -> dict[str, Any]:
        document: dict[str, Any] = {"kind": self.task.kind, "name": self.task.name,
                                    "approximate_angles": self.task.approximate}
        document.update(_KIND_JSON[type(self.result)](self.result, self.digits))
        document["mechanisms"] = [m.to_json(digits=self.digits) for m in self.mechanisms]
        if isinstance(self.result, FivePoses):  # each four-bar's two Burmester pairs, crank's first
            for shown, mechanism in zip(document["mechanisms"], self.mechanisms):
                shown["pairs"] = [document["burmester"][j] for j in mechanism.solutions]
        document["usable"] = sum(m.checked.usable for m in self.mechanisms)
        document["timings"] = dict(self.timings)
        return document


@one_at_a_time
def synthesize(task: Task | str | os.PathLike[str], *, bits: int = 128, digits: int = DIGITS,
               min_transmission: float = MIN_TRANSMISSION, budget: Budget | Deadline | None = None) -> Synthesis:
    """Solve ``task`` (a Task, or a synthesis file's path or example's name) completely: its real
    solutions in balls of ``bits`` bits, shown to ``digits`` digits, each four-bar made of them
    checked, defects judged with transmission angles kept within [``min_transmission``, 180 -
    it]. A ``Budget`` (or the ``Deadline`` of one running) bounds the time."""
    if isinstance(bits, bool) or not isinstance(bits, numbers.Integral) or not 64 <= bits <= 4096:
        raise UsageError("bits", bits, "expected a whole number of bits in [64, 4096]")
    bits = int(bits)  # numpy's integers too
    if isinstance(digits, bool) or not isinstance(digits, numbers.Integral) or not 1 <= digits <= bits * 3 // 10:
        raise UsageError("digits", digits, f"expected a whole number of digits in [1, {bits * 3 // 10}] "
                                           f"(at most what {bits} bits hold)")
    digits = int(digits)
    if isinstance(min_transmission, bool) or not isinstance(min_transmission, numbers.Real) \
            or not 0 <= min_transmission < 90:
        raise UsageError("min_transmission", min_transmission, "expected degrees in [0, 90)")
    deadline = started(validation.budget(budget))
    task = task if isinstance(task, Task) else read_task(task)
    return deadline.run(functools.partial(_synthesized, task, bits=bits, digits=digits,
                                          min_transmission=min_transmission, deadline=deadline))


def _synthesized(task: Task, *, bits: int, digits: int, min_transmission: float, deadline: Deadline) -> Synthesis:
    start = time.perf_counter()
    deadline.note(f"solving {task.name}'s {task.kind} synthesis equations")
    result = _solve(task, bits)
    solved = time.perf_counter()
    designs = _designs(task, result)
    mechanisms = []
    for number, (indexes, design) in enumerate(designs, 1):
        deadline.note(f"checking four-bar {number} of {len(designs)} ({design.name})")
        mechanisms.append(SynthesizedMechanism(indexes, design, check_design(design, min_transmission=min_transmission)))
    timings = {"solve": solved - start, "check": time.perf_counter() - solved}
    return Synthesis(task, result, tuple(mechanisms), timings, digits)


def _solve(task: Task, bits: int) -> Result:
    if task.kind == "motion":
        if len(task.poses) not in (4, 5):
            raise UsageError("poses", len(task.poses), "motion synthesis takes 4 poses (the centre-point and "
                             f"circle-point curves) or 5 (the Burmester pairs), not {len(task.poses)}")
        return curves(task.poses) if len(task.poses) == 4 else burmester(task.poses, bits=bits)
    if task.kind == "function":
        return freudenstein(task.pairs, unknown_start=task.unknown_start, ground=task.ground, bits=bits)
    assert task.pivots is not None, "a path task has its pivots (files)"
    return path_synthesis(task.points, crank_pivot=task.pivots[0], rocker_pivot=task.pivots[1], bits=bits)


def _designs(task: Task, result: Result) -> list[tuple[tuple[int, ...], FourBar]]:
    """Every four-bar the result makes, named ``<task>-<k>``, with the solutions it is made of."""
    made: list[tuple[tuple[int, ...], FourBar]]
    if isinstance(result, FivePoses):
        made = [((j, k), _motion_design(task.poses, result.pairs[j], result.pairs[k]))
                for j, k in itertools.combinations(range(len(result.pairs)), 2)]
    elif isinstance(result, FunctionSynthesis):
        made = [((j,), _function_design(task, s)) for j, s in enumerate(result.solutions)]
    elif isinstance(result, PathSynthesis):
        made = [((j,), _path_design(task, s)) for j, s in enumerate(result.solutions)]
    else:
        return []
    return [(indexes, attrs.evolve(design, name=f"{safe_name(task.name)}-{n + 1}"))
            for n, (indexes, design) in enumerate(made)]


def _motion_design(poses: Sequence[Pose], crank: BurmesterPair, rocker: BurmesterPair) -> FourBar:
    """The crank on one Burmester pair, the rocker on the other; the coupler point the moving frame's origin."""
    with flint.ctx.workprec(BITS):
        positions = tuple(Position(pose.place(*crank.circle), pose.place(*rocker.circle)) for pose in poses)
        origin = (flint.arb(poses[0].x), flint.arb(poses[0].y))
    return FourBar("", crank_pivot=crank.centre, rocker_pivot=rocker.centre, positions=positions,
                   coupler_point=origin)


def _function_design(task: Task, solution: FreudensteinSolution) -> FourBar:
    """Ground from (0, 0) to (d, 0); the crank and rocker at each pair's angles, the starts being
    the angles at the first pair (turned by 180 degrees where a link's length was made positive)."""
    first = task.pairs[0]
    with flint.ctx.workprec(BITS):
        crank, rocker, ground = (flint.arb(v) for v in (solution.crank, solution.rocker, solution.ground))
        positions = []
        for pair in task.pairs:
            phi = _turned(solution.start_input, _between(first.input, pair.input))
            psi = _turned(solution.start_output, _between(first.output, pair.output))
            positions.append(Position((crank * phi[0], crank * phi[1]), (ground + rocker * psi[0], rocker * psi[1])))
        return FourBar("", crank_pivot=(flint.arb(0), flint.arb(0)), rocker_pivot=(ground, flint.arb(0)),
                       positions=tuple(positions))


def _between(first: Angle, other: Angle) -> tuple[flint.fmpq, flint.fmpq]:
    """The cos and sin of ``other`` minus ``first``."""
    return (other.cos * first.cos + other.sin * first.sin, other.sin * first.cos - other.cos * first.sin)


def _turned(start: tuple[Any, Any], by: tuple[flint.fmpq, flint.fmpq]) -> Ball2:
    """The direction of ``start`` (a cos and sin, exact or balls) turned by the angle ``by``."""
    c0, s0 = flint.arb(start[0]), flint.arb(start[1])
    return c0 * by[0] - s0 * by[1], s0 * by[0] + c0 * by[1]


def _path_design(task: Task, solution: PathSolution) -> FourBar:
    """The moving pivots carried with the coupler: at point j turned by theta_j about it."""
    assert task.pivots is not None
    first = task.points[0]
    with flint.ctx.workprec(BITS):
        crank_arm = _minus(solution.crank_joint, first)
        rocker_arm = _minus(solution.rocker_joint, first)
        rotations = [(flint.arb(1), flint.arb(0)), *solution.rotations]
        positions = tuple(Position(_carried(point, rotation, crank_arm), _carried(point, rotation, rocker_arm))
                          for point, rotation in zip(task.points, rotations))
        pivots = [(flint.arb(x), flint.arb(y)) for x, y in task.pivots]
        return FourBar("", crank_pivot=pivots[0], rocker_pivot=pivots[1], positions=positions,
                       coupler_point=(flint.arb(first[0]), flint.arb(first[1])))


def _minus(p: Ball2, q: Point) -> Ball2:
    return p[0] - q[0], p[1] - q[1]


def _carried(point: Point, rotation: tuple[flint.arb, flint.arb], arm: Ball2) -> Ball2:
    cos, sin = rotation
    return point[0] + cos * arm[0] - sin * arm[1], point[1] + sin * arm[0] + cos * arm[1]


def _text(value: flint.arb | flint.fmpq, digits: int) -> str:
    """An exact value as itself (``41``, ``3/5``), a ball's midpoint to ``digits`` digits."""
    if isinstance(value, flint.fmpq):
        return str(value)
    return str(value.mid().str(digits, radius=False))


def _pair(xy: Sequence[flint.arb], digits: int) -> list[str]:
    return [_text(v, digits) for v in xy]


def _poses(poses: Sequence[Pose]) -> list[dict[str, Any]]:
    return [{"x": str(p.x), "y": str(p.y), "angle": {"cos": str(p.angle.cos), "sin": str(p.angle.sin)}}
            for p in poses]


def _four_json(result: FourPoses, digits: int) -> dict[str, Any]:
    return {"poses": _poses(result.poses), "centre_curve": str(result.centre_curve),
            "circle_curve": str(result.circle_curve)}


def _five_json(result: FivePoses, digits: int) -> dict[str, Any]:
    return {"poses": _poses(result.poses), "complex_count": result.complex_count,
            "burmester": [{"centre": _pair(p.centre, digits), "circle": _pair(p.circle, digits)}
                          for p in result.pairs],
            "excluded": [{"factor": factor, "reason": reason} for factor, reason in result.excluded]}


def _function_json(result: FunctionSynthesis, digits: int) -> dict[str, Any]:
    def start(angle: tuple[Any, Any]) -> dict[str, Any]:
        with flint.ctx.workprec(BITS):
            degrees = flint.arb.atan2(flint.arb(angle[1]), flint.arb(angle[0])) * 180 / flint.arb.pi()
        return {"cos": _text(angle[0], digits), "sin": _text(angle[1], digits), "degrees": float(degrees.mid())}

    return {"complex_count": result.complex_count, "real_count": result.real_count,
            "excluded": [{"reason": e.reason, "complex_count": e.complex_count, "real_count": e.real_count,
                          "counted": e.solutions} for e in result.excluded],
            "solutions": [{"lengths": {k: _text(getattr(s, k), digits)
                                       for k in ("ground", "crank", "coupler", "rocker")},
                           "start": {"input": start(s.start_input), "output": start(s.start_output)}}
                          for s in result.solutions]}


def _path_json(result: PathSynthesis, digits: int) -> dict[str, Any]:
    size, turns = result.size, len(result.points) - 1
    return {"complex_count": result.complex_count, "real_count": result.real_count,
            # the system (per further point a turn's cos and sin, its circle and one row per dyad; both
            # joints' z) and the five points' elimination: its sizes, and how many solutions it has
            "size": {"points": len(result.points), "equations": 3 * turns, "unknowns": 2 * turns + 4,
                     "intermediate_degrees": list(size.intermediate), "eliminant_degree": size.resultant_degree,
                     "eliminant_terms": size.resultant_terms, "eliminant_bits": size.resultant_bits,
                     "five_point_solutions": size.solution_degree},
            "excluded": [{"factor": e.factor, "degree": e.degree, "multiplicity": e.multiplicity, "reason": e.reason}
                         for e in result.excluded],
            "solutions": [{"crank_joint": _pair(s.crank_joint, digits), "rocker_joint": _pair(s.rocker_joint, digits),
                           "lengths": {"crank": _text(s.crank, digits), "coupler": _text(s.coupler, digits),
                                       "rocker": _text(s.rocker, digits)}}
                          for s in result.solutions]}


_KIND_JSON: dict[type, Callable[[Any, int], dict[str, Any]]] = {
    FourPoses: _four_json, FivePoses: _five_json, FunctionSynthesis: _function_json, PathSynthesis: _path_json}
