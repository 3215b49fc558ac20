"""The seed-like Python API against the seed's own vector derivation."""

import math

import pytest
import sympy

import algkin

from .extremum.arm_by_hand import hand_minimum

theta, b = sympy.Symbol("theta", real=True), sympy.Symbol("b", real=True)


@pytest.fixture(scope="module")
def ab():
    return algkin.load("arm-string", params=["b"]).dist("A", "B")


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
    found = algkin.load("arm-string").output("AB").extremum()
    assert found.closed_form is None
    assert float(found.minimum.input_deg) == pytest.approx(math.degrees(math.atan2(400, 80)), abs=1e-9)


def test_points_are_not_scalars():
    with pytest.raises(algkin.AlgkinError, match="scalar"):
        algkin.load("chebyshev-lambda").output("B").extremum()


def test_quantity_gives_both_spellings_of_the_input():
    """``expr`` in cos(theta)/sin(theta); ``expr_cs`` in c_theta/s_theta, equal to derive's branch."""
    import algkin
    from algkin.system import symbol

    AB = algkin.load("arm-string", params=["b"]).dist("A", "B")
    c, s, theta = symbol("c_theta"), symbol("s_theta"), AB.input
    assert AB.expr_cs.xreplace({c: sympy.cos(theta), s: sympy.sin(theta)}) == AB.expr
    assert AB.relation_cs.xreplace({c: sympy.cos(theta), s: sympy.sin(theta)}) == AB.relation
    derived = algkin.derive("arm-string", ["AB"], params=["b"], samples=0)
    chosen = next(b for b in derived.branches if b.to_json()["selected"])
    assert AB.expr_cs == chosen.values["AB"]
    assert not AB.expr_cs.has(sympy.cos) and {c, s} <= AB.expr_cs.free_symbols
