"""A numpy function of float arrays recorded as a straight-line scalar program, and printed.

The stabilised evaluators are written once, in numpy, with their operations in a chosen
order (a difference taken before a product, a root that cannot cancel). ``trace`` runs such
a function on ``Value`` stand-ins instead of arrays: every arithmetic operator and every
numpy ufunc it calls (``tan``, ``sqrt``, ``hypot``, ``copysign``, ``maximum``, comparisons)
and ``np.where`` appends one line ``v<k> = <op>(<operands>)`` to a ``Program``. Constants
(anything computed from Python floats alone) are folded as numpy folds them. The program
holds the very operations the numpy evaluator performs, in its order, so printed in another
language (numba's Python, C, JavaScript, numpy) it rounds as the numpy form does; no
computer algebra reorders it (sympy would flatten ``(t - high) - low`` into one sum and lose
the exactness of ``t - high``). A branch on a traced value (``if x > 0``) cannot be recorded
and raises ``TypeError``.

>>> import numpy as np
>>> program = trace(lambda t: [np.sqrt((1 - t) * (1 + t)), np.where(t > 0, t, -t)], ["t"])
>>> print(program.body("python"))
v0 = 1.0 - t
v1 = 1.0 + t
v2 = v0 * v1
v3 = np.sqrt(v2)
v4 = t > 0.0
v5 = -t
v6 = t if v4 else v5
>>> program.outputs
['v3', 'v6']
"""

from __future__ import annotations

import re

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import ClassVar, SupportsFloat, TypeAlias

import numpy as np

__all__ = ["trace", "Program", "Value", "LANGUAGES"]

_BINARY = {"add": "+", "sub": "-", "mul": "*", "div": "/", "gt": ">", "ge": ">=", "lt": "<", "le": "<=",
           "eq": "==", "ne": "!="}
_UFUNCS = {np.add: "add", np.subtract: "sub", np.multiply: "mul", np.true_divide: "div", np.greater: "gt",
           np.greater_equal: "ge", np.less: "lt", np.less_equal: "le", np.equal: "eq", np.not_equal: "ne",
           np.negative: "neg", np.sqrt: "sqrt", np.tan: "tan", np.cos: "cos", np.sin: "sin", np.hypot: "hypot",
           np.copysign: "copysign", np.maximum: "maximum", np.minimum: "minimum", np.absolute: "abs",
           np.square: "square"}

Operand: TypeAlias = "str | float"  # a traced value's name, or a constant
Line: TypeAlias = "tuple[str, str, tuple[Operand, ...]]"  # (name, op, operands)

# Each language's spelling of the operations a program holds; {0}, {1}, {2} are operands.
LANGUAGES = {
    "python": {"neg": "-{0}", "sqrt": "np.sqrt({0})", "tan": "np.tan({0})", "cos": "np.cos({0})",
               "sin": "np.sin({0})", "hypot": "np.hypot({0}, {1})", "copysign": "np.copysign({0}, {1})",
               "maximum": "np.maximum({0}, {1})", "minimum": "np.minimum({0}, {1})", "abs": "abs({0})",
               "where": "{1} if {0} else {2}", "nan": "np.nan"},
    "numpy": {"neg": "-{0}", "sqrt": "np.sqrt({0})", "tan": "np.tan({0})", "cos": "np.cos({0})",
              "sin": "np.sin({0})", "hypot": "np.hypot({0}, {1})", "copysign": "np.copysign({0}, {1})",
              "maximum": "np.maximum({0}, {1})", "minimum": "np.minimum({0}, {1})", "abs": "np.abs({0})",
              "where": "np.where({0}, {1}, {2})", "nan": "np.nan"},
    "c": {"neg": "-{0}", "sqrt": "sqrt({0})", "tan": "tan({0})", "cos": "cos({0})", "sin": "sin({0})",
          "hypot": "hypot({0}, {1})", "copysign": "copysign({0}, {1})", "maximum": "algkin_max({0}, {1})",
          "minimum": "algkin_min({0}, {1})", "abs": "fabs({0})", "where": "({0}) ? ({1}) : ({2})", "nan": "NAN"},
    "js": {"neg": "-{0}", "sqrt": "Math.sqrt({0})", "tan": "Math.tan({0})", "cos": "Math.cos({0})",
           "sin": "Math.sin({0})", "hypot": "Math.hypot({0}, {1})", "copysign": "copysign({0}, {1})",
           "maximum": "algkin_max({0}, {1})", "minimum": "algkin_min({0}, {1})", "abs": "Math.abs({0})",
           "where": "({0}) ? ({1}) : ({2})", "nan": "NaN"},
}


@dataclass
class Program:
    """Straight-line code: ``lines`` of ``(name, op, operands)``, operands names or floats."""

    inputs: list[str]
    lines: list[Line] = field(default_factory=list)
    outputs: list[Operand] = field(default_factory=list)  # names, or floats where an output is constant
    prefix: str = "v"  # of the temporaries' names: v0, v1, ... (v_0, ... if an input is called v0)

    def __post_init__(self) -> None:
        while any(re.fullmatch(re.escape(self.prefix) + r"\d+", n) for n in self.inputs):
            self.prefix += "_"

    def emit(self, op: str, *operands: object) -> Value:
        name = f"{self.prefix}{len(self.lines)}"
        self.lines.append((name, op, tuple(_operand(a) for a in operands)))
        return Value(self, name)

    def expression(self, op: str, operands: Sequence[Operand], language: str) -> str:
        """One operation in ``language``."""
        code = [self.atom(a, language) for a in operands]
        if op in _BINARY:
            return f"{code[0]} {_BINARY[op]} {code[1]}"
        if op == "square":  # numpy's square is one exact product; so is x * x
            return f"{code[0]} * {code[0]}"
        return LANGUAGES[language][op].format(*code)

    def atom(self, operand: Operand, language: str) -> str:
        if isinstance(operand, str):
            return operand
        value = float(operand)
        if np.isnan(value):
            return LANGUAGES[language]["nan"]
        if np.isinf(value):
            return {"c": "INFINITY", "js": "Infinity"}.get(language, "np.inf") if value > 0 else \
                "-" + {"c": "INFINITY", "js": "Infinity"}.get(language, "np.inf")
        text = repr(value)  # shortest round-trip decimal: the same double in every language
        return f"({text})" if value < 0 else text

    def body(self, language: str, declare: str = "", end: str = "", indent: str = "") -> str:
        """Every line as ``<declare>name = expression<end>``, one per line."""
        return "\n".join(f"{indent}{declare}{name} = {self.expression(op, operands, language)}{end}"
                         for name, op, operands in self.lines)

    def output_names(self) -> list[str]:
        """The outputs, each a line's name (a program none of whose outputs is constant, as a prelude)."""
        names = [o for o in self.outputs if isinstance(o, str)]
        if len(names) < len(self.outputs):
            raise TypeError("a constant output has no name")
        return names

    def reads(self) -> set[str]:
        """The names some line or output reads."""
        names = {a for _, _, operands in self.lines for a in operands if isinstance(a, str)}
        return names | {o for o in self.outputs if isinstance(o, str)}

    def select(self, outputs: Sequence[int]) -> Program:
        """The program of the outputs at positions ``outputs`` only, the lines none of them needs dropped."""
        kept = [self.outputs[k] for k in outputs]
        needed = {o for o in kept if isinstance(o, str)}
        lines: list[Line] = []
        for name, op, operands in reversed(self.lines):
            if name in needed:
                lines.append((name, op, operands))
                needed.update(a for a in operands if isinstance(a, str))
        return Program(list(self.inputs), lines[::-1], kept, self.prefix)


class Value:
    """A traced float: arithmetic on it and numpy ufuncs of it append lines to its program."""

    __array_priority__ = 1000  # numpy defers to our operators, never makes an object array
    # the arithmetic and comparisons, each appending its line (set below the class, by _binary)
    __add__: ClassVar[Callable[[Value, object], Value]]
    __radd__: ClassVar[Callable[[Value, object], Value]]
    __sub__: ClassVar[Callable[[Value, object], Value]]
    __rsub__: ClassVar[Callable[[Value, object], Value]]
    __mul__: ClassVar[Callable[[Value, object], Value]]
    __rmul__: ClassVar[Callable[[Value, object], Value]]
    __truediv__: ClassVar[Callable[[Value, object], Value]]
    __rtruediv__: ClassVar[Callable[[Value, object], Value]]
    __gt__: ClassVar[Callable[[Value, object], Value]]
    __ge__: ClassVar[Callable[[Value, object], Value]]
    __lt__: ClassVar[Callable[[Value, object], Value]]
    __le__: ClassVar[Callable[[Value, object], Value]]
    __eq__: ClassVar[Callable[[Value, object], Value]]  # type: ignore[assignment]  # traced, not compared
    __ne__: ClassVar[Callable[[Value, object], Value]]  # type: ignore[assignment]  # traced, not compared

    def __init__(self, program: Program, name: str) -> None:
        self.program, self.name = program, name

    def __array_ufunc__(self, ufunc: np.ufunc, method: str, *inputs: object, **kwargs: object) -> Value:
        if method != "__call__" or kwargs or ufunc not in _UFUNCS:
            raise TypeError(f"cannot trace numpy's {ufunc.__name__}.{method}")
        return self.program.emit(_UFUNCS[ufunc], *inputs)

    def __array_function__(self, func: Callable[..., object], types: object, args: tuple[object, ...],
                           kwargs: dict[str, object]) -> object:
        if func is np.where and not kwargs:
            return self.program.emit("where", *args)
        if func is np.full_like:  # a constant the shape of the samples: in a scalar loop, the constant
            return _constant(args[1] if len(args) > 1 else kwargs["fill_value"])
        raise TypeError(f"cannot trace numpy's {func.__name__}")

    def __bool__(self) -> bool:
        raise TypeError("a branch on a traced value cannot be recorded: use np.where")

    def __pow__(self, exponent: object) -> Value:
        if exponent == 2:
            return self.program.emit("square", self)
        if isinstance(exponent, int) and exponent > 2:
            return self * self ** (exponent - 1)
        if exponent == 0.5:
            return self.program.emit("sqrt", self)
        raise TypeError(f"cannot trace the power {exponent}")

    def __neg__(self) -> Value:
        return self.program.emit("neg", self)

    def __pos__(self) -> Value:
        return self

    def __abs__(self) -> Value:
        return self.program.emit("abs", self)

    __hash__ = None  # type: ignore[assignment]  # == is traced, so Values are not keys


def _binary(op: str, reflected: bool = False) -> Callable[[Value, object], Value]:
    if reflected:
        return lambda self, other: self.program.emit(op, other, self)
    return lambda self, other: self.program.emit(op, self, other)


for _op, _python in (("add", "add"), ("sub", "sub"), ("mul", "mul"), ("div", "truediv")):
    setattr(Value, f"__{_python}__", _binary(_op))
    setattr(Value, f"__r{_python}__", _binary(_op, reflected=True))
for _op in ("gt", "ge", "lt", "le", "eq", "ne"):
    setattr(Value, f"__{_op}__", _binary(_op))


def _operand(value: object) -> Operand:
    """A traced value's name, or a constant as a float (numpy scalars, ints and bools alike)."""
    if isinstance(value, Value):
        return value.name
    return _constant(value)


def _constant(value: object) -> float:
    if isinstance(value, (bool, np.bool_)):
        return float(bool(value))
    if isinstance(value, SupportsFloat):
        return float(value)
    raise TypeError(f"cannot trace the constant {value!r}")


def trace(function: Callable[..., Sequence[object]], inputs: Sequence[str]) -> Program:
    """``function``'s operations on one sample of each input, as a program returning its outputs
    (the operations no output needs left out)."""
    program = Program(list(inputs))
    results = function(*(Value(program, n) for n in inputs))
    program.outputs = [_operand(r) for r in results]
    return program.select(range(len(program.outputs)))
