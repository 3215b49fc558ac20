"""numpy_function: sympy's lambdify for numpy, the same code and values, without numpy's star import."""

import inspect
import subprocess
import sys

import numpy as np
import sympy

from algkin.evaluate.lambdified import numpy_function

c, s, length = sympy.symbols("c s length")
FORMS = [sympy.sqrt((5 - 4 * c) * (c + 5)) * s / (5 - 4 * c) + c / 2, sympy.atan2(s, c),
         sympy.Abs(c) + sympy.Rational(1, 3) * length, sympy.Max(c, s), sympy.I * c]


def test_the_code_and_values_of_lambdify_numpy():
    grid = np.linspace(-1.0, 1.0, 9)
    for cse in (False, True):
        theirs = sympy.lambdify([c, s, length], FORMS, "numpy", cse=cse)
        ours = numpy_function([c, s, length], FORMS, cse=cse)
        assert inspect.getsource(ours) == inspect.getsource(theirs)
        for mine, expected in zip(ours(grid, grid[::-1], grid), theirs(grid, grid[::-1], grid)):
            np.testing.assert_array_equal(mine, expected)


def test_numpys_lazy_submodules_stay_unloaded():
    """lambdify's "numpy" runs ``from numpy import *``, which loads numpy.f2py and numpy.testing."""
    probe = ("import sys, sympy; from algkin.evaluate.lambdified import numpy_function; "
             "x = sympy.Symbol('x'); numpy_function([x], sympy.sqrt(x))(4.0); "
             "print(sorted({'numpy.f2py', 'numpy.testing'} & set(sys.modules)))")
    loaded = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True).stdout
    assert loaded.strip() == "[]"
