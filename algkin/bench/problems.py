"""The bench suite: elimination problems from the catalog, each exactly the call algkin makes.

Every problem is an ``EliminationTask`` (equations, what to eliminate and keep, witness
configurations) built the way ``derive``, ``curve`` or ``extremum`` builds it, so the
methods are timed on what a user's command runs, plus that command itself, end to end
(compile, eliminate, factor, select, verify) with the default method.

>>> sorted(PROBLEMS)[:3]
['arm-extremum', 'fourbar-symbolic', 'lambda-coupler']
"""

from collections.abc import Callable, Sequence
from dataclasses import dataclass

from ..runtime import suggest
from ..derivation.tasks import EliminationTask, curve_task, eliminant_tasks
from ..errors import UsageError

__all__ = ["Problem", "PROBLEMS", "problem_names", "build"]

FOURBAR_DIMENSIONS = ("a", "d", "l", "m", "p", "q")
FAMILY_PARAMETERS = ("u", "v")  # the tracing point's frame coordinates in stephenson-iii-family


@dataclass(frozen=True)
class Problem:
    name: str
    description: str
    task: EliminationTask
    end_to_end: Callable[[], object]  # algkin's default path for the problem, with its own figures


def _curve(scene: str, point: str, params: Sequence[str] = ()) -> EliminationTask:
    from ..derivation.prepared import prepare

    prepared = prepare(scene, outputs=[point], params=params)
    return curve_task(prepared.compiled, prepared.witnesses, point)


def _curve_run(scene: str, point: str, params: Sequence[str] = ()) -> Callable[[], object]:
    from ..derivation.pipeline import curve

    return lambda: curve(scene, point, params=params)


def _two_circles() -> EliminationTask:
    from ..derivation.prepared import prepare

    prepared = prepare("chebyshev-lambda", outputs=["B"])
    return eliminant_tasks(prepared.compiled, prepared.witnesses)["B_y"]


def _two_circles_run() -> Callable[[], object]:
    from ..derivation.pipeline import derive

    return lambda: derive("chebyshev-lambda", ["B"])


def _arm() -> EliminationTask:
    from ..analyses.extremum import problem_for
    from ..derivation.pipeline import derive

    problem = problem_for(derive("arm-string", ["AB"], params=["b"], samples=0), "AB")
    names = tuple(p.name for p in problem.parameters)
    return EliminationTask(tuple(problem.half_angle()), (problem.t.name,), (problem.u.name,) + names, names, ())


def _arm_run() -> Callable[[], object]:
    from ..analyses.extremum import extremum

    return lambda: extremum("arm-string", "AB", params=["b"])


# name -> (what it is, its task's maker, its end-to-end run's maker)
PROBLEMS: dict[str, tuple[str, Callable[[], EliminationTask], Callable[[], Callable[[], object]]]] = {
    "two-circles": ("the seed connector: B_y of the Chebyshev lambda, B_x eliminated from two circles",
                    _two_circles, _two_circles_run),
    "lambda-coupler": ("the lambda's coupler curve of P (the seed notebook's extension)",
                       lambda: _curve("chebyshev-lambda", "P"), lambda: _curve_run("chebyshev-lambda", "P")),
    "fourbar-symbolic": ("the general four-bar coupler curve, all six dimensions symbolic",
                         lambda: _curve("fourbar", "P", FOURBAR_DIMENSIONS),
                         lambda: _curve_run("fourbar", "P", FOURBAR_DIMENSIONS)),
    "arm-extremum": ("the arm's |AB| value polynomial, b symbolic (the seed's minimum against b)",
                     _arm, _arm_run),
    "slider-crank": ("the offset slider-crank's rod midpoint curve",
                     lambda: _curve("slider-crank", "M"), lambda: _curve_run("slider-crank", "M")),
    "watt-i": ("the Watt I six-bar coupler curve", lambda: _curve("watt-i", "P"), lambda: _curve_run("watt-i", "P")),
    "stephenson-iii": ("the Stephenson III six-bar coupler curve (degree 18, circularity 9)",
                       lambda: _curve("stephenson-iii", "P"), lambda: _curve_run("stephenson-iii", "P")),
    "stephenson-iii-family": ("the Stephenson III's coupler curves with the tracing point (u, v) symbolic: "
                              "one polynomial in x, y, u, v",
                              lambda: _curve("stephenson-iii-family", "P", FAMILY_PARAMETERS),
                              lambda: _curve_run("stephenson-iii-family", "P", FAMILY_PARAMETERS)),
}


def problem_names() -> list[str]:
    """The elimination problems, then the forward-kinematics ones (``bench.kinematics``), then
    synthesis's (``bench.synthesis``)."""
    from .kinematics import KINEMATICS
    from .synthesis import SYNTHESIS

    return list(PROBLEMS) + list(KINEMATICS) + list(SYNTHESIS)


def build(name: str) -> Problem:
    """The ``Problem`` called ``name``; a UsageError naming the valid ones otherwise."""
    if name not in PROBLEMS:
        raise UsageError("problems", name, "unknown problem" + suggest.known(name, PROBLEMS, plural="valid"))
    description, task, run = PROBLEMS[name]
    return Problem(name, description, task(), run())
