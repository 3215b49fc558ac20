"""algkin.verify.solve: a block's Jacobian is the one sympy's matrices give, expression for expression; a
block in one unknown solved without numpy.ma, a linear one to LAPACK's bit; a Jacobian's inverse made only
for a proof that uses it."""

import functools
import subprocess
import sys

import flint
import numpy as np
import sympy
from hypothesis import given, settings, strategies as st

from algkin.system import System, symbol
from algkin.verify import solve
from algkin.verify.balls import certifier_of, certify_parameters
from algkin.verify.check import WORKING_BITS
from algkin.verify.solve import blocks_of, derivative, jacobian, solve_floats

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


def test_a_block_linear_in_its_unknown_gives_lapacks_eigenvalue_to_the_bit():
    # c x - s = 0: the 1 x 1 companion [[s / c]], whose eigenvalue LAPACK gives exactly, save where it
    # rescales a matrix near the floats' ends (below 1e-138): samples with such a one still go to LAPACK
    system = System(("x",), (), {"t": ("c", "s")}, (c * x - symbol("s"),))
    for cs, ss in [([3.0, -7.0, 2.0, 5.0, 1e150, 3.0], [1.0, 2.0, 0.0, -0.0, 1e-150, 1e-120]),
                   ([3.0, 1.0, 1e-100], [1.0, 1e-300, 1e-290])]:
        cs, ss = np.array(cs), np.array(ss)
        found = solve_floats(blocks_of(system), {"c": cs, "s": ss}, np.random.default_rng(0))
        expected = np.linalg.eigvals((-(-ss / cs))[:, None, None]).real.ravel()
        assert found.owner.tolist() == list(range(len(cs)))
        assert [float(v).hex() for v in found.values["x"]] == [float(v).hex() for v in expected]


def test_roots_near_1e15_are_found_beside_a_leading_coefficient_1e_30_of_the_constant():
    # x**2 - 10**30 c: roots +-1e15 sqrt(c), by hand; its leading 1 was once taken for zero beside 1e30
    system = System(("x",), (), {"t": ("c", "s")}, (x**2 - 10**30 * c,))
    found = solve_floats(blocks_of(system), {"c": np.array([1.0, 0.25]), "s": np.array([0.0, 0.0])},
                         np.random.default_rng(0))
    assert found.owner.tolist() == [0, 0, 1, 1]
    assert np.allclose(sorted(found.values["x"][:2]), [-1e15, 1e15], rtol=1e-15)
    assert np.allclose(sorted(found.values["x"][2:]), [-5e14, 5e14], rtol=1e-15)


def test_a_leading_coefficient_within_its_own_rounding_of_zero_is_zero():
    # (c + s - 3/10) x**2 + x - 1 at c = 0.1, s = 0.2: the leading coefficient is 0, rounded to
    # 5.6e-17 in floats; only the linear equation's root, 1, is a root (not one near -1.8e16)
    system = System(("x",), (), {"t": ("c", "s")}, ((c + symbol("s") - sympy.Rational(3, 10)) * x**2 + x - 1,))
    found = solve_floats(blocks_of(system), {"c": np.array([0.1]), "s": np.array([0.2])}, np.random.default_rng(0))
    assert found.values["x"].tolist() == [1.0]


def test_a_jacobians_inverse_is_made_only_for_a_proof_that_asks_for_it(monkeypatch):
    # two circles are proved by their pencil: no inverse; a circle and a hyperbola by Krawczyk's test
    # from the float inverse: one block's inverses, made once for all its candidates
    made = []
    inverses = solve._inverses
    monkeypatch.setattr(solve, "_inverses", lambda *arguments: made.append(1) or inverses(*arguments))
    circle = x**2 + y**2 - 4
    for other, asked in [((x - c)**2 + y**2 - 4, 0), (x * y - c, 1)]:
        made.clear()
        system = System(("x", "y"), (), {"t": ("c", "s")}, (circle, other))
        blocks = blocks_of(system)
        found = solve_floats(blocks, {"c": np.array([1.0, 1.5]), "s": np.array([0.0, 0.0])}, np.random.default_rng(0))
        certify, parameters = certifier_of(blocks.blocks[0]), certify_parameters(blocks.blocks[0])
        with flint.ctx.workprec(WORKING_BITS):
            proved = [certify([found.values["x"][r], found.values["y"][r]],
                              [flint.arb(found.values[n][r]) for n in parameters],
                              functools.partial(found.inverses.at, 0, r)) for r in range(len(found.owner))]
        assert len(proved) >= 4 and all(root is not None for root in proved)
        assert len(made) == asked
