"""scene -> system -> elimination -> closed-form branches -> verification.

``derive`` and ``curve`` take a scene (a catalog name, a file, a ``Scene``) or a ``Prepared``
one (``algkin.derivation.prepared``): given a scene they prepare it themselves, and nothing of
one call is kept for the next.

>>> result = curve("chebyshev-lambda", "P")
>>> result.degree, result.circularity, result.irreducible, result.verification.passed
(6, 3, True, True)
"""

from __future__ import annotations

import functools
import time
from collections.abc import Mapping, Sequence

import attrs
import sympy

from ..runtime import suggest
from ..eliminate import DEFAULT_METHOD
from ..errors import UsageError
from ..runtime import validation
from ..runtime.budget import Budget, Deadline, started
from ..runtime.exclusive import one_at_a_time
from ..scene import Compiled, Scene, compile_scene
from ..scene.load import SceneLike, Values
from ..verify import Verification
from .assembles import certify_labels
from .curves import curve_figures, family_method, refuse_still
from .modes import Followed, follow_modes, mode_witnesses, moded_points, other_modes
from .checking import verify_prepared
from .prepared import Prepared, given, load, prepare, prepared_from, timed
from .results import CurveResult, Derivation
from .tasks import Eliminant, curve_task, eliminant_tasks

__all__ = ["derive", "curve", "Engine"]


@attrs.frozen(kw_only=True)
class Engine:
    """How a derivation or a curve computes: the elimination's method and backend, and the
    verification's samples (0: none) and seed."""

    method: str = DEFAULT_METHOD
    backend: str = "flint"
    samples: int = 40
    seed: int = 0


@attrs.frozen(kw_only=True)
class _Source:
    """What a computation starts from: a scene and what to prepare it with (outputs, symbolic
    dimensions, values), or a ``Prepared`` one."""

    scene: SceneLike | Prepared
    outputs: tuple[str, ...] | None = None
    params: tuple[str, ...] = ()
    values: Values | None = attrs.field(default=None, eq=False)

    def prepared(self, deadline: Deadline) -> Prepared:
        """The scene prepared (itself, if it is already), telling ``deadline`` what it does."""
        if isinstance(self.scene, Prepared):
            return self.scene
        return prepare(self.scene, outputs=self.outputs, params=self.params, set=self.values, deadline=deadline)


def _source(scene: SceneLike | Prepared, engine: Engine, *, outputs: Sequence[str] | None = None,
            params: Sequence[str], values: Values | None) -> _Source:
    """What to start from, the arguments checked (a ``Prepared`` scene's own are not given again)."""
    given(scene, outputs=outputs, params=params, set=values)
    validation.count("samples", engine.samples, validation.MAX_VERIFY_SAMPLES)
    validation.seed(engine.seed)
    return _Source(scene=scene, outputs=validation.names("outputs", outputs),
                   params=validation.names("params", params) or (), values=values)


@one_at_a_time
def derive(scene: SceneLike | Prepared, outputs: Sequence[str] | None = None, *, method: str = DEFAULT_METHOD,
           backend: str = "flint", params: Sequence[str] = (), samples: int = 40, seed: int = 0,
           certify: bool = True, budget: Budget | Deadline | None = None,
           set: Values | None = None) -> Derivation:  # noqa: A002 - ``set=`` is the public name (the command line's --set)
    """Eliminants, closed-form branches and their verification for ``outputs`` of ``scene``.

    ``scene`` may be a ``Prepared`` one (``prepare``), which says its outputs, symbolic
    dimensions and values itself. ``certify`` also certifies each branch's label per input
    interval (the slowest stage); a ``Budget`` bounds the time of the whole derivation, loading
    and compiling the scene included, and the size of its eliminants (the ``Deadline`` of one
    already running: the derivation counts against it). ``set`` gives dimensions exact values
    (``{"a": "3/2"}``) in place of their defaults.
    """
    engine = Engine(method=method, backend=backend, samples=samples, seed=seed)
    certify = validation.flag("certify", certify)
    source = _source(scene, engine, outputs=outputs, params=params, values=set)
    deadline = started(validation.budget(budget))
    return deadline.run(functools.partial(_derive, source, engine, certify=certify, deadline=deadline,
                                          start=time.perf_counter()))


def _derive(source: _Source, engine: Engine, *, certify: bool, deadline: Deadline, start: float) -> Derivation:
    prepared = source.prepared(deadline)
    compiled, branches = prepared.compiled, prepared.branches
    timings = dict(prepared.timings)
    with timed(timings, "eliminate"):
        eliminations = {u: task.run(engine.method, engine.backend, deadline)
                        for u, task in eliminant_tasks(compiled, prepared.witnesses).items()}
    deadline.note(f"verifying the branches of {compiled.scene.name}")
    with timed(timings, "verify"):
        verification = _verify(prepared, engine, eliminations)
    deadline.note(f"certifying the branch labels of {compiled.scene.name}")
    with timed(timings, "certify"):
        certified = certify_labels(compiled, branches) if certify else [None] * len(branches)
    modes: tuple[Followed, ...] = ()
    if moded_points(compiled.scene):
        deadline.note(f"following the named modes of {compiled.scene.name}")
        with timed(timings, "modes"):
            modes = follow_modes(compiled.scene, {s.point for s in compiled.implicit}, deadline=deadline)
    timings["total"] = time.perf_counter() - start
    return Derivation(compiled, engine.method, engine.backend, eliminations, branches, verification, timings, certified,
                      modes)


def _verify(prepared: Prepared, engine: Engine, eliminations: Mapping[str, Eliminant]) -> Verification:
    """The independent check, each eliminant's kept factors with it."""
    return verify_prepared(prepared, samples=engine.samples, seed=engine.seed,
                           polynomials={u: e.exact[0] for u, e in eliminations.items()},
                           factors={u: e.exact[1] for u, e in eliminations.items()})


@one_at_a_time
def curve(scene: SceneLike | Prepared, point: str, *, method: str = DEFAULT_METHOD, backend: str = "flint",
          params: Sequence[str] = (), samples: int = 40, seed: int = 0, budget: Budget | Deadline | None = None,
          set: Values | None = None) -> CurveResult:  # noqa: A002 - as in derive
    """The implicit curve ``F(point_x, point_y) = 0`` traced by ``point`` (a one-input motion).

    ``scene`` may be a ``Prepared`` one with ``point`` among its outputs. A ``Budget`` bounds the
    time of the whole computation, loading and compiling the scene included, and the size of its
    eliminants (or the ``Deadline`` of one running, as in ``derive``). ``set`` gives dimensions
    exact values.
    """
    engine = Engine(method=method, backend=backend, samples=samples, seed=seed)
    source = _source(scene, engine, params=params, values=set)
    deadline = started(validation.budget(budget))
    return deadline.run(functools.partial(_curve, source, engine, point=point, deadline=deadline,
                                          start=time.perf_counter()))


def _curve(source: _Source, engine: Engine, *, point: str, deadline: Deadline, start: float) -> CurveResult:
    prepared = _prepared_for_curve(source, point, deadline)
    compiled = prepared.compiled
    timings = dict(prepared.timings)
    refuse_still(compiled, prepared.branches, point)
    modes = follow_modes(compiled.scene, {s.point for s in compiled.implicit}, deadline=deadline) \
        if moded_points(compiled.scene) else ()
    with timed(timings, "eliminate"):
        # on a named mode, its configurations are the witnesses: the curve keeps the mode's factors
        groups = tuple(g for m in modes for g in mode_witnesses(compiled, prepared.branches, m)) or prepared.witnesses
        task = curve_task(compiled, groups, point)
        result = task.run(family_method(task, engine.method), engine.backend, deadline)
    variables = task.keep[:2]
    degree, circularity = curve_figures(result.exact[0], variables)
    others = other_modes(result, prepared.witnesses) if modes else ()
    deadline.note(f"verifying the curve of {point} in {compiled.scene.name}")
    with timed(timings, "verify"):
        if others:  # every branch is checked: on the curve of the whole motion, the other modes' factors with it
            verification = verify_prepared(prepared, samples=engine.samples, seed=engine.seed,
                                           polynomials={"curve": sympy.Mul(result.polynomial, *others)},
                                           factors={"curve": [*result.factors, *others]})
        else:
            verification = _verify(prepared, engine, {"curve": result})
    timings["total"] = time.perf_counter() - start
    return CurveResult(compiled, point, variables, result, degree, circularity, len(result.raw_factors or ()) == 1,
                       verification, timings, modes, tuple(str(f) for f in others))


def _prepared_for_curve(source: _Source, point: str, deadline: Deadline) -> Prepared:
    """The scene prepared for ``point``, refused before its branches are sought when ``point`` is
    not a point of it or moves with more than one input."""
    if isinstance(source.scene, Prepared):
        prepared = source.scene
        _check_point(prepared.scene, point)
        if point not in prepared.compiled.outputs:
            raise UsageError("point", point, f"not an output {prepared.scene.name} was prepared for"
                             + suggest.known(point, prepared.compiled.outputs, plural="outputs"))
        _check_one_input(prepared.compiled, point)
        return prepared
    scene = load(source.scene, values=source.values, params=source.params, deadline=deadline)
    _check_point(scene, point)
    deadline.note(f"compiling {scene.name}")
    timings: dict[str, float] = {}
    with timed(timings, "compile"):
        compiled = compile_scene(scene, [point], source.params)
    _check_one_input(compiled, point)
    deadline.note(f"finding the branches of {scene.name}")
    return prepared_from(compiled, timings)


def _check_point(scene: Scene, point: str) -> None:
    if not isinstance(point, str) or point not in scene.points:
        raise UsageError("point", point, f"not a point of {scene.name}" + suggest.known(point, scene.points, plural="points"))


def _check_one_input(compiled: Compiled, point: str) -> None:
    if len(compiled.system.inputs) > 1:
        raise UsageError("point", point, f"moves with {len(compiled.system.inputs)} inputs "
                         f"({', '.join(compiled.system.inputs)}) in {compiled.scene.name}: its trajectory is a "
                         "region, not a curve")
