"""The Chebyshev notebook, done without picking branches by hand."""

import json
import random
import subprocess
import sys

import mpmath
import pytest
import sympy

from algkin.eliminate import BACKENDS, METHODS

from .seed_values import RX, RY

c, s, x, y = sympy.symbols("c_angle s_angle B_x B_y")
PX, PY = sympy.symbols("P_x P_y")


def run(*args):
    out = subprocess.run([sys.executable, "-m", "algkin", *args, "--json"], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    return json.loads(out.stdout)


def seed_poly(text, unknown):
    expr = sympy.parse_expr(text.replace("^", "**"), local_dict={"c": c, "s": s, "x": x, "y": y})
    return expr.subs({sympy.Symbol("x"): x, sympy.Symbol("y"): y}) if unknown else expr


def same_up_to_constant(a, b, gens):
    ratio = sympy.cancel(sympy.parse_expr(str(a)) / sympy.parse_expr(str(b)))
    return ratio.is_number and ratio != 0


@pytest.fixture(scope="module")
def derived():
    return run("derive", "chebyshev-lambda", "--outputs", "B")


def test_eliminants_are_the_notebooks_resultants(derived):
    elim = derived["eliminants"]
    assert same_up_to_constant(elim["B_y"], seed_poly(RY, True), (y, c, s))
    assert same_up_to_constant(elim["B_x"], seed_poly(RX, True), (x, c, s))


@pytest.mark.parametrize("method", sorted(METHODS))
@pytest.mark.parametrize("backend", sorted(BACKENDS))
def test_every_method_and_backend_gives_the_notebooks_resultants(method, backend):
    import algkin

    result = algkin.derive("chebyshev-lambda", outputs=["B"], method=method, backend=backend, samples=0)
    assert same_up_to_constant(result.eliminations["B_y"].polynomial, seed_poly(RY, True), ())
    assert same_up_to_constant(result.eliminations["B_x"].polynomial, seed_poly(RX, True), ())


def test_two_labelled_branches_satisfy_both_circles_and_sides(derived):
    branches = {b["label"]: b for b in derived["branches"]}
    assert set(branches) == {"left", "right"}
    assert derived["inputs"] == {"angle": {"cos": "c_angle", "sin": "s_angle"}}
    rng = random.Random(7)
    mpmath.mp.dps = 40
    for _ in range(25):
        angle = mpmath.mpf(rng.uniform(0, 2 * 3.141592653589793))
        cv, sv = mpmath.cos(angle), mpmath.sin(angle)
        for label, branch in branches.items():
            bx = sympy.parse_expr(branch["values"]["B_x"]).subs({c: cv, s: sv}).evalf(40)
            by = sympy.parse_expr(branch["values"]["B_y"]).subs({c: cv, s: sv}).evalf(40)
            # Geometry of the notebook: |B - A| = 5/2 with A = (cos, sin), |B - D| = 5/2, D = (2, 0).
            assert abs((bx - cv) ** 2 + (by - sv) ** 2 - 6.25) < 1e-30
            assert abs((bx - 2) ** 2 + by**2 - 6.25) < 1e-30
            cross = (2 - cv) * (by - sv) - (0 - sv) * (bx - cv)
            assert (cross > 0) == (label == "left")
    mpmath.mp.dps = 15
    assert derived["verification"]["passed"]
    assert derived["verification"]["samples"] > 0


def test_timings_per_stage(derived):
    assert {"compile", "eliminate", "verify", "total"} <= set(derived["timings"])
    assert all(v >= 0 for v in derived["timings"].values())


def coupler_point(theta, branch_sign):
    """P by hand: B on the circle of radius 5/2 about D, at 5/2 from A; P = A + 2(B - A)."""
    ax, ay = mpmath.cos(theta), mpmath.sin(theta)
    dx, dy = 2 - ax, -ay
    dist = mpmath.sqrt(dx**2 + dy**2)
    # Isosceles triangle A, B, D: B sits above the midpoint of AD at height h.
    h = mpmath.sqrt(mpmath.mpf(25) / 4 - dist**2 / 4)
    bx = ax + dx / 2 - branch_sign * h * dy / dist
    by = ay + dy / 2 + branch_sign * h * dx / dist
    return 2 * bx - ax, 2 * by - ay


def test_coupler_curve_is_an_irreducible_tricircular_sextic():
    curve = run("curve", "chebyshev-lambda", "--point", "P")
    assert curve["variables"] == ["P_x", "P_y"]
    poly = sympy.Poly(sympy.parse_expr(curve["curve"]), PX, PY)
    # A four-bar coupler curve is a tricircular sextic (Hunt, Kinematic Geometry of Mechanisms).
    assert poly.total_degree() == curve["degree"] == 6
    top = sum(sympy.Mul(coef, PX**i, PY**j) for (i, j), coef in poly.terms() if i + j == 6)
    assert sympy.cancel(top / (PX**2 + PY**2) ** 3).is_number
    assert curve["circularity"] == 3
    assert len(sympy.factor_list(poly.as_expr())[1]) == 1
    assert curve["dropped_factors"], "the resultant chain brings extraneous factors"
    assert curve["verification"]["passed"]
    mpmath.mp.dps = 40
    evaluate = sympy.lambdify((PX, PY), poly.as_expr(), "mpmath")
    for k in range(12):
        for sign in (1, -1):
            assert abs(evaluate(*coupler_point(mpmath.mpf(k) / 2, sign))) < 1e-25
    mpmath.mp.dps = 15
