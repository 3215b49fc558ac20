"""algkin.verify.solve: a block's Jacobian is the one sympy's matrices give, expression for expression; a
block in one unknown solved without numpy.ma."""

import subprocess
import sys

import sympy
from hypothesis import given, settings, strategies as st

from algkin.system import symbol
from algkin.verify.solve import derivative, jacobian

from ..processes import ENV

x, y, c = symbol("x"), symbol("y"), symbol("c")
LEAVES = st.sampled_from([x, y, c, sympy.Symbol("x")]) | st.fractions(-7, 7, max_denominator=5).map(sympy.Rational)


def _polynomials(children):
    return (st.tuples(children, children).map(lambda p: p[0] + p[1])
            | st.tuples(children, children).map(lambda p: p[0] * p[1])
            | st.tuples(children, children, children).map(lambda p: p[0] * p[1] * p[2])
            | st.tuples(children, st.integers(-3, 4)).map(lambda p: p[0] ** p[1]))


EXPRESSIONS = st.recursive(LEAVES, _polynomials, max_leaves=12)


@settings(max_examples=300, deadline=None)
@given(EXPRESSIONS, st.sampled_from([x, y, c]))
def test_a_derivative_is_sympys_diff_node_for_node(expr, u):
    assert sympy.srepr(derivative(expr, u)) == sympy.srepr(expr.diff(u))


@settings(max_examples=100, deadline=None)
@given(st.lists(EXPRESSIONS.map(sympy.expand), min_size=1, max_size=3))
def test_a_jacobian_is_the_matrix_jacobian_row_by_row(equations):
    unknowns = [x, y][:len(equations)] or [x]
    assert [sympy.srepr(e) for e in jacobian(equations, unknowns)] == \
        [sympy.srepr(e) for e in sympy.Matrix(equations).jacobian(unknowns)]


def test_a_block_in_one_unknown_is_solved_without_loading_numpy_ma():
    # np.unique loads numpy.ma on first use: 10 ms of a cold curve's verification
    code = ("import sys; import numpy as np; from algkin.system import System, symbol;"
            "from algkin.verify.solve import blocks_of, solve_floats; x, c = symbol('x'), symbol('c');"
            "system = System(('x',), (), {'t': ('c', 's')}, (x**2 - c - 2,));"
            "found = solve_floats(blocks_of(system), {'c': np.array([0.0, 2.0]), 's': np.array([1.0, 0.0])},"
            " np.random.default_rng(0));"
            "print(sorted(found.values['x'].round(12).tolist()), 'numpy.ma' in sys.modules)")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120, env=ENV)
    assert done.stdout.splitlines()[-1] == "[-2.0, -1.414213562373, 1.414213562373, 2.0] False", done.stderr[-300:]
