"""Evaluation in balls: powers of balls around zero stay finite (python-flint's arb ** int is nan there)."""

import flint
import pytest
import sympy

from algkin.evaluate import ARB, FLOAT, NUMPY, evaluate
from algkin.evaluate.tree import integer_power

x, y = sympy.symbols("x y", real=True)


def test_even_power_of_a_ball_around_zero_is_a_small_ball():
    around_zero = flint.arb(0, 1e-30)
    value = evaluate(x**2 + 4, {"x": around_zero}, ARB)
    assert value.is_finite() and value > 0 and value.contains(4)
    assert evaluate(x**3, {"x": around_zero}, ARB).contains(0)


def test_odd_half_powers_and_negative_powers():
    two = flint.arb(2)
    assert evaluate(x ** sympy.Rational(3, 2), {"x": two}, ARB).overlaps(two * two.sqrt())
    assert evaluate(x**-2, {"x": two}, ARB).contains(flint.arb(1) / 4)


def test_numpy_arrays_evaluate_elementwise():
    import numpy as np

    values = evaluate(sympy.sqrt(x**2 + y**2), {"x": np.array([3.0, 5.0]), "y": np.array([4.0, 12.0])}, NUMPY)
    assert values.tolist() == [5.0, 13.0]


def test_absolute_values_in_every_kind():
    # |x - 3| at x = 1 is 2: floats, arrays (elementwise) and balls alike
    import numpy as np

    assert evaluate(sympy.Abs(x - 3), {"x": 1.0}, FLOAT) == 2.0
    assert evaluate(sympy.Abs(x - 3), {"x": np.array([1.0, 5.0])}, NUMPY).tolist() == [2.0, 2.0]
    assert evaluate(sympy.Abs(x - 3), {"x": flint.arb(1)}, ARB).contains(2)


def test_integer_power_refuses_an_exponent_below_one():
    # a power of 0 or less is no product of the base: refused (it returned None for 0, and never ended below)
    for n in (0, -1):
        with pytest.raises(ValueError, match="n >= 1"):
            integer_power(2.0, n)
    assert integer_power(3.0, 5) == 243.0
