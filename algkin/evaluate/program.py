"""Expressions compiled once into straight-line Python, for evaluation many times over.

``evaluate`` walks a sympy tree on every call; a verification evaluates the same closed
forms, discriminants and equations at thousands of points. ``compile_program`` turns a
list of expressions (closed-form vocabulary only: sums, products, integer and half-integer
powers, ``Abs``, rationals, named variables) into one Python function, shared
subexpressions computed once, for one ``NumberKind``:

- rationals are made by the kind when the function is called, so balls get the caller's
  precision (``flint.ctx.workprec``), never a float's;
- integer powers are products (python-flint's ``arb ** int`` is nan on a ball around 0).

>>> import sympy
>>> x, y = sympy.symbols("x y", real=True)
>>> f = compile_program([sympy.sqrt(x**2 + y**2), x * y / 2 - 1], ["x", "y"], FLOAT)
>>> f(3.0, 4.0)
[5.0, 5.0]
>>> import flint
>>> with flint.ctx.workprec(200):
...     third = compile_program([x / 3], ["x"], ARB)(flint.arb(1))[0]
>>> third.rad() < 1e-59
True
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Iterable, Sequence
from typing import Any, Generic, TypeAlias

import flint
import numpy as np
import sympy

from ..runtime.cache import BoundedCache
from .tree import ARB, FLOAT, MPMATH, NUMPY  # noqa: F401 - the kinds a program is compiled for
from .tree import Floats, N, NumberKind, integer_power

__all__ = ["compile_program", "numpy_function", "columns", "Floats", "CompiledProgram", "ArrayProgram", "BallProgram"]

# A compiled program: the values of its names in, one value out per expression (an integer
# where the expression is one)
CompiledProgram: TypeAlias = Callable[..., list[N | int]]
# ``compile_program(..., NUMPY)``: arrays in, one value out per expression (a number where the
# expression is constant)
ArrayProgram: TypeAlias = CompiledProgram[Floats | float]
# ``compile_program(..., ARB)``: balls in
BallProgram: TypeAlias = CompiledProgram[flint.arb]


# Programs by their expressions, names and kind: a second verification of a scene finds its programs here.
PROGRAMS: BoundedCache[_Program[Any]] = BoundedCache(512, name="compiled programs")


def compile_program(exprs: Iterable[sympy.Expr], names: Iterable[str], kind: NumberKind[N]) -> CompiledProgram[N]:
    """A function of the values of ``names`` (in order) returning ``exprs``' values, as a list.

    Compiled once per ``(exprs, names, kind)`` and kept (``PROGRAMS``): a second verification of the same
    scene reuses it. Compiled when it is first called: a program kept for a case that does not
    come (a block's Newton iteration where its pencil solves it) costs no ``cse``.
    """
    key = (tuple(sympy.sympify(e) for e in exprs), tuple(names), kind)
    program: _Program[N] = PROGRAMS.get(key, lambda: _Program(*key))
    return program


def numpy_function(arguments: Iterable[sympy.Symbol], exprs: sympy.Expr | Iterable[sympy.Expr]) -> Callable[..., Any]:
    """``exprs`` (one expression, or several) as a function of float arrays, one per symbol of
    ``arguments`` in order: ``compile_program`` for ``NUMPY``, one value for one expression.

    It replaced sympy's ``lambdify``, whose printing and ``cse`` were milliseconds of each cold
    command, and which loads numpy's lazy submodules by ``from numpy import *``.

    >>> x = sympy.Symbol("x")
    >>> numpy_function([x], [sympy.sqrt(x) / 3, x**2])(np.array([4.0, 9.0]))
    [array([0.66666667, 1.        ]), array([16., 81.])]
    >>> numpy_function([x], 1 / x)(np.array([4.0]))
    array([0.25])
    """
    names = [str(a) for a in arguments]
    if isinstance(exprs, sympy.Basic):
        program = compile_program([exprs], names, NUMPY)
        return lambda *values: program(*values)[0]
    return compile_program(exprs, names, NUMPY)


class _Program(Generic[N]):
    """A program compiled on its first call (``_Code`` writes it)."""

    def __init__(self, exprs: tuple[sympy.Expr, ...], names: tuple[str, ...], kind: NumberKind[N]) -> None:
        self.source = (exprs, names, kind)

    def __call__(self, *values: N) -> list[N | int]:
        return self.program(*values)

    @functools.cached_property
    def program(self) -> CompiledProgram[N]:
        # written whole before it is kept: two threads calling first each write one, alike
        return _Code(*self.source).program


class _Code(Generic[N]):
    """The straight-line Python of ``exprs`` in ``names``, and the rationals it makes in ``kind``."""

    def __init__(self, exprs: tuple[sympy.Expr, ...], names: tuple[str, ...], kind: NumberKind[N]) -> None:
        self.kind = kind
        self.rationals: list[tuple[int, int]] = []
        arguments = {sympy.Symbol(n, real=True): f"a{k}" for k, n in enumerate(names)}
        arguments.update({sympy.Symbol(n): f"a{k}" for k, n in enumerate(names)})
        self.arguments: dict[sympy.Expr, str] = arguments
        self.shared = _repeated(exprs)
        self.lines: list[str] = []
        results = [self._code(e) for e in exprs]
        lines = self.lines + [f"    return [{', '.join(results)}]"]
        # the rationals, made in the kind at call time, only where there are any
        lines[:0] = [f"def program({', '.join(f'a{k}' for k in range(len(names)))}):"] + \
            (["    q = constants()"] if self.rationals else [])
        scope: dict[str, Any] = {"constants": self._constants, "power": integer_power, "sqrt": kind.sqrt}
        exec(compile("\n".join(lines), "<algkin program>", "exec"), scope)  # noqa: S102 - our own code, from a sympy tree
        self.program: CompiledProgram[N] = scope["program"]  # exec's namespace holds what the code defined
        self._made: tuple[int | None, list[N]] = (None, [])

    def _constants(self) -> list[N]:
        """The rationals in the kind, remade when the working precision changed (balls' precision;
        floats and arrays ignore it)."""
        precision = flint.ctx.prec
        if self._made[0] != precision:
            self._made = (precision, [self.kind.number(p, q) for p, q in self.rationals])
        return self._made[1]

    def _code(self, node: sympy.Expr) -> str:
        """``node``'s value: its text, or the name of the line that computed it once where it is shared."""
        if node in self.arguments:
            return self.arguments[node]
        text = self._text(node)
        if node not in self.shared:
            return text
        name = f"_t{len(self.lines)}"
        self.lines.append(f"    {name} = {text}")
        self.arguments[node] = name
        return name

    def _text(self, node: sympy.Expr) -> str:
        if node.is_Integer:
            return f"({int(node)})"
        if node.is_Rational:
            return self._constant(node)
        if node.is_Add:
            return "(" + " + ".join(self._code(a) for a in node.args) + ")"
        if node.is_Mul:
            return "(" + " * ".join(self._code(a) for a in node.args) + ")"
        if node.is_Pow:
            return self._power(node)
        if isinstance(node, sympy.Abs):
            return f"abs({self._code(node.args[0])})"
        raise TypeError(f"cannot compile {type(node).__name__} in {node}")

    def _constant(self, node: sympy.Rational) -> str:
        """A rational made by the kind at call time (an integer too, where a root is taken of it)."""
        self.rationals.append((int(node.p), int(node.q)))
        return f"q[{len(self.rationals) - 1}]"

    def _power(self, node: sympy.Pow) -> str:
        exponent = node.exp
        base = self._constant(node.base) if node.base.is_Rational else self._code(node.base)
        if exponent.is_Rational and exponent.q == 2:
            base, exponent = f"sqrt({base})", sympy.Integer(exponent.p)
        if not exponent.is_Integer:
            raise TypeError(f"cannot compile the power {exponent}")
        n = int(exponent)
        if n == 1:
            return base
        if abs(n) == 2 and base.isidentifier():  # a square: a product inline, no call
            raised = f"({base} * {base})"
        else:
            raised = f"power({base}, {abs(n)})" if abs(n) > 1 else base
        return raised if n > 0 else f"(1 / {raised})"


def _repeated(exprs: Iterable[sympy.Expr]) -> set[sympy.Expr]:
    """The subexpressions met more than once in ``exprs`` (atoms aside): each is computed once.

    Only whole subtrees are shared, each sum and product evaluated in its own terms' order; sympy's
    ``cse`` also regroups terms that sums have in common, at several times the cost.

    >>> x, y = sympy.symbols("x y")
    >>> sorted(map(str, _repeated([sympy.sqrt(x + y) * x, (x + y) ** 2])))
    ['x + y']
    """
    seen: set[sympy.Expr] = set()
    repeated: set[sympy.Expr] = set()
    pending = list(exprs)
    while pending:
        node = pending.pop()
        if node.is_Atom:
            continue
        if node in seen:
            repeated.add(node)
            continue
        seen.add(node)
        pending.extend(node.args)
    return repeated


def columns(outputs: Sequence[Floats | float], count: int) -> Floats:
    """``count x len(outputs)``: a numpy program's outputs over ``count`` rows, a constant
    output (a Jacobian's ``2``) spread over every row.

    >>> columns([np.array([1.0, 2.0]), 3], 2).tolist()
    [[1.0, 3.0], [2.0, 3.0]]
    """
    out = np.empty((count, len(outputs)))
    for k, v in enumerate(outputs):
        out[:, k] = v
    return out
