"""Extremes of a branch that does not assemble over the whole range lie at its dead centres."""

import math

import pytest
import sympy

from algkin.analyses.extremum import extremum
from algkin.analyses.extremum.closed import value_factors
from algkin.analyses.extremum.critical import Problem
from algkin.system import symbol
from algkin.system.angles import Parametrisation


def test_triple_rocker_minimum_of_b_y_is_at_the_dead_centre():
    # fourbar-nongrashof: crank 2 about O, ground 5, coupler 3, rocker 7/2. Below the dead
    # centre the left branch's B.y falls steeply to the toggle, where A, B and D are collinear
    # (|AD| = l + m = 13/2, cos(theta) = -53/80); no stationary point is there.
    found = extremum("fourbar-nongrashof", "B.y")
    theta = -math.acos(-53 / 80)
    ay = 2 * math.sin(theta)  # A = 2 (cos, sin)
    by = ay + 3 / 6.5 * (0 - ay)  # B = A + l/(l + m) * (D - A), D = (5, 0)
    assert found.minimum.kind == "dead centre"
    assert float(found.minimum.input_deg) == pytest.approx(math.degrees(theta), abs=1e-9)
    assert float(found.minimum.value) == pytest.approx(by, abs=1e-9)
    assert float(found.maximum.value) > float(found.minimum.value)


def test_turning_crank_has_no_dead_centre_candidates():
    # The lambda's crank turns fully: B is real everywhere, so no extreme is a dead centre.
    found = extremum("chebyshev-lambda", "B.y")
    assert all(p.kind != "dead centre" for p in found.critical_points)


@pytest.mark.slow  # 7 s: a six-bar's distance, its second dyad on the first's root
def test_a_six_bars_distance_has_extremes_where_its_second_dyad_is_built_on_a_root():
    """Stephenson III's |OP|: the second dyad's discriminant holds the first's square root, so where
    its branch stops is found from the discriminant times its conjugate. (It raised TypeError, after
    minutes.) The maximum by mpmath: the old, sympy-expanded closed forms of the selected branch sampled
    every 0.1 degree, then the derivative's root (findroot at 30 digits): 3.78251206361934 at
    156.584481610082 degrees."""
    found = extremum("stephenson-iii", "dist(P, O)")
    assert float(found.maximum.input_deg) == pytest.approx(156.584481610082, abs=1e-9)
    assert float(found.maximum.value) == pytest.approx(3.78251206361934, abs=1e-12)
    assert float(found.minimum.value) < float(found.maximum.value)


def test_values_are_found_where_the_eliminants_highest_terms_hold_the_circle():
    """An eliminant whose highest terms carry ``c**2 + s**2`` (here ``(c**2 + s**2) (u - s)``: ``u = sin``)
    has ``1 + t**2`` in its half-angle numerator, and so has its derivative along the input: the two
    shared a factor and every resultant in ``t`` vanished (``extremum stephenson-iii --of 'angle(C, F)'``
    failed so). That factor has no real root: without it, the values are those where the sine stops,
    +1 and -1 (at 90 and 270 degrees)."""
    c, s, t, u = (symbol(n) for n in ("c", "s", "t", "u"))
    problem = Problem(sympy.expand((c**2 + s**2) * (u - s)), s, u, Parametrisation((c, s), t), ())
    assert sorted(sympy.solve(sympy.Mul(*value_factors(problem)), u)) == [-1, 1]


@pytest.mark.slow  # 3 s
def test_a_six_bars_link_direction_has_extremes():
    """Stephenson III's direction of CF, C on the four-bar's coupler, F the second dyad's: its eliminant's
    highest terms hold the circle (it failed: the resultant in t vanished). By mpmath, independently: the
    scene's points from circle-circle intersections at 30 digits, the angle's derivative's roots by findroot
    from a 0.25-degree scan: 118.985998993366 at 262.567300491505 degrees, 165.393606899217 at
    66.0204742325034."""
    found = extremum("stephenson-iii", "angle(C, F)")
    assert float(found.minimum.input_deg) == pytest.approx(262.567300491505, abs=1e-9)
    assert float(found.minimum.value) == pytest.approx(118.985998993366, abs=1e-9)
    assert float(found.maximum.input_deg) == pytest.approx(66.0204742325034, abs=1e-9)
    assert float(found.maximum.value) == pytest.approx(165.393606899217, abs=1e-9)


def test_an_extreme_where_a_dyads_discriminant_touches_zero_is_kept():
    """Hart's inversor on its scene's modes: at 300 degrees the crossed dyad C's discriminant touches zero
    (|BD| = a - b = 2, C folded; both modes meet and part again), and there |OQ| is greatest. At the root
    found for it the discriminant read a rounding below zero, and the maximum was given as the dead centre
    at 284.48 degrees (2.9155). By mpmath, independently (circle-circle intersections at 30 digits from the
    scene's dimensions, 0.25-degree scan, then findroot on the derivative): 3 at 300 degrees, and the
    minimum 1.5 at 28.9550243718598."""
    found = extremum("hart-inversor", "dist(Q, O)")
    assert float(found.maximum.input_deg) == pytest.approx(300, abs=1e-9)
    assert float(found.maximum.value) == pytest.approx(3, abs=1e-12)
    assert float(found.minimum.input_deg) == pytest.approx(28.9550243718598, abs=1e-9)
    assert float(found.minimum.value) == pytest.approx(1.5, abs=1e-12)
