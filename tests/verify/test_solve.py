"""algkin.verify.solve: a block's Jacobian is the one sympy's matrices give, expression for expression."""

import sympy
from hypothesis import given, settings, strategies as st

from algkin.system import symbol
from algkin.verify.solve import derivative, jacobian

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
