"""meet = [[A, B], [C, D]]: where two moving lines meet, against mpmath's solution of the two line equations.

Two cranks turned by one input through gears of ratio -1 (about O1 and O2); I is where the
cranks' lines meet, J where the line through both crank tips meets the ground line O1 O2. The
reference solves each pair of line equations by mpmath's LU decomposition at 50 digits, from
the crank tips computed with mpmath's cos and sin, never from algkin's forms.
"""

import mpmath
import pytest
import sympy

import algkin
from algkin.scene import load_scene_text

SCENE = '''
[inputs]
t = { range = [0, 360], unit = "deg" }
u = { driven_by = "t", ratio = "-1" }

[points]
O1 = { fixed = [0, 0] }
O2 = { fixed = [4, 0] }
A = { crank = "O1", length = 1, input = "t" }
B = { crank = "O2", length = 2, input = "u", phase = { cos = "3/5", sin = "4/5" } }
I = { meet = [["O1", "A"], ["O2", "B"]] }
J = { meet = [["A", "B"], ["O1", "O2"]] }

[outputs]
I = "I"
J = "J"
'''
SAMPLES = [-150, -20, 7, 33, 64, 101, 200, 299]


def meet(a, b, c, d):
    """The point on both lines a-b and c-d: (b - a) x (X - a) = 0, (d - c) x (X - c) = 0 solved as a 2x2 system."""
    rows = mpmath.matrix([[-(b[1] - a[1]), b[0] - a[0]], [-(d[1] - c[1]), d[0] - c[0]]])
    rhs = mpmath.matrix([(b[0] - a[0]) * a[1] - (b[1] - a[1]) * a[0], (d[0] - c[0]) * c[1] - (d[1] - c[1]) * c[0]])
    x = mpmath.lu_solve(rows, rhs)
    return x[0], x[1]


def geometry(degrees):
    t = mpmath.radians(degrees)
    phase = mpmath.atan2(4, 3)
    a = (mpmath.cos(t), mpmath.sin(t))
    b = (4 + 2 * mpmath.cos(-t + phase), 2 * mpmath.sin(-t + phase))
    return {"I": meet((0, 0), a, (4, 0), b), "J": meet(a, b, (0, 0), (4, 0))}


@pytest.fixture(scope="module")
def derived():
    return algkin.derive(load_scene_text(SCENE, "meet.toml"))


def _forms(branch):
    c, s = sympy.Symbol("c_t", real=True), sympy.Symbol("s_t", real=True)
    return {u: sympy.lambdify((c, s), v, "mpmath") for u, v in branch.values.items()}


def test_closed_form_is_where_the_lines_meet(derived):
    (branch,) = derived.branches  # one point: no branch to choose
    forms = _forms(branch)
    with mpmath.workdps(50):
        for degrees in SAMPLES:
            t = mpmath.radians(degrees)
            for point, (x, y) in geometry(degrees).items():
                got = [forms[f"{point}_{axis}"](mpmath.cos(t), mpmath.sin(t)) for axis in "xy"]
                scale = max(1, abs(x), abs(y))
                assert abs(got[0] - x) < 1e-40 * scale and abs(got[1] - y) < 1e-40 * scale, (point, degrees)
    assert derived.verification.passed


def test_valid_where_the_lines_are_not_parallel(derived):
    (branch,) = derived.branches
    text = branch.valid_when
    assert "!= 0" in text and ">= 0" not in text, text  # no square root: it is real wherever it exists
    # OA and O2B are parallel where t = -t + atan2(4, 3) (mod 180 deg): cos t = 2/sqrt(5), sin t = 1/sqrt(5)
    c, s = sympy.Symbol("c_t", real=True), sympy.Symbol("s_t", real=True)
    square = branch.discriminants["I"]
    at = {c: 2 / sympy.sqrt(5), s: 1 / sympy.sqrt(5)}
    assert sympy.simplify(square.xreplace(at)) == 0
    assert sympy.simplify(square.xreplace({c: 1, s: 0})) != 0


def test_curve_of_the_meet_holds_at_independent_points():
    document = algkin.curve(load_scene_text(SCENE, "meet.toml"), "I").to_json()
    x, y = (sympy.Symbol(v) for v in document["variables"])
    poly = sympy.Poly(sympy.parse_expr(document["curve"]), x, y)
    with mpmath.workdps(50):
        for degrees in SAMPLES:
            px, py = geometry(degrees)["I"]
            value = sum(mpmath.mpf(int(k.p)) / int(k.q) * px**i * py**j for (i, j), k in poly.terms())
            size = sum(abs(mpmath.mpf(int(k.p)) / int(k.q)) * max(1, abs(px), abs(py)) ** (i + j)
                       for (i, j), k in poly.terms())
            assert abs(value) / size < 1e-40, degrees
    assert document["verification"]["passed"]


def test_solve_takes_a_meet():
    scene = load_scene_text(SCENE, "meet.toml")
    (configuration,) = algkin.solve(scene, at={"t": 33}).to_json()["configurations"]
    with mpmath.workdps(50):
        for point, (x, y) in geometry(33).items():
            got = [mpmath.mpf(v) for v in configuration["points"][point]]
            assert abs(got[0] - x) < 1e-25 and abs(got[1] - y) < 1e-25, point
