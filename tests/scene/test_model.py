"""A scene moved away (``Scene.translated``, the accuracy run's far case) is the same mechanism: its
ground points and the configurations that name its modes move together, its modes stay the ones meant;
an input's range in radians is the float sympy's pi gives, and a range in radians the degrees sympy's ``deg`` gives."""

from fractions import Fraction

import sympy
from hypothesis import example, given, strategies as st

from algkin.derivation.modes import resolve_modes
from algkin.scene import load_scene
from algkin.scene.model import Input

FAR = 10**7


def test_a_mode_named_by_a_configuration_moves_with_the_scene():
    # Hart's inversor names C's mode by C near (-1, 1.7) at angle 0; moved by (1e7, 1e7) its C is there
    # plus (1e7, 1e7), so the same mode is meant (before: refused, the nearest C 1.41e7 from the old place)
    scene = load_scene("hart-inversor")
    moved = scene.translated(FAR)
    assert moved.points["C"].mode.near == (scene.points["C"].mode.near[0] + FAR, scene.points["C"].mode.near[1] + FAR)
    assert (moved.points["O"].x, moved.points["O"].y) == (FAR, FAR)
    assert resolve_modes(moved).points["C"].branch == resolve_modes(scene).points["C"].branch


@given(st.fractions(-36000, 36000, max_denominator=10**6))
@example(Fraction(360))
@example(Fraction(-90))
@example(Fraction(1, 3))
def test_an_angle_in_radians_is_the_float_sympy_rounds_it_to(degrees):
    value = sympy.Rational(degrees.numerator, degrees.denominator)
    assert Input("t", value, value + 1).radians(value) == float(value * sympy.pi / 180)
    assert Input("t", value, value + 1, "rad").radians(value) == float(value)


@given(st.fractions(-630, 630, max_denominator=10**6) | st.fractions(max_denominator=10**30))
@example(Fraction(1, 10))  # 5.729577951308232 deg; the float of 1/10 times the float of 180/pi is one ulp above
@example(Fraction(1, 1))  # 180/pi
@example(Fraction(1, 180))  # 1/pi, a power alone
@example(Fraction(-1, 180))  # -1/pi, a product
@example(Fraction(0))
def test_a_range_in_radians_spans_the_degrees_sympy_rounds_it_to(radians):
    # the float sympy's deg (``r/pi*180``) gives, as users read a range in radians in every document
    value = sympy.Rational(radians.numerator, radians.denominator)
    assert Input("t", value, value + 1, "rad").span == (float(sympy.deg(value)), float(sympy.deg(value + 1)))
    assert Input("t", value, value + 1).span == (float(value), float(value + 1))
