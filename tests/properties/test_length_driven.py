"""Scenes driven by a length (``strategies.length_driven``): closed forms verified, and equal to
the triangle the law of cosines draws by hand at random lengths in the range."""

import mpmath
import sympy
from hypothesis import assume, given, settings, strategies as st

from algkin.derivation.pipeline import curve, derive
from algkin.testing import strategies


def _hand(scene, s, side):
    """A and P from the definitions: A at r from O and at s from D (or at l from B = O + s (D - O))."""
    number = lambda name: mpmath.mpf(sympy.Rational(scene.parameters[name]).p) / sympy.Rational(scene.parameters[name]).q  # noqa: E731
    point = lambda name: tuple(mpmath.mpf(sympy.Rational(v).p) / sympy.Rational(v).q  # noqa: E731
                               for v in (scene.points[name].x, scene.points[name].y))
    o, d = point("O"), point("D")
    r, l, u = number("r"), number("l"), number("u")
    if "B" in scene.points:
        far, reach = (o[0] + s * (d[0] - o[0]), o[1] + s * (d[1] - o[1])), l
    else:
        far, reach = d, s
    dx, dy = far[0] - o[0], far[1] - o[1]
    cos_at_o = (r**2 + dx**2 + dy**2 - reach**2) / (2 * r * mpmath.hypot(dx, dy))
    angle = mpmath.atan2(dy, dx) + side * mpmath.acos(cos_at_o)
    a = (o[0] + r * mpmath.cos(angle), o[1] + r * mpmath.sin(angle))
    return a, (o[0] + u * (a[0] - o[0]), o[1] + u * (a[1] - o[1])), angle


@settings(max_examples=15, deadline=None)
@given(strategies.length_driven(), st.integers(0, 2**16), st.floats(0.01, 0.99))
def test_length_driven_forms_are_the_triangle_drawn_by_hand(scene, seed, where):
    result = derive(scene, ["A", "P", "phi"], samples=2, seed=seed, certify=False)
    assert result.verification.passed, result.verification.failures
    assert result.verification.compared > 0
    given = scene.inputs["s"]
    with mpmath.workdps(40):
        s = mpmath.mpf(given.lo.p) / given.lo.q + where * (mpmath.mpf(given.hi.p) / given.hi.q
                                                             - mpmath.mpf(given.lo.p) / given.lo.q)
        for branch in result.branches:
            side = 1 if branch.label == "left" else -1
            a, p, angle = _hand(scene, s, side)
            got = {u: sympy.N(v.subs(sympy.Symbol("s", real=True), sympy.Float(s, 40)), 40)
                   for u, v in branch.values.items()}
            expected = {"A_x": a[0], "A_y": a[1], "P_x": p[0], "P_y": p[1],
                        "cos_phi": mpmath.cos(angle), "sin_phi": mpmath.sin(angle)}
            for unknown, value in expected.items():
                assert abs(mpmath.mpf(str(got[unknown])) - value) < mpmath.mpf(10) ** -25, (branch.label, unknown)


@settings(max_examples=8, deadline=None)
@given(strategies.length_driven())
def test_the_curve_of_a_length_driven_point_is_its_circle(scene):
    """P stays on the circle of radius |u| r about O, whatever the length: the curve says so exactly."""
    radius = sympy.Rational(scene.parameters["u"]) * sympy.Rational(scene.parameters["r"])
    assume(radius != 0)  # P is O itself: it stays put, no curve (a usage error says so)
    result = curve(scene, "P", samples=0)
    x, y = (sympy.Symbol(v, real=True) for v in result.variables)
    o = [sympy.Rational(v) for v in (scene.points["O"].x, scene.points["O"].y)]
    circle = sympy.expand((x - o[0]) ** 2 + (y - o[1]) ** 2 - radius**2)
    polynomial = sympy.expand(result.elimination.polynomial)
    assert sympy.rem(polynomial, circle, x) == 0 or sympy.cancel(polynomial / circle).is_number
