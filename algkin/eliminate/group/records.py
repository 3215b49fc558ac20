"""What solving a group answers: frozen, hashable records.

A python-flint polynomial is not hashable, so a record holds a ``Polynomial``: the names and
the terms, turned back into python-flint when asked (``to_flint``).

>>> import flint
>>> ctx = flint.fmpq_mpoly_ctx.get(("u", "r"), "lex")
>>> u, r = ctx.gens()
>>> poly = Polynomial.of(u**2 - r / 3)
>>> poly.to_flint() == u**2 - r / 3, str(poly), hash(poly) == hash(Polynomial.of(u**2 - r / 3))
(True, 'u**2 - 1/3*r', True)
"""

from __future__ import annotations

import functools

import attrs
import flint

from ...runtime.frozen import FrozenDict, frozen
from ...system.roots import RealRoot

__all__ = ["Polynomial", "Lift", "GroupSolution", "Mode", "Values"]

Term = tuple[tuple[int, ...], int, int]
Values = dict[str | int, int | flint.fmpz | flint.fmpq]
"""Exact values of some variables, by name: what python-flint's ``subs`` takes."""


@attrs.frozen
class Polynomial:
    """A polynomial over QQ in ``names`` (lex): ``terms`` are ``(exponents, numerator, denominator)``."""

    names: tuple[str, ...]
    terms: tuple[Term, ...]

    @classmethod
    def of(cls, poly: flint.fmpq_mpoly) -> Polynomial:
        """The record of a python-flint polynomial."""
        coeffs = poly.coeffs()  # lists mapped, no generator per term: a lift has hundreds of terms
        terms = tuple(zip([tuple(map(int, m)) for m in poly.monoms()], [int(c.p) for c in coeffs],
                          [int(c.q) for c in coeffs]))
        return cls(tuple(str(n) for n in poly.context().names()), terms)

    def to_flint(self) -> flint.fmpq_mpoly:
        """The python-flint polynomial (a new one each call: python-flint's are mutable in place)."""
        return self._flint * 1

    @functools.cached_property
    def _flint(self) -> flint.fmpq_mpoly:
        ctx = flint.fmpq_mpoly_ctx.get(self.names, "lex")
        return ctx.from_dict({m: flint.fmpq(p, q) for m, p, q in self.terms})

    def degree(self, name: str) -> int:
        index = self.names.index(name)
        return max((m[index] for m, _, _ in self.terms), default=0)

    def __str__(self) -> str:
        return str(self.to_flint()).replace("^", "**")


@attrs.frozen
class Lift:
    """An unknown as ``numerator / denominator``, both polynomials in the group's variable and
    parameters: its value at every root of the eliminant where the denominator does not vanish."""

    unknown: str
    numerator: Polynomial
    denominator: Polynomial


@attrs.frozen
class GroupSolution:
    """A group of unknowns solved together (a rational univariate representation).

    ``variable``: the separating unknown, or the name of a linear ``form`` of the unknowns
    (``unknown -> integer coefficient``) when no unknown separates the solutions;
    ``eliminant``: its polynomial, in it and the ``parameters``, squarefree, its extraneous
    factors ``dropped``; ``lifts``: every other unknown rational in it; ``complex_count``:
    the number of complex solutions at generic parameters (the eliminant's degree in the
    variable); ``rejected``: the variables tried first, and why each failed.
    """

    unknowns: tuple[str, ...]
    parameters: tuple[str, ...]
    variable: str
    eliminant: Polynomial
    lifts: tuple[Lift, ...]
    form: FrozenDict[str, int] = attrs.field(converter=frozen, factory=FrozenDict)
    dropped: tuple[Polynomial, ...] = ()
    rejected: tuple[tuple[str, str], ...] = ()

    @property
    def complex_count(self) -> int:
        return self.eliminant.degree(self.variable)


@attrs.frozen
class Mode:
    """One real solution of a group at a sample: each unknown's (and the variable's) value as a
    ball, certified; ``index``: its place among the real roots of the eliminant, in increasing
    order; ``root``: that root exactly (its irreducible factor and rank), its ball the variable's;
    None for a group solved after another, whose parameters took an earlier mode's balls (the
    mode is then told by its ``index`` under that earlier mode), or at an input known only as a
    ball (an angle's irrational cos and sin).
    The exact root is the mode's identity: the balls, like a ``RealRoot``'s, are not compared
    (nor hashed: a ball is no exact number)."""

    index: int
    root: RealRoot | None
    values: FrozenDict[str, flint.arb] = attrs.field(converter=frozen, eq=False)
