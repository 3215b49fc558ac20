"""Evaluate a sympy expression tree in any number type: balls, mpmath, floats, arrays.

Only what closed forms contain is accepted: sums, products, integer powers, square
roots, absolute values (``sqrt(r**2)`` of a real dimension ``r`` is ``Abs(r)``), rationals
and named variables. Shared subexpressions are evaluated once.

>>> import sympy
>>> x = sympy.Symbol("x")
>>> evaluate(sympy.sqrt(x**2 + 9) - sympy.Rational(1, 2), {"x": 4}, FLOAT)
4.5
>>> evaluate(sympy.sqrt(sympy.Symbol("r", real=True)**2), {"r": -2.5}, FLOAT)
2.5
>>> print(evaluate(sympy.sqrt(x), {"x": ARB.number(2, 1)}, ARB))
[1.41421356237309...]
"""

import math
from dataclasses import dataclass
from typing import Callable

import flint
import mpmath
import numpy as np
import sympy

__all__ = ["evaluate", "NumberKind", "ARB", "MPMATH", "FLOAT", "NUMPY"]


@dataclass(frozen=True)
class NumberKind:
    """How to make a rational and take a square root in one number type."""

    name: str
    number: Callable  # (numerator, denominator) -> value
    sqrt: Callable


ARB = NumberKind("arb", lambda p, q: flint.arb(flint.fmpq(p, q)), lambda v: v.sqrt())
MPMATH = NumberKind("mpmath", lambda p, q: mpmath.mpf(p) / q, mpmath.sqrt)
FLOAT = NumberKind("float", lambda p, q: p / q, math.sqrt)
NUMPY = NumberKind("numpy", lambda p, q: p / q, np.sqrt)  # float64 arrays, vectorised


def evaluate(expr, values, kind):
    """Value of ``expr`` with variables from ``values`` (name -> number) in ``kind``."""
    memo = {}

    def walk(node):
        if node in memo:
            return memo[node]
        if node.is_Symbol:
            result = values[node.name]
        elif node.is_Rational:
            result = kind.number(int(node.p), int(node.q))
        elif node.is_Add:
            args = [walk(a) for a in node.args]
            result = args[0]
            for a in args[1:]:
                result = result + a
        elif node.is_Mul:
            args = [walk(a) for a in node.args]
            result = args[0]
            for a in args[1:]:
                result = result * a
        elif node.is_Pow:
            result = _power(walk(node.base), node.exp, kind)
        elif isinstance(node, sympy.Abs):
            result = abs(walk(node.args[0]))  # floats, arrays, mpmath and arb balls all have abs
        else:
            raise TypeError(f"cannot evaluate {type(node).__name__} in {node}")
        memo[node] = result
        return result

    return walk(sympy.sympify(expr))


def integer_power(base, n):
    """``base**n`` (n >= 1) by squaring: python-flint's ``arb ** int`` is nan on a ball around 0."""
    result = None
    while n:
        if n & 1:
            result = base if result is None else result * base
        n >>= 1
        if n:
            base = base * base
    return result


def _power(base, exponent, kind):
    if exponent.is_Integer:
        n = int(exponent)
        return integer_power(base, n) if n > 0 else kind.number(1, 1) / integer_power(base, -n)
    if exponent.is_Rational and exponent.q == 2:
        root = kind.sqrt(base)
        n = int(exponent.p)
        return integer_power(root, n) if n > 0 else kind.number(1, 1) / integer_power(root, -n)
    raise TypeError(f"cannot evaluate the power {exponent}")
