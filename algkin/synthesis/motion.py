"""Motion generation (Burmester theory): the dyads whose coupler point reaches given poses.

A dyad is a circle point ``c = (x, y)`` of the moving plane and a centre point ``C = (X, Y)``
of the fixed one, the crank ``|C - c|`` long: it reaches pose ``i`` when
``|pose_i.place(c) - C|**2`` is the same for every pose. That squared distance is
``|c|**2 + |C|**2`` plus terms linear in ``c`` and in ``C`` and one bilinear term, so pose
``i``'s equation minus the first's is **bilinear** in ``(x, y)`` and ``(X, Y)``:

- four poses give three equations: for a given ``C`` they are linear in ``(x, y, 1)``, and
  have a solution where their 3x3 determinant vanishes: the **centre-point curve**, a
  circular cubic in ``X, Y`` (``curves``); given ``c``, likewise the **circle-point curve**;
  each point of one is matched to a point of the other by the linear solve
  (``circle_point``, ``centre_point``);
- five poses give four equations in four unknowns: their solutions are the **Burmester
  pairs**, at most four (``burmester``). Bilinear equations in two pairs of unknowns have six
  solutions in the product of two projective planes: two of them are always the circular
  points at infinity (``c`` and ``C`` both there), outside the affine equations solved here,
  which leaves four. A solution with a zero-length crank would make ``C`` the fixed point of
  every displacement from the first pose: refused before solving (``_check_poses``), so no
  affine solution is degenerate; what elimination brings in and drops is listed in
  ``excluded``.

>>> q = flint.fmpq
>>> poses = [Pose(q(0), q(0), Angle.of_tan_half(q(0))), Pose(q(1), q(1, 2), Angle.of_tan_half(q(1, 3))),
...          Pose(q(2), q(3, 2), Angle.of_tan_half(q(2, 3))), Pose(q(3), q(1), Angle.of_tan_half(q(1)))]
>>> four = curves(poses)
>>> four.centre_curve.degree("X"), four.circle_curve.degree("x")
(3, 3)
>>> five = burmester(poses + [Pose(q(4), q(-1), Angle.of_tan_half(q(3, 2)))])
>>> five.complex_count, len(five.pairs)
(4, 2)
>>> [pair.centre[0].str(6, radius=False) for pair in five.pairs]
['-29.1544', '-3.57873']
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence

import attrs
import flint
import sympy

from ..eliminate.group import GroupSolution, Polynomial, modes, solve_group
from ..eliminate.group.records import Values
from ..eliminate.group.algebra import coefficients, primitive
from ..errors import ComputationError, UsageError
from ..system.roots import RealRoot
from .data import Angle, Point, Pose

__all__ = ["FourPoses", "FivePoses", "BurmesterPair", "curves", "circle_point", "centre_point", "burmester",
           "system", "UNKNOWNS"]

UNKNOWNS = ("X", "Y", "x", "y")
"""The centre point (fixed frame), then the circle point (moving frame); the centre's ``X``
is the separating variable tried first, so pairs come in increasing ``X``."""


@attrs.frozen
class FourPoses:
    """Four poses and their curves: the centre points (``X, Y``, fixed frame) and the circle
    points (``x, y``, moving frame) of every dyad reaching them, each with integer
    coefficients, primitive: a circular cubic, of lower degree where poses share an angle."""

    poses: tuple[Pose, ...]
    centre_curve: Polynomial
    circle_curve: Polynomial


@attrs.frozen
class BurmesterPair:
    """A dyad reaching five poses: its ``centre`` (fixed frame) and ``circle`` point (moving
    frame) in balls that hold the true values; told exactly by ``root``, the root of the
    eliminant (``FivePoses.solution``) it came from, ``index`` its rank among the real ones."""

    index: int
    root: RealRoot
    centre: tuple[flint.arb, flint.arb] = attrs.field(eq=False)
    circle: tuple[flint.arb, flint.arb] = attrs.field(eq=False)


@attrs.frozen
class FivePoses:
    """Five poses and their Burmester pairs: the real ones (``pairs``, in increasing order of
    the separating variable, the centre's ``X`` unless it fails to separate), and the number
    of complex solutions, real ones included (``complex_count``, at most four);
    ``solution``: the exact rational univariate representation they came from, None where
    there is no solution at all (every one at infinity: four poses of one angle, say);
    ``excluded``: the factors elimination brought into the eliminant, dropped, each with the
    reason."""

    poses: tuple[Pose, ...]
    pairs: tuple[BurmesterPair, ...]
    complex_count: int
    solution: GroupSolution | None
    excluded: tuple[tuple[str, str], ...] = ()


def system(poses: Sequence[Pose]) -> tuple[list[flint.fmpq_mpoly], list[str]]:
    """The dyad's equations for four or five poses: pose ``i``'s squared distance from the
    circle point to the centre minus the first pose's, made primitive with integer
    coefficients; and the unknowns ``X, Y`` (centre), ``x, y`` (circle point).

    >>> q = flint.fmpq
    >>> still, turned = Pose(q(0), q(0), Angle(q(1), q(0))), Pose(q(2), q(0), Angle(q(0), q(1)))
    >>> shifted = Pose(q(0), q(2), Angle(q(0), q(1)))
    >>> equations, unknowns = system([still, turned, shifted, Pose(q(1), q(1), Angle(q(-1), q(0)))])
    >>> unknowns, [str(e) for e in equations][:2]
    (['X', 'Y', 'x', 'y'], ['X*x + X*y - 2*X - Y*x + Y*y - 2*y + 2', 'X*x + X*y - Y*x + Y*y - 2*Y + 2*x + 2'])
    """
    _check_poses(poses, counts=(4, 5))
    return _equations(poses), list(UNKNOWNS)


def curves(poses: Sequence[Pose]) -> FourPoses:
    """The centre-point and circle-point curves of four poses (the module's example).

    Given the centre, the three equations are linear in ``(x, y, 1)``: a circle point exists
    where their determinant vanishes, a cubic in ``X, Y``; the same with the roles swapped."""
    _check_poses(poses, counts=(4,))
    equations = _equations(poses)
    centre = _curve(equations, solve_for=("x", "y"), names=("X", "Y"))
    circle = _curve(equations, solve_for=("X", "Y"), names=("x", "y"))
    return FourPoses(tuple(poses), centre, circle)


def circle_point(poses: Sequence[Pose], centre: Point) -> Point | None:
    """The circle point matched to a ``centre`` on the centre-point curve of four poses,
    exactly: the one solution of the equations, linear in it; None where that solution is not
    unique (the equations of rank 1) or lies at infinity. A UsageError where ``centre`` is off
    the curve.

    >>> q = flint.fmpq
    >>> on_circle = [(5, 0), (3, 4), (0, 5), (-4, 3)]        # the moving origin's positions, 5 from (0, 0)
    >>> poses = [Pose(q(x), q(y), Angle.of_tan_half(t)) for (x, y), t in zip(on_circle, [q(0), q(1, 3), q(1, 2), q(1)])]
    >>> [str(v) for v in circle_point(poses, (q(0), q(0)))]
    ['0', '0']
    >>> circle_point(poses, (q(3), q(1)))
    Traceback (most recent call last):
    ...
    algkin.errors.UsageError: centre=('3', '1'): not on the centre-point curve of these poses
    """
    return _matched(poses, centre, known=("X", "Y"), unknown=("x", "y"), argument="centre")


def centre_point(poses: Sequence[Pose], circle: Point) -> Point | None:
    """The centre point matched to a ``circle`` point on the circle-point curve of four poses,
    exactly (``circle_point`` the other way): the centre of the circle through the circle
    point's four positions.

    >>> q = flint.fmpq
    >>> poses = [Pose(q(0), q(0), Angle(q(1), q(0))), Pose(q(2), q(0), Angle(q(0), q(1))),
    ...          Pose(q(0), q(2), Angle(q(0), q(1))), Pose(q(2), q(2), Angle(q(-1), q(0)))]
    >>> [str(v) for v in centre_point(poses, (q(0), q(0)))]     # the origin's positions: a square's corners
    ['1', '1']
    >>> circle_point(poses, (q(1), q(1))) is None     # the pole of two displacements: 1 to 2 and 1 to 4
    True
    """
    return _matched(poses, circle, known=("x", "y"), unknown=("X", "Y"), argument="circle")


def burmester(poses: Sequence[Pose], *, bits: int = 128) -> FivePoses:
    """The Burmester pairs of five poses (the module's example): every real one, its centre
    and circle point in balls of radius about ``2**-bits`` relative, and the complex count.

    The four equations (``system``) are solved by ``solve_group``, exactly: an eliminant in
    the separating variable, every other unknown rational in its root; the real roots
    certified (``modes``). No solution at all, even complex, is an answer: no pairs, a
    complex count of 0. A UsageError for degenerate poses (``_check_poses``), or where the
    equations are not zero-dimensional.

    >>> q, turn = flint.fmpq, Angle(flint.fmpq(0), flint.fmpq(1))
    >>> translated = [Pose(q(x), q(y), turn) for x, y in [(-4, 3), (1, 2), (4, -4), (-3, -2)]]
    >>> burmester(translated + [Pose(q(0), q(-3), Angle(q(4, 5), q(-3, 5)))]).complex_count
    0
    """
    _check_poses(poses, counts=(5,))
    equations = _equations(poses)
    try:
        solution = solve_group(equations, list(UNKNOWNS))
    except ComputationError:
        if _solutions(poses, equations):
            raise
        return FivePoses(tuple(poses), (), 0, None)
    pairs = tuple(BurmesterPair(mode.index, mode.root, (mode.values["X"], mode.values["Y"]),
                                (mode.values["x"], mode.values["y"]))
                  for mode in modes(solution, {}, bits=bits + 16) if mode.root is not None)
    # modes refines each root until a value's radius is 2**(16 - bits) relative: 16 bits more than asked
    excluded = tuple((str(factor), "brought in by elimination (a multiplier's factor): the lifts fail the "
                      "equations at its roots") for factor in solution.dropped)
    return FivePoses(tuple(poses), pairs, solution.complex_count, solution, excluded)


def _equations(poses: Sequence[Pose]) -> list[flint.fmpq_mpoly]:
    ctx = flint.fmpq_mpoly_ctx.get(UNKNOWNS, "lex")
    big_x, big_y, x, y = ctx.gens()

    def squared(pose: Pose) -> flint.fmpq_mpoly:
        px, py = pose.place(x, y)
        return (px - big_x)**2 + (py - big_y)**2

    first = squared(poses[0])
    return [primitive(squared(pose) - first) for pose in poses[1:]]


def _rows(equations: Sequence[flint.fmpq_mpoly], solve_for: tuple[str, str]) -> list[list[flint.fmpq_mpoly]]:
    """Each equation's coefficients of ``solve_for[0]``, ``solve_for[1]`` and 1: polynomials in the other pair."""
    u, v = solve_for
    rows = []
    for equation in equations:
        free_u, with_u = (coefficients(equation, u) + [equation.context().from_dict({})])[:2]
        free_uv, with_v = (coefficients(free_u, v) + [equation.context().from_dict({})])[:2]
        rows.append([with_u, with_v, free_uv])
    return rows


def _curve(equations: Sequence[flint.fmpq_mpoly], *, solve_for: tuple[str, str], names: tuple[str, str]) -> Polynomial:
    (a, b, c), (d, e, f), (g, h, i) = _rows(equations, solve_for)
    determinant = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g)
    if determinant.is_zero():  # every pose a turn about one point does it, refused by _check_poses; no other known
        raise ComputationError(f"the {'-'.join(names)} curve vanishes identically")
    home = flint.fmpq_mpoly_ctx.get(names, "lex")
    return Polynomial.of(primitive(determinant).project_to_context(home))


def _matched(poses: Sequence[Pose], point: Point, *, known: tuple[str, str], unknown: tuple[str, str],
             argument: str) -> Point | None:
    """The solution in ``unknown`` of the four poses' equations with ``known`` at ``point``."""
    _check_poses(poses, counts=(4,))
    at: Values = {known[0]: flint.fmpq(point[0]), known[1]: flint.fmpq(point[1])}
    rows = [[_number(p.subs(at)) for p in row] for row in _rows(_equations(poses), unknown)]
    if flint.fmpq_mat(rows).det() != 0:
        raise UsageError(argument, tuple(str(v) for v in point), f"not on the {'centre' if argument == 'centre' else 'circle'}"
                         "-point curve of these poses")
    for first, second in itertools.combinations(rows, 2):
        kernel = _cross(first, second)
        if any(k != 0 for k in kernel):  # two independent rows: the rank is 2, the solution the kernel
            return None if kernel[2] == 0 else (kernel[0] / kernel[2], kernel[1] / kernel[2])
    return None


def _number(poly: flint.fmpq_mpoly) -> flint.fmpq:
    return poly.coeffs()[0] if not poly.is_zero() else flint.fmpq(0)


def _cross(u: Sequence[flint.fmpq], v: Sequence[flint.fmpq]) -> tuple[flint.fmpq, flint.fmpq, flint.fmpq]:
    return u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]


def _check_poses(poses: Sequence[Pose], *, counts: tuple[int, ...]) -> None:
    """A UsageError unless there are ``counts`` poses, no two equal, not all of one angle, and
    not all turns of the first about one point (then every circle point has that point for
    centre, with a zero-length crank at its preimage: the equations are not zero-dimensional)."""
    if len(poses) not in counts:
        raise UsageError("poses", len(poses), f"needs {' or '.join(map(str, counts))} poses, not {len(poses)}")
    keys = [(p.x, p.y, p.angle.cos, p.angle.sin) for p in poses]
    for (i, one), (j, other) in itertools.combinations(enumerate(keys, 1), 2):
        if one == other:
            raise UsageError("poses", len(poses), f"poses {i} and {j} are the same pose")
    if all(_same_angle(p.angle, poses[0].angle) for p in poses):
        raise UsageError("poses", len(poses), "every pose has the same angle (a pure translation): no dyad is "
                         "determined by them (the equations are not zero-dimensional)")
    poles = {_pole(poses[0], p) for p in poses[1:]}
    if len(poles) == 1 and None not in poles:
        (pole,) = poles
        assert pole is not None
        raise UsageError("poses", len(poses), f"every pose is the first turned about one point, ({pole[0]}, {pole[1]}): "
                         "every circle point has it for centre (the equations are not zero-dimensional)")


def _same_angle(one: Angle, other: Angle) -> bool:
    return bool(one.cos == other.cos and one.sin == other.sin)


def _pole(first: Pose, second: Pose) -> Point | None:
    """The fixed point of the displacement from ``first`` to ``second``; None for a translation.
    The displacement is ``p -> R p + t`` (``R`` the turn by the angle between them); its fixed
    point solves ``(I - R) p = t``."""
    if _same_angle(first.angle, second.angle):
        return None
    # R = R2 R1^-1: the turn by angle2 - angle1
    cos = second.angle.cos * first.angle.cos + second.angle.sin * first.angle.sin
    sin = second.angle.sin * first.angle.cos - second.angle.cos * first.angle.sin
    turned = Angle(cos, sin).rotate(first.x, first.y)
    tx, ty = second.x - turned[0], second.y - turned[1]
    # (I - R)^-1 = ((1 - cos) I + sin J) / ((1 - cos)**2 + sin**2), J the quarter turn
    scale = (1 - cos)**2 + sin**2
    return ((1 - cos) * tx - sin * ty) / scale, (sin * tx + (1 - cos) * ty) / scale


def _solutions(poses: Sequence[Pose], equations: Sequence[flint.fmpq_mpoly]) -> bool:
    """Where ``solve_group`` failed: whether the equations have a solution (a Groebner basis
    says); a UsageError if they have infinitely many."""
    symbols = sympy.symbols(UNKNOWNS)
    basis = sympy.groebner([sympy.sympify(str(e).replace("^", "**")) for e in equations], *symbols, order="grevlex")
    if basis.exprs == [1]:
        return False
    if not basis.is_zero_dimensional:
        raise UsageError("poses", len(poses), "the poses are degenerate: the dyads reaching them form a curve, "
                         "not finitely many pairs (the equations are not zero-dimensional)")
    return True
