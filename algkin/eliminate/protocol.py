"""The interface every polynomial backend implements, and the methods rely on.

A backend holds polynomials of its own type ``P`` over QQ in a fixed tuple of variable
names, and answers the operations below on them. The methods do ring arithmetic on ``P``
directly (``+``, ``-``, ``*``), and everything else through the backend.

The figures (``degree``, ``total_degree``, ``is_constant``, ``nterms``, ``terms``,
``coefficient_bits``) are asked only of non-zero polynomials: the zero polynomial's differ
between the backends (python-flint gives degree -1, sympy -oo), and the methods test
``is_zero`` first.
"""

from collections.abc import Callable, Mapping, Sequence, Set as AbstractSet
from typing import TYPE_CHECKING, Any, Protocol, TypeVar

import flint
import sympy

if TYPE_CHECKING:
    from .factor import IrreducibilityProof

__all__ = ["Ring", "P", "Term", "Backend", "BackendFactory"]

_R = TypeVar("_R", bound="Ring")


class Ring(Protocol):
    """What the methods do to a backend's polynomials without the backend: ring arithmetic."""

    def __add__(self: _R, other: _R, /) -> _R: ...
    def __sub__(self: _R, other: _R, /) -> _R: ...
    def __mul__(self: _R, other: _R, /) -> _R: ...
    def __neg__(self: _R) -> _R: ...


P = TypeVar("P", bound=Ring)

Term = tuple[tuple[int, ...], int, int]
"""One term: the exponents of the backend's names, and the coefficient's numerator and denominator."""


class Backend(Protocol[P]):
    """Polynomials of type ``P`` over QQ in the variables ``names``, and what the methods ask of them."""

    name: str
    names: tuple[str, ...]

    def from_sympy(self, expr: sympy.Expr) -> P:
        """A sympy polynomial (expression or ``Poly``) in the backend's names, as ``P``."""

    def from_flint(self, poly: flint.fmpq_mpoly) -> P:
        """A python-flint rational polynomial over any names (a subset of ``names`` held) as ``P``."""

    def to_sympy(self, poly: P) -> sympy.Expr:
        """``poly`` as a sympy expression in algkin's (real) symbols."""

    def variables(self, poly: P) -> AbstractSet[str]:
        """The names ``poly`` holds (of degree above zero)."""

    def forget(self) -> None:
        """Let go of whatever the backend keeps of the polynomials it was given (an elimination is over)."""

    def degree(self, poly: P, var: str) -> int:
        """The degree of ``poly`` in ``var``."""

    def is_constant(self, poly: P) -> bool:
        """Whether ``poly`` is a number."""

    def total_degree(self, poly: P) -> int:
        """The largest sum of exponents of a term."""

    def nterms(self, poly: P) -> int:
        """The number of terms."""

    def coefficient_bits(self, poly: P) -> int:
        """The largest bits of a coefficient's numerator plus its denominator's."""

    def is_zero(self, poly: P) -> bool:
        """Whether ``poly`` is the zero polynomial."""

    def resultant(self, f: P, g: P, var: str) -> P:
        """The Sylvester resultant of ``f`` and ``g`` in ``var``."""

    def factors(self, poly: P) -> list[P]:
        """The distinct irreducible factors of ``poly`` over QQ, without the content or multiplicities."""

    def irreducibility(self, poly: P) -> "IrreducibilityProof | None":
        """A proof that ``poly`` is irreducible over QQ, found more cheaply than by factoring; None if not found."""

    def gcd(self, f: P, g: P) -> P:
        """A greatest common divisor of ``f`` and ``g`` (up to a number)."""

    def derivative(self, poly: P, var: str) -> P:
        """The partial derivative of ``poly`` in ``var``."""

    def specialize(self, poly: P, values: Mapping[str, flint.fmpq]) -> P:
        """``poly`` with the variables of ``values`` replaced by those rationals."""

    def scale(self, poly: P, numerator: int, denominator: int) -> P:
        """``poly`` times ``numerator / denominator``."""

    def substitute(self, poly: P, var: str, value: P) -> P:
        """``poly`` with ``var`` replaced by the polynomial ``value``."""

    def terms(self, poly: P) -> list[Term]:
        """Every term as ``(exponents, numerator, denominator)``, in lex order from the largest."""

    def zero(self) -> P:
        """The zero polynomial."""

    def one(self) -> P:
        """The polynomial 1."""

    def divide(self, f: P, g: P) -> P:
        """``f / g``, where ``g`` is known to divide ``f``."""

    def quotient(self, f: P, g: P) -> P | None:
        """``f / g`` if ``g`` divides ``f``, else None."""

    def split(self, poly: P, variables: Sequence[str]) -> dict[tuple[int, ...], P]:
        """``{exponents in variables: non-zero coefficient free of them}``."""

    def join(self, parts: Mapping[tuple[int, ...], P], variables: Sequence[str]) -> P:
        """The inverse of ``split``."""

    def primitive(self, poly: P) -> P:
        """``poly`` times the number that makes its coefficients coprime integers, the lex-leading one positive."""

    def groebner_lex(self, polys: Sequence[P], order: Sequence[str]) -> list[P]:
        """A reduced lex Gröbner basis of ``polys``, variables ordered as ``order`` (first is largest)."""


BackendFactory = Callable[[Sequence[str]], Backend[Any]]
"""A backend class: made for a tuple of variable names."""
