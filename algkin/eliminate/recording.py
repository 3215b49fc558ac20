"""A backend that answers as another does and keeps every factor it was asked for.

The ``interpolate`` method learns, from one exact elimination, which intermediate factors the
elimination met (``algkin.eliminate.interpolate``): it runs that elimination on a ``Recording``
of its backend. Any backend of the protocol can be recorded; the recording is one too, so
every method runs on it unchanged.

>>> import sympy
>>> from algkin.eliminate.backends import FlintBackend
>>> x, y = sympy.symbols("x y")
>>> recording = Recording(FlintBackend(("x", "y")))
>>> parts = recording.factors(recording.from_sympy(x**2 - y**2))
>>> sorted(str(recording.to_sympy(p)) for p in recording.seen)
['x + y', 'x - y']
"""

from collections.abc import Mapping, Sequence, Set as AbstractSet
from typing import TYPE_CHECKING, Generic

import flint
import sympy

from .protocol import Backend, P, Term

if TYPE_CHECKING:
    from .factor import IrreducibilityProof

__all__ = ["Recording"]


class Recording(Generic[P]):
    """``inner``'s answers; the factors ``factors`` found, in order, in ``seen``."""

    def __init__(self, inner: Backend[P]) -> None:
        self.inner = inner
        self.name, self.names = inner.name, inner.names
        self.seen: list[P] = []

    def factors(self, poly: P) -> list[P]:
        found = self.inner.factors(poly)
        self.seen.extend(found)
        return found

    # -- the rest of the protocol, as ``inner`` answers -------------------------------------------

    def from_sympy(self, expr: sympy.Expr) -> P:
        return self.inner.from_sympy(expr)

    def from_flint(self, poly: flint.fmpq_mpoly) -> P:
        return self.inner.from_flint(poly)

    def to_sympy(self, poly: P) -> sympy.Expr:
        return self.inner.to_sympy(poly)

    def variables(self, poly: P) -> AbstractSet[str]:
        return self.inner.variables(poly)

    def forget(self) -> None:
        self.inner.forget()

    def degree(self, poly: P, var: str) -> int:
        return self.inner.degree(poly, var)

    def is_constant(self, poly: P) -> bool:
        return self.inner.is_constant(poly)

    def total_degree(self, poly: P) -> int:
        return self.inner.total_degree(poly)

    def nterms(self, poly: P) -> int:
        return self.inner.nterms(poly)

    def coefficient_bits(self, poly: P) -> int:
        return self.inner.coefficient_bits(poly)

    def is_zero(self, poly: P) -> bool:
        return self.inner.is_zero(poly)

    def resultant(self, f: P, g: P, var: str) -> P:
        return self.inner.resultant(f, g, var)

    def irreducibility(self, poly: P) -> "IrreducibilityProof | None":
        return self.inner.irreducibility(poly)

    def gcd(self, f: P, g: P) -> P:
        return self.inner.gcd(f, g)

    def derivative(self, poly: P, var: str) -> P:
        return self.inner.derivative(poly, var)

    def specialize(self, poly: P, values: Mapping[str, flint.fmpq]) -> P:
        return self.inner.specialize(poly, values)

    def scale(self, poly: P, numerator: int, denominator: int) -> P:
        return self.inner.scale(poly, numerator, denominator)

    def substitute(self, poly: P, var: str, value: P) -> P:
        return self.inner.substitute(poly, var, value)

    def terms(self, poly: P) -> list[Term]:
        return self.inner.terms(poly)

    def zero(self) -> P:
        return self.inner.zero()

    def one(self) -> P:
        return self.inner.one()

    def divide(self, f: P, g: P) -> P:
        return self.inner.divide(f, g)

    def quotient(self, f: P, g: P) -> P | None:
        return self.inner.quotient(f, g)

    def split(self, poly: P, variables: Sequence[str]) -> dict[tuple[int, ...], P]:
        return self.inner.split(poly, variables)

    def join(self, parts: Mapping[tuple[int, ...], P], variables: Sequence[str]) -> P:
        return self.inner.join(parts, variables)

    def primitive(self, poly: P) -> P:
        return self.inner.primitive(poly)

    def groebner_lex(self, polys: Sequence[P], order: Sequence[str]) -> list[P]:
        return self.inner.groebner_lex(polys, order)
