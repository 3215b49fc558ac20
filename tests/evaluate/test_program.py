"""Compiled programs give what the tree walker gives, in every number kind, and keep balls exact."""

import subprocess
import sys

import flint
import numpy as np
import pytest
import sympy
from hypothesis import given, settings, strategies as st

from algkin.evaluate import ARB, FLOAT, NUMPY, evaluate
from algkin.evaluate import program as program_module
from algkin.evaluate.program import compile_program, numpy_function

x, y = sympy.symbols("x y", real=True)
EXPRESSIONS = [sympy.sqrt(x**2 + 3 * y**2 + 1) / 7 - x * y**3, 1 / (x**2 + 1), sympy.sqrt(2) * x,
               sympy.Abs(x - y) ** 3, (x + sympy.Rational(1, 3)) ** -2]


@settings(max_examples=50, deadline=None)
@given(st.floats(-5, 5), st.floats(-5, 5))
def test_a_program_equals_the_tree_walker_in_floats(a, b):
    compiled = compile_program(EXPRESSIONS, ["x", "y"], FLOAT)(a, b)
    walked = [evaluate(e, {"x": a, "y": b}, FLOAT) for e in EXPRESSIONS]
    assert np.allclose(compiled, walked, rtol=1e-13, atol=1e-13)


def test_arrays_are_evaluated_elementwise():
    a, b = np.array([0.5, -2.0]), np.array([1.0, 3.0])
    compiled = compile_program(EXPRESSIONS, ["x", "y"], NUMPY)(a, b)
    for value, expr in zip(compiled, EXPRESSIONS):
        assert np.allclose(value, [float(expr.subs({x: p, y: q})) for p, q in zip(a, b)])


def test_balls_enclose_the_exact_value_at_the_callers_precision():
    # at x = 1/3 exactly (a ball from a rational): 1/(x**2 + 1) = 9/10
    with flint.ctx.workprec(300):
        value = compile_program([1 / (x**2 + 1)], ["x"], ARB)(flint.arb(1) / 3)[0]
        assert value.contains(flint.arb(9) / 10) and value.rad() < 1e-85


def test_an_even_power_of_a_ball_around_zero_stays_finite():
    value = compile_program([x**2 + 4], ["x"], ARB)(flint.arb(0, 1e-30))[0]
    assert value.is_finite() and value.contains(4)


def test_a_program_is_compiled_at_its_first_call_and_once(monkeypatch):
    # a program kept for a case that never comes (a block's Newton iteration where its pencil
    # solves it) costs a cold command no compilation
    written = []
    repeated = program_module._repeated
    monkeypatch.setattr(program_module, "_repeated", lambda exprs: written.append(exprs) or repeated(exprs))
    z = sympy.Symbol("z_first_call", real=True)  # an expression no other test compiled (the cache)
    program = compile_program([(z + 1)**2 / 4, sympy.sqrt(z + 1)], ["z_first_call"], FLOAT)
    assert written == []
    assert program(3.0) == [4.0, 2.0] and program(8.0) == [20.25, 3.0]
    assert len(written) == 1


c, s, length = sympy.symbols("c s length")
FORMS = [sympy.sqrt((5 - 4 * c) * (c + 5)) * s / (5 - 4 * c) + c / 2, sympy.Abs(c) + sympy.Rational(1, 3) * length,
         (c - s) ** 3 - 1 / (length**2 + 1)]


def test_numpy_function_gives_lambdifys_values():
    grid = np.linspace(-1.0, 1.0, 9)
    theirs = sympy.lambdify([c, s, length], FORMS, "numpy")(grid, grid[::-1], grid)
    ours = numpy_function([c, s, length], FORMS)(grid, grid[::-1], grid)
    for mine, expected in zip(ours, theirs):
        np.testing.assert_allclose(mine, expected, rtol=1e-15, atol=1e-15)
    one = numpy_function([c, s, length], FORMS[2])(grid, grid, grid)
    np.testing.assert_allclose(one, -1 / (grid**2 + 1), rtol=1e-15)


def test_numpy_function_takes_closed_forms_only():
    with pytest.raises(TypeError, match="atan2"):
        numpy_function([c, s], sympy.atan2(s, c))(np.array([1.0]), np.array([0.0]))


def test_numpys_lazy_submodules_stay_unloaded():
    """sympy's lambdify to "numpy" runs ``from numpy import *``, which loads numpy.f2py and numpy.testing."""
    probe = ("import sys, sympy; from algkin.evaluate.program import numpy_function; "
             "x = sympy.Symbol('x'); numpy_function([x], sympy.sqrt(x))(4.0); "
             "print(sorted({'numpy.f2py', 'numpy.testing'} & set(sys.modules)))")
    loaded = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True).stdout
    assert loaded.strip() == "[]"
