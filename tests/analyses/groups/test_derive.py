"""``derive`` on a scene with points solved together: the eliminant, the lifts, the closed forms per mode."""

import mpmath
import pytest
import sympy

from algkin.analyses.groups.derive import derive_groups
from algkin.analyses.solve import solve

from .triad import LOOPS, ax, c, s


@pytest.fixture(scope="module")
def triad():
    return derive_groups("stephenson-iii-triad", samples=8)


def test_the_triad_has_a_sextic_eliminant_and_two_real_modes_at_zero(triad):
    # the coupler curve of C (a tricircular sextic) meets the circle of radius 3 about F in
    # 2*6 - 2*3 = 6 points: six assembly modes over the complex numbers
    group, = triad.groups
    assert (group.points, group.variable, group.degree) == (("A", "B"), "A_x", 6)
    assert triad.reference.shown == "0°"
    assert [m.label for m in group.modes] == [c.mode for c in solve("stephenson-iii-triad", at={"theta": 0}).configurations]
    assert triad.verification["passed"]


def test_each_mode_at_the_reference_solves_the_loop_equations(triad):
    """The closed forms (the root of the eliminant, the other unknowns its lifts) at theta = 0,
    put into the loop equations written by hand."""
    group, = triad.groups
    eliminant = sympy.sympify(group.eliminant).subs({sympy.Symbol("c_theta"): 1, sympy.Symbol("s_theta"): 0})
    with mpmath.workdps(50):
        for mode in group.modes:
            root = mpmath.findroot(lambda x: eliminant.subs(ax, x).evalf(60), mpmath.mpf(mode.value))
            values = {ax: root, c: 1, s: 0}
            for name in ("A_y", "B_x", "B_y"):
                form = sympy.sympify(mode.values[name]).subs({sympy.Symbol("c_theta"): 1, sympy.Symbol("s_theta"): 0})
                values[sympy.Symbol(name)] = form.subs(ax, root).evalf(60)
            for equation in LOOPS:
                assert abs(equation.subs(values).evalf(50)) < 1e-40


def test_the_json_has_derives_keys_and_the_groups():
    document = derive_groups("3rpr", samples=0).to_json()
    assert {"scene", "method", "backend", "inputs", "system", "eliminants", "branches", "verification",
            "timings", "groups", "reference"} <= set(document)
    assert document["eliminants"].keys() == {"P1_x"}
    assert sympy.Poly(sympy.sympify(document["eliminants"]["P1_x"]), sympy.Symbol("P1_x")).degree() == 6
    assert [b["label"] for b in document["branches"]] == ["---", "+++"]
    assert document["branches"][0]["values"]["P1_x"] == "root 1 of factor 1"
    assert document["verification"]["status"] == "skipped"


def test_a_quadratic_factor_is_given_in_radicals():
    from algkin.scene import load_scene_text

    scene = load_scene_text('''
[inputs]
r = { range = [1, 3], unit = "length" }
[points]
A = { fixed = [0, 0] }
B = { fixed = [4, 0] }
P = { unknown = true }
[constraints]
a = "dist(A, P) = r"
b = "dist(B, P) = 3"
''', "two-circles.toml")
    found = derive_groups(scene, samples=4)
    group, = found.groups
    r = sympy.Symbol("r")
    x = (r**2 + 7) / 8  # the radical axis of |AP| = r and |BP| = 3: x**2 - (x - 4)**2 = r**2 - 9
    assert sympy.simplify(sympy.sympify(group.lifts["P_x"]) - x) == 0
    lower, upper = (sympy.sympify(m.values["P_y"]) for m in group.modes)
    for form in (lower, upper):  # y**2 = r**2 - x**2, in radicals, no "root k of"
        assert sympy.simplify(form**2 - (r**2 - x**2)) == 0
    at = found.reference.values["r"]
    assert lower.subs(r, at) < 0 < upper.subs(r, at)
    assert found.verification["passed"]
