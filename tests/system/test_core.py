"""A System holds polynomials over the rationals, and says which equation is not one."""

import pytest
import sympy
from sympy.printing.str import StrPrinter

from algkin.errors import ComputationError
from algkin.scene import compile_scene, load_scene
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


def _refuse_printing(self, expr):
    raise AssertionError(f"sympy printed {expr}")


@pytest.mark.parametrize("name", ["fourbar", "stephenson-iii", "watt-i", "chebyshev-lambda"])
def test_a_compiled_systems_equations_are_written_as_sympy_writes_them_without_sympys_printer(name, monkeypatch):
    system = compile_scene(load_scene(name)).system
    expected = [str(e) for e in system.equations]
    monkeypatch.setattr(StrPrinter, "doprint", _refuse_printing)
    assert system.to_json()["equations"] == expected


def test_an_equation_not_as_its_polynomial_is_written_by_sympy():
    # (x - c)**2 unexpanded: written as given, not as its expanded polynomial
    equation = (x - c) ** 2 - s / 2
    assert _system(equation).to_json()["equations"] == ["-s/2 + (-c + x)**2", "c**2 + s**2 - 1"] == \
        [str(equation), str(c**2 + s**2 - 1)]
