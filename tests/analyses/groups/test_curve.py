"""``curve`` on a scene with points solved together: the triad's coupler point, by a second method
(Singular's Gröbner elimination of the loop equations; sympy's lex basis agrees too, in about two
minutes: not run here), the dyad pipeline's four-bar, and configurations found by hand."""

import shutil
import subprocess

import mpmath
import pytest
import sympy

from algkin.analyses.groups.curve import curve_groups
from algkin.analyses.solve import solve
from algkin.errors import UsageError

from .triad import LOOPS, POINT, R, px, py, frame


@pytest.fixture(scope="module")
def triad_curve():
    return curve_groups("stephenson-iii-triad", "P", samples=12)


def _curve(found):
    return sympy.Poly(sympy.sympify(found.curve), px, py)


def _same_up_to_a_constant(first, second):
    ratio = sympy.cancel(first.as_expr() / second.as_expr())
    return ratio.is_number and ratio != 0


def test_the_triad_coupler_point_traces_a_sextic_with_three_circular_points(triad_curve):
    # P lies on the coupler A B C: whatever drives the chain, its path is the four-bar O-A-B-D's
    # coupler curve, a tricircular sextic
    assert (triad_curve.degree, triad_curve.circularity) == (6, 3)
    assert triad_curve.dropped == ("P_x + 2*P_y",)
    assert triad_curve.verification["passed"] and triad_curve.verification["compared"] > 0


@pytest.mark.skipif(shutil.which("Singular") is None, reason="Singular is not installed")
def test_the_curve_is_singulars_elimination_of_the_loop_equations(triad_curve, tmp_path):
    names = "c,s,A_x,A_y,B_x,B_y,P_x,P_y"
    ideal = ",\n".join(str(e).replace("**", "^") for e in LOOPS + POINT)
    script = (f"ring r = 0, ({names}), dp;\nideal I = {ideal};\n"
              "ideal J = eliminate(I, c*s*A_x*A_y*B_x*B_y);\nprint(size(J));\nprint(J[1]);\nquit;\n")
    (tmp_path / "triad.sing").write_text(script)
    done = subprocess.run(["Singular", "-q", str(tmp_path / "triad.sing")], capture_output=True, text=True,
                          timeout=300, check=True)
    count, generator = done.stdout.split("\n", 1)
    assert count.strip() == "1"  # the elimination ideal is principal: one curve
    singular = sympy.Poly(sympy.sympify(generator.replace("^", "**").strip()), px, py)
    assert _same_up_to_a_constant(singular, _curve(triad_curve))


def test_a_configuration_found_by_hand_lies_on_the_curve(triad_curve):
    # A = (1, 0): B on the circles |AB| = 3 and |DB| = 7/2, D = (4, 0): their radical axis gives
    # 6x - 15 = 9 - 49/4, x = 47/24, y = sqrt(9 - (23/24)**2) = sqrt(4655)/24. C is then at
    # distance 1.27 < |CE| < 5.27 from E = (-1, 5), so F, 2 from E and 3 from C, exists: a real
    # configuration of the triad.
    a, b = (1, 0), (R(47, 24), sympy.sqrt(4655) / 24)
    assert sympy.simplify((b[0] - 1)**2 + b[1]**2 - 9) == 0 and sympy.simplify((b[0] - 4)**2 + b[1]**2 - R(49, 4)) == 0
    centre = frame(a, b, R(1, 2), R(1, 2))
    assert 1 < sympy.sqrt((centre[0] + 1)**2 + (centre[1] - 5)**2) < 5
    x, y = frame(a, b, R(1, 2), R(-1, 4))
    assert sympy.expand(_curve(triad_curve).as_expr().subs({px: x, py: y})) == 0
    assert sympy.expand(_curve(triad_curve).as_expr().subs({px: x + R(1, 100), py: y})) != 0


def test_the_points_algkin_solve_certifies_lie_on_the_curve(triad_curve):
    found = solve("stephenson-iii-triad", at={"theta": 0}, digits=40)
    assert len(found.configurations) == 2
    curve = _curve(triad_curve)
    with mpmath.workdps(60):
        for configuration in found.configurations:
            x, y = (mpmath.mpf(v) for v in configuration.points["P"])
            value = sum(mpmath.mpf(int(k.p)) / int(k.q) * x**i * y**j for (i, j), k in curve.terms())
            assert abs(value) < mpmath.mpf(10) ** -30


def test_the_curve_is_the_coupler_curve_of_the_four_bar_built_point_by_point(triad_curve):
    from algkin.derivation.pipeline import curve
    from algkin.scene import load_scene_text

    fourbar = load_scene_text('''
[inputs]
theta = { range = [0, 360], unit = "deg" }
[points]
O = { fixed = [0, 0] }
D = { fixed = [4, 0] }
A = { crank = "O", length = 1, input = "theta" }
B = { dyad = ["A", "D"], lengths = [3, "7/2"], branch = "left" }
P = { frame = ["A", "B"], at = ["1/2", "-1/4"] }
''', "fourbar-p.toml")
    dyads = curve(fourbar, "P", samples=0)
    assert _same_up_to_a_constant(sympy.Poly(sympy.sympify(dyads.elimination.text), px, py), _curve(triad_curve))


def test_a_point_that_does_not_move_has_no_curve():
    with pytest.raises(UsageError, match="fixed at"):
        curve_groups("stephenson-iii-triad", "O", samples=0)
    with pytest.raises(UsageError, match="not a point"):
        curve_groups("stephenson-iii-triad", "Q", samples=0)


def test_the_3rpr_platform_corner_moves_on_the_circle_of_its_fixed_leg():
    found = curve_groups("3rpr", "P3", samples=4)
    x, y = sympy.symbols("P3_x P3_y")
    assert _same_up_to_a_constant(sympy.Poly(sympy.sympify(found.curve), x, y),
                                  sympy.Poly((x - 3)**2 + (y - 8)**2 - 64, x, y))  # |A3 P3| = r3 = 8
    assert found.verification["passed"]


def test_a_point_solved_for_traces_its_coupler_curve():
    """P1 of 3rpr is an unknown itself (its curve's variables are its unknowns: the elimination
    once kept and eliminated P1_x at once, "the system is inconsistent"). With leg 1 driven, the
    platform is the coupler of the four-bar A2 P2 P3 A3 and P1 a coupler point: a tricircular
    sextic through the configurations built here by hand, at 40 digits."""
    found = curve_groups("3rpr", "P1", samples=4)
    assert (found.degree, found.circularity) == (6, 3) and found.verification["passed"]
    x, y = sympy.symbols("P1_x P1_y")
    curve = sympy.lambdify((x, y), sympy.sympify(found.curve), "mpmath")
    checked = 0
    with mpmath.workdps(40):
        for angle in (1.1, 1.6, 3.0, 3.5):  # where P3 reaches its circle
            p2 = mpmath.matrix([10 + 9 * mpmath.cos(angle), 9 * mpmath.sin(angle)])  # |A2 P2| = 9
            # P3 = P1 + d/2 + 3/4 rot90(d), d = P2 - P1: |P2 P3| = 5 sqrt(13)/4; |A3 P3| = 8
            for p3 in _circles_meet(p2, 5 * mpmath.sqrt(13) / 4, mpmath.matrix([3, 8]), 8):
                # P3 - P2 = M d, M = [[-1/2, -3/4], [3/4, -1/2]]
                d = mpmath.lu_solve(mpmath.matrix([[-0.5, -0.75], [0.75, -0.5]]), p3 - p2)
                p1 = p2 - d
                assert abs(mpmath.norm(p2 - p1) - 5) < mpmath.mpf(10) ** -35
                assert abs(curve(p1[0], p1[1])) < mpmath.mpf(10) ** -25
                checked += 1
    assert checked == 8


def _circles_meet(c1, r1, c2, r2):
    """The real intersections of two circles (mpmath)."""
    gap = c2 - c1
    distance = mpmath.norm(gap)
    along = (distance**2 + r1**2 - r2**2) / (2 * distance)
    across = mpmath.sqrt(r1**2 - along**2) if r1**2 >= along**2 else None
    if across is None:
        return []
    unit = gap / distance
    normal = mpmath.matrix([-unit[1], unit[0]])
    return [c1 + along * unit + sign * across * normal for sign in (1, -1)]
