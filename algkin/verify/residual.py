"""How far a polynomial is from vanishing at certified roots: ``|p(K)| / sum |terms|``.

The numerator is ``p`` evaluated in balls on the root's enclosure ``K``, its upper bound:
a polynomial that vanishes on the root gives a ball around 0 as narrow as the enclosure;
one that does not is proved nonzero there. A polynomial comes as a python-flint
``fmpq_mpoly`` (an eliminant, straight from the elimination) or a sympy expression;
dimensions kept symbolic take their exact values first (python-flint substitution). It is
then grouped by the monomials of all but its variable of highest degree, each group an
``arb_poly`` in that variable (evaluated in C). The denominator, the sum of the terms'
absolute values, only scales the figure: it is evaluated in floats, for all roots at once.
Both are of ``p / scale``, ``scale`` a power of two within a factor 2 of the largest coefficient: the
figure is the same, and coefficients past a float's range (a dimension written with 90-digit
integers, raised to the eighth power) still give finite floats.

>>> import flint, numpy as np, sympy
>>> x, y, r = sympy.symbols("x y r", real=True)
>>> circle = Polynomial(x**2 + y**2 - r**2, ["x", "y"], {"r": 5})
>>> with flint.ctx.workprec(200):
...     on, off = circle.balls({"x": flint.arb(3), "y": flint.arb(4)}), circle.balls({"x": flint.arb(3), "y": flint.arb(5)})
>>> on.contains(0), off.contains(0)
(True, False)
>>> circle.scale
16
>>> circle.magnitude({"x": np.array([3.0]), "y": np.array([4.0])}).tolist()   # (9 + 16 + 25) / 16
[3.125]
"""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Iterable, Mapping, Sequence
from fractions import Fraction
from typing import TypeAlias

import flint
import numpy as np
import sympy
from numpy.typing import NDArray

from ..evaluate import ARB
from ..runtime.cache import BoundedCache
from ..system.convert import flint_context, to_flint

__all__ = ["Polynomial", "exact", "fraction", "polynomial_of"]

# An eliminant as the elimination hands it over, or as a caller writes it
PolynomialLike: TypeAlias = flint.fmpq_mpoly | flint.fmpz_mpoly | sympy.Expr
# An exact value, read back from its printed form (``Fraction(str(value))``)
ExactValue: TypeAlias = sympy.Rational | Fraction | int | float
# Monomial exponents of all but the inner variable -> [(inner exponent, coefficient)]
Groups: TypeAlias = dict[tuple[int, ...], list[tuple[int, flint.fmpq | flint.fmpz]]]


def polynomial_of(polynomial: PolynomialLike, names: Sequence[str],
                  fixed: Mapping[str, ExactValue] | None = None) -> Polynomial:
    """The ``Polynomial`` of ``polynomial``, built once for the same terms, names and values."""
    poly = exact(polynomial)
    key = (tuple(map(str, poly.context().names())), str(poly), tuple(names),
           tuple(sorted((n, str(v)) for n, v in (fixed or {}).items())))
    return POLYNOMIALS.get(key, lambda: Polynomial(poly, names, fixed))


POLYNOMIALS: BoundedCache[Polynomial] = BoundedCache(256, name="polynomials ready for balls")


def fraction(value: ExactValue) -> Fraction:
    """``value`` exactly as it is printed, ``Fraction(str(value))`` (a float as it is written, not
    its binary value), without printing and parsing a rational.

    >>> fraction(0.1), fraction(sympy.Rational(-3, 4)), fraction(Fraction(5, 2)), fraction(7)
    (Fraction(1, 10), Fraction(-3, 4), Fraction(5, 2), Fraction(7, 1))
    """
    if isinstance(value, Fraction):
        return value
    if isinstance(value, sympy.Rational):
        return Fraction(int(value.p), int(value.q))
    if type(value) is int:
        return Fraction(value)
    return Fraction(str(value))


def exact(polynomial: PolynomialLike) -> flint.fmpq_mpoly | flint.fmpz_mpoly:
    """``polynomial`` as an ``fmpq_mpoly`` (a sympy expression is converted, a flint one kept)."""
    if isinstance(polynomial, (flint.fmpq_mpoly, flint.fmpz_mpoly)):
        return polynomial
    expr = sympy.sympify(polynomial)
    return to_flint(expr, flint_context(sorted(str(v) for v in expr.free_symbols) or ["_"]))


class Polynomial:
    """A polynomial in ``names`` (with the variables in ``fixed`` at exact values), ready for
    balls and float magnitudes."""

    def __init__(self, polynomial: PolynomialLike, names: Sequence[str],
                 fixed: Mapping[str, ExactValue] | None = None) -> None:
        self.exact = poly = exact(polynomial)
        variables = [str(n) for n in poly.context().names()]
        degrees = poly.degrees()
        known = {n: fraction(v) for n, v in (fixed or {}).items()}
        unknown = {v for v, d in zip(variables, degrees) if d} - set(names) - set(known)
        if unknown:
            raise ValueError(f"the polynomial {poly} has variables {sorted(unknown)} with no value")
        given: dict[str | int, flint.fmpq] = {n: flint.fmpq(v.numerator, v.denominator)
                                              for n, v in known.items() if n in variables}
        # an fmpz_mpoly takes integer values only; the polynomials given values are fmpq_mpoly
        poly = poly.subs(given) if given else poly  # type: ignore[arg-type]
        degrees = poly.degrees()
        keep = [k for k, (n, d) in enumerate(zip(variables, degrees)) if d and n not in given]
        self.names = [variables[k] for k in keep]
        # with ``monoms()``, the terms in ``to_dict``'s order, at half its cost (its stub says flint_scalar)
        coefficients: list[flint.fmpq | flint.fmpz] = poly.coeffs()  # type: ignore[assignment]
        self.scale = _scale(coefficients)
        terms = {tuple([int(m[k]) for k in keep]): flint.fmpq(c) / self.scale
                 for m, c in zip(poly.monoms(), coefficients)}
        # the variable of highest degree (the first of them) is the inner one
        self.inner = max(range(len(keep)), key=lambda k: degrees[keep[k]]) if keep else None
        self.groups = _groups(terms, self.inner)
        self.outer = [n for k, n in enumerate(self.names) if k != self.inner]
        # where each variable sits among ``names``, for ``at``: the inner one, then the outer ones
        self.slots = [list(names).index(n) for n in
                      ([] if self.inner is None else [self.names[self.inner]]) + self.outer]
        # each outer variable's highest power, and each group's outer powers that are not 0
        self.tops = [max(m[k] for m in self.groups) for k in range(len(self.outer))]
        self.raised = {m: [(k, e) for k, e in enumerate(m) if e] for m in self.groups}
        self.exponents = np.array(list(terms) or [()], dtype=float).reshape(len(terms) or 1, len(keep))
        self.sizes = np.array([abs(float(c)) for c in terms.values()] or [0.0])
        # (precision, the groups as arb_poly at it): made on first use, remade when the precision changes
        self.made: tuple[int | None, tuple[list[tuple[flint.arb_poly, list[tuple[int, int]]]],
                                           list[flint.arb_poly | None]]] = (None, ([], []))

    def balls(self, values: Mapping[str, flint.arb]) -> flint.arb:
        """``p / scale`` at ``values`` (name -> ball), a ball."""
        if self.inner is None:
            return self._value(None, [])
        return self._value(values[self.names[self.inner]], [values[n] for n in self.outer])

    def at(self, values: Sequence[flint.arb]) -> flint.arb:
        """``p / scale`` at ``values``, one ball per name of the ``names`` it was made with, in
        their order: ``balls`` without a mapping (the same ball)."""
        if self.inner is None:
            return self._value(None, [])
        slots = self.slots
        return self._value(values[slots[0]], [values[k] for k in slots[1:]])

    def _value(self, x: flint.arb | None, outer: list[flint.arb]) -> flint.arb:
        """``p / scale`` with its inner variable at ``x`` and its outer ones at ``outer``."""
        groups, horner = self._polys()
        if x is None:
            return sum((p(0) for p, _ in groups), flint.arb(0))
        if len(outer) == 1:  # a curve: Horner in the other coordinate, no table of powers
            y = outer[0]
            total = horner[0](x)  # type: ignore[misc]  # the highest power's group is never missing
            for poly in horner[1:]:
                total = total * y if poly is None else total * y + poly(x)
            return total
        powers = [_powers(v, top) for v, top in zip(outer, self.tops)]
        total = flint.arb(0)
        for poly, raised in groups:
            term = poly(x)
            for k, e in raised:
                term = term * powers[k][e]
            total += term
        return total

    def magnitude(self, values: Mapping[str, NDArray[np.float64]]) -> NDArray[np.float64]:
        """The sum of the absolute values of the terms of ``p / scale``, for float arrays ``values`` (all at once)."""
        if not self.names:
            return np.full(1, self.sizes.sum())
        points = np.abs(np.stack([np.asarray(values[n], dtype=float) for n in self.names], axis=-1))
        return np.asarray(np.prod(points[:, None, :] ** self.exponents[None], axis=-1) @ self.sizes, dtype=np.float64)

    def _polys(self) -> tuple[list[tuple[flint.arb_poly, list[tuple[int, int]]]], list[flint.arb_poly | None]]:
        """The groups as ``arb_poly`` with their outer powers, and (one outer variable) the groups
        by outer power from the highest down for Horner: remade when the working precision changed."""
        precision = flint.ctx.prec
        if self.made[0] != precision:
            polys = {m: _arb_poly(terms) for m, terms in self.groups.items()}
            horner = [polys.get((e,)) for e in range(self.tops[0], -1, -1)] if len(self.outer) == 1 else []
            self.made = (precision, ([(p, self.raised[m]) for m, p in polys.items()], horner))
        return self.made[1]


def _scale(coefficients: Iterable[flint.fmpq | flint.fmpz]) -> flint.fmpq:
    """A power of two within a factor 2 of the largest of ``coefficients`` (1 when all are 0),
    found from their bit lengths: their floats may overflow.

    >>> _scale([flint.fmpq(3, 4), flint.fmpz(-10) ** 400]) == flint.fmpq(2) ** 1328
    True
    """
    bits = [c.p.bit_length() - c.q.bit_length() for c in map(flint.fmpq, coefficients) if c]
    return flint.fmpq(2) ** max(bits) if bits else flint.fmpq(1)


def _groups(terms: Mapping[tuple[int, ...], flint.fmpq | flint.fmpz], inner: int | None) -> Groups:
    """``outer monomial -> [(inner exponent, coefficient)]``."""
    groups: defaultdict[tuple[int, ...], list[tuple[int, flint.fmpq | flint.fmpz]]] = defaultdict(list)
    for monomial, coefficient in terms.items():
        if inner is None:
            groups[()].append((0, coefficient))
        else:
            groups[monomial[:inner] + monomial[inner + 1:]].append((monomial[inner], coefficient))
    return dict(groups) or {(): [(0, flint.fmpq(0))]}


def _arb_poly(terms: Sequence[tuple[int, flint.fmpq | flint.fmpz]]) -> flint.arb_poly:
    coefficients = [ARB.number(0, 1)] * (max(e for e, _ in terms) + 1)
    for exponent, c in terms:
        c = flint.fmpq(c)
        coefficients[exponent] = ARB.number(int(c.p), int(c.q))
    return flint.arb_poly(coefficients)


def _powers(value: flint.arb, top: int) -> list[flint.arb]:
    """``[1, v, v**2, ..., v**top]`` by products (``arb ** int`` is nan on a ball around 0)."""
    powers = [flint.arb(1)]
    for _ in range(top):
        powers.append(powers[-1] * value)
    return powers
