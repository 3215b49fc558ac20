"""The eight-bar with a triad (catalog ``eightbar-triad-dyad``): a crank drives a triad (A, B, C
rigid) whose joint B drives a dyad G on B and H, P on the dyad's link BG. Groups solved in turn:
the triad's, then the dyad's at each of its modes. Checked against the whole loop written out
by hand and solved numerically (mpmath, many starts), the dyad's closed form, and P's curve
derived by hand (the four-bar D-B-G-H's coupler curve)."""

import pathlib

import mpmath
import numpy as np
import pytest
import sympy

import algkin
from algkin.analyses.follow import follow
from algkin.analyses.groups.curve import curve_groups
from algkin.analyses.groups.derive import derive_groups
from algkin.analyses.groups.toggles import toggles_groups
from algkin.analyses.groups.verify import verify_groups
from algkin.analyses.solve import solve
from algkin.scene import load_scene_text

SCENE = "eightbar-triad-dyad"
Q = mpmath.mpf
O, D, E, H = (0, 0), (4, 0), (1, 5), (5, 5)


def frame(a, b, u, v):
    """``a + u*(b - a) + v*rot90(b - a)``, rot90(x, y) = (-y, x)."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    return a[0] + u * dx - v * dy, a[1] + u * dy + v * dx


def loops(theta_degrees, number=Q):
    """The eight-bar's six loop equations in (A, B, G), written from its description; in mpmath
    numbers, or (``number=float``) in floats, for numpy arrays of unknowns."""
    angle = mpmath.radians(theta_degrees)
    f = (number(E[0] + mpmath.cos(angle)), number(E[1] + mpmath.sin(angle)))  # the crank EF, length 1
    half, rocker = number(1) / 2, number(49) / 4

    def equations(ax, ay, bx, by, gx, gy):
        c = frame((ax, ay), (bx, by), half, half)
        return [ax**2 + ay**2 - 1,                                   # |OA| = 1
                (bx - 4)**2 + by**2 - rocker,                        # |DB| = 7/2
                (ax - bx)**2 + (ay - by)**2 - 9,                     # |AB| = 3
                (c[0] - f[0])**2 + (c[1] - f[1])**2 - 9,             # |CF| = 3
                (gx - bx)**2 + (gy - by)**2 - 9,                     # |BG| = 3
                (gx - H[0])**2 + (gy - H[1])**2 - 9]                 # |HG| = 3
    return equations


def numeric_solutions(theta_degrees, starts=2000, seed=1):
    """Every real solution Newton's method finds from ``starts`` random starts (numpy, all at once,
    a finite-difference Jacobian), refined to 60 digits by mpmath's findroot, distinct."""
    rng = np.random.default_rng(seed)
    floats, exact = loops(theta_degrees, float), loops(theta_degrees)

    def residuals(points):
        with np.errstate(all="ignore"):
            return np.stack(floats(*points.T), axis=1)

    points = rng.uniform(-2, 7, size=(starts, 6))
    for _ in range(60):
        values = residuals(points)
        jacobian = np.stack([(residuals(points + 1e-7 * np.eye(6)[k]) - values) / 1e-7 for k in range(6)], axis=2)
        with np.errstate(all="ignore"):
            solvable = np.isfinite(jacobian).all(axis=(1, 2)) & (np.abs(np.linalg.det(jacobian)) > 1e-12)
        points[solvable] -= np.linalg.solve(jacobian[solvable], values[solvable][..., None])[..., 0]
        points[~np.isfinite(points)] = 1e6
    converged = points[np.max(np.abs(residuals(points)), axis=1) < 1e-8]
    distinct = {tuple(np.round(p, 6)): p for p in converged}.values()  # refined once each
    found = []
    for guess in distinct:
        with mpmath.workdps(60):
            root = mpmath.findroot(lambda *v: exact(*v), [Q(float(g)) for g in guess], tol=Q(10) ** -55)
            if max(abs(e) for e in exact(*root)) > Q(10) ** -45:
                continue
            if all(max(abs(a - b) for a, b in zip(root, other)) > Q(10) ** -30 for other in found):
                found.append(list(root))
    return found


@pytest.fixture(scope="module")
def solved():
    return {theta: solve(SCENE, at={"theta": theta}, digits=40) for theta in (0, 90, 180)}


@pytest.mark.parametrize("theta", [0, 90, 180])
def test_the_configurations_are_every_real_solution_of_the_whole_loop(solved, theta):
    found = solved[theta].configurations
    expected = numeric_solutions(theta)
    assert len(found) == len(expected) == {0: 4, 90: 0, 180: 4}[theta]
    with mpmath.workdps(60):
        for root in expected:
            matches = [c for c in found
                       if max(abs(Q(v) - r) for v, r in zip((*c.points["A"], *c.points["B"], *c.points["G"]), root))
                       < Q(10) ** -20]
            assert len(matches) == 1
            # the dyad's label: left when G lies left of B -> H, cross(H - B, G - B) > 0
            (bx, by), (gx, gy) = root[2:4], root[4:6]
            side = "left" if (H[0] - bx) * (gy - by) - (H[1] - by) * (gx - bx) > 0 else "right"
            assert matches[0].mode.endswith(f" G:{side}")


def test_the_dyad_point_is_the_dyads_closed_form_at_each_triad_mode(solved):
    """G from the two circles about B (radius 3) and H (radius 3), by the textbook formula."""
    with mpmath.workdps(60):
        for configuration in solved[180].configurations:
            bx, by = (Q(v) for v in configuration.points["B"])
            dx, dy = H[0] - bx, H[1] - by
            d = mpmath.sqrt(dx**2 + dy**2)
            a = (9 - 9 + d**2) / (2 * d)
            h = mpmath.sqrt(9 - a**2)
            sign = 1 if configuration.mode.endswith("G:left") else -1   # rot90(H - B) points left
            expected = (bx + a * dx / d - sign * h * dy / d, by + a * dy / d + sign * h * dx / d)
            assert all(abs(Q(v) - e) < Q(10) ** -35 for v, e in zip(configuration.points["G"], expected))


def test_configurations_are_the_triads_modes_times_the_dyads_sides(solved):
    labels = [c.mode for c in solved[0].configurations]
    assert labels == ["-++ G:left", "-++ G:right", "+++ G:left", "+++ G:right"]
    assert solved[0].complex_count == 12  # the triad's sextic, the dyad's two


def coupler_curve():
    """P's path by hand: B on the circle about D; P - B = N (G - B) with N = I/2 + rot90/4, so
    |P - B|**2 = (5/16)|G - B|**2 = 45/16 and G = B + N**-1 (P - B), N**-1 = (8/5) I - (4/5) rot90;
    then |G - H| = 3. B eliminated by resultants: the four-bar D-B-G-H's coupler curve."""
    x, y, bx, by = sympy.symbols("P_x P_y b_x b_y")
    wx, wy = x - bx, y - by
    gx, gy = bx + sympy.Rational(8, 5) * wx + sympy.Rational(4, 5) * wy, by + sympy.Rational(8, 5) * wy - sympy.Rational(4, 5) * wx
    circle_d = (bx - 4)**2 + by**2 - sympy.Rational(49, 4)
    circle_p = wx**2 + wy**2 - sympy.Rational(45, 16)
    link = sympy.expand((gx - 5)**2 + (gy - 5)**2 - 9)
    chord = sympy.expand(circle_d - circle_p)                           # linear in b_x, b_y
    first = sympy.resultant(chord, circle_d, bx)
    second = sympy.resultant(chord, link, bx)
    return sympy.factor_list(sympy.resultant(first, second, by))[1], (x, y)


def test_the_curve_of_p_is_the_four_bar_coupler_sextic_and_holds_every_configuration(solved):
    found = curve_groups(SCENE, "P", samples=6)
    assert (found.degree, found.circularity) == (6, 3) and found.verification["passed"]
    factors, (x, y) = coupler_curve()
    curve = sympy.Poly(sympy.sympify(found.curve), x, y)
    assert any(sympy.cancel(curve.as_expr() / f.as_expr()).is_number for f, _ in factors)
    with mpmath.workdps(60):
        for theta in (0, 180):
            for configuration in solved[theta].configurations:
                px, py = (Q(v) for v in configuration.points["P"])
                value = curve.as_expr().subs({x: sympy.Float(str(px), 60), y: sympy.Float(str(py), 60)})
                assert abs(value) < 1e-25


def test_derive_gives_the_triads_sextic_and_the_dyads_quadratic_in_its_radicals():
    found = derive_groups(SCENE, samples=6)
    triad, dyad = found.groups
    assert (triad.points, triad.degree, dyad.points, dyad.degree, dyad.after) == (("A", "B"), 6, ("G",), 2, ("A", "B"))
    assert [m.label for m in dyad.modes] == ["G:left", "G:right"] * 2
    assert all("sqrt(" in m.values["G_x"] for m in dyad.modes)
    assert [b["label"] for b in found.to_json()["branches"]] == ["-++ G:left", "-++ G:right", "+++ G:left",
                                                                 "+++ G:right"]
    assert found.passed and found.verification["status"] == "passed"


def test_verify_matches_every_proved_solution_of_the_triad_and_the_triad_with_its_dyad():
    found = verify_groups(SCENE, samples=6)
    assert found.passed and found.verification["compared"] > 0


def test_toggles_are_the_triads_where_the_dyad_never_straightens():
    """|B - H| stays below 6 = |BG| + |GH| wherever the triad assembles: the dyad has no toggle there."""
    found = toggles_groups(SCENE)
    assert [(t.points, t.certified) for t in found.toggles] == [(("A", "B"), True)] * 2
    assert 45 < found.toggles[0].value < 46 and 90 < found.toggles[1].value < 91


def test_follow_keeps_the_triads_mode_and_the_dyads_side_up_to_the_triads_toggle():
    path = follow(SCENE, mode="+++ G:left", start={"theta": 0}, stop=60, digits=10)
    assert path.ended == "meets" and 45 <= float(path.meeting["from"]) <= float(path.meeting["to"]) <= 46
    with mpmath.workdps(30):
        for sample in path.samples:
            (bx, by), (gx, gy) = ((Q(v) for v in sample.points[p]) for p in ("B", "G"))
            assert (H[0] - bx) * (gy - by) - (H[1] - by) * (gx - bx) > 0     # G stays left of B -> H


def test_a_dyad_beside_a_triad_may_name_its_mode_by_a_configuration():
    """G named near (4.8, 2) at 0 degrees: the right side of B -> H there (G = (4.77, 2.01) and
    (5.15, 2.00) on the two triad modes), so solve keeps the G:right configurations elsewhere."""
    text = (pathlib.Path(algkin.__file__).parent / "catalog" / f"{SCENE}.toml").read_text()
    text = text.replace('branch = "left"', 'mode = { at = { theta = 0 }, near = [4.8, 2.0] }')
    found = solve(load_scene_text(text, "named.toml"), at={"theta": 180}, digits=20)
    assert found.named_modes == ("G",) and found.left_out == 2
    assert [c.mode.split(" ")[1] for c in found.configurations] == ["G:right", "G:right"]


def test_rates_of_groups_solved_in_turn_are_refused_naming_the_later_group():
    from algkin.analyses.groups.rates import group_rates
    from algkin.errors import UsageError

    with pytest.raises(UsageError, match="its group of G is solved after another"):
        group_rates(SCENE, samples=0)
