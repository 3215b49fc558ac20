"""The slider construction against hand geometry: a line meets a circle, labelled by the side
of the foot of the perpendicular (``ahead`` / ``behind`` along the line's direction)."""

import math
from fractions import Fraction

from hypothesis import given, settings, strategies as st

import algkin
from algkin.branches import closed_forms
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
