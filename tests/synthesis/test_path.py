"""Five-point path generation with both ground pivots given (Morgan and Wampler 1990).

Expected values from independent sources: the general count 36 (Morgan and Wampler; the
twelve equations' Groebner basis in Singular, where installed); the straight-line example,
their Problem 7, with its count of solutions (33, 15 real) and one real four-bar as PHCpack's
documentation reports them (phcpy's "design of a 4-bar mechanism", numerical continuation);
a four-bar built by hand with rational dimensions, whose coupler point gives the five points;
and every real solution put back into the original distance equations with mpmath at 50 digits.
"""

from __future__ import annotations

import functools
import random
import shutil
import subprocess
from typing import NamedTuple

import flint
import mpmath
import pytest
import sympy

from algkin.errors import ComputationError, UsageError
from algkin.synthesis.path import GENERIC_COUNT, PathSolution, PathSynthesis, five_point_path, path_synthesis, system

Q = flint.fmpq


def _points(pairs: list[tuple[object, object]]) -> list[tuple[flint.fmpq, flint.fmpq]]:
    return [(Q(str(x)), Q(str(y))) if not isinstance(x, flint.fmpq) else (x, y) for x, y in pairs]


GENERIC = _points([(3, -2), (7, 5), (-4, 9), (11, -6), (2, 13)])
GENERIC_PIVOTS = {"crank_pivot": (Q(-5), Q(1)), "rocker_pivot": (Q(8), Q(-3))}

# Morgan and Wampler's Problem 7: five points on the line y = x + 0.56, pivots (0, 0) and (1, 0)
# (as phcpy's documentation copies them).
PROBLEM_7 = [(Q(50, 100), Q(106, 100)), (Q(-83, 100), Q(-27, 100)), (Q(-34, 100), Q(22, 100)),
             (Q(-13, 100), Q(43, 100)), (Q(22, 100), Q(78, 100))]
PROBLEM_7_PIVOTS = {"crank_pivot": (Q(0), Q(0)), "rocker_pivot": (Q(1), Q(0))}


def _random_data(seed: int) -> tuple[list[tuple[flint.fmpq, flint.fmpq]], dict[str, tuple[flint.fmpq, flint.fmpq]]]:
    rng = random.Random(seed)

    def number() -> flint.fmpq:
        return Q(rng.randint(-99, 99), rng.randint(1, 9))

    points = [(number(), number()) for _ in range(5)]
    return points, {"crank_pivot": (number(), number()), "rocker_pivot": (number(), number())}


def _mp(ball: flint.arb) -> mpmath.mpf:
    return mpmath.mpf(ball.mid().str(60, radius=False))


def _distance_errors(result: PathSynthesis) -> list[mpmath.mpf]:
    """For every real solution, each dyad's |P_j + R_j z - pivot| - |P_0 + z - pivot| (j = 1..4),
    and cos**2 + sin**2 - 1, at 50 digits, from the solution's balls."""
    errors = []
    with mpmath.workdps(50):
        points = [(mpmath.mpf(int(x.p)) / int(x.q), mpmath.mpf(int(y.p)) / int(y.q)) for x, y in result.points]
        for solution in result.solutions:
            turns = [(mpmath.mpf(1), mpmath.mpf(0))] + [(_mp(c), _mp(s)) for c, s in solution.rotations]
            errors += [c * c + s * s - 1 for c, s in turns]
            for joint, pivot in ((solution.crank_joint, result.crank_pivot),
                                 (solution.rocker_joint, result.rocker_pivot)):
                z = (_mp(joint[0]) - points[0][0], _mp(joint[1]) - points[0][1])
                a = (mpmath.mpf(int(pivot[0].p)) / int(pivot[0].q), mpmath.mpf(int(pivot[1].p)) / int(pivot[1].q))
                lengths = [mpmath.hypot(p[0] + c * z[0] - s * z[1] - a[0], p[1] + s * z[0] + c * z[1] - a[1])
                           for p, (c, s) in zip(points, turns)]
                errors += [length - lengths[0] for length in lengths[1:]]
    return errors


def test_general_data_have_36_solutions() -> None:
    for seed in (1, 2):
        points, pivots = _random_data(seed)
        result = five_point_path(points, **pivots)
        assert result.complex_count == GENERIC_COUNT == 36
        assert result.size.resultant_degree == 72 and result.size.solution_degree == 36
        # every factor of the eliminant is accounted for: the solutions' or excluded with a reason
        assert result.size.solution_degree + sum(e.degree * e.multiplicity for e in result.excluded) == 72
        assert all(e.reason for e in result.excluded)


def test_general_data_spurious_factors_are_the_circle_points_and_dependent_rows() -> None:
    result = five_point_path(GENERIC, **GENERIC_PIVOTS)
    assert [(e.degree, e.multiplicity) for e in result.excluded] == [(2, 1), (2, 4), (2, 4), (2, 9)]
    once, crank, rocker, circle = (e.reason for e in result.excluded)
    assert "circle point (1 + t3**2 = 0)" in once
    assert {"crank's rows at theta_1, theta_2 are dependent" in r for r in (crank, rocker)} == {True, False}
    assert {"rocker's rows at theta_1, theta_2 are dependent" in r for r in (crank, rocker)} == {True, False}
    assert circle.startswith("theta_1 at a circle point (1 + t1**2 = 0)")


@pytest.mark.skipif(shutil.which("Singular") is None, reason="Singular is not installed")
def test_count_agrees_with_singular() -> None:
    """The twelve equations handed to Singular: a Groebner basis over a prime field, and the
    dimension of its quotient ring (the complex solutions with multiplicity)."""
    for points, pivots in ((GENERIC, GENERIC_PIVOTS), _random_data(1)):
        equations, names = system(points, **pivots)
        script = (f"ring r = 32003, ({','.join(names)}), dp;\n"
                  f"ideal I = {', '.join(str(e) for e in equations)};\n"
                  "ideal G = std(I); print(dim(G)); print(vdim(G)); quit;\n")
        run = subprocess.run(["Singular", "-q"], input=script, capture_output=True, text=True, timeout=60)
        dimension, count = run.stdout.split()
        assert (dimension, count) == ("0", "36")
        assert five_point_path(points, **pivots).complex_count == int(count)


def test_morgan_wampler_problem_7() -> None:
    """Five points on a line: 33 solutions, 15 real (phcpy's documentation of Problem 7), one of
    them the straight-line four-bar it draws: z = (-0.0877960434509, -0.851386907516) for the
    crank at (0, 0), (0.235837391307, -1.41899202704) for the rocker at (1, 0), turned by
    1.44734213756, 0.928413708131, 0.751699211109, 0.387116282208 radians."""
    result = five_point_path(PROBLEM_7, **PROBLEM_7_PIVOTS)
    assert (result.complex_count, result.real_count) == (33, 15)
    x0, y0 = 0.50, 1.06
    drawn = [s for s in result.solutions
             if abs(float(s.crank_joint[0].mid()) - (x0 - 0.0877960434509)) < 1e-9
             and abs(float(s.crank_joint[1].mid()) - (y0 - 0.851386907516)) < 1e-9]
    assert len(drawn) == 1
    solution, = drawn
    assert abs(float(solution.rocker_joint[0].mid()) - (x0 + 0.235837391307)) < 1e-9
    assert abs(float(solution.rocker_joint[1].mid()) - (y0 - 1.41899202704)) < 1e-9
    for (c, s), angle in zip(solution.rotations, (1.44734213756, 0.928413708131, 0.751699211109, 0.387116282208)):
        assert abs(float(c.mid()) - mpmath.cos(angle)) < 1e-9 and abs(float(s.mid()) - mpmath.sin(angle)) < 1e-9
    # collinear data: theta_1 = 0 (t1 = 0) is a spurious root, said so
    zero, = [e for e in result.excluded if e.factor == "t1"]
    assert "joint is undetermined or at infinity" in zero.reason


class Known(NamedTuple):
    points: list[tuple[sympy.Expr, sympy.Expr]]
    turns: list[tuple[sympy.Expr, sympy.Expr]]
    crank_joint: tuple[sympy.Expr, ...]
    rocker_joint: tuple[sympy.Expr, ...]
    crank_pivot: tuple[sympy.Expr, sympy.Expr]
    rocker_pivot: tuple[sympy.Expr, sympy.Expr]
    rocker2: sympy.Expr


def _known_fourbar(*, held: bool = False, count: int = 5) -> Known:
    """A four-bar with rational dimensions (crank 2 at (0, 0), coupler 5, rocker pivot (4, 0))
    at ``count`` configurations where every angle has rational cos and sin: from one configuration,
    the others by the two involutions of its configuration curve (the crank held, the coupler's
    other assembly; the coupler's direction held, the crank's other place), each the other root
    of a quadratic with one rational root. Its coupler point: (1, 2) in the coupler's frame."""
    u, v = sympy.symbols("u v")
    crank_pivot, rocker_pivot = (sympy.Integer(0), sympy.Integer(0)), (sympy.Integer(4), sympy.Integer(0))
    crank, coupler, w = sympy.Integer(2), sympy.Integer(5), (sympy.Integer(1), sympy.Integer(2))

    def unit(t: sympy.Expr) -> tuple[sympy.Expr, sympy.Expr]:
        return (1 - t**2) / (1 + t**2), 2 * t / (1 + t**2)

    def joints(a: sympy.Expr, b: sympy.Expr) -> tuple[tuple[sympy.Expr, ...], tuple[sympy.Expr, ...]]:
        first = tuple(p + crank * e for p, e in zip(crank_pivot, unit(a)))
        return first, tuple(p + coupler * e for p, e in zip(first, unit(b)))

    start = (sympy.Rational(1, 3), sympy.Rational(1, 2))
    rocker2 = sum((j - p)**2 for j, p in zip(joints(*start)[1], rocker_pivot))
    d = [q - p for p, q in zip(crank_pivot, rocker_pivot)]
    ea, eb = (1 - u**2, 2 * u), (1 - v**2, 2 * v)
    curve = sympy.expand(2 * crank * coupler * (ea[0] * eb[0] + ea[1] * eb[1])
                         - 2 * crank * (ea[0] * d[0] + ea[1] * d[1]) * (1 + v**2)
                         - 2 * coupler * (eb[0] * d[0] + eb[1] * d[1]) * (1 + u**2)
                         + (crank**2 + coupler**2 + d[0]**2 + d[1]**2 - rocker2) * (1 + u**2) * (1 + v**2))

    def other(var: sympy.Symbol, fixed: dict[sympy.Symbol, sympy.Expr], known: sympy.Expr) -> sympy.Expr:
        quadratic = sympy.Poly(curve.subs(fixed), var).all_coeffs()
        return -quadratic[1] / quadratic[0] - known

    configurations = [start]
    a, b = start
    while len(configurations) < count:  # both involutions in turn (``held``: each configuration kept,
        b = other(v, {u: a}, b)     # two in turn sharing the crank's angle or the coupler's)
        if held:
            configurations.append((a, b))
        a = other(u, {v: b}, a)
        configurations.append((a, b))
    configurations = configurations[:count]
    points, turns = [], []
    for a, b in configurations:
        first, _ = joints(a, b)
        c, s = unit(b)
        points.append((first[0] + c * w[0] - s * w[1], first[1] + s * w[0] + c * w[1]))
        c0, s0 = unit(configurations[0][1])
        turns.append((c * c0 + s * s0, s * c0 - c * s0))  # turned from configuration 0
    crank_joint, rocker_joint = joints(*configurations[0])
    for a, b in configurations:  # the rocker keeps its length: a four-bar indeed
        assert sum((j - p)**2 for j, p in zip(joints(a, b)[1], rocker_pivot)) == rocker2
    return Known(points, turns[1:], crank_joint, rocker_joint, crank_pivot, rocker_pivot, rocker2)


def _fmpq(value: sympy.Expr) -> flint.fmpq:
    rational = sympy.Rational(value)
    return Q(int(rational.p), int(rational.q))


def test_a_known_four_bar_is_among_the_solutions() -> None:
    known = _known_fourbar()
    points = [(_fmpq(x), _fmpq(y)) for x, y in known.points]
    result = five_point_path(points, crank_pivot=(_fmpq(known.crank_pivot[0]), _fmpq(known.crank_pivot[1])),
                             rocker_pivot=(_fmpq(known.rocker_pivot[0]), _fmpq(known.rocker_pivot[1])))
    assert 0 < result.complex_count <= GENERIC_COUNT

    def holds(ball: flint.arb, value: sympy.Expr) -> bool:
        with flint.ctx.workprec(300):
            return (ball - flint.arb(_fmpq(value))).contains(0)

    found = [s for s in result.solutions
             if all(holds(b, x) for b, x in zip(s.crank_joint, known.crank_joint))
             and all(holds(b, x) for b, x in zip(s.rocker_joint, known.rocker_joint))]
    assert len(found) == 1
    solution, = found
    for (c, s), (cos, sin) in zip(solution.rotations, known.turns):
        assert holds(c, cos) and holds(s, sin)
    assert solution.crank.contains(2) and solution.coupler.contains(5)
    with flint.ctx.workprec(300):
        assert (solution.rocker**2 - flint.arb(_fmpq(known.rocker2))).contains(0)
    # its turns have rational tangents: the solution is a rational root, known exactly: the
    # half-angle tangent of theta_1, sin / (1 + cos)
    assert result.offset.cos == 1
    cos, sin = known.turns[0]
    assert solution.root.exact() == _fmpq(sin / (1 + cos)) == Q(-11, 2)


def test_points_of_a_four_bar_with_its_crank_held_are_special_and_said_so() -> None:
    """Two of the points reached with the crank at one angle (the coupler's other assembly): the
    first resultant has a factor in t1 alone (for that turn, every t2 has a t3), which the
    elimination does not follow: a ComputationError, on one line."""
    known = _known_fourbar(held=True)
    points = [(_fmpq(x), _fmpq(y)) for x, y in known.points]
    with pytest.raises(ComputationError) as error:
        five_point_path(points, crank_pivot=(Q(0), Q(0)), rocker_pivot=(Q(4), Q(0)))
    assert "in one angle alone: the data are special" in str(error.value) and "\n" not in str(error.value)


KNOWN_PIVOTS = {"crank_pivot": (Q(0), Q(0)), "rocker_pivot": (Q(4), Q(0))}


@functools.cache
def _five_known(points: tuple[tuple[flint.fmpq, flint.fmpq], ...]) -> PathSynthesis:
    """``five_point_path`` of ``points`` with the known four-bar's pivots, solved once: the tests past
    five points compare with the solutions of the same five (the known four-bar's first five, whatever
    its count)."""
    return five_point_path(list(points), **KNOWN_PIVOTS)


def _holds(ball: flint.arb, value: sympy.Expr) -> bool:
    with flint.ctx.workprec(300):
        return (ball - flint.arb(_fmpq(value))).contains(0)


@pytest.mark.parametrize("count", [6, 7])
def test_more_points_of_a_known_four_bar_give_it_alone(count: int) -> None:
    """Past five points the problem is overdetermined: the four-bar the points came from is its
    one solution, complex ones counted, with the construction's turn at every point."""
    known = _known_fourbar(count=count)
    points = [(_fmpq(x), _fmpq(y)) for x, y in known.points]
    assert len(set(points)) == count
    result = path_synthesis(points, **KNOWN_PIVOTS)
    assert (result.complex_count, result.real_count) == (1, 1)
    solution, = result.solutions
    assert all(_holds(b, x) for b, x in zip(solution.crank_joint + solution.rocker_joint,
                                            known.crank_joint + known.rocker_joint))
    assert len(solution.rotations) == count - 1
    assert all(_holds(c, cos) and _holds(s, sin) for (c, s), (cos, sin) in zip(solution.rotations, known.turns))
    assert solution.crank.contains(2) and solution.coupler.contains(5)
    # the first five points' other solutions are all left out, each factor with the point it misses
    missed = [e for e in result.excluded if "miss point" in e.reason]
    assert sum(e.degree for e in missed) == _five_known(tuple(points[:5])).complex_count - 1


def test_five_points_are_the_five_point_problem() -> None:
    assert path_synthesis(GENERIC, **GENERIC_PIVOTS) == five_point_path(GENERIC, **GENERIC_PIVOTS)


def _geometric_miss(solution: PathSolution, result: PathSynthesis, point: tuple[flint.fmpq, flint.fmpq]
                    ) -> mpmath.mpf:
    """How far the four-bar of ``solution`` is from putting its coupler point at ``point``, by
    geometry alone (50 digits): its joints there lie on their pivots' circles and on circles about
    the point of the coupler's own radii; of those, the pairs of the coupler's orientation are
    compared with the coupler's length. Infinity where no such pair exists."""
    def number(q: flint.fmpq) -> mpmath.mpf:
        return mpmath.mpf(int(q.p)) / int(q.q)

    def meeting(c1: tuple[mpmath.mpf, mpmath.mpf], r1: mpmath.mpf, c2: tuple[mpmath.mpf, mpmath.mpf],
                r2: mpmath.mpf) -> list[tuple[mpmath.mpf, mpmath.mpf]]:
        d = mpmath.hypot(c2[0] - c1[0], c2[1] - c1[1])
        along = (r1 * r1 - r2 * r2 + d * d) / (2 * d)
        if r1 * r1 < along * along:
            return []
        h = mpmath.sqrt(r1 * r1 - along * along)
        ux, uy = (c2[0] - c1[0]) / d, (c2[1] - c1[1]) / d
        base = (c1[0] + along * ux, c1[1] + along * uy)
        return [(base[0] - sign * h * uy, base[1] + sign * h * ux) for sign in (1, -1)]

    def cross(o: tuple[mpmath.mpf, ...], a: tuple[mpmath.mpf, ...], b: tuple[mpmath.mpf, ...]) -> mpmath.mpf:
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    with mpmath.workdps(50):
        p0, p = (tuple(number(v) for v in q) for q in (result.points[0], point))
        a, b = (tuple(number(v) for v in q) for q in (result.crank_pivot, result.rocker_pivot))
        ja, jb = (tuple(_mp(v) for v in joint) for joint in (solution.crank_joint, solution.rocker_joint))
        reach = {name: mpmath.hypot(j[0] - p0[0], j[1] - p0[1]) for name, j in (("a", ja), ("b", jb))}
        coupler, turning = mpmath.hypot(ja[0] - jb[0], ja[1] - jb[1]), cross(p0, ja, jb)
        crank, rocker = mpmath.hypot(ja[0] - a[0], ja[1] - a[1]), mpmath.hypot(jb[0] - b[0], jb[1] - b[1])
        gaps = [abs(mpmath.hypot(x[0] - y[0], x[1] - y[1]) - coupler)
                for x in meeting(a, crank, p, reach["a"]) for y in meeting(b, rocker, p, reach["b"])
                if cross(p, x, y) * turning > 0]
        return min(gaps, default=mpmath.inf)


def test_a_sixth_point_off_the_curve_is_reached_by_no_four_bar() -> None:
    """The known four-bar's sixth point moved by 1/1000: no four-bar through all six (complex ones
    counted: none), exit-0 answer; the five points' real four-bars each miss the moved point by
    geometry, while the known four-bar reaches the true one."""
    known = _known_fourbar(count=6)
    points = [(_fmpq(x), _fmpq(y)) for x, y in known.points]
    moved = points[:5] + [(points[5][0] + Q(1, 1000), points[5][1])]
    result = path_synthesis(moved, **KNOWN_PIVOTS)
    assert (result.complex_count, result.real_count, result.solutions) == (0, 0, ())
    five = _five_known(tuple(points[:5]))
    assert sum(e.degree for e in result.excluded if "miss point 5" in e.reason) == five.complex_count
    misses = [_geometric_miss(s, five, moved[5]) for s in five.solutions]
    assert len(misses) == five.real_count and min(misses) > 1e-6
    reached = [_geometric_miss(s, five, points[5]) for s in five.solutions]
    assert sorted(reached)[0] < 1e-40 < sorted(reached)[1]


def _parallel_conditions_point(known: Known) -> tuple[sympy.Expr, sympy.Expr]:
    """A point P (not a pivot) where the known four-bar's two dyads say the same of the coupler's
    turn up to a constant: the angle from ``P - pivot`` to the dyad's arm (joint minus coupler
    point) is the same for both, modulo 180 degrees (their dot and cross products proportional).
    Those points are a conic through both pivots: its second point on the diagonal through the
    crank's pivot (the rocker's is on the horizontal, the vertical is tangent to it)."""
    t = sympy.Symbol("t")
    p0 = known.points[0]
    arms = [tuple(j - q for j, q in zip(joint, p0)) for joint in (known.crank_joint, known.rocker_joint)]
    point = (known.crank_pivot[0] + t, known.crank_pivot[1] + t)
    d = [tuple(c - q for c, q in zip(point, pivot)) for pivot in (known.crank_pivot, known.rocker_pivot)]
    dot = [e[0] * a[0] + e[1] * a[1] for e, a in zip(d, arms)]
    cross = [e[0] * a[1] - e[1] * a[0] for e, a in zip(d, arms)]
    roots = [r for r in sympy.solve(sympy.factor(dot[0] * cross[1] - dot[1] * cross[0]), t) if r != 0]
    assert len(roots) == 1 and roots[0].is_rational
    return point[0].subs(t, roots[0]), point[1].subs(t, roots[0])


@pytest.mark.parametrize("sixth", ["crank pivot", "rocker pivot", "parallel conditions"])
def test_a_sixth_point_where_the_dyads_conditions_are_dependent_is_decided(sixth: str) -> None:
    """A sixth point where the known four-bar's two dyads' conditions on the coupler's turn are
    dependent (a pivot; a point where they are parallel lines in (cos, sin)) but contradict each
    other: a miss, exit-0 answer (was a ComputationError, "the data are special"). By geometry: the
    coupler point reaches a pivot only where that dyad's arm is as long as its link; otherwise
    ``_geometric_miss``."""
    known = _known_fourbar(count=6)
    points = [(_fmpq(x), _fmpq(y)) for x, y in known.points[:5]]
    target = {"crank pivot": known.crank_pivot, "rocker pivot": known.rocker_pivot,
              "parallel conditions": _parallel_conditions_point(known)}[sixth]
    result = path_synthesis(points + [(_fmpq(target[0]), _fmpq(target[1]))], **KNOWN_PIVOTS)
    assert (result.complex_count, result.real_count, result.solutions) == (0, 0, ())
    five = _five_known(tuple(points))
    assert sum(e.degree for e in result.excluded if "miss point 5" in e.reason) == five.complex_count
    with mpmath.workdps(50):
        for solution in five.solutions:
            if sixth == "parallel conditions":
                assert _geometric_miss(solution, five, (_fmpq(target[0]), _fmpq(target[1]))) > 1e-6
                continue
            joint, pivot = ((solution.crank_joint, five.crank_pivot) if sixth == "crank pivot"
                            else (solution.rocker_joint, five.rocker_pivot))
            arm = mpmath.hypot(_mp(joint[0]) - int(points[0][0].p) / mpmath.mpf(int(points[0][0].q)),
                               _mp(joint[1]) - int(points[0][1].p) / mpmath.mpf(int(points[0][1].q)))
            link = mpmath.hypot(_mp(joint[0]) - int(pivot[0].p), _mp(joint[1]) - int(pivot[1].p))
            assert abs(arm - link) > 1e-6


def test_special_first_five_points_say_that_another_order_may_do() -> None:
    """Two of the first five points at one distance from a pivot (its dyad's row between them
    vanishes at one turn: every arm satisfies it) make the five-point problem special; past five
    points the user can put others first, and is told so on the one line."""
    known = _known_fourbar(count=6)
    points = [(_fmpq(x), _fmpq(y)) for x, y in known.points]
    mirrored = (points[0][0], -points[0][1])  # as far from both pivots, on the x axis, as the first point
    with pytest.raises(ComputationError) as error:
        path_synthesis([points[0], mirrored] + points[1:], **KNOWN_PIVOTS)
    assert "give the points in another order" in str(error.value) and "\n" not in str(error.value)


@pytest.mark.parametrize(("points", "says"), [
    (GENERIC[:4], "at least five points"),
    (GENERIC + [GENERIC[2]], "points 2 and 5 are equal"),
])
def test_path_synthesis_bad_input_is_one_line(points: list[tuple[flint.fmpq, flint.fmpq]], says: str) -> None:
    with pytest.raises(UsageError) as error:
        path_synthesis(points, **GENERIC_PIVOTS)
    assert error.value.argument == "points" and says in str(error.value) and "\n" not in str(error.value)


@pytest.mark.parametrize("data", ["general", "problem 7"])
def test_every_real_solution_holds_in_the_original_equations(data: str) -> None:
    points, pivots = (GENERIC, GENERIC_PIVOTS) if data == "general" else (PROBLEM_7, PROBLEM_7_PIVOTS)
    result = five_point_path(points, **pivots, bits=200)
    assert result.solutions
    errors = _distance_errors(result)
    assert max(abs(e) for e in errors) < mpmath.mpf(10) ** -45
    for solution in result.solutions:  # the lengths reported are the joints' distances
        for ball in (solution.crank, solution.coupler, solution.rocker, *solution.crank_joint):
            assert ball.rad() < mpmath.mpf(2) ** -150 * max(1, abs(float(ball.mid())))


def test_solutions_are_told_by_their_exact_root() -> None:
    first, second = (five_point_path(GENERIC, **GENERIC_PIVOTS, bits=bits) for bits in (64, 128))
    assert first.solutions == second.solutions
    assert len(set(first.solutions)) == first.real_count


@pytest.mark.parametrize(("points", "pivots", "argument", "says"), [
    (GENERIC[:4], GENERIC_PIVOTS, "points", "exactly five points"),
    (GENERIC[:4] + GENERIC[1:2], GENERIC_PIVOTS, "points", "points 1 and 4 are equal"),
    (GENERIC, {"crank_pivot": (Q(1), Q(2)), "rocker_pivot": (Q(1), Q(2))}, "rocker_pivot", "equal to the crank's"),
])
def test_bad_input_is_one_line(points: list[tuple[flint.fmpq, flint.fmpq]],
                               pivots: dict[str, tuple[flint.fmpq, flint.fmpq]], argument: str, says: str) -> None:
    for call in (five_point_path, system):
        with pytest.raises(UsageError) as error:
            call(points, **pivots)
        assert error.value.argument == argument and says in str(error.value) and "\n" not in str(error.value)
