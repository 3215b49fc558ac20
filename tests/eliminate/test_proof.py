"""An eliminant proved irreducible needs no choice at the witnesses; a multiplier's factor still does.

Expected eliminants come from sympy's resultant of the original equations (a second
implementation), never from algkin's own elimination.
"""

import pickle

import flint
import pytest
import sympy

from algkin.bench.problems import build
from algkin.derivation.pipeline import curve
from algkin.eliminate import Witness, eliminate
from algkin.errors import ComputationError
from algkin.eliminate.factor import FACTORED, IrreducibilityProof
from algkin.system import System, symbol


def proportional(a, b):
    ratio = sympy.cancel(sympy.sympify(a) / sympy.sympify(b))
    return ratio.is_number and ratio != 0


def test_the_seed_connector_is_proved_irreducible_and_is_sympys_resultant():
    task = build("two-circles").task  # B_y of the lambda: B_x eliminated from the two circles
    result = task.run("linear", "flint")
    bx = symbol("B_x")
    expected = sympy.resultant(*task.equations, bx)
    assert proportional(result.polynomial, expected)
    # quadratic in B_y, decided by its discriminant; sympy's factoring agrees it is irreducible
    assert result.proof == IrreducibilityProof("B_y", (), 2, by_discriminant=True)
    assert ("proved-irreducible", "B_y") in result.log and sympy.Poly(expected).is_irreducible
    assert result.dropped == []


def test_a_multiplier_factor_is_still_dropped_at_the_witnesses():
    # the lambda's coupler curve: the linear method multiplies by a coordinate of P on the
    # way, which the motion does not lie on (P is off the axes at the witnesses); the sextic
    # left is proved irreducible, and it alone is the curve
    task = build("lambda-coupler").task
    result = task.run("linear", "flint")
    px, py = symbol("P_x"), symbol("P_y")
    assert result.dropped in ([px], [py])
    assert result.proof is not None and result.degree == 6
    assert sympy.Poly(result.polynomial, px, py).is_irreducible


def test_the_proof_is_of_the_eliminant_itself():
    # the line defines x = y - t, substituted into the circle: (y - t)**2 + y**2 - 1, a conic
    # in (y, t) with no factor (its quadratic part 2*y**2 - 2*t*y + t**2 has a negative discriminant)
    x, y, t = (symbol(n) for n in "xyt")
    circle, line = x**2 + y**2 - 1, y - x - t
    result = eliminate([circle, line], ["x"], ["y", "t"], method="resultant")
    assert proportional(result.polynomial, sympy.resultant(circle, line, x))
    assert result.proof == FACTORED


def test_a_system_pickles_without_its_flint_forms_and_converts_them_again():
    x, c = symbol("x"), symbol("c")
    system = System(("x",), (), {"t": ("c",)}, (x**2 - c,))
    assert str(system.polynomials[0]) == "x^2 - c"
    again = pickle.loads(pickle.dumps(system))
    assert "polynomials" not in system.__getstate__() and again.polynomials == system.polynomials


def test_the_curve_document_says_why_no_factor_was_chosen():
    document = curve("chebyshev-lambda", "P", samples=4).to_json()
    assert document["irreducible"] and document["irreducibility"].startswith("irreducible over QQ: ")


def test_an_eliminant_of_divided_equations_is_still_chosen_at_the_witnesses():
    # the general four-bar's curve: the linear method divides equations by factors of its
    # multipliers on the way, so its eliminant lies only in the ideal's saturation, and no
    # proof spares a factor its evaluation at the witnesses
    result = build("fourbar-symbolic").task.run("linear", "flint")
    assert ("stripped", "c_theta") in result.log and result.proof is None
    assert not any(kind == "proved-irreducible" for kind, _ in result.log)


def _witness(**values):
    return Witness({name: flint.arb(value) for name, value in values.items()},
                   exact={name: flint.fmpq(value) for name, value in values.items() if name == "a"})


def test_an_interpolated_eliminant_is_checked_at_every_branch():
    # t = 0 or 1 puts the point on y = x + a or on y = x**2: two branches, one per line of
    # witnesses; interpolation keeps the factors a signature read at the first witness
    # chose, so it is not the elimination ideal's own eliminant, and the second branch,
    # on y = x**2, refuses it (linear and resultant keep both factors)
    t, x, y, a = (symbol(n) for n in "txya")
    equations = [t * (t - 1), y - (x + a) - t * (x**2 - x - a)]
    groups = [[_witness(t=0, x=1, y=3, a=2), _witness(t=0, x=2, y=4, a=2)],
              [_witness(t=1, x=3, y=9, a=2), _witness(t=1, x=5, y=25, a=2)]]
    found = eliminate(equations, ["t"], ["x", "y", "a"], method="linear", witnesses=groups, parameters=["a"])
    assert proportional(found.polynomial, (y - x - a) * (y - x**2))
    with pytest.raises(ComputationError, match="no kept factor vanishes at a witness"):
        eliminate(equations, ["t"], ["x", "y", "a"], method="interpolate", witnesses=groups, parameters=["a"])


def test_a_branch_off_the_proved_factor_is_refused():
    # y*(t - x) and t**2 - y - 1: the multiplier y's line and the parabola y = x**2 - 1; a
    # branch whose witness (x, y) = (5, 0) lies on the line only, not on the parabola the
    # proof keeps, is refused rather than passed
    t, x, y = (symbol(n) for n in "txy")
    equations = [y * (t - x), t**2 - y - 1]
    with pytest.raises(ComputationError, match="no kept factor vanishes at a witness"):
        eliminate(equations, ["t"], ["x", "y"], witnesses=[[_witness(t=1, x=5, y=0), _witness(t=2, x=2, y=3)]])
    both = eliminate(equations, ["t"], ["x", "y"], witnesses=[[_witness(t=1, x=5, y=0)], [_witness(t=2, x=2, y=3)]])
    assert proportional(both.polynomial, y * (x**2 - y - 1))
