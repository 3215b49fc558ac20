"""A System holds polynomials over the rationals, and says which equation is not one."""

import pytest
import sympy

from algkin.errors import ComputationError
from algkin.system import System, symbol

x, c, s = symbol("x"), symbol("c"), symbol("s")


def _system(equation):
    return System(unknowns=("x",), parameters=(), inputs={"t": ("c", "s")}, equations=(equation, c**2 + s**2 - 1))


def test_rational_coefficients_are_taken():
    assert _system(x**2 / 3 - c * x + sympy.Rational(7, 2)).equations[0] == x**2 / 3 - c * x + sympy.Rational(7, 2)


@pytest.mark.parametrize("coefficient", [sympy.sqrt(17), sympy.Float(0.5), sympy.pi, sympy.I])
def test_a_coefficient_outside_the_rationals_is_named(coefficient):
    with pytest.raises(ComputationError, match=r"equation .* has coefficients outside the rationals"):
        _system(x**2 - coefficient * c)


def test_a_quotient_by_a_variable_is_no_polynomial():
    with pytest.raises(ComputationError, match="outside the rationals"):
        _system(x - 1 / c)
