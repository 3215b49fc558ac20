"""What every implicit point's compiled spec describes: its geometry, never its branch algebra.

A construction that brings two unknowns (a dyad, a slider) compiles into a spec: its
point's coordinates in system variables, its assembly modes' labels, and for the certified
reference its equations as written and a textbook float start. Its closed form per label,
its toggle conditions and its stable float evaluator are branch algebra: they live in
``algkin.branches.constructions``, dispatched on the spec's type. A new construction is one
more subclass of ``ImplicitSpec`` here and one more module there.
"""

from abc import ABC, abstractmethod
from collections.abc import Sequence
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
import sympy
from numpy.typing import NDArray

__all__ = ["ImplicitSpec", "Point", "FloatArray", "FloatPoint"]

Point = tuple[sympy.Expr, sympy.Expr]
FloatArray = NDArray[np.float64]
FloatPoint = tuple[FloatArray, FloatArray]


@dataclass(frozen=True)
class ImplicitSpec(ABC):
    """An implicit point compiled: its name, its two unknowns, the label the scene chose."""

    point: str
    unknowns: tuple[str, str]
    branch: str
    labels: ClassVar[tuple[str, ...]]  # the two assembly modes (the first has sigma = +1), or none
    never_meets: ClassVar[str]  # why it cannot assemble, where its discriminant is negative

    def sign(self, label: str) -> int:
        """``sigma`` of the mode ``label``: +1 for the first label, -1 for the second."""
        return 1 if label == self.labels[0] else -1

    def unknown_symbols(self) -> tuple[sympy.Symbol, sympy.Symbol]:
        """Its two unknowns as the system's symbols."""
        x, y = (sympy.Symbol(u, real=True) for u in self.unknowns)
        return x, y

    def side(self) -> tuple[sympy.Expr, str] | None:
        """For a point without modes of its own: an expression in system variables that is > 0
        where it lies as its scene says, and what is wrong where it does not; else ``None``."""
        return None

    @abstractmethod
    def written(self) -> list[sympy.Expr]:
        """Its two equations as the construction writes them (unexpanded, in system variables):
        expanded, the system's own; in balls, fewer operations than expanded."""

    @abstractmethod
    def start_parts(self) -> tuple[sympy.Expr, ...]:
        """The expressions (in system variables) that ``start`` takes, in its order."""

    @staticmethod
    @abstractmethod
    def start(parts: Sequence[FloatArray], sigma: float) -> FloatPoint:
        """A float starting point for Newton from ``start_parts``' values, on the mode ``sigma``: the
        textbook formula, no stabilisation (where it cannot assemble, a point off the fold)."""
