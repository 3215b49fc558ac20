"""Resultant chains, Gröbner bases and the linear method give the same eliminant, up to a
constant factor.

All keep the factors the same witness configurations satisfy; sympy's resultant may be the
negative of python-flint's, which a constant factor covers.
"""

import sympy
import pytest
from hypothesis import given, settings

from algkin.branches import closed_forms
from algkin.eliminate import eliminate
from algkin.derivation.witnesses import witnesses
from algkin.derivation.tasks import eliminant_tasks
from algkin.scene import compile_scene
from algkin.system import symbol
from algkin.testing import strategies

RIVALS = {"flint": (("resultant", "flint"), ("groebner", "flint"), ("linear", "flint")),
          "sympy": (("resultant", "flint"), ("resultant", "sympy"))}


def b_equations(scene, params):
    """B's two equations, the variables kept, and the witnesses: compiled once for all the rivals."""
    compiled = compile_scene(scene, ["B"], params)
    groups = witnesses(compiled, closed_forms(compiled))
    system = compiled.system
    keep = list(system.input_variables) + list(system.parameters)
    equations = [e for e in system.equations if {"B_x", "B_y"} & {str(v) for v in e.free_symbols}]
    return equations, keep, groups


def eliminants(equations, keep, groups, method, backend):
    """B_x and B_y each by eliminating the other from B's two equations, at shared witnesses."""
    return {u: eliminate(equations, [o], [u] + keep, method=method, backend=backend, witnesses=groups).polynomial
            for u, o in (("B_x", "B_y"), ("B_y", "B_x"))}


def assert_agree(scene, params, rivals):
    equations, keep, groups = b_equations(scene, params)
    first, *others = (eliminants(equations, keep, groups, *rival) for rival in rivals)
    for unknown in first:
        assert first[unknown].has(sympy.Symbol(unknown, real=True))
        for other in others:
            ratio = sympy.cancel(first[unknown] / other[unknown])
            assert ratio.is_Rational and ratio != 0, (unknown, first[unknown], other[unknown])


@pytest.mark.slow
@settings(max_examples=120)
@given(strategies.scenes())
def test_resultant_groebner_and_linear_agree(scene):
    assert_agree(scene, (), RIVALS["flint"])


@settings(max_examples=40)
@given(strategies.with_symbolic(max_symbols=1))
def test_they_agree_with_a_symbolic_dimension(scene_and_params):
    assert_agree(*scene_and_params, RIVALS["flint"])


@settings(max_examples=40)
@given(strategies.scenes())
def test_flint_and_sympy_resultants_agree(scene):
    assert_agree(scene, (), RIVALS["sympy"])


@settings(max_examples=30)
@given(strategies.scenes())
def test_from_the_systems_flint_forms_as_sympy_from_its_equations(scene):
    # derive's tasks eliminate from System.polynomials, where a proof of irreducibility may
    # spare the witnesses; sympy's resultant chain, from the sympy equations, chooses every
    # factor at them: the same eliminant, and its flint-printed text reads back to it
    compiled = compile_scene(scene, ["B"], ())
    groups = witnesses(compiled, closed_forms(compiled))
    for unknown, task in eliminant_tasks(compiled, groups).items():
        fast = task.run("linear", "flint")
        slow = eliminate(task.equations, task.eliminate, task.keep, method="resultant", backend="sympy",
                         witnesses=groups, parameters=task.parameters)
        ratio = sympy.cancel(fast.polynomial / slow.polynomial)
        assert ratio.is_Rational and ratio != 0, (unknown, fast.polynomial, slow.polynomial)
        names = {name: symbol(name) for name in fast.variables}
        assert sympy.parse_expr(fast.text, local_dict=names) == fast.polynomial
