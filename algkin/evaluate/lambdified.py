"""sympy's ``lambdify`` for numpy, without the star import of numpy it does once per process.

``sympy.lambdify(arguments, expr, "numpy")`` first fills its namespace by ``from numpy import *``,
which loads numpy's lazily loaded submodules (f2py, testing, random, ma, polynomial...): about
70 ms of a cold command, for names the printed code never uses. Given numpy's own module (and the
``I`` and ``numpy`` of sympy's numpy namespace), lambdify picks the same printer (NumPyPrinter) and
resolves the same functions; a name outside numpy's top level (``numpy.linalg``'s) the printer
imports by name as it always does.
"""

from collections.abc import Callable, Iterable
from typing import Any, Union

import numpy as np
import sympy

__all__ = ["numpy_function"]

_NUMPY = [{"I": 1j, "numpy": np}, np]  # what "numpy" gives, without the star import


def numpy_function(arguments: Iterable[sympy.Symbol],
                   expr: Union[sympy.Expr, Iterable[Any]], *, cse: bool = False) -> Callable[..., Any]:
    """``sympy.lambdify(arguments, expr, "numpy", cse=cse)``: the same code, the same values.

    >>> x = sympy.Symbol("x")
    >>> numpy_function([x], [sympy.sqrt(x) / 3, x**2])(np.array([4.0, 9.0]))
    [array([0.66666667, 1.        ]), array([16., 81.])]
    """
    function: Callable[..., Any] = sympy.lambdify(arguments, expr, _NUMPY, cse=cse)
    return function
