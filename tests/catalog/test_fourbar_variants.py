"""The non-Grashof and the near-change-point four-bars against Grashof's rule and the law of
cosines."""

from fractions import Fraction

import mpmath
import sympy

from algkin.scene import load_scene

from .geometry import at_angle, branch, circles, exact_at, run, same


def dims(name):
    return {k: Fraction(str(v)) for k, v in load_scene(name).parameters.items()}


def test_nongrashof_is_a_triple_rocker():
    d = dims("fourbar-nongrashof")
    links = sorted([d["a"], d["d"], d["l"], d["m"]])
    assert links[0] + links[3] > links[1] + links[2]


def test_nongrashof_is_derived_not_refused_and_real_between_its_dead_centres():
    document = run("derive", "fourbar-nongrashof", "--outputs", "B", "--samples", "12")
    assert document["verification"]["passed"] and document["verification"]["compared"] > 0
    # Law of cosines: A = 2(cos, sin), D = (5, 0); the triangle A, B, D closes while
    # |AD|**2 = 29 - 20 cos(theta) <= (3 + 7/2)**2, i.e. cos(theta) >= -53/80: |theta| <= 131.49 deg.
    dead = mpmath.degrees(mpmath.acos(mpmath.mpf(-53) / 80))
    assert 131.4 < dead < 131.5
    c, s = sympy.symbols("c_theta s_theta")
    for label in ("left", "right"):
        disc = branch(document, label)["discriminants"]["B"]
        disc = sympy.lambdify((c, s), sympy.parse_expr(disc), "mpmath")
        for k in range(-180, 181, 3):
            t = mpmath.radians(k)
            assert (disc(mpmath.cos(t), mpmath.sin(t)) > 0) == (abs(k) < dead), k
    with mpmath.workdps(40):
        for theta in (-120, -60, 0, 45, 131):
            a = (2 * mpmath.cos(mpmath.radians(theta)), 2 * mpmath.sin(mpmath.radians(theta)))
            b = circles(a, 3, (5, 0), mpmath.mpf(7) / 2, 1)
            values = branch(document, "left")["values"]
            assert abs(at_angle(values["B_x"], theta) - b[0]) < 1e-25
            assert abs(at_angle(values["B_y"], theta) - b[1]) < 1e-25


def test_near_toggle_is_grashof_by_one_thousandth():
    d = dims("fourbar-near-toggle")
    links = sorted([d["a"], d["d"], d["l"], d["m"]])
    assert links[1] + links[2] - (links[0] + links[3]) == Fraction(1, 1000)
    assert links[0] == d["a"]


def test_near_toggle_at_180_degrees_exactly():
    # theta = 180: A = (-1, 0), |AD| = 5 against l + m = 5.001. The dyad's discriminant is
    # ((l + m)**2 - |AD|**2) * (|AD|**2 - (l - m)**2), and B closes the triangle with sides
    # 3, 2001/1000, 5: cos of the angle at A = (9 + 25 - m**2) / 30.
    document = run("derive", "fourbar-near-toggle", "--outputs", "B", "--samples", "12")
    assert document["verification"]["passed"]
    left = branch(document, "left")
    l, m = sympy.Integer(3), sympy.Rational(2001, 1000)
    disc = exact_at(left["discriminants"]["B"], -1, 0)
    assert sympy.simplify(disc - ((l + m) ** 2 - 25) * (25 - (l - m) ** 2)) == 0
    cos_a = (9 + 25 - m**2) / 30
    assert same(exact_at(left["values"]["B_x"], -1, 0), -1 + 3 * cos_a)
    assert same(exact_at(left["values"]["B_y"], -1, 0), 3 * sympy.sqrt(1 - cos_a**2))
    # Near the toggle the coupler and rocker almost fold: B is 3*sin(angle at A) ~ 0.049 above the ground.
    assert 0.045 < float(3 * sympy.sqrt(1 - cos_a**2)) < 0.055


def test_near_toggle_coupler_curve():
    document = run("curve", "fourbar-near-toggle", "--point", "P", "--samples", "12")
    assert (document["degree"], document["circularity"]) == (6, 3)
    assert document["verification"]["passed"]
