"""Stationary conditions where the eliminant's numerator in ``t = tan(theta/2)`` shares a factor with
its derivative: a repeated factor, or a component on which the output keeps one value. The resultant
in the output vanished (``algkin: failed: no stationary condition ... the equations share a factor``)."""

import math

import pytest
import sympy

from algkin.analyses.extremum import extremum
from algkin.analyses.extremum.critical import Problem, stationary_factors
from algkin.errors import UsageError
from algkin.system import symbol
from algkin.system.angles import Parametrisation

C, S, T, U = (symbol(n) for n in ("c", "s", "t", "u"))
CIRCLE = Parametrisation((C, S), T)


def _stationary_inputs(eliminant: sympy.Expr) -> list[sympy.Expr]:
    """The real ``t`` of the stationary factors of ``u = sin(theta)`` with ``eliminant`` its polynomial."""
    factors = stationary_factors(Problem(sympy.expand(eliminant), S, U, CIRCLE, ()))
    return sorted(r for f in factors for r in sympy.real_roots(sympy.Poly(f, T)))


def test_two_factors_equal_on_the_circle_are_one():
    """``u - s`` and ``u (c**2 + s**2) - s`` differ in ``c, s`` but are one polynomial in ``t``: the
    numerator held it squared. ``u = sin`` is stationary at 90 and 270 degrees, ``t = 1, -1``."""
    assert _stationary_inputs((U - S) * (U * (C**2 + S**2) - S)) == [-1, 1]


def test_a_component_where_the_output_keeps_one_value_is_set_apart():
    """``2u + 3`` holds no input: on it ``u`` is -3/2 throughout, and it divided the derivative too."""
    assert _stationary_inputs((2 * U + 3) * (U - S)) == [-1, 1]


def test_hart_inversors_q_y_is_extreme_on_its_named_mode():
    """Hart's Q runs on the line x = -3/2. By mpmath at 50 digits, independently: A, B = +-(a/2)(cos, sin),
    D the left intersection of the circles about A (radius b) and W = 2Z - A (2r), C the intersection of
    the circles about B (b) and D (a) that is not the parallelogram's B + D - A (the crossed mode the
    scene names), Q = (B + C)/2; a 4000-step scan of the range where D assembles (cos >= 1/4), then
    findroot on the derivative: Q.y is greatest, 2.59807621135331594 (3 sqrt(3)/2), at -60 = 300
    degrees, where the two modes cross; least at the dead centre acos(1/4) = 75.5224878140700761
    degrees, -1.93649167310370844 (-sqrt(15)/2). On [284.48, 300] the mode is C's right-hand branch:
    the scene's left-hand one there (the parallelogram) would put the maximum at 285.41 degrees, 2.92."""
    found = extremum("hart-inversor", "Q.y")
    assert float(found.maximum.input_deg) == pytest.approx(300, abs=1e-9)
    assert float(found.maximum.value) == pytest.approx(2.59807621135331594, abs=1e-12)
    assert found.minimum.kind == "dead centre"
    assert float(found.minimum.input_deg) == pytest.approx(75.5224878140700761, abs=1e-9)
    assert float(found.minimum.value) == pytest.approx(-1.93649167310370844, abs=1e-12)
    dead = [p for p in found.critical_points if p.kind == "dead centre"]
    assert [float(p.value) for p in dead] == pytest.approx([-1.93649167310370844, 1.93649167310370844], abs=1e-12)


@pytest.mark.parametrize(("scene", "output", "value"), [("hart-inversor", "Q.x", "-3/2"),
                                                         ("peaucellier-lipkin", "P.x", "5/2")])
def test_a_coordinate_that_does_not_move_is_refused_with_its_value(scene: str, output: str, value: str):
    """Both inversors' points run on a line x = const: -(a^2 - b^2)/(8r) = -3/2 for Hart's, (L^2 - s^2)/(2r)
    = 5/2 for Peaucellier's."""
    with pytest.raises(UsageError, match=f"does not depend on the input: it is {value} throughout"):
        extremum(scene, output)


def test_peaucellier_lipkins_p_y_is_extreme_where_the_arms_cannot_reach():
    """P is A inverted in O: |OA| |OP| = L^2 - s^2 = 5, A = (1 + cos, sin), so P = 5 A / |A|^2 and
    P.y = (5/2) tan(theta/2): increasing, extreme at the range's ends +-120 degrees, where |OA| = L - s
    and the rhombus folds (a dead centre): +-(5/2) sqrt(3). (It raised TypeError: its branch's
    discriminant is a quotient.)"""
    found = extremum("peaucellier-lipkin", "P.y")
    assert float(found.minimum.input_deg) == pytest.approx(-120, abs=1e-9)
    assert float(found.minimum.value) == pytest.approx(-2.5 * math.sqrt(3), abs=1e-12)
    assert float(found.maximum.input_deg) == pytest.approx(120, abs=1e-9)
    assert float(found.maximum.value) == pytest.approx(2.5 * math.sqrt(3), abs=1e-12)
