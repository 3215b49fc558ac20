"""What the branch algebra of one implicit point supplies, whatever its construction.

``algebra_of(spec)`` (in ``algkin.branches.constructions``) gives it for a compiled spec; each
construction's own is in its module (``dyad``, ``slider``, ``mirror``).
"""

from abc import ABC, abstractmethod
from collections.abc import Callable, Mapping, Sequence
from typing import ClassVar, Protocol

import sympy

from ...scene.implicit.algebra import Circles
from ...scene.implicit.base import FloatArray, Point

__all__ = ["BranchAlgebra", "StableEvaluator", "Substitution", "Mode", "Fix", "HalfAngle"]

Substitution = Mapping[sympy.Symbol, sympy.Expr]  # earlier points' unknowns -> their closed forms
Mode = Callable[[int], tuple[Point, sympy.Expr]]  # sigma -> ((x, y), discriminant) on that mode
Fix = Callable[[sympy.Expr], sympy.Expr]  # dimensions at their defaults, reduced on the circles
HalfAngle = tuple[FloatArray, FloatArray]  # an input's t = tan(theta/2) and w = 1/(1 + t**2)


class StableEvaluator(Protocol):
    """One implicit point in float64, vectorised, without cancellation."""

    @property
    def unknowns(self) -> tuple[str, str]: ...

    def __call__(self, values: Sequence[FloatArray], half: Sequence[HalfAngle]) -> tuple[FloatArray, FloatArray]:
        """``(x, y)`` from ``values`` (each input's c, s, then earlier points' x, y) and each input's ``half``."""
        ...


class BranchAlgebra(ABC):
    """The branch algebra of one implicit point: its closed form per mode, its toggles, its stable floats."""

    # True when the discriminant ``closed_form`` gives is a square ``f**2`` (real everywhere): the
    # point exists where ``f != 0`` (a meet's determinant), which ``valid_when`` says
    square: ClassVar[bool] = False

    def closed_form(self, substitution: Substitution, *, sigma: int, inputs: Circles) -> tuple[Point, sympy.Expr]:
        """``((x, y), discriminant)`` on the mode ``sigma``, real where the discriminant is >= 0.

        Earlier points' unknowns are replaced by ``substitution`` (their closed forms), and
        polynomials are reduced on the ``inputs``' circles.
        """
        return self.modes(substitution, inputs=inputs)(sigma)

    @abstractmethod
    def modes(self, substitution: Substitution, *, inputs: Circles) -> Mode:
        """``closed_form`` of each mode ``sigma``: the algebra the two modes share done once."""

    @abstractmethod
    def toggle_conditions(self) -> dict[str, sympy.Expr]:
        """``{kind: expression}`` in system variables, each zero where the two modes meet."""

    @abstractmethod
    def stable_evaluator(self, *, fix: Fix, arguments: Sequence[sympy.Symbol], half_angles: Circles,
                         sigma: float) -> StableEvaluator:
        """The float evaluator of the mode ``sigma``, its expressions taken through ``fix`` and
        compiled in ``arguments`` (each input's c, s, then earlier points' unknowns)."""
