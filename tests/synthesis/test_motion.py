"""Motion generation (Burmester theory), every expected value found independently of the code:

- four poses: the poles (fixed points of the displacements, solved by sympy from their
  definition) lie on the centre-point curve exactly, their preimages on the circle-point curve;
  a circle point's circumcentre (sympy) is on the curve exactly when its fourth position is on
  that circle; the curves are circular cubics;
- five poses: the Burmester pairs against a lex Groebner basis of the same equations (sympy)
  and against Newton's method on the original dyad equations (five circles of one unknown
  radius R, in x, y, X, Y, R) from hundreds of complex starts, polished by mpmath at 50 digits:
  the same real pairs, inside their balls, and as many complex solutions; a pose set built
  around a known rational dyad finds it exactly; each pair reaches all five poses.
"""

import itertools
import random

import flint
import mpmath
import numpy as np
import pytest
import sympy

from algkin.errors import UsageError
from algkin.synthesis.data import Angle, Pose, dyad_poses
from algkin.synthesis.motion import burmester, centre_point, circle_point, curves, system

q = flint.fmpq
X, Y, x, y = sympy.symbols("X Y x y")


def _pose(px, py, cos, sin):
    return Pose(q(px), q(py), Angle.of_cos_sin(q(cos), q(sin)))


def _poses(rows):
    return [_pose(*row) for row in rows]


def _built(crank_halves, coupler_halves, *, circle, centre, radius):
    """Poses that the dyad (``circle``, ``centre``) reaches, the crank's and the plane's angles by half-angle tangents."""
    half = lambda t: Angle.of_tan_half(q(t))  # noqa: E731
    return dyad_poses([half(t) for t in crank_halves], [half(t) for t in coupler_halves],
                      circle=(q(circle[0]), q(circle[1])), centre=(q(centre[0]), q(centre[1])), radius=q(radius))


FOUR = _poses([(0, 0, 1, 0), (1, "1/2", "4/5", "3/5"), (2, "3/2", "5/13", "12/13"), (3, 1, 0, 1)])
CIRCLE, CENTRE = (1, 2), (3, -1)
FOUR_ON_DYAD = _built([0, "1/2", "1/3", 2], [0, "1/4", "2/3", 1], circle=CIRCLE, centre=CENTRE, radius=5)

DOCSTRING = FOUR + [Pose(q(4), q(-1), Angle.of_tan_half(q(3, 2)))]              # the module's example
FOUR_REAL = _poses([(-2, -3, 0, -1), (3, 3, 1, 0), (2, -1, "-5/13", "-12/13"), (-4, 2, 1, 0), (-4, 3, "4/5", "-3/5")])
NONE_REAL = _poses([(-1, -3, 0, -1), (-4, -4, "5/13", "12/13"), (-4, 2, "-3/5", "4/5"), (2, -4, 0, 1),
                    (3, 3, 0, 1)])
# poses 3 and 5 of one angle: a solution goes to infinity
ONE_OF_THREE = _poses([(4, 1, 1, 0), (-4, -1, "-3/5", "4/5"), (4, -2, "-4/5", "3/5"), (4, 0, 0, -1),
                       (-3, -3, "-4/5", "3/5")])
ON_DYAD = _built([0, "1/2", "1/3", 2, "-1/2"], [0, "1/4", "2/3", 1, "-1/3"], circle=CIRCLE, centre=CENTRE, radius=5)
FIVE_SETS = {"docstring": DOCSTRING, "four real": FOUR_REAL, "none real": NONE_REAL, "one of three": ONE_OF_THREE,
             "on a dyad": ON_DYAD}


# ---------------------------------------------------------------- exact geometry, by sympy


def _rational(value):
    return sympy.Rational(int(value.p), int(value.q))


def _placed(pose, point):
    """The moving plane's ``point`` in ``pose``, in sympy."""
    cos, sin = _rational(pose.angle.cos), _rational(pose.angle.sin)
    return (_rational(pose.x) + cos * point[0] - sin * point[1], _rational(pose.y) + sin * point[0] + cos * point[1])


def _pole(one, other):
    """The fixed point of the displacement from ``one`` to ``other``: where a point of the moving
    plane is in both, solved from that definition."""
    u, v = sympy.symbols("u v")
    first, second = _placed(one, (u, v)), _placed(other, (u, v))
    (solution,) = sympy.linsolve([first[0] - second[0], first[1] - second[1]], [u, v])
    return _placed(one, solution), solution


def _circumcentre(a, b, c):
    (solution,) = sympy.linsolve([sympy.expand((X - a[0])**2 + (Y - a[1])**2 - (X - p[0])**2 - (Y - p[1])**2)
                                  for p in (b, c)], [X, Y])
    return solution


def _squared(p, centre):
    return (p[0] - centre[0])**2 + (p[1] - centre[1])**2


def _expr(polynomial):
    return sympy.sympify(str(polynomial))


# ---------------------------------------------------------------- four poses


@pytest.mark.parametrize("poses", [FOUR, FOUR_ON_DYAD], ids=["generic", "on a dyad"])
def test_every_pole_is_on_the_centre_curve_and_its_preimage_on_the_circle_curve(poses):
    four = curves(poses)
    centre_curve, circle_curve = _expr(four.centre_curve), _expr(four.circle_curve)
    for one, other in itertools.combinations(poses, 2):
        pole, preimage = _pole(one, other)
        assert centre_curve.subs({X: pole[0], Y: pole[1]}) == 0
        assert circle_curve.subs({x: preimage[0], y: preimage[1]}) == 0


def test_a_circumcentre_is_on_the_centre_curve_exactly_when_the_fourth_position_is_on_its_circle():
    rng = random.Random(5)
    circles = [(sympy.Rational(rng.randint(-9, 9), rng.randint(1, 5)), sympy.Rational(rng.randint(-9, 9), 3))
               for _ in range(6)]
    for poses, points in [(FOUR, circles), (FOUR_ON_DYAD, circles + [CIRCLE])]:
        centre_curve = _expr(curves(poses).centre_curve)
        seen = set()
        for point in points:
            positions = [_placed(pose, point) for pose in poses]
            centre = _circumcentre(*positions[:3])
            on_circle = _squared(positions[3], centre) == _squared(positions[0], centre)
            assert (centre_curve.subs({X: centre[0], Y: centre[1]}) == 0) == on_circle
            seen.add(on_circle)
    assert seen == {True, False}


@pytest.mark.parametrize("poses", [FOUR, FOUR_ON_DYAD], ids=["generic", "on a dyad"])
def test_the_curves_are_circular_cubics(poses):
    four = curves(poses)
    for curve, (u, v) in [(four.centre_curve, (X, Y)), (four.circle_curve, (x, y))]:
        poly = sympy.Poly(_expr(curve), u, v)
        assert poly.total_degree() == 3
        assert all(c.is_integer for c in poly.coeffs()) and sympy.gcd_list(poly.coeffs()) == 1
        cubic = sum(c * u**i * v**j for (i, j), c in poly.terms() if i + j == 3)
        assert sympy.rem(cubic, u**2 + v**2, u) == 0


def test_matched_points_are_the_dyad_the_poses_were_built_on():
    assert circle_point(FOUR_ON_DYAD, (q(3), q(-1))) == (1, 2)
    assert centre_point(FOUR_ON_DYAD, (q(1), q(2))) == (3, -1)


@pytest.mark.parametrize("poses", [FOUR, FOUR_ON_DYAD], ids=["generic", "on a dyad"])
def test_a_poles_matched_circle_point_is_equally_far_from_it_in_every_pose(poses):
    for one, other in [(0, 1), (1, 3), (2, 3)]:
        pole, _ = _pole(poses[one], poses[other])
        matched = circle_point(poses, (q(int(pole[0].p), int(pole[0].q)), q(int(pole[1].p), int(pole[1].q))))
        assert matched is not None
        point = (_rational(matched[0]), _rational(matched[1]))
        assert len({_squared(_placed(pose, point), pole) for pose in poses}) == 1
        back = centre_point(poses, matched)
        assert back is None or back == (pole[0], pole[1])


def test_a_point_off_the_curve_is_refused():
    with pytest.raises(UsageError, match="not on the centre-point curve"):
        circle_point(FOUR, (q(7), q(7)))
    with pytest.raises(UsageError, match="not on the circle-point curve"):
        centre_point(FOUR, (q(7), q(7)))


# ---------------------------------------------------------------- five poses


def _ball_holds(ball, value):
    """Whether ``ball`` holds ``value`` (50 digits: a slack of 1e-45 for its error)."""
    with mpmath.workdps(60):
        mid, rad = mpmath.mpf(ball.mid().str(60, radius=False)), mpmath.mpf(ball.rad().str(5, radius=False))
        return abs(value - mid) <= rad + mpmath.mpf(10)**-45


def _pair_holds(pair, values):
    """Whether ``pair``'s balls hold the solution ``values`` (X, Y, x, y)."""
    balls = pair.centre + pair.circle
    return all(_ball_holds(b, v) for b, v in zip(balls, values))


def _groebner_solutions(poses):
    """The complex count and the real solutions (X, Y, x, y), at 50 digits, from a lex Groebner
    basis of the same equations (x > y > Y > X: in shape position, the last a polynomial in X)."""
    equations, _ = system(poses)
    basis = sympy.groebner([_expr(e) for e in equations], x, y, Y, X, order="lex")
    *linear, last = basis.exprs
    assert [sympy.Poly(g, x, y, Y, X).monoms()[0][:3] for g in linear] == [(1, 0, 0), (0, 1, 0), (0, 0, 1)]
    eliminant = sympy.Poly(last, X)
    assert sympy.degree(sympy.gcd(eliminant, eliminant.diff(X)), X) == 0
    found = []
    lifts = {v: sympy.solve(g, v)[0] for g, v in zip(linear, (x, y, Y))}     # each a polynomial in X
    for root in eliminant.real_roots():
        values = [root] + [lifts[v].subs(X, root) for v in (Y, x, y)]
        with mpmath.workdps(60):
            found.append(tuple(mpmath.mpf(str(sympy.N(v, 60))) for v in values))
    return eliminant.degree(), found


def _numeric_solutions(poses, *, starts=400, seed=0):
    """Every solution (X, Y, x, y) found by Newton's method on the original dyad equations,
    |pose_i.place(c) - C|**2 = R**2 in x, y, X, Y, R: in floats from ``starts`` random complex
    starts, each converged one polished by mpmath at 50 digits, deduplicated (R and -R alike)."""
    data = [(complex(p.x), complex(p.y), complex(p.angle.cos), complex(p.angle.sin)) for p in poses]
    rng = np.random.default_rng(seed)
    z = (rng.normal(size=(starts, 5)) + 1j * rng.normal(size=(starts, 5))) * 4
    for _ in range(100):
        z = z - np.linalg.solve(_jacobian(z, data, np), _residuals(z, data, np)[..., None])[..., 0]
        z[~np.isfinite(z).all(axis=1)] = 1e6
    residuals = np.abs(_residuals(z, data, np)).max(axis=1)
    distinct = []
    for start in z[(residuals < 1e-8) & (np.abs(z).max(axis=1) < 1e5)]:
        if all(np.abs(start[:4] - other[:4]).max() > 1e-6 for other in distinct):   # R and -R alike
            distinct.append(start)
    found = []
    with mpmath.workdps(50):
        exact = [tuple(mpmath.mpf(int(v.p)) / int(v.q) for v in (p.x, p.y, p.angle.cos, p.angle.sin)) for p in poses]
        for start in distinct:
            root = mpmath.findroot(lambda *v: _residuals(v, exact, mpmath), [mpmath.mpc(s) for s in start],
                                   tol=mpmath.mpf(10)**-45)
            assert max(abs(r) for r in _residuals(list(root), exact, mpmath)) < mpmath.mpf(10)**-40
            solution = tuple(root[k] for k in (2, 3, 0, 1))                 # X, Y, x, y
            assert all(max(abs(a - b) for a, b in zip(solution, other)) > mpmath.mpf(10)**-30 for other in found)
            found.append(solution)
    return found


def _residuals(v, data, m):
    """|pose_i.place(c) - C|**2 - R**2 for each pose; ``v`` = (x, y, X, Y, R), over numpy or mpmath (``m``)."""
    x_, y_, big_x, big_y, radius = (v[..., k] for k in range(5)) if m is np else v
    rows = [(dx + c * x_ - s * y_ - big_x)**2 + (dy + s * x_ + c * y_ - big_y)**2 - radius**2 for dx, dy, c, s in data]
    return np.stack(rows, axis=-1) if m is np else rows


def _jacobian(z, data, m):
    x_, y_, big_x, big_y, radius = (z[..., k] for k in range(5))
    rows = []
    for dx, dy, c, s in data:
        u, w = dx + c * x_ - s * y_ - big_x, dy + s * x_ + c * y_ - big_y
        rows.append(np.stack([2 * (u * c + w * s), 2 * (-u * s + w * c), -2 * u, -2 * w, -2 * radius], axis=-1))
    return np.stack(rows, axis=-2)


@pytest.mark.parametrize("name", list(FIVE_SETS))
def test_the_pairs_are_those_of_a_groebner_basis(name):
    five = burmester(FIVE_SETS[name])
    count, real = _groebner_solutions(FIVE_SETS[name])
    assert five.complex_count == count
    assert len(five.pairs) == len(real)
    for pair, values in zip(five.pairs, sorted(real)):          # both in increasing X
        assert _pair_holds(pair, values)


@pytest.mark.parametrize("name", list(FIVE_SETS))
def test_the_pairs_are_every_real_solution_of_the_dyad_equations_and_the_count_every_complex_one(name):
    five = burmester(FIVE_SETS[name])
    found = _numeric_solutions(FIVE_SETS[name])
    real = [s for s in found if max(abs(mpmath.im(v)) for v in s) < mpmath.mpf(10)**-30]
    assert len(found) == five.complex_count
    assert len(real) == len(five.pairs)
    for values in real:
        assert sum(_pair_holds(pair, [mpmath.re(v) for v in values]) for pair in five.pairs) == 1


def test_the_counts_are_those_expected():
    counts = {name: (len(burmester(poses).pairs), burmester(poses).complex_count) for name, poses in FIVE_SETS.items()}
    assert counts == {"docstring": (2, 4), "four real": (4, 4), "none real": (0, 4), "one of three": (1, 3),
                      "on a dyad": (4, 4)}


def test_the_dyad_the_poses_were_built_on_is_found_exactly():
    five = burmester(ON_DYAD)
    (pair,) = [p for p in five.pairs if p.centre[0].contains(3)]
    assert five.solution is not None and five.solution.variable == "X"
    assert pair.root.exact() == 3                                    # X = 3: a rational root of the eliminant
    assert all(b.contains(v) for b, v in zip(pair.centre + pair.circle, (3, -1, 1, 2)))


@pytest.mark.parametrize("name", list(FIVE_SETS))
def test_each_pair_reaches_all_five_poses(name):
    five = burmester(FIVE_SETS[name])
    for pair in five.pairs:
        squared = []
        with flint.ctx.workprec(200):
            for p in five.poses:
                u = p.x + p.angle.cos * pair.circle[0] - p.angle.sin * pair.circle[1] - pair.centre[0]
                w = p.y + p.angle.sin * pair.circle[0] + p.angle.cos * pair.circle[1] - pair.centre[1]
                squared.append(u * u + w * w)           # not w**2: python-flint's power of a ball holding 0 is nan
        assert all(s.overlaps(squared[0]) for s in squared)
        assert squared[0] > 0 and squared[0].rad() < flint.arb(2)**-100 * squared[0]


def test_the_balls_are_as_narrow_as_asked():
    for bits in (64, 300):
        for pair in burmester(FOUR_REAL, bits=bits).pairs:
            for ball in pair.centre + pair.circle:
                assert ball.rad() <= flint.arb(2)**-bits * max(abs(ball.mid()), flint.arb(1))


@pytest.mark.parametrize("name", ["docstring", "four real", "none real", "on a dyad"])
def test_the_two_solutions_beyond_the_four_are_the_circular_points_at_infinity(name):
    """Four bilinear equations in two planes have 6 solutions in the product of two projective
    planes (the coefficient of a**2 b**2 in (a + b)**4); two are the circle and centre point
    both at a circular point at infinity, (1, i, 0) or (1, -i, 0), where every bihomogenized
    equation vanishes; the other four are affine, and none was excluded."""
    w, big_w = sympy.symbols("w W")
    equations, _ = system(FIVE_SETS[name])
    homogeneous = [sympy.expand(_expr(e).subs({x: x / w, y: y / w, X: X / big_w, Y: Y / big_w}) * w * big_w)
                   for e in equations]
    for i in (sympy.I, -sympy.I):
        at = {x: 1, y: i, w: 0, X: 1, Y: i, big_w: 0}
        assert all(sympy.expand(h.subs(at)) == 0 for h in homogeneous)
        mixed = {x: 1, y: i, w: 0, X: 1, Y: -i, big_w: 0}                    # the circle point at the other one
        assert any(sympy.expand(h.subs(mixed)) != 0 for h in homogeneous)
    five = burmester(FIVE_SETS[name])
    assert five.complex_count == sympy.binomial(4, 2) - 2 and five.excluded == ()


def test_no_solution_at_all_is_an_answer():
    translated = [_pose(px, py, 0, 1) for px, py in [(-4, 3), (1, 2), (4, -4), (-3, -2)]]
    five = burmester(translated + [_pose(0, -3, "4/5", "-3/5")])
    assert (five.pairs, five.complex_count, five.solution) == ((), 0, None)
    # three of the equations say (d_i - d_1).(R c - C) = constant: three lines in one point R c - C
    equations, _ = system(five.poses)
    assert sympy.groebner([_expr(e) for e in equations], X, Y, x, y).exprs == [1]


def test_the_order_is_deterministic():
    assert burmester(FOUR_REAL).pairs == burmester(FOUR_REAL).pairs
    centres = [float(p.centre[0].mid()) for p in burmester(FOUR_REAL).pairs]
    assert centres == sorted(centres)


# ---------------------------------------------------------------- bad input


@pytest.mark.parametrize("call, poses, message", [
    (curves, FOUR[:3], "needs 4 poses, not 3"),
    (burmester, FOUR, "needs 5 poses, not 4"),
    (burmester, DOCSTRING + FOUR[:1], "needs 5 poses, not 6"),
    (curves, FOUR[:3] + FOUR[1:2], "poses 2 and 4 are the same pose"),
    (burmester, [_pose(k, k * k, "3/5", "4/5") for k in range(5)], "every pose has the same angle"),
    (burmester, [_pose(0, 0, 1, 0), _pose(2, 0, 0, 1), _pose(2, 2, -1, 0), _pose(0, 2, 0, -1),
                 _pose("6/5", "-2/5", "3/5", "4/5")], r"turned about one point, \(1, 1\)"),
    # four turns about (1, 1) and a translation: the centre (1, 1) with any circle point on a line
    (burmester, [_pose(0, 0, 1, 0), _pose(2, 0, 0, 1), _pose(2, 2, -1, 0), _pose(0, 2, 0, -1), _pose(3, 1, 1, 0)],
     "the dyads reaching them form a curve"),
])
def test_degenerate_poses_are_refused_in_one_line(call, poses, message):
    with pytest.raises(UsageError, match=message) as caught:
        call(poses)
    assert caught.value.argument == "poses" and "\n" not in str(caught.value)
