"""A scene prepared for the pipeline: compiled, its branches found, checked to assemble, witnesses drawn.

``prepare`` does the stages every derivation, curve and analysis of a scene shares, once,
and hands them out as one immutable value, ``Prepared``, that ``derive``, ``curve`` and the
analyses take in place of a scene: a caller that asks several questions of one scene
prepares it once. Nothing is kept behind the caller's back: a call given a scene prepares
it afresh, whatever ran before it in the process.

>>> prepared = prepare("fourbar", outputs=["B"])
>>> prepared
Prepared(fourbar, outputs B, branches left right)
>>> prepared.compiled.system.unknowns
('B_x', 'B_y')
>>> [len(group) for group in prepared.witnesses]
[3, 3]
>>> import algkin
>>> derived = algkin.derive(prepared, samples=5)
>>> derived.compiled == prepared.compiled, derived.verification.passed
(True, True)
>>> prepared == prepare("fourbar", outputs=["B"]) and hash(prepared) == hash(prepare("fourbar", outputs=["B"]))
True
"""

from __future__ import annotations

import contextlib
import time
from collections.abc import Iterable, Iterator, Mapping, Sequence

import attrs

from ..branches import Branch, check_assembly, closed_forms
from ..errors import UsageError
from ..runtime import validation
from ..runtime.budget import Deadline, started
from ..runtime.frozen import FrozenDict, frozen
from ..runtime.exclusive import one_at_a_time
from ..scene import Compiled, Scene, compile_scene
from ..scene.compile import resolve_outputs
from ..scene.load import SceneLike, Values, as_scene
from ..scene.settings import with_values
from .assembles import Pieces, where_assembled
from .modes import resolve_modes
from .witnesses import Groups, sampled_witnesses

__all__ = ["Prepared", "prepare", "prepared_from", "load", "given", "require_outputs", "timed"]


def _branches(branches: Iterable[Branch]) -> tuple[Branch, ...]:
    return tuple(branches)


def _pieces(where: Mapping[str, Pieces] | None) -> FrozenDict[str, tuple[tuple[float, float], ...]] | None:
    return None if where is None else frozen({n: tuple(p) for n, p in where.items()})


@attrs.frozen(repr=False)
class Prepared:
    """A compiled scene with its branches (checked to assemble), where they assemble and their witnesses.

    An immutable value, equal (and hashed) by its compiled scene and branches: the rest follows
    from those two. ``timings`` are the seconds compiling and branching took.
    """

    compiled: Compiled
    branches: tuple[Branch, ...] = attrs.field(converter=_branches)
    # {input: ((lo, hi), ...)} outside which no branch assembles, None for the whole range (where_assembled)
    where: FrozenDict[str, tuple[tuple[float, float], ...]] | None = attrs.field(converter=_pieces, eq=False)
    witnesses: Groups = attrs.field(eq=False, repr=False)  # per branch (python-flint balls: not hashable)
    timings: FrozenDict[str, float] = attrs.field(converter=frozen, eq=False, repr=False)

    @property
    def scene(self) -> Scene:
        return self.compiled.scene

    def __repr__(self) -> str:
        return (f"Prepared({self.scene.name}, outputs {' '.join(self.compiled.outputs)}, "
                f"branches {' '.join(b.label for b in self.branches)})")


@one_at_a_time
def prepare(scene: SceneLike, *, outputs: Sequence[str] | None = None, params: Sequence[str] = (),
            set: Values | None = None,  # noqa: A002 - ``set=`` is the public name (the command line's --set)
            deadline: Deadline | None = None) -> Prepared:
    """``scene`` (a catalog name, a file, a ``Scene``) compiled for ``outputs`` (all of them by
    default) with the dimensions ``params`` symbolic and those in ``set`` given exact values, its
    branches found and checked to assemble, and their witnesses drawn.

    It runs in the caller's process, telling ``deadline`` (if any) what it does; ``derive(scene,
    budget=...)`` bounds the preparation too."""
    outputs, params = validation.names("outputs", outputs), validation.names("params", params) or ()
    deadline = started(validation.budget(deadline, "deadline"))
    loaded = load(scene, values=set, params=params, deadline=deadline)
    deadline.note(f"compiling {loaded.name} and finding its branches")
    timings: dict[str, float] = {}
    with timed(timings, "compile"):
        compiled = compile_scene(loaded, outputs, params)
    return prepared_from(compiled, timings)


def load(scene: SceneLike, *, values: Values | None, params: Sequence[str], deadline: Deadline) -> Scene:
    """The scene, loaded (or a given one checked), with the dimensions in ``values`` set and the
    modes it names by a configuration resolved (``algkin.derivation.modes``)."""
    deadline.note(f"loading {getattr(scene, 'name', scene)}")
    return resolve_modes(with_values(as_scene(scene), values, params))


def prepared_from(compiled: Compiled, timings: Mapping[str, float] = FrozenDict()) -> Prepared:
    """A compiled scene's branches, checked to assemble, and their witnesses; ``timings`` so far
    (the compilation's) with the seconds this took as ``branches``."""
    timings = dict(timings)
    with timed(timings, "branches"):
        branches = tuple(closed_forms(compiled))
        check_assembly(compiled, branches)
        where = where_assembled(compiled, branches)  # a structure refused before its witnesses
        groups = sampled_witnesses(compiled, branches, where)
    return Prepared(compiled, branches, where, groups, timings)


def given(scene: SceneLike | Prepared, **arguments: Sequence[str] | Values | None) -> Prepared | None:
    """``scene`` if it is a ``Prepared``, with none of ``arguments`` (what it was prepared with:
    outputs, params, set) given again (empty is not given); None for a scene still to prepare.

    >>> given("fourbar", params=["a"]) is None
    True
    >>> given(prepare("fourbar", outputs=["B"]), set={"a": 2})
    Traceback (most recent call last):
    ...
    algkin.errors.UsageError: set={'a': 2}: given with a Prepared scene: pass it to prepare() instead
    """
    if not isinstance(scene, Prepared):
        return None
    for name, value in arguments.items():
        if value:
            raise UsageError(name, value, "given with a Prepared scene: pass it to prepare() instead")
    return scene


def require_outputs(prepared: Prepared, argument: str, outputs: Sequence[str]) -> None:
    """UsageError naming ``argument`` unless ``prepared`` was prepared for ``outputs`` exactly
    (an analysis of an output reads the one output of its compiled scene)."""
    if [o.name for o in resolve_outputs(prepared.scene, outputs)] != list(prepared.compiled.outputs):
        value = outputs[0] if len(outputs) == 1 else list(outputs)
        raise UsageError(argument, value, f"not what {prepared.scene.name} was prepared for (outputs: "
                         f"{', '.join(prepared.compiled.outputs)}): prepare it with outputs={list(outputs)}")


@contextlib.contextmanager
def timed(timings: dict[str, float], stage: str) -> Iterator[None]:
    """``timings[stage]``: the seconds the block took."""
    mark = time.perf_counter()
    try:
        yield
    finally:
        timings[stage] = time.perf_counter() - mark
