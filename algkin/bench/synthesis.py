"""Synthesis problems in the bench: each a zero-dimensional system, every real solution compared.

Each is a ``-real`` kinematics problem (``algkin.bench.kinematics``): algkin's row is
``solve_group`` and ``modes`` on the synthesis system (what ``algkin.synthesis`` runs), the
peers' msolve's, Singular's and PARI/GP's real solutions of the same equations, compared count
and values.

The five-point path problem (Morgan and Wampler's Problem 7) is solved by
``algkin.synthesis.path.five_point_path``'s resultant chain (``solve_group`` does not take its
twelve equations), its real solutions given in the system's unknowns.

>>> sorted(SYNTHESIS)
['burmester-five-poses-real', 'freudenstein-five-pairs-real', 'path-five-points-real']
>>> problem = SYNTHESIS["burmester-five-poses-real"]()
>>> problem.unknowns, len(problem.equations)
(('X', 'Y', 'x', 'y'), 4)
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

import flint

from ..synthesis import function, motion, path
from ..synthesis.data import Angle, AnglePair, Pose
from .kinematics import Kinematics

__all__ = ["SYNTHESIS"]

# (x, y, cos, sin) of five poses with four real Burmester pairs (the motion tests' FOUR_REAL)
POSES = ((-2, -3, 0, -1), (3, 3, 1, 0), (2, -1, "-5/13", "-12/13"), (-4, 2, 1, 0), (-4, 3, "4/5", "-3/5"))
# Morgan and Wampler's Problem 7: five points on y = x + 0.56, pivots (0, 0) and (1, 0)
POINTS = (("0.50", "1.06"), ("-0.83", "-0.27"), ("-0.34", "0.22"), ("-0.13", "0.43"), ("0.22", "0.78"))
CRANK_PIVOT, ROCKER_PIVOT = (flint.fmpq(0), flint.fmpq(0)), (flint.fmpq(1), flint.fmpq(0))
# half-angle tangents of five crank and rocker offsets with three real four-bars
PAIRS = (("0", "0"), ("1/4", "1/7"), ("1/2", "1/3"), ("1", "3/5"), ("2", "1"))


def _poses() -> list[Pose]:
    q = flint.fmpq
    return [Pose(q(x), q(y), Angle.of_cos_sin(q(c), q(s))) for x, y, c, s in POSES]


def _pairs() -> list[AnglePair]:
    half = Angle.of_tan_half
    return [AnglePair(half(flint.fmpq(a)), half(flint.fmpq(b))) for a, b in PAIRS]


def _points() -> list[tuple[flint.fmpq, flint.fmpq]]:
    return [(_decimal(x), _decimal(y)) for x, y in POINTS]


def _decimal(text: str) -> flint.fmpq:
    return flint.fmpq(int(text.replace(".", "")), 100)


def _path_solved() -> tuple[int, list[tuple[str, ...]]]:
    """``five_point_path`` on Problem 7: its count, and each real solution in ``path.UNKNOWNS``
    (the turns' cos and sin, then each joint less the first point: the coupler's ``z``)."""
    points = _points()
    found = path.five_point_path(points, crank_pivot=CRANK_PIVOT, rocker_pivot=ROCKER_PIVOT)
    rows = []
    for solution in found.solutions:
        with flint.ctx.workprec(160):
            values = [v for turn in solution.rotations for v in turn]
            values += [solution.crank_joint[k] - points[0][k] for k in (0, 1)]
            values += [solution.rocker_joint[k] - points[0][k] for k in (0, 1)]
        rows.append(tuple(v.mid().str(40, radius=False) for v in values))
    return found.complex_count, rows


def _path_problem() -> Kinematics:
    equations, unknowns = path.system(_points(), crank_pivot=CRANK_PIVOT, rocker_pivot=ROCKER_PIVOT)
    return Kinematics("path-five-points-real", "path synthesis: Morgan and Wampler's Problem 7, five points and both "
                      "pivots (33 complex, 15 real)", tuple(equations), tuple(unknowns), (), {}, own=_path_solved,
                      variable="c1")


def _problem(name: str, description: str, system: tuple[Sequence[flint.fmpq_mpoly], Sequence[str]]) -> Kinematics:
    equations, unknowns = system
    return Kinematics(name, description, tuple(equations), tuple(unknowns), (), {})


SYNTHESIS: dict[str, Callable[[], Kinematics]] = {
    "burmester-five-poses-real": lambda: _problem(
        "burmester-five-poses-real", "motion synthesis: the Burmester pairs of five poses (four real)",
        motion.system(_poses())),
    "freudenstein-five-pairs-real": lambda: _problem(
        "freudenstein-five-pairs-real", "function synthesis: five angle pairs, both starts unknown: the two "
        "minors on the circles of twice the starts (six real: three four-bars, three where the first three "
        "pairs alone fall in rank, which algkin.synthesis.function then drops)", _minors(_pairs())),
    "path-five-points-real": _path_problem,
}


def _minors(pairs: Sequence[AnglePair]) -> tuple[list[flint.fmpq_mpoly], list[str]]:
    """``function.system`` without its last equation (``w D - 1``, which leaves out the solutions
    where Cramer's determinant ``D`` vanishes): the system every peer and ``solve_group`` can take."""
    equations, unknowns = function.system(pairs, unknown_start=True)
    return equations[:-1], unknowns[:-1]
