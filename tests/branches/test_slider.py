"""The slider construction against hand geometry: a line meets a circle, labelled by the side
of the foot of the perpendicular (``ahead`` / ``behind`` along the line's direction)."""

import math
from fractions import Fraction

import numpy as np
import sympy
from hypothesis import given, settings, strategies as st

import algkin
from algkin.branches import closed_forms
from algkin.branches.stable import StableBranch
from algkin.evaluate import FLOAT, evaluate
from algkin.scene import compile_scene, load_scene_text

# The line passes through the crank's end A, so it moves with the input; the circle is about Q.
SLIDER = """
[inputs]
t = {{ range = [0, 360] }}
[points]
O = {{ fixed = [0, 0] }}
Q = {{ fixed = ["{qx}", "{qy}"] }}
A = {{ crank = "O", length = "{crank}", input = "t" }}
X = {{ slider = {{ through = "A", direction = ["{dx}", "{dy}"] }}, distance = {{ to = "Q", length = "{length}" }}, branch = "ahead" }}
[outputs]
X = "X"
"""

small = st.fractions(min_value=-5, max_value=5, max_denominator=8)
positive = st.fractions(min_value=Fraction(1, 4), max_value=8, max_denominator=8)


def by_hand(point, direction, center, length):
    """Solve |point + u*direction - center| = length for u; return both points by the sign of
    dot(direction, X - center), or None when the line misses the circle."""
    (px, py), (dx, dy), (qx, qy) = point, direction, center
    wx, wy = px - qx, py - qy
    a, b, c = dx * dx + dy * dy, 2 * (dx * wx + dy * wy), wx * wx + wy * wy - length * length
    disc = b * b - 4 * a * c
    if disc < 1e-9:
        return None
    points = {}
    for u in ((-b + math.sqrt(disc)) / (2 * a), (-b - math.sqrt(disc)) / (2 * a)):
        x, y = px + u * dx, py + u * dy
        points["ahead" if dx * (x - qx) + dy * (y - qy) > 0 else "behind"] = (x, y)
    return points


@settings(max_examples=60)
@given(small, small, positive, small, small, positive, st.floats(0, 2 * math.pi))
def test_branches_match_a_line_circle_intersection(qx, qy, crank, dx, dy, length, theta):
    if dx == 0 and dy == 0:
        return
    text = SLIDER.format(qx=qx, qy=qy, crank=crank, dx=dx, dy=dy, length=length)
    compiled = compile_scene(load_scene_text(text, "slider.toml"))
    values = {"c_t": math.cos(theta), "s_t": math.sin(theta)}
    a = (float(crank) * math.cos(theta), float(crank) * math.sin(theta))
    expected = by_hand(a, (float(dx), float(dy)), (float(qx), float(qy)), float(length))
    branches = closed_forms(compiled)
    assert sorted(b.label for b in branches) == ["ahead", "behind"]
    for branch in branches:
        disc = evaluate(branch.discriminants["X"], values, FLOAT)
        if expected is None or abs(disc) < 1e-6:
            continue
        x = evaluate(branch.values["X_x"], values, FLOAT)
        y = evaluate(branch.values["X_y"], values, FLOAT)
        scale = 1 + float(abs(qx) + abs(qy) + crank + length)
        assert math.hypot(x - expected[branch.label][0], y - expected[branch.label][1]) < 1e-8 * scale


def test_oblique_slider_on_a_moving_line_is_verified():
    # Direction (3, 4): |d| = 5 is rational, so the discriminant is a difference of squares.
    text = SLIDER.format(qx=2, qy=-1, crank=1, dx=3, dy=4, length=3)
    result = algkin.derive(load_scene_text(text, "slider.toml"), samples=12)
    assert result.verification.passed and result.verification.compared > 0
    assert [b.label for b in result.branches] == ["ahead", "behind"]
    # At t = 0: A = (1, 0), the line (1, 0) + u*(3, 4) meets the circle of radius 3 about (2, -1):
    # |(3u - 1, 4u + 1)|**2 = 9 gives 25u**2 + 2u - 7 = 0, u = (-1 +- 4*sqrt(11))/25;
    # ahead is dot((3, 4), X - Q) = 25u + 1 > 0, the larger root.
    ahead = next(b for b in result.branches if b.label == "ahead")
    u = (-1 + 4 * math.sqrt(11)) / 25
    values = {"c_t": 1.0, "s_t": 0.0}
    assert abs(evaluate(ahead.values["X_x"], values, FLOAT) - (1 + 3 * u)) < 1e-12
    assert abs(evaluate(ahead.values["X_y"], values, FLOAT) - 4 * u) < 1e-12


# The line through R toward the crank tip A moves with the input: its direction is A - R.
TOWARD = """
[inputs]
t = {{ range = [0, 360] }}
[points]
O = {{ fixed = [0, 0] }}
Q = {{ fixed = ["{qx}", "{qy}"] }}
R = {{ fixed = ["{rx}", "{ry}"] }}
A = {{ crank = "O", length = "{crank}", input = "t" }}
X = {{ slider = {{ through = "R", toward = "A" }}, distance = {{ to = "Q", length = "{length}" }}, branch = "{branch}" }}
[outputs]
X = "X"
"""


@settings(max_examples=60, deadline=None)
@given(small, small, small, small, positive, positive, st.sampled_from(["ahead", "behind"]),
       st.floats(0, 2 * math.pi))
def test_moving_line_branches_and_stable_floats_match_a_line_circle_intersection(qx, qy, rx, ry, crank, length,
                                                                                 label, theta):
    text = TOWARD.format(qx=qx, qy=qy, rx=rx, ry=ry, crank=crank, length=length, branch=label)
    compiled = compile_scene(load_scene_text(text, "toward.toml"))
    a = (float(crank) * math.cos(theta), float(crank) * math.sin(theta))
    r = (float(rx), float(ry))
    direction = (a[0] - r[0], a[1] - r[1])
    if math.hypot(*direction) < 1e-3:  # A over R: the line has no direction there
        return
    expected = by_hand(r, direction, (float(qx), float(qy)), float(length))
    values = {"c_t": math.cos(theta), "s_t": math.sin(theta)}
    branch = next(b for b in closed_forms(compiled) if b.label == label)
    disc = evaluate(branch.discriminants["X"], values, FLOAT)
    stable = StableBranch(compiled, branch)(np.array([theta]))
    if expected is None or abs(disc) < 1e-6:
        return
    scale = 1 + float(abs(qx) + abs(qy) + abs(rx) + abs(ry) + crank + length)
    want = expected[label]
    x, y = (evaluate(branch.values[u], values, FLOAT) for u in ("X_x", "X_y"))
    assert math.hypot(x - want[0], y - want[1]) < 1e-8 * scale
    assert math.hypot(stable["X_x"][0] - want[0], stable["X_y"][0] - want[1]) < 1e-8 * scale


def test_toward_a_crank_tip_from_its_centre_keeps_the_difference_of_squares():
    # d = A - O = 2 (c, s): |d| = 2 is rational though d moves, so the discriminant factors
    # (l |d| - cross)(l |d| + cross); X is on the ray O -> A at distance 3 from Q = (1, 0):
    # |u (c, s) - (1, 0)| = 3, u**2 - 2 c u - 8 = 0, u = c + sqrt(c**2 + 8) ahead.
    text = TOWARD.format(qx=1, qy=0, rx=0, ry=0, crank=2, length=3, branch="ahead").replace('"R", toward', '"O", toward')
    compiled = compile_scene(load_scene_text(text, "toward.toml"))
    (branch, _) = closed_forms(compiled)
    assert branch.label == "ahead"
    assert len(sympy.Mul.make_args(branch.discriminants["X"])) >= 2  # a product, not one polynomial
    for theta in (0.0, 0.7, 2.0, -2.5):
        c, s = math.cos(theta), math.sin(theta)
        u = c + math.sqrt(c * c + 8)
        values = {"c_t": c, "s_t": s}
        assert abs(evaluate(branch.values["X_x"], values, FLOAT) - u * c) < 1e-12
        assert abs(evaluate(branch.values["X_y"], values, FLOAT) - u * s) < 1e-12
        stable = StableBranch(compiled, branch)(np.array([theta]))
        assert abs(stable["X_x"][0] - u * c) < 1e-12 and abs(stable["X_y"][0] - u * s) < 1e-12


def test_moving_line_indicator_is_dot_of_the_moving_direction():
    text = TOWARD.format(qx=1, qy=2, rx=0, ry=-5, crank=3, length=2, branch="behind")
    compiled = compile_scene(load_scene_text(text, "toward.toml"))
    (indicator,) = compiled.indicators
    x, y, c, s = sympy.symbols("X_x X_y c_t s_t", real=True)
    # d = A - R = (3c, 3s + 5); dot(d, X - Q)
    assert sympy.expand(indicator.expr - (3 * c * (x - 1) + (3 * s + 5) * (y - 2))) == 0
    assert (indicator.positive, indicator.negative, indicator.chosen) == ("ahead", "behind", "behind")
    line, circle = compiled.system.equations[:2]
    assert sympy.expand(line - (3 * c * (y + 5) - (3 * s + 5) * x)) == 0
    assert sympy.expand(circle - ((x - 1) ** 2 + (y - 2) ** 2 - 4)) == 0
