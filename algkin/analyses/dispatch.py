"""``derive`` and ``curve`` as ``algkin`` gives them: on any scene, as the commands do.

A scene of constructions (or a ``Prepared`` one) goes through the derivation pipeline
(``algkin.derivation.pipeline``); a scene with points solved together (``unknown = true``)
through the groups' own (``derive_groups``, ``curve_groups``), which return a ``GroupDerivation``
or a ``GroupCurve``. These take ``set``, ``samples``, ``seed`` and a budget of seconds; what
only the pipeline has (``outputs``, ``params``, another ``method`` or ``backend``, ``certify=False``,
a budget of terms) is refused by name, as the command line refuses its flags.

>>> [m.label for m in derive("3rpr", samples=0).groups[0].modes]
['---', '+++']
>>> derive("3rpr", method="groebner")
Traceback (most recent call last):
...
algkin.errors.UsageError: method='groebner': is not taken with points solved together (unknown = true) yet
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Sequence
from typing import TypeVar

from ..derivation import pipeline
from ..derivation.prepared import Prepared
from ..derivation.results import CurveResult, Derivation
from ..eliminate import DEFAULT_METHOD
from ..errors import UsageError
from ..runtime import validation
from ..runtime.budget import Budget, Deadline, started
from ..runtime.exclusive import one_at_a_time
from ..scene import Scene
from ..scene.load import SceneLike, Values, as_scene
from ..scene.settings import with_values
from .groups.curve import GroupCurve, curve_groups
from .groups.derive import GroupDerivation, derive_groups

__all__ = ["derive", "curve"]

NOT_YET = "is not taken with points solved together (unknown = true) yet"

T = TypeVar("T")


@one_at_a_time
def derive(scene: SceneLike | Prepared, outputs: Sequence[str] | None = None, *, method: str = DEFAULT_METHOD,
           backend: str = "flint", params: Sequence[str] = (), samples: int = 40, seed: int = 0,
           certify: bool = True, budget: Budget | Deadline | None = None,
           set: Values | None = None) -> Derivation | GroupDerivation:  # noqa: A002 - the pipeline's public name
    """The closed forms of ``scene``: ``algkin.derivation.pipeline.derive`` for a scene of
    constructions, ``derive_groups`` for one with points solved together.

    On points solved together, ``outputs``, ``params``, ``method``, ``backend`` and ``certify``
    given other than by default are refused by name, and a ``Budget`` bounds the time of the work
    (in a child process, as the pipeline's), not the size of its eliminants: one with ``terms`` is refused.
    """
    together = _solved_together(scene, set)
    if together is None:
        return pipeline.derive(scene, outputs, method=method, backend=backend, params=params, samples=samples,
                               seed=seed, certify=certify, budget=budget, set=set)
    _refuse(outputs=(outputs, None), params=(params, ()), method=(method, DEFAULT_METHOD), backend=(backend, "flint"),
            certify=(certify, True))
    return _within(budget, functools.partial(derive_groups, together, **_sampling(samples, seed)))


@one_at_a_time
def curve(scene: SceneLike | Prepared, point: str, *, method: str = DEFAULT_METHOD, backend: str = "flint",
          params: Sequence[str] = (), samples: int = 40, seed: int = 0, budget: Budget | Deadline | None = None,
          set: Values | None = None) -> CurveResult | GroupCurve:  # noqa: A002 - as in derive
    """The implicit curve traced by ``point``: ``algkin.derivation.pipeline.curve`` for a scene of
    constructions, ``curve_groups`` for one with points solved together (refusals and a budget as
    in ``derive``)."""
    together = _solved_together(scene, set)
    if together is None:
        return pipeline.curve(scene, point, method=method, backend=backend, params=params, samples=samples, seed=seed,
                              budget=budget, set=set)
    _refuse(params=(params, ()), method=(method, DEFAULT_METHOD), backend=(backend, "flint"))
    return _within(budget, functools.partial(curve_groups, together, point, **_sampling(samples, seed)))


def _solved_together(scene: SceneLike | Prepared, values: Values | None) -> Scene | None:
    """The scene, its dimensions in ``values`` set, when it has points solved together; else None
    (the pipeline loads it itself, within its budget). A ``Prepared`` scene never has them."""
    if isinstance(scene, Prepared):
        return None
    loaded = as_scene(scene)
    return with_values(loaded, values) if loaded.unknown_points else None


def _refuse(**arguments: tuple[object, object]) -> None:
    """UsageError naming the first argument given a value other than its default: ``arguments``
    maps each name to ``(value, default)``; an empty list is no names, as on the command line."""
    for name, (value, default) in arguments.items():
        nothing = isinstance(value, (list, tuple)) and not value and default in (None, ())
        if not (nothing or (type(value) is type(default) and value == default)):
            raise UsageError(name, value, NOT_YET)


def _sampling(samples: int, seed: int) -> dict[str, int]:
    """The verification's ``samples`` and ``seed``, checked as the pipeline checks them."""
    return {"samples": validation.count("samples", samples, validation.MAX_VERIFY_SAMPLES),
            "seed": validation.seed(seed)}


def _within(budget: Budget | Deadline | None, work: Callable[[], T]) -> T:
    """``work()`` kept to ``budget``'s seconds; its terms, which the groups' work does not count, refused."""
    budget = validation.budget(budget)
    terms = (budget.budget if isinstance(budget, Deadline) else budget).terms if budget is not None else None
    if terms is not None:
        raise UsageError("budget", budget, f"a budget of terms ({terms}) {NOT_YET}: give seconds only")
    return started(budget).run(work)
