"""Angle outputs derived: Freudenstein's equation, and closed forms against hand geometry.

Freudenstein's equation for a four-bar with crank a (angle theta from the ground line), ground
d, coupler l and rocker m (angle phi, the direction from D to B): with B = D + m*(cos phi, sin phi)
and A = a*(cos theta, sin theta), |B - A|**2 = l**2 expands to

    K1*cos(phi) - K2*cos(theta) + K3 = cos(theta - phi),
    K1 = d/a, K2 = d/m, K3 = (a**2 - l**2 + m**2 + d**2) / (2*a*m).

With cos(theta - phi) = cos(theta)*cos(phi) + sin(theta)*sin(phi), moving the sine term alone to
one side and squaring eliminates sin(phi): a polynomial in cos(phi), cos(theta), sin(theta).
"""

import mpmath
import sympy
from hypothesis import given, settings, strategies as st

import algkin
from algkin.evaluate import MPMATH, evaluate

from ..catalog.geometry import circles

a, d, l, m, c, s = (sympy.Symbol(n, real=True) for n in ("a", "d", "l", "m", "c_theta", "s_theta"))
cos_phi, sin_phi = sympy.Symbol("cos_angle_D_B", real=True), sympy.Symbol("sin_angle_D_B", real=True)


def on_circle(expr):
    """The normal form modulo cos**2 + sin**2 = 1 (sin**2 -> 1 - cos**2)."""
    return sympy.expand(sympy.rem(sympy.expand(expr), s**2 + c**2 - 1, s))


def freudenstein():
    k1, k2, k3 = d / a, d / m, (a**2 - l**2 + m**2 + d**2) / (2 * a * m)
    lone_sine = k1 * cos_phi - k2 * c + k3 - c * cos_phi  # = sin(theta) * sin(phi)
    return sympy.expand((lone_sine**2 - s**2 * (1 - cos_phi**2)) * (2 * a * m) ** 2)


def test_rocker_cosine_eliminant_is_freudensteins_equation():
    result = algkin.derive("fourbar", outputs=["angle(D, B)"], params=["a", "d", "l", "m"], samples=20)
    assert result.verification.passed
    eliminant = result.eliminations["cos_angle_D_B"].polynomial
    ratio = sympy.cancel(on_circle(eliminant) / on_circle(freudenstein()))
    assert ratio.is_number and ratio != 0, ratio  # equal up to a constant, exactly
    # and the same with the sine: Freudenstein before squaring vanishes on both closed forms
    k1, k2, k3 = d / a, d / m, (a**2 - l**2 + m**2 + d**2) / (2 * a * m)
    defaults = {a: 1, d: 4, l: 3, m: sympy.Rational(7, 2)}
    for branch in result.branches:
        unsquared = (k1 * cos_phi - k2 * c + k3 - c * cos_phi - s * sin_phi).xreplace(
            {cos_phi: branch.values["cos_angle_D_B"], sin_phi: branch.values["sin_angle_D_B"]})
        for t in (sympy.Rational(1, 7), sympy.Rational(3, 2), -sympy.Rational(5, 3)):  # exact points of the circle
            on = {c: (1 - t**2) / (1 + t**2), s: 2 * t / (1 + t**2)}
            assert abs(sympy.N(unsquared.xreplace(defaults).xreplace(on), 50)) < 1e-40


def test_angle_outputs_of_the_catalog_four_bar_are_verified():
    result = algkin.derive("fourbar", outputs=["angle(D, B)", "angle(A, B)", "angle(A, B, D)", "angle(D, P)"],
                           samples=30)
    assert result.verification.passed and result.verification.compared > 0
    assert set(result.compiled.outputs) == {"angle_D_B", "angle_A_B", "angle_A_B_D", "angle_D_P"}
    for branch in result.branches:
        assert {"cos_angle_D_B", "sin_angle_D_B", "cos_angle_A_B_D", "len_angle_D_P"} <= set(branch.values)
        # the transmission angle's cosine is the textbook's on both modes
        assert sympy.simplify(branch.values["cos_angle_A_B_D"] - (32 * c + 17) / 84) == 0


FOURBAR = {"a": 1, "d": 4, "l": 3, "m": mpmath.mpf(7) / 2, "p": mpmath.mpf(1) / 2, "q": mpmath.mpf(1) / 2}


def hand_configuration(theta_deg, side):
    """O, A, B, D, P of the catalog four-bar, by the law of cosines (``geometry.circles``)."""
    o, dd = (mpmath.mpf(0), mpmath.mpf(0)), (mpmath.mpf(FOURBAR["d"]), mpmath.mpf(0))
    t = mpmath.radians(theta_deg)
    aa = (FOURBAR["a"] * mpmath.cos(t), FOURBAR["a"] * mpmath.sin(t))
    b = circles(aa, FOURBAR["l"], dd, FOURBAR["m"], side)
    p = (aa[0] + FOURBAR["p"] * (b[0] - aa[0]) - FOURBAR["q"] * (b[1] - aa[1]),
         aa[1] + FOURBAR["p"] * (b[1] - aa[1]) + FOURBAR["q"] * (b[0] - aa[0]))
    return {"O": o, "A": aa, "B": b, "D": dd, "P": p}


_derived = {}


def derived():
    if not _derived:
        _derived["r"] = algkin.derive("fourbar", outputs=["angle(D, B)", "angle(D, P)", "angle(A, B, D)"],
                                      samples=0, certify=False)
    return _derived["r"]


@settings(max_examples=40, deadline=None)
@given(st.floats(min_value=0, max_value=360, allow_nan=False, exclude_max=True))
def test_direction_closed_forms_are_a_unit_vector_at_the_hand_solved_angle(theta):
    with mpmath.workdps(30):
        values = {"c_theta": mpmath.cos(mpmath.radians(theta)), "s_theta": mpmath.sin(mpmath.radians(theta))}
        for branch in derived().branches:
            side = 1 if branch.label == "left" else -1
            points = hand_configuration(theta, side)
            for name, (p, q) in (("angle_D_B", ("D", "B")), ("angle_D_P", ("D", "P"))):
                cos_v = evaluate(branch.values[f"cos_{name}"], values, MPMATH)
                sin_v = evaluate(branch.values[f"sin_{name}"], values, MPMATH)
                assert abs(cos_v**2 + sin_v**2 - 1) < 1e-20
                hand = mpmath.atan2(points[q][1] - points[p][1], points[q][0] - points[p][0])
                assert abs(mpmath.atan2(sin_v, cos_v) - hand) < 1e-20
            ba = [points["A"][k] - points["B"][k] for k in (0, 1)]
            bd = [points["D"][k] - points["B"][k] for k in (0, 1)]
            mu = mpmath.acos((ba[0] * bd[0] + ba[1] * bd[1]) / (mpmath.norm(ba) * mpmath.norm(bd)))
            cos_mu = evaluate(branch.values["cos_angle_A_B_D"], values, MPMATH)
            assert abs(mpmath.acos(cos_mu) - mu) < 1e-15
