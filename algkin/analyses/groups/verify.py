"""``verify`` on a scene with points solved together: the modes against independent solutions.

At seeded inputs in range (exact: rational lengths, rational points of the circle; half of them
where the groups assemble), each group's
modes come from its eliminant (``GroupScene.modes``: real roots certified, the other unknowns
their lifts); independently (``algkin.verify.groups``, which never sees the eliminant) its
original equations are solved by Newton's method from many random starts and every root is
proved in balls. Every proved root must match exactly one mode (their balls overlap) and every
mode one root: none missing, none extra. It passes only when something was compared. A group
solved after others (a dyad on a triad's joint) is solved with their equations, all at once:
each proved root matched to one configuration of them all.

>>> found = verify_groups("3rpr", samples=4)
>>> found.verification["passed"], found.verification["compared"] > 0
(True, True)
"""

from __future__ import annotations

import random
import time
from collections.abc import Mapping, Sequence
from fractions import Fraction
from typing import Any

import attrs
import flint
import numpy as np

from ...errors import ComputationError
from ...runtime.frozen import FrozenDict, frozen
from ...scene import Scene
from ...verify.groups import STARTS, real_solutions
from .curve import assembling
from .scene import GroupScene, Sample, prepare_groups

__all__ = ["verify_groups", "GroupVerification", "RETRY"]

RETRY = 4
"""How many times as many starts a sample with a mode not found numerically is tried again with."""


@attrs.frozen
class GroupVerification:
    """The check's document (``verification``) and its timings."""

    scene: Scene
    verification: FrozenDict[str, Any] = attrs.field(converter=frozen)
    timings: FrozenDict[str, float] = attrs.field(converter=frozen)

    @property
    def passed(self) -> bool:
        return bool(self.verification["passed"])

    def to_json(self) -> dict[str, Any]:
        return {"scene": self.scene.name, "verification": dict(self.verification), "timings": dict(self.timings)}


def verify_groups(scene: Scene | str | GroupScene, *, samples: int = 40, seed: int = 0) -> GroupVerification:
    """Each group's modes at ``samples`` seeded inputs against proved numeric solutions of its equations."""
    start = time.perf_counter()
    prepared = scene if isinstance(scene, GroupScene) else prepare_groups(scene, command="verify")
    rng = random.Random(seed)
    drawn = _draw(prepared, samples, rng)
    tally = _Tally()
    groups = prepared.compiled.groups
    for index, group in enumerate(groups):
        inputs = {n: v for n, v in prepared.compiled.inputs.items() if set(v) & set(prepared.variables)}
        chain = prepared.chain(index)  # a later group with the groups it is solved after: their equations together
        unknowns = tuple(u for k in chain for u in groups[k].unknowns)
        equations = tuple(e for k in chain for e in groups[k].equations)
        expected = [_expected(prepared, sample, index, chain) for sample in drawn]
        usable = [k for k, e in enumerate(expected) if e is not None]
        found = real_solutions(unknowns, equations, inputs, [drawn[k].exact() for k in usable],
                               np.random.default_rng(seed))
        for k, roots in zip(usable, found):
            modes = expected[k]
            assert modes is not None
            if len(roots) < len(modes):  # a root Newton's starts missed: more starts, once
                roots = real_solutions(unknowns, equations, inputs, [drawn[k].exact()],
                                       np.random.default_rng(seed + k + 1), starts=STARTS * RETRY)[0]
            tally.compare(", ".join(group.points), drawn[k], modes, roots)
        tally.skipped += len(drawn) - len(usable)
    timings = {"total": time.perf_counter() - start}
    return GroupVerification(prepared.scene, tally.document(samples), timings)


def _draw(prepared: GroupScene, count: int, rng: random.Random) -> list[Sample]:
    """``count`` seeded inputs: half where every group assembles (a group may assemble over a
    small part of the range only), the rest drawn anywhere in range (where none may be found)."""
    if prepared.input is None:
        return []
    lo, hi = prepared.input.span
    found = assembling(prepared, (count + 1) // 2, rng)
    return found + [prepared.sample(Fraction(rng.uniform(lo, hi)).limit_denominator(1000))
                    for _ in range(count - len(found))]


def _expected(prepared: GroupScene, sample: Sample, index: int, chain: Sequence[int]
              ) -> list[Mapping[str, flint.arb]] | None:
    """The group's modes at ``sample`` from its eliminant (None where modes meet exactly there);
    a later group's: with those of the groups in its ``chain``, one per configuration of them."""
    groups = prepared.compiled.groups
    try:
        if len(chain) == 1:
            found = prepared.modes(sample, bits=192)[index]
            return [{u: m.values[u] for u in groups[index].unknowns} for m in found]
        configurations = prepared.configurations(sample, bits=192)
    except ComputationError:
        return None
    distinct = {tuple(id(c[k]) for k in chain): c for c in configurations}
    return [{u: c[k].values[u] for k in chain for u in groups[k].unknowns} for c in distinct.values()]


@attrs.define
class _Tally:
    compared: int = 0
    configurations: int = 0
    worst: float = 0.0
    skipped: int = 0
    failures: list[str] = attrs.field(factory=list)

    def compare(self, group: str, sample: Sample, modes: Sequence[Mapping[str, flint.arb]],
                roots: Sequence[Mapping[str, flint.arb]]) -> None:
        """Every root matched to one mode, every mode to one root."""
        matched = [0] * len(modes)
        for root in roots:
            owners = [k for k, mode in enumerate(modes) if all(mode[u].overlaps(v) for u, v in root.items())]
            if len(owners) != 1:
                what = "no mode" if not owners else f"{len(owners)} modes"
                self.failures.append(f"group {group} at {sample.shown}: a proved solution matches {what}")
                continue
            matched[owners[0]] += 1
            mode = modes[owners[0]]
            for u, v in root.items():
                self.worst = max(self.worst, float(abs(mode[u] - v).upper()))
                self.compared += 1
            self.configurations += 1
        for k, count in enumerate(matched):
            if count != 1:
                self.failures.append(f"group {group} at {sample.shown}: mode {k + 1} matched by {count} proved "
                                     "solutions" + (" (missing)" if not count else ""))

    def document(self, samples: int) -> dict[str, Any]:
        failures = list(self.failures)
        if not self.compared:
            failures.append("nothing compared: no sample assembles")
        passed = not failures
        return {"status": "passed" if passed else "failed", "passed": passed, "samples": samples,
                "compared": self.compared, "configurations": self.configurations, "skipped": self.skipped,
                "max_abs_error": self.worst, "failures": failures,
                "method": f"Newton from {STARTS} random starts per sample on each group's own equations (numpy), "
                          "every root proved in arb balls by a Krawczyk test; each matched to one mode of the "
                          "eliminant, none missing, none extra"}
