"""Singular points of catalog coupler curves against a second method and against the linkage.

Three independent checks: a lex Gröbner basis of (F, F_x, F_y) (sympy's Buchberger, no
resultant, no number field), Newton on F_x = F_y = 0 from a grid of starts polished with mpmath
at 60 digits, and the four-bar itself: a crunode must be reached by two different crank angles,
an acnode by none (both found from the bar lengths by intersecting circles, then the closed
forms evaluated there).
"""

import itertools

import mpmath
import numpy as np
import pytest
import sympy

import algkin
from algkin.analyses.singular import singular, singular_points
from algkin.evaluate import MPMATH, evaluate

DIGITS = 60
AGREE = mpmath.mpf("1e-40")
FOURBARS = {  # scene: (crank a, ground d, coupler l, rocker m, coupler point p, q), from the scene files
    "fourbar": (1, 4, 3, mpmath.mpf(7) / 2, mpmath.mpf(1) / 2, mpmath.mpf(1) / 2),
    "fourbar-nongrashof": (2, 5, 3, mpmath.mpf(7) / 2, mpmath.mpf(1) / 2, mpmath.mpf(1) / 2),
    "chebyshev-lambda": (1, 2, mpmath.mpf(5) / 2, mpmath.mpf(5) / 2, 2, 0),
}


@pytest.fixture(scope="module")
def found():
    return {name: singular(name, "P", samples=0) for name in [*FOURBARS, "watt-straight-line"]}


def groebner_points(polynomial):
    """Real solutions of F = F_x = F_y = 0 from a lex basis (y > x): its last element is the
    x-eliminant, and one element is linear in y (shape position), giving y at each root."""
    px, py = sorted(polynomial.free_symbols, key=str)
    basis = sympy.groebner([polynomial, polynomial.diff(px), polynomial.diff(py)], py, px, order="lex").exprs
    eliminant = basis[-1]
    assert eliminant.free_symbols == {px}
    linear = next(b for b in basis if sympy.degree(b, py) == 1)
    slope, rest = sympy.Poly(linear, py).all_coeffs()
    points = []
    for root in sympy.Poly(eliminant, px).real_roots():
        x0 = sympy.N(root, DIGITS)
        points.append((mpmath.mpf(str(x0)), mpmath.mpf(str(sympy.N(-rest.subs(px, x0) / slope.subs(px, x0), DIGITS)))))
    return sorted(points), sympy.degree(eliminant, px)


@pytest.mark.parametrize("name", [*FOURBARS, "watt-straight-line"])
def test_real_singular_points_agree_with_a_groebner_basis(found, name):
    result = found[name]
    with mpmath.workdps(DIGITS):
        expected, total = groebner_points(result.curve)
        got = [(mpmath.mpf(p.x.ball.mid().str(50, radius=False)), mpmath.mpf(p.y.ball.mid().str(50, radius=False)))
               for p in result.points]
        assert len(got) == len(expected)
        for (gx, gy), (ex, ey) in zip(got, expected):
            assert abs(gx - ex) < AGREE and abs(gy - ey) < AGREE
        for point, (ex, ey) in zip(result.points, expected):  # the exact forms, evaluated by sympy, agree too
            assert abs(mpmath.mpf(str(sympy.N(point.x.exact, 50))) - ex) < AGREE
            assert abs(mpmath.mpf(str(sympy.N(point.y.exact, 50))) - ey) < AGREE
    # every singular point, complex ones too: the eliminant of a radical ideal has one root each
    assert len(result.points) + sum(c["count"] for c in result.complex) == total


@pytest.mark.parametrize("name", ["fourbar", "chebyshev-lambda", "fourbar-nongrashof"])
def test_real_singular_points_agree_with_newton_from_many_starts(found, name):
    result = found[name]
    expected = newton_singular_points(result.curve)
    assert len(expected) == len(result.points)
    for point, (ex, ey) in zip(result.points, expected):
        with mpmath.workdps(DIGITS):
            assert abs(mpmath.mpf(point.x.ball.mid().str(50, radius=False)) - ex) < AGREE
            assert abs(mpmath.mpf(point.y.ball.mid().str(50, radius=False)) - ey) < AGREE


def newton_singular_points(polynomial, box=12.0, grid=40):
    """Critical points of F (Newton on F_x = F_y = 0 in floats from a grid of starts, then mpmath
    at 60 digits), kept where F vanishes too."""
    px, py = sorted(polynomial.free_symbols, key=str)
    fx, fy = polynomial.diff(px), polynomial.diff(py)
    jac = [[fx.diff(px), fx.diff(py)], [fy.diff(px), fy.diff(py)]]
    numeric = sympy.lambdify((px, py), [fx, fy, *itertools.chain(*jac)], "numpy")
    xs, ys = np.meshgrid(np.linspace(-box, box, grid), np.linspace(-box, box, grid))
    x, y = xs.ravel(), ys.ravel()
    with np.errstate(all="ignore"):
        for _ in range(60):
            gx, gy, a, b, c, d = (np.broadcast_to(v, x.shape) for v in numeric(x, y))
            det = a * d - b * c
            x, y = x - (d * gx - b * gy) / det, y - (a * gy - c * gx) / det
    ok = np.isfinite(x) & np.isfinite(y)
    starts = {(round(float(u), 6), round(float(v), 6)) for u, v in zip(x[ok], y[ok])}  # one per critical point
    found = []
    exact = sympy.lambdify((px, py), [polynomial, fx, fy], "mpmath")
    with mpmath.workdps(DIGITS):
        for x0, y0 in sorted(starts):
            try:
                root = mpmath.findroot(lambda u, v: exact(u, v)[1:], (mpmath.mpf(x0), mpmath.mpf(y0)))
            except (ValueError, ZeroDivisionError):
                continue
            u, v = root[0], root[1]
            if abs(exact(u, v)[0]) < AGREE and all(abs(u - a) + abs(v - b) > AGREE for a, b in found):
                found.append((u, v))
    return sorted(found)


def configurations(point, a, d, l, m, p, q):
    """Crank angles where a four-bar (crank a about (0, 0), rocker m about (d, 0), coupler l, P
    at (p, q) in the coupler's frame) puts P at ``point``: |A| = a and |P - A| = l*sqrt(p² + q²)
    give A (two circles), then B - A = (p I + q J)⁻¹ (P - A) and |B - D| = m must hold."""
    px, py = point
    r = l * mpmath.sqrt(p * p + q * q)
    dist = mpmath.sqrt(px * px + py * py)
    along = (a * a - r * r + dist * dist) / (2 * dist)
    if a * a - along * along < 0:
        return []
    across = mpmath.sqrt(a * a - along * along)
    angles = []
    for sign in (1, -1):
        ax = (along * px - sign * across * py) / dist
        ay = (along * py + sign * across * px) / dist
        vx, vy = px - ax, py - ay
        scale = p * p + q * q
        bx, by = ax + (p * vx + q * vy) / scale, ay + (-q * vx + p * vy) / scale
        if abs(mpmath.sqrt((bx - d) ** 2 + by**2) - m) < AGREE:
            angles.append(mpmath.atan2(ay, ax))
    return angles


def closed_form_points(name, angle):
    """P at the crank ``angle`` on every branch the closed forms give (real ones)."""
    derived = algkin.derive(name, outputs=["P"], samples=0, certify=False)
    (c, s), = derived.compiled.system.inputs.values()
    points = []
    for branch in derived.branches:
        values = {c: mpmath.cos(angle), s: mpmath.sin(angle)}
        try:
            point = [evaluate(branch.values[u], values, MPMATH) for u in ("P_x", "P_y")]
        except (ValueError, ZeroDivisionError):
            continue
        if all(mpmath.im(v) == 0 for v in point):
            points.append(point)
    return points


@pytest.mark.parametrize("name", list(FOURBARS))
def test_crunodes_are_reached_twice_and_acnodes_never(found, name):
    kinds = {p.kind for p in found[name].points}
    assert kinds <= {"crunode", "acnode"}
    for point in found[name].points:
        with mpmath.workdps(DIGITS):
            target = tuple(mpmath.mpf(c.ball.mid().str(55, radius=False)) for c in (point.x, point.y))
            angles = configurations(target, *FOURBARS[name])
            if point.kind == "acnode":
                assert angles == []
                continue
            assert len(angles) == 2 and abs(angles[0] - angles[1]) > 1e-6
            for angle in angles:  # the closed forms, at each angle, put P on the crossing
                assert any(abs(px - target[0]) + abs(py - target[1]) < AGREE
                           for px, py in closed_form_points(name, angle))


def test_catalog_coupler_points_as_found(found):
    """What the checks above hold: the default four-bar has one real double point (an acnode)
    and two complex ones; the non-Grashof one two crunodes and an acnode; the lambda three
    acnodes on its axis of symmetry, its curve never crossing itself."""
    assert [p.kind for p in found["fourbar"].points] == ["acnode"]
    assert [c["count"] for c in found["fourbar"].complex] == [2]
    assert sorted(p.kind for p in found["fourbar-nongrashof"].points) == ["acnode", "crunode", "crunode"]
    assert [p.kind for p in found["chebyshev-lambda"].points] == ["acnode"] * 3
    assert all(p.y.exact == 0 for p in found["chebyshev-lambda"].points)


def test_watts_figure_eight_crosses_at_its_centre(found):
    """Watt's linkage (arms 2 about (∓2, ±1/2), coupler 1, P its midpoint): P = 0 means B = -A,
    and then |B - O2| = |A - O1| = 2 holds by symmetry; |AB| = 1 asks |A| = 1/2, which meets
    |A - O1| = 2 at two points: two configurations through the origin, a crossing."""
    kinds = {(p.x.exact, p.y.exact): p.kind for p in found["watt-straight-line"].points}
    assert kinds[(0, 0)] == "crunode"


@pytest.mark.parametrize("name", list(FOURBARS))
def test_four_bar_coupler_curves_are_tricircular_sextics(found, name):
    """The coupler curve of a four-bar has degree 6 and passes three times through each circular
    point at infinity (Roberts; Hartenberg & Denavit): circularity 3. Genus 1 leaves exactly three
    finite double points, real or not."""
    result = found[name]
    assert (result.degree, result.circularity) == (6, 3)
    assert len(result.points) + sum(c["count"] for c in result.complex) == 3
    assert all(p.multiplicity == 2 for p in result.points)


def test_a_curve_given_by_algkin_curve_is_taken_as_it_is():
    curve = algkin.curve("chebyshev-lambda", "P", samples=0)
    assert [p.to_json() for p in singular_points(curve).points] == \
        [p.to_json() for p in singular("chebyshev-lambda", "P", samples=0).points]


def test_cusp_where_the_coupler_point_is_the_instant_centre():
    """A coupler point at rest is a cusp of its path: at the crank angle with A = (3/5, 4/5), the
    four-bar with a = 1, d = 3, l = 5/2, m = 3/2 has B = (3, 3/2) (|AB| = 5/2, |DB| = 3/2); the
    instant centre of the coupler is where the lines OA and DB meet, I = (3, 4). The coupler point
    placed there: P - A = (12/5, 16/5) = p (B - A) + q rot90(B - A) with B - A = (12/5, 7/10)
    gives p = 32/25, q = 24/25. The same four-bar is a change point (1 + 3 = 5/2 + 3/2): flat
    at A = (-1, 0), B = (3/2, 0), where its two circuits meet, at P = A + (5/2)(p, q) = (11/5, 12/5),
    a crunode; with it, four finite double points (the curve's genus drops from 1 to 0)."""
    found = singular("fourbar", "P", set={"a": 1, "d": 3, "l": "5/2", "m": "3/2", "p": "32/25", "q": "24/25"},
                     samples=0)
    kinds = {(p.x.exact, p.y.exact): p for p in found.points}
    cusp = kinds[sympy.Integer(3), sympy.Integer(4)]
    assert (cusp.kind, cusp.local["a_k"], cusp.local["tangents"]) == ("cusp", 2, {"distinct": 1, "real": 1})
    assert kinds[sympy.Rational(11, 5), sympy.Rational(12, 5)].kind == "crunode"
    assert len(found.points) + sum(c["count"] for c in found.complex) == 4
