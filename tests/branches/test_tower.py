"""Closed forms over square roots (``algkin.branches.tower``): the same functions as sympy's expansion
of the same algebra, written with each root once and the circles reduced."""

import gzip
import json
from pathlib import Path

import mpmath
import pytest
import sympy
from hypothesis import given, settings
from hypothesis import strategies as st

import algkin
from algkin.branches.tower import Tower, root_free

# The closed forms of the catalog's scenes with a dyad on another's closed form as sympy's expansion
# wrote them before the tower (tests/derivation/catalog_before.json.gz at commit 683cb89)
EXPANDED = Path(__file__).with_name("nested_forms_expanded.json.gz")
NESTED = ["stephenson-iii", "watt-i", "hart-inversor"]


@pytest.fixture(scope="module")
def expanded() -> dict:
    with gzip.open(EXPANDED, "rt", encoding="utf-8") as text:
        return json.load(text)


def _on_the_circle(expr: sympy.Expr, symbols: dict):
    """``expr`` as a function of the angle, in mpmath at its working precision (complex where a root's
    radicand is negative): compiled once, then evaluated at each angle."""
    function = sympy.lambdify((symbols["c"], symbols["s"]), expr, "mpmath")
    return lambda angle: mpmath.mpc(function(mpmath.cos(angle), mpmath.sin(angle)))


@pytest.mark.parametrize("name", NESTED)
def test_a_nested_dyads_closed_forms_are_sympys_expanded_ones(name: str, expanded: dict) -> None:
    """At angles where each branch is real (and where it is not: the same complex values), every
    coordinate of every branch equals the form sympy's expansion gave, to 20 digits of the 50
    evaluated (Hart's inversor has discriminants that vanish at some of these angles, where a root
    of a 50-digit zero is 1e-25)."""
    derived = algkin.derive(name)
    (angle_name,) = expanded[name]["inputs"]
    symbols = {"c": sympy.Symbol(f"c_{angle_name}", real=True), "s": sympy.Symbol(f"s_{angle_name}", real=True)}
    locals_ = {**{str(v): v for v in symbols.values()}, **symbols}
    before = expanded[name]["branches"]
    compared = 0
    with mpmath.workdps(50):
        for branch in derived.branches:
            for unknown, value in branch.values.items():
                old_at = _on_the_circle(sympy.sympify(before[branch.label][unknown], locals=locals_), symbols)
                new_at = _on_the_circle(value, symbols)
                for degrees in (17, 95, 211, 300):
                    angle = mpmath.radians(degrees)
                    old, new = old_at(angle), new_at(angle)
                    assert abs(new - old) <= mpmath.mpf(10) ** -20 * max(1, abs(old)), (branch.label, unknown, degrees)
                    compared += 1
    assert compared == 4 * sum(len(b.values) for b in derived.branches)


@pytest.mark.parametrize("name", NESTED)
def test_a_nested_dyads_forms_write_each_root_once_and_reduce_the_circle(name: str) -> None:
    """No ``s**2`` is left under a root or anywhere (``s**2 = 1 - c**2``), and the earlier dyad's root is
    the very atom of its own closed form, never its expansion (sympy's wrote it two ways)."""
    derived = algkin.derive(name)
    (angle,) = derived.compiled.system.inputs
    sine = sympy.Symbol(f"s_{angle}", real=True)
    for branch in derived.branches:
        for value in [*branch.values.values(), *branch.discriminants.values()]:
            assert not any(p.base == sine and p.exp >= 2 for p in value.atoms(sympy.Pow))
            radicands = [sympy.expand(p.base) for p in value.atoms(sympy.Pow) if p.exp == sympy.Rational(1, 2)]
            assert len(radicands) == len(set(radicands))


c, s, a = sympy.symbols("c s a")
_leaves = st.sampled_from([c, s, a, sympy.Integer(2), sympy.Rational(-3, 5), sympy.sqrt(5 - 4 * c),
                           sympy.sqrt(a**2 + 1)])
_exprs = st.recursive(_leaves, lambda inner: st.one_of(
    st.builds(lambda x, y: x + y, inner, inner), st.builds(lambda x, y: x * y, inner, inner),
    st.builds(lambda x: x**2, inner)), max_leaves=8)


@settings(max_examples=60, deadline=None)
@given(_exprs, st.floats(0.1, 3.0), st.floats(-2, 2))
def test_a_value_in_the_tower_is_the_same_function(expr: sympy.Expr, angle: float, parameter: float) -> None:
    """An expression taken into the tower and written back is the same function on the circle."""
    tower = Tower([expr], [(c, s)])
    written = tower.expr(tower.value(expr))
    point = {c: sympy.cos(sympy.Float(angle, 30)), s: sympy.sin(sympy.Float(angle, 30)), a: sympy.Float(parameter, 30)}
    before, after = (complex(sympy.N(e.xreplace(point), 30)) for e in (expr, written))
    assert abs(after - before) <= 1e-20 * max(1.0, abs(before))


def test_an_absolute_value_is_the_root_of_a_square():
    # sympy writes sqrt(R**2) of a real R as Abs(R): a symbolic length's, as a Whitworth lever's R
    c, length = sympy.symbols("c R", real=True)
    assert sympy.sqrt(length**2) == sympy.Abs(length)
    # (c - |R|) (c + |R|) = c**2 - R**2, by hand
    assert sympy.expand(root_free(c - sympy.sqrt(length**2)) - (c**2 - length**2)) == 0
