"""The general four-bar against hand geometry (law of cosines), Grashof's rule and the
literature's figure for its coupler curve: a tricircular sextic (Roberts 1875; Hunt,
Kinematic Geometry of Mechanisms, 1978)."""

import random
from fractions import Fraction

import mpmath
import pytest
import sympy

import algkin
from algkin.scene import load_scene

from .geometry import at_angle, branch, circles, curve_at, exact_at, rigid, run, same


def dims(name):
    return {k: Fraction(str(v)) for k, v in load_scene(name).parameters.items()}


def test_defaults_are_a_grashof_crank_rocker():
    d = dims("fourbar")
    links = sorted([d["a"], d["d"], d["l"], d["m"]])
    assert links[0] + links[3] <= links[1] + links[2]          # Grashof
    assert links[0] == d["a"]                                   # the crank is the shortest: it turns fully


@pytest.fixture(scope="module")
def derived():
    return run("derive", "fourbar", "--samples", "12")


def hand(theta, side=1, a=1, d=4, l=3, m=mpmath.mpf(7) / 2, p=mpmath.mpf(1) / 2, q=mpmath.mpf(1) / 2):
    a_ = (a * mpmath.cos(mpmath.radians(theta)), a * mpmath.sin(mpmath.radians(theta)))
    b = circles(a_, l, (d, 0), m, side)
    return b, rigid(a_, b, p, q)


def test_theta_zero_exactly():
    # A = (1, 0), |AD| = 3: the triangle A, B, D has sides 3, 7/2, 3, so the angle at A has
    # cos = (9 + 9 - 49/4) / 18 = 23/72 and B = A + 3*(23/72, +sqrt(1 - (23/72)**2)) (left: above).
    document = run("derive", "fourbar", "--outputs", "B", "--samples", "0")
    left = branch(document, "left")["values"]
    cos_a = sympy.Rational(23, 72)
    sin_a = sympy.sqrt(1 - cos_a**2)
    assert same(exact_at(left["B_x"], 1, 0), 1 + 3 * cos_a)
    assert same(exact_at(left["B_y"], 1, 0), 3 * sin_a)


@pytest.mark.parametrize("theta", [0, 30, 90, 135, 180, 250, 300])
def test_both_branches_by_the_law_of_cosines(derived, theta):
    mpmath.mp.dps = 40
    for label, side in (("left", 1), ("right", -1)):
        values = branch(derived, label)["values"]
        b, p = hand(theta, side)
        assert abs(at_angle(values["B_x"], theta) - b[0]) < 1e-30
        assert abs(at_angle(values["B_y"], theta) - b[1]) < 1e-30
        assert abs(at_angle(values["P_x"], theta) - p[0]) < 1e-30
        assert abs(at_angle(values["P_y"], theta) - p[1]) < 1e-30
    mpmath.mp.dps = 15
    assert derived["verification"]["passed"]


def test_crank_rocker_assembles_over_the_whole_turn(derived):
    # Grashof crank-rocker: |l - m| < |AD| < l + m for every crank angle, so the discriminant
    # (valid_when) of the chosen branch is positive all the way round.
    disc = sympy.parse_expr(branch(derived, "left")["discriminants"]["B"])
    c, s = sympy.symbols("c_theta s_theta")
    f = sympy.lambdify((c, s), disc, "mpmath")
    for k in range(0, 360, 5):
        t = mpmath.radians(k)
        ad2 = 1 + 16 - 8 * mpmath.cos(t)
        assert (mpmath.mpf(1) / 4 < ad2 < mpmath.mpf(169) / 4) and f(mpmath.cos(t), mpmath.sin(t)) > 0


def test_coupler_curve_is_a_verified_tricircular_sextic():
    document = run("curve", "fourbar", "--point", "P", "--samples", "12")
    assert document["degree"] == 6 and document["circularity"] == 3
    assert document["irreducible"] and document["verification"]["passed"]
    mpmath.mp.dps = 40
    for theta in range(0, 360, 40):
        for side in (1, -1):
            assert abs(curve_at(document, hand(theta, side)[1])) < 1e-30
    mpmath.mp.dps = 15


def test_symbolic_dimensions_follow_the_law_of_cosines():
    result = algkin.derive("fourbar", outputs=["B"], params=["a", "d", "l", "m"], samples=0)
    left = next(b for b in result.branches if b.label == "left")
    symbols = {n: sympy.Symbol(n, real=True) for n in ("a", "d", "l", "m")}
    c, s = sympy.Symbol("c_theta", real=True), sympy.Symbol("s_theta", real=True)
    rng = random.Random(5)
    mpmath.mp.dps = 30
    checked = 0
    while checked < 10:
        a, d, l, m = (mpmath.mpf(rng.randint(4, 40)) / 8 for _ in range(4))
        theta = rng.uniform(0, 360)
        t = mpmath.radians(theta)
        ad = mpmath.hypot(d - a * mpmath.cos(t), a * mpmath.sin(t))
        if not abs(l - m) + 1e-3 < ad < l + m - 1e-3:
            continue  # the triangle A, B, D does not close at this angle
        b = hand(theta, 1, a, d, l, m)[0]
        subs = {symbols["a"]: a, symbols["d"]: d, symbols["l"]: l, symbols["m"]: m,
                c: mpmath.cos(mpmath.radians(theta)), s: mpmath.sin(mpmath.radians(theta))}
        assert abs(sympy.N(left.values["B_x"].subs(subs), 30) - b[0]) < 1e-20
        assert abs(sympy.N(left.values["B_y"].subs(subs), 30) - b[1]) < 1e-20
        checked += 1
    mpmath.mp.dps = 15
