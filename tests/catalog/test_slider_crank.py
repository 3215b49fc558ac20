"""The slider-crank against its textbook position formula
x = r cos(t) + sqrt(l**2 - (r sin(t) - e)**2), and its coupler curves: a straight line for the
slider, quartics for points of the rod (Hartenberg & Denavit, Kinematic Synthesis of Linkages,
1964: slider-crank coupler curves are of degree four)."""

import random

import mpmath
import sympy

import algkin

from .geometry import at_angle, branch, curve_at, exact_at, rigid, run, same


def x_by_hand(theta, r=1, l=3, e=sympy.Rational(1, 2), sign=1):
    c, s = theta
    return r * c + sign * sympy.sqrt(l**2 - (r * s - e) ** 2)


def test_slider_position_at_quarter_turns_exactly():
    document = run("derive", "slider-crank", "--outputs", "B", "--samples", "12")
    assert document["verification"]["passed"]
    assert [b["label"] for b in document["branches"]] == ["ahead", "behind"]
    for label, sign in (("ahead", 1), ("behind", -1)):
        values = branch(document, label)["values"]
        for cs in ((1, 0), (0, 1), (-1, 0), (0, -1), (sympy.Rational(3, 5), sympy.Rational(4, 5))):
            assert same(exact_at(values["B_x"], *cs), x_by_hand(cs, sign=sign))
            assert same(exact_at(values["B_y"], *cs), sympy.Rational(1, 2))
    # e.g. theta = 0: x = 1 + sqrt(9 - 1/4) = 1 + sqrt(35)/2
    assert same(exact_at(branch(document, "ahead")["values"]["B_x"], 1, 0), 1 + sympy.sqrt(35) / 2)


def test_slider_position_along_the_turn():
    document = run("derive", "slider-crank", "--samples", "0")
    assert document["outputs"] == {"x": ["B_x"]}
    x = branch(document, "ahead")["values"]["B_x"]
    mpmath.mp.dps = 40
    for k in range(0, 360, 15):
        t = mpmath.radians(k)
        hand = mpmath.cos(t) + mpmath.sqrt(9 - (mpmath.sin(t) - mpmath.mpf(1) / 2) ** 2)
        assert abs(at_angle(x, k) - hand) < 1e-30
    mpmath.mp.dps = 15


def test_symbolic_dimensions_give_the_textbook_formula():
    result = algkin.derive("slider-crank", outputs=["B"], params=["r", "l", "e"], samples=0)
    ahead = next(b for b in result.branches if b.label == "ahead")
    r, l, e, c, s = (sympy.Symbol(n, real=True) for n in ("r", "l", "e", "c_theta", "s_theta"))
    rng = random.Random(11)
    for _ in range(20):
        vr, vl, ve = sympy.Rational(rng.randint(1, 20), 4), sympy.Rational(rng.randint(30, 60), 4), \
            sympy.Rational(rng.randint(-8, 8), 4)
        t = rng.uniform(0, 6.283)
        subs = {r: vr, l: vl, e: ve, c: sympy.cos(t), s: sympy.sin(t)}
        hand = vr * sympy.cos(t) + sympy.sqrt(vl**2 - (vr * sympy.sin(t) - ve) ** 2)
        assert abs(sympy.N(ahead.values["B_x"].subs(subs) - hand, 30)) < 1e-12
        assert ahead.values["B_y"].subs(subs) == ve


def test_curves_of_the_slider_and_of_the_rod():
    line = run("curve", "slider-crank", "--point", "B", "--samples", "8")
    assert line["degree"] == 1  # the line y = e = 1/2
    assert sympy.cancel(sympy.parse_expr(line["curve"]) / (2 * sympy.Symbol("B_y") - 1)).is_number
    rod = run("curve", "slider-crank", "--point", "M", "--samples", "8")
    assert rod["degree"] == 4 and rod["verification"]["passed"]
    # Points at infinity: with z = exp(i*theta) -> oo, one branch of the rod turns with z and
    # sends M to a circular point, the other sends M along a non-isotropic direction: the
    # quartic passes once through each circular point.
    assert rod["circularity"] == 1
    mpmath.mp.dps = 40
    for k in range(0, 360, 30):
        t = mpmath.radians(k)
        a = (mpmath.cos(t), mpmath.sin(t))
        for sign in (1, -1):
            b = (a[0] + sign * mpmath.sqrt(9 - (a[1] - mpmath.mpf(1) / 2) ** 2), mpmath.mpf(1) / 2)
            assert abs(curve_at(rod, rigid(a, b, mpmath.mpf(1) / 2, 0))) < 1e-30
    mpmath.mp.dps = 15
