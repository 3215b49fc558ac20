"""What every implicit point's compiled spec supplies, so that nothing above dispatches on its kind.

A construction that brings two unknowns (a dyad, a slider) compiles into a spec: its
point's coordinates in system variables, and the behaviour branches and analyses ask of
it (its closed form per label, a stable float evaluator, its toggle conditions, and for the
certified reference its equations as written and a textbook float start). A new
construction is one more subclass of ``ImplicitSpec``.
"""

from abc import ABC, abstractmethod
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import ClassVar, Protocol

import sympy

from .algebra import Circles
from .floats import FloatArray

__all__ = ["ImplicitSpec", "StableEvaluator", "Point", "Fix", "HalfAngle", "FloatPoint"]

Point = tuple[sympy.Expr, sympy.Expr]
Fix = Callable[[sympy.Expr], sympy.Expr]  # dimensions at their defaults, reduced on the circles
HalfAngle = tuple[FloatArray, FloatArray]  # an input's t = tan(theta/2) and w = 1/(1 + t**2)
FloatPoint = tuple[FloatArray, FloatArray]


class StableEvaluator(Protocol):
    """One implicit point in float64, vectorised, without cancellation."""

    unknowns: tuple[str, str]

    def __call__(self, values: Sequence[FloatArray], half: Sequence[HalfAngle]) -> tuple[FloatArray, FloatArray]:
        """``(x, y)`` from ``values`` (each input's c, s, then earlier points' x, y) and each input's ``half``."""
        ...


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

    @abstractmethod
    def closed_form(self, substitution: Mapping[sympy.Symbol, sympy.Expr], sigma: int,
                    inputs: Circles) -> tuple[Point, sympy.Expr]:
        """``((x, y), discriminant)`` on the mode ``sigma``, real where the discriminant is >= 0.

        Earlier points' unknowns are replaced by ``substitution`` (their closed forms), and
        polynomials are reduced on the ``inputs``' circles.
        """

    def side(self) -> tuple[sympy.Expr, str] | None:
        """For a point without modes of its own: an expression in system variables that is > 0
        where it lies as its scene says, and what is wrong where it does not; else ``None``."""
        return None

    @abstractmethod
    def toggle_conditions(self) -> dict[str, sympy.Expr]:
        """``{kind: expression}`` in system variables, each zero where the two modes meet."""

    @abstractmethod
    def stable_evaluator(self, fix: Fix, arguments: list[sympy.Symbol], half_angles: Circles,
                         sigma: float) -> StableEvaluator:
        """The float evaluator of the mode ``sigma``, its expressions taken through ``fix`` and
        compiled in ``arguments`` (each input's c, s, then earlier points' unknowns)."""

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
