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

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Generic, Protocol, TypeAlias, TypeVar

import flint
import mpmath
import numpy as np
import sympy
from numpy.typing import NDArray

__all__ = ["evaluate", "NumberKind", "Arithmetic", "Floats", "ARB", "MPMATH", "FLOAT", "NUMPY"]

_A = TypeVar("_A", bound="Arithmetic")


class Arithmetic(Protocol):
    """What a closed form's evaluation asks of its numbers: sums, products, quotients."""

    def __add__(self: _A, other: _A, /) -> _A: ...
    def __mul__(self: _A, other: _A, /) -> _A: ...
    def __truediv__(self: _A, other: _A, /) -> _A: ...


N = TypeVar("N", bound=Arithmetic)
Floats: TypeAlias = NDArray[np.float64]


@dataclass(frozen=True)
class NumberKind(Generic[N]):
    """How to make a rational, take a square root and an absolute value in one number type."""

    name: str
    number: Callable[[int, int], N]  # (numerator, denominator) -> value
    sqrt: Callable[[N], N]
    absolute: Callable[[N], N]


ARB: NumberKind[flint.arb] = NumberKind("arb", number=lambda p, q: flint.arb(flint.fmpq(p, q)),
                                        sqrt=lambda v: v.sqrt(), absolute=abs)
MPMATH: NumberKind[mpmath.mpf] = NumberKind("mpmath", number=lambda p, q: mpmath.mpf(p) / q, sqrt=mpmath.sqrt,
                                            absolute=abs)
FLOAT: NumberKind[float] = NumberKind("float", number=lambda p, q: p / q, sqrt=math.sqrt, absolute=abs)


def _absolute(value: Floats | float) -> Floats | float:
    return np.absolute(value) if isinstance(value, np.ndarray) else abs(value)


# float64 arrays, vectorised; a rational stays a float
NUMPY: NumberKind[Floats | float] = NumberKind("numpy", number=lambda p, q: p / q, sqrt=np.sqrt, absolute=_absolute)


def evaluate(expr: sympy.Expr, values: Mapping[str, N], kind: NumberKind[N]) -> N:
    """Value of ``expr`` with variables from ``values`` (name -> number) in ``kind``."""
    memo: dict[sympy.Expr, N] = {}

    def walk(node: sympy.Expr) -> N:
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
            result = kind.absolute(walk(node.args[0]))
        else:
            raise TypeError(f"cannot evaluate {type(node).__name__} in {node}")
        memo[node] = result
        return result

    return walk(sympy.sympify(expr))


def integer_power(base: N, n: int) -> N:
    """``base**n`` (n >= 1) by squaring: python-flint's ``arb ** int`` is nan on a ball around 0."""
    if n < 1:
        raise ValueError(f"integer_power takes n >= 1, not {n}")
    result: N | None = None
    while n:
        if n & 1:
            result = base if result is None else result * base
        n >>= 1
        if n:
            base = base * base
    assert result is not None  # n >= 1 multiplied it in at least once
    return result


def _power(base: N, exponent: sympy.Rational, kind: NumberKind[N]) -> N:
    if exponent.is_Integer:
        n = int(exponent)
        return integer_power(base, n) if n > 0 else kind.number(1, 1) / integer_power(base, -n)
    if exponent.is_Rational and exponent.q == 2:
        root = kind.sqrt(base)
        n = int(exponent.p)
        return integer_power(root, n) if n > 0 else kind.number(1, 1) / integer_power(root, -n)
    raise TypeError(f"cannot evaluate the power {exponent}")
