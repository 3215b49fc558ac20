"""Exact polynomial systems: equations over QQ in named variables, nothing about mechanisms.

>>> import sympy
>>> x, c, s = sympy.symbols("x c s")
>>> system = System(unknowns=("x",), parameters=(), inputs={"t": ("c", "s")},
...                 equations=(x**2 - c, c**2 + s**2 - 1))
>>> system.variables
('x', 'c', 's')
>>> system.to_json()["equations"]
['-c + x**2', 'c**2 + s**2 - 1']
"""

from __future__ import annotations

import functools
from collections.abc import Mapping
from typing import Any, overload

import attrs
import flint
import numpy as np
import sympy
from numpy.typing import NDArray

from ..errors import ComputationError
from ..runtime.frozen import FrozenDict, frozen

__all__ = ["System", "symbol", "variables_of", "inputs_json", "input_values"]


def symbol(name: str) -> sympy.Symbol:
    """The sympy symbol algkin uses for a variable name (real, so sqrt(x**2) simplifies)."""
    return sympy.Symbol(name, real=True)


def variables_of(expr: sympy.Basic) -> list[str]:
    """Names of the free symbols of ``expr``, sorted."""
    return sorted(str(s) for s in expr.free_symbols)


def inputs_json(inputs: Mapping[str, tuple[str, ...]]) -> dict[str, dict[str, str]]:
    """Each input's variables by role: ``{"cos": c, "sin": s}`` for an angle, ``{"value": t}`` for a length."""
    return {name: dict(zip(("cos", "sin") if len(v) == 2 else ("value",), v)) for name, v in inputs.items()}


@overload
def input_values(variables: tuple[str, ...], value: flint.arb) -> dict[str, flint.arb]: ...
@overload
def input_values(variables: tuple[str, ...], value: NDArray[np.float64]) -> dict[str, NDArray[np.float64]]: ...
@overload
def input_values(variables: tuple[str, ...], value: float) -> dict[str, float]: ...


def input_values(variables: tuple[str, ...], value: flint.arb | NDArray[np.float64] | float
                 ) -> Mapping[str, flint.arb | NDArray[np.float64] | float]:
    """An input's variables at ``value`` (radians for an angle's pair, the length itself):
    floats, numpy arrays or python-flint balls (which know their own ``cos`` and ``sin``).

    >>> input_values(("t",), 2.5)
    {'t': 2.5}
    >>> input_values(("c", "s"), np.array([0.0]))
    {'c': array([1.]), 's': array([0.])}
    """
    if len(variables) == 1:
        return {variables[0]: value}
    if isinstance(value, flint.arb):
        return {variables[0]: value.cos(), variables[1]: value.sin()}
    return {variables[0]: np.cos(value), variables[1]: np.sin(value)}


@attrs.frozen
class System:
    """Polynomial equations ``= 0`` with exact rational coefficients.

    ``unknowns`` are solved for; ``inputs`` map an input name to its variables: an angle's
    ``(cos, sin)`` pair, tied by ``cos**2 + sin**2 - 1`` among the equations, or a length's
    one variable ``(t,)``; ``parameters`` are symbolic dimensions; ``nonnegative`` lists
    unknowns known to be >= 0 (distances). An immutable, hashable value.
    """

    unknowns: tuple[str, ...]
    parameters: tuple[str, ...]
    inputs: FrozenDict[str, tuple[str, ...]] = attrs.field(converter=frozen)
    equations: tuple[sympy.Expr, ...]
    nonnegative: tuple[str, ...] = ()

    def __attrs_post_init__(self) -> None:
        from .convert import to_flint  # convert builds on this module

        known, ring = set(self.variables), self._ring()
        polynomials = []
        for eq in self.equations:
            stray = set(variables_of(eq)) - known
            if stray:
                raise ComputationError(f"equation {eq} uses undeclared variables {sorted(stray)}")
            try:  # checked by converting it, once: ``polynomials`` (its cached value, set below)
                polynomials.append(to_flint(eq, ring))
            except TypeError:  # a root, a float, a quotient: not over the rationals
                raise ComputationError(f"equation {eq} has coefficients outside the rationals") from None
        object.__setattr__(self, "polynomials", tuple(polynomials))

    @property
    def input_variables(self) -> tuple[str, ...]:
        return tuple(v for pair in self.inputs.values() for v in pair)

    @property
    def variables(self) -> tuple[str, ...]:
        return tuple(self.unknowns) + self.input_variables + tuple(self.parameters)

    @functools.cached_property
    def polynomials(self) -> tuple[flint.fmpq_mpoly, ...]:
        """The equations as python-flint polynomials over ``variables`` (lex), converted once, as the
        system is made and checked (``__attrs_post_init__``; here for a system unpickled, which is
        not made again), so that every elimination of the system starts in python-flint.

        >>> x, c = sympy.symbols("x c")
        >>> System(("x",), (), {"t": ("c",)}, (x**2 - c,)).polynomials
        (x^2 - c,)
        """
        from .convert import to_flint

        ring = self._ring()
        return tuple(to_flint(e, ring) for e in self.equations)

    def _ring(self) -> flint.fmpq_mpoly_ctx:
        from .convert import flint_context  # convert builds on this module

        return flint_context(self.variables or ("_",))

    def to_json(self) -> dict[str, Any]:
        return {
            "unknowns": list(self.unknowns),
            "parameters": list(self.parameters),
            "inputs": inputs_json(self.inputs),
            "equations": self._equation_texts(),
        }

    def _equation_texts(self) -> list[str]:
        """``str`` of each equation, written from python-flint (``sympy_text``) where the equation is the
        expression ``to_sympy`` makes of its polynomial, as the compiler's are: sympy's printing of a
        six-bar's equations took milliseconds of a cold command."""
        from .convert import sympy_text, to_sympy  # convert builds on this module

        return [sympy_text(p, p.context()) if e == to_sympy(p, p.context()) else str(e)
                for e, p in zip(self.equations, self.polynomials)]
