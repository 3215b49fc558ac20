"""The seed-like Python API against the seed's own vector derivation."""

import math

import mpmath
import numpy as np

import pytest
import sympy

import algkin
from algkin.errors import BudgetExceeded, UsageError

from ..hand_linkages import CHEBYSHEV, fourbar
from .extremum.arm_by_hand import hand_minimum

theta, b = sympy.Symbol("theta", real=True), sympy.Symbol("b", real=True)


@pytest.fixture(scope="module")
def ab():
    return algkin.load_quantities("arm-string", params=["b"]).dist("A", "B")


def test_expression_is_the_seeds_norm(ab):
    # The seed: r_AB = r_OB - 350 (sin t, -cos t), with r_OB = (400, -b).
    seed = sympy.sqrt((400 - 350 * sympy.sin(theta)) ** 2 + (-b + 350 * sympy.cos(theta)) ** 2)
    assert sympy.simplify(ab.expr**2 - seed**2) == 0
    assert ab.at(theta=30, b=80) == pytest.approx(float(seed.subs({theta: sympy.pi / 6, b: 80})), rel=1e-12)


def test_relation_holds_on_the_expression(ab):
    on_motion = ab.relation.subs(ab.symbol, ab.expr)
    assert sympy.simplify(sympy.expand(on_motion)) == 0


def test_extremum_reads_like_the_seed(ab):
    found = ab.extremum(range=(0, 180))
    assert float(found.minimum.value) == pytest.approx(hand_minimum(400, 80), abs=1e-9)
    assert str(found.closed_form.value) == "sqrt(b**2 + 160000) - 350"


def test_fixed_dimensions_have_no_closed_form_in_them():
    found = algkin.load_quantities("arm-string").output("AB").extremum()
    assert found.closed_form is None
    assert float(found.minimum.input_deg) == pytest.approx(math.degrees(math.atan2(400, 80)), abs=1e-9)


def test_points_are_not_scalars():
    with pytest.raises(algkin.AlgkinError, match="scalar"):
        algkin.load_quantities("chebyshev-lambda").output("B").extremum()


def test_quantity_gives_both_spellings_of_the_input():
    """``expr`` in cos(theta)/sin(theta); ``expr_cs`` in c_theta/s_theta, equal to derive's branch."""
    import algkin
    from algkin.system import symbol

    AB = algkin.load_quantities("arm-string", params=["b"]).dist("A", "B")
    c, s, theta = symbol("c_theta"), symbol("s_theta"), AB.input
    assert AB.expr_cs.xreplace({c: sympy.cos(theta), s: sympy.sin(theta)}) == AB.expr
    assert AB.relation_cs.xreplace({c: sympy.cos(theta), s: sympy.sin(theta)}) == AB.relation
    derived = algkin.derive("arm-string", ["AB"], params=["b"], samples=0)
    chosen = next(b for b in derived.branches if b.to_json()["selected"])
    assert AB.expr_cs == chosen.values["AB"]
    assert not AB.expr_cs.has(sympy.cos) and {c, s} <= AB.expr_cs.free_symbols


def test_an_array_of_inputs_is_nan_where_the_label_is_not_certified_never_a_branch_guessed():
    """The triple rocker's dead centre by the law of cosines, |AD| = l + m: cos(theta) = -13.25/20.
    There, and past it where B cannot assemble, floats say nothing; inside, they are B by hand."""
    toggle = math.degrees(math.acos(-13.25 / 20))
    bx = algkin.load_quantities("fourbar-nongrashof").x("B")
    inside = [0.0, 90.0, toggle - 1e-3, -toggle + 1e-3]
    found = bx.at(theta=np.array([toggle, -toggle, toggle + 1e-9, 170.0, *inside]))
    assert np.all(np.isnan(found[:4]))
    hand = [fourbar(theta, a=2, d=5, l=3, m=mpmath.mpf(7) / 2, p=0, q=0)["B"][0] for theta in inside]
    assert np.allclose(found[4:], hand, rtol=0, atol=1e-12)


@pytest.mark.parametrize("mode", ["left", "right"])
def test_a_coordinate_on_either_assembly_mode_is_the_hand_geometrys(mode):
    # Issue 35: m.x("B") could not choose the assembly mode; mode= takes the labels derive gives.
    lam = algkin.load_quantities("chebyshev-lambda")
    Bx, By = lam.x("B", mode=mode), lam.y("B", mode=mode)
    assert Bx.modes == By.modes == ["left", "right"]
    for angle in (30, 63, 200):
        expected = fourbar(angle, **CHEBYSHEV, branch=mode)["B"]
        assert (Bx.at(angle=angle), By.at(angle=angle)) == pytest.approx(expected, abs=1e-12)
        assert float(By.expr.subs(By.input, sympy.rad(angle))) == pytest.approx(expected[1], abs=1e-12)
    swept = By.at(angle=np.array([30.0, 63.0, 200.0]))  # the stabilised kernel: on the same mode
    hand = [fourbar(a, **CHEBYSHEV, branch=mode)["B"][1] for a in (30, 63, 200)]
    assert swept == pytest.approx(hand, abs=1e-12)


def test_the_default_mode_is_the_scenes_and_an_unknown_one_is_refused_with_the_labels():
    lam = algkin.load_quantities("chebyshev-lambda")  # the scene asks for left
    assert lam.y("B").at(angle=63) == lam.y("B", mode="left").at(angle=63) != lam.y("B", mode="right").at(angle=63)
    with pytest.raises(algkin.AlgkinError, match=r"^mode='up': not a mode of B\.y in chebyshev-lambda \(modes: left, right\)"):
        lam.y("B", mode="up").at(angle=63)


def test_the_extremum_of_a_mode_is_that_modes():
    # B's height over the turn, its least and greatest on each mode against a dense sweep of the hand geometry
    lam = algkin.load_quantities("chebyshev-lambda")
    for mode in ("left", "right"):
        found = lam.y("B", mode=mode).extremum()
        dense = [fourbar(a, **CHEBYSHEV, branch=mode)["B"][1] for a in np.linspace(0, 360, 3601)]
        assert float(found.maximum.value) == pytest.approx(max(dense), abs=1e-5)
        assert float(found.minimum.value) == pytest.approx(min(dense), abs=1e-5)


def test_a_budget_bounds_the_eliminations_of_its_quantities():
    # B's eliminant comes from the dyad's two circles, (B_x - a c)^2 + (B_y - a s)^2 = l^2 and one about D:
    # by hand, more than 3 terms each.
    quantity = algkin.load_quantities("fourbar", budget=algkin.Budget(terms=3)).output("dist(P, D)")
    with pytest.raises(BudgetExceeded, match="max_terms=3: "):
        quantity.extremum()
    with pytest.raises(UsageError, match="budget=10: expected an algkin.Budget"):
        algkin.load_quantities("fourbar", budget=10)


@pytest.mark.parametrize("make, said", [
    (lambda: algkin.Quantity(None, "dist(A, B)"), "mechanism=None: expected an algkin.Mechanism"),  # an AttributeError
    (lambda: algkin.Quantity(algkin.load_quantities("arm-string"), 5), "text=5: expected an output's text"),
    (lambda: algkin.Mechanism(None), "scene=None: expected a catalog name"),  # an AttributeError at its first use
    (lambda: algkin.Mechanism("arm-string", params="b"), "params='b': expected a list of names"),
    (lambda: algkin.Mechanism("arm-string", deadline=5), "deadline=5: expected an algkin.Budget"),
], ids=["quantity-mechanism", "quantity-text", "mechanism-scene", "mechanism-params", "mechanism-deadline"])
def test_a_mechanism_or_quantity_made_of_the_wrong_things_is_refused_naming_them(make, said):
    with pytest.raises(UsageError) as caught:
        make()
    assert str(caught.value).startswith(said)


def test_a_mechanism_takes_a_catalog_name_as_load_quantities_does():
    # its scene was the string itself, and .parameters an AttributeError
    assert algkin.Mechanism("arm-string").parameters == algkin.load_quantities("arm-string").parameters
