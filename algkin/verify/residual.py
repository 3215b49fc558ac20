"""How far a polynomial is from vanishing at certified roots: ``|p(K)| / sum |terms|``.

The numerator is ``p`` evaluated in balls on the root's enclosure ``K``, its upper bound:
a polynomial that vanishes on the root gives a ball around 0 as narrow as the enclosure;
one that does not is proved nonzero there. A polynomial comes as a python-flint
``fmpq_mpoly`` (an eliminant, straight from the elimination) or a sympy expression;
dimensions kept symbolic take their exact values first (python-flint substitution). Its
terms are then laid out by the powers of its two variables of highest degree, one table per
monomial of the rest. A curve (two variables) is evaluated by Horner's rule in both, an
``arb_poly`` per power of the second; a polynomial in more, a table at a time, as
``row * table * column`` (``arb_mat`` products, a few calls into C where one ``arb_poly`` per
monomial made hundreds of calls from Python). The denominator, the sum of the terms'
absolute values, only scales the figure: it is evaluated in floats, for all roots at once,
from tables of each variable's powers.
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
# The rest's exponents -> {(power of the row variable, power of the inner one): coefficient}
Tables: TypeAlias = dict[tuple[int, ...], dict[tuple[int, int], flint.fmpq]]
# A curve's arb_poly per power of the row variable from the highest (None where there is no term)
Horner: TypeAlias = list[flint.arb_poly | None]
# Per table of a polynomial in more variables: the rest's (variable, power) pairs and the arb_mat
Matrices: TypeAlias = list[tuple[list[tuple[int, int]], flint.arb_mat]]


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
        tops = [max((m[k] for m in terms), default=0) for k in range(len(keep))]
        # the variable of highest degree (the first of them) is the inner one, the next the row one
        order = sorted(range(len(keep)), key=lambda k: -tops[k])
        self.tops = [tops[k] for k in order]
        self.tables = _tables(terms, order)
        # where each variable sits among ``names``, for ``at``: the inner one, the row one, then the rest
        self.slots = [list(names).index(self.names[k]) for k in order]
        self.order = [self.names[k] for k in order]
        self.exponents = np.array(list(terms) or [()], dtype=np.intp).reshape(len(terms) or 1, len(keep))
        self.sizes = np.array([abs(float(c)) for c in terms.values()] or [0.0])
        # (precision, the tables in balls at it): made on first use, remade when the precision changes
        self.made: tuple[int | None, Horner, Matrices] = (None, [], [])

    def balls(self, values: Mapping[str, flint.arb]) -> flint.arb:
        """``p / scale`` at ``values`` (name -> ball), a ball."""
        return self._value([values[n] for n in self.order])

    def at(self, values: Sequence[flint.arb]) -> flint.arb:
        """``p / scale`` at ``values``, one ball per name of the ``names`` it was made with, in
        their order: ``balls`` without a mapping (the same ball)."""
        return self._value([values[k] for k in self.slots])

    def _value(self, values: list[flint.arb]) -> flint.arb:
        """``p / scale`` with its variables (inner, row, the rest) at ``values``."""
        horner, matrices = self._made()
        # fewer than two variables: the missing ones are never raised
        inner, row = (values + [flint.arb(0), flint.arb(0)])[:2]
        if len(values) <= 2:
            total = flint.arb(0)
            for poly in horner:
                total = total * row if poly is None else total * row + poly(inner)
            return total
        tops = self.tops
        column = flint.arb_mat(tops[0] + 1, 1, _powers(inner, tops[0]))
        line = flint.arb_mat(1, tops[1] + 1, _powers(row, tops[1]))
        powers = [_powers(v, top) for v, top in zip(values[2:], tops[2:])]
        total = flint.arb(0)
        for raised, table in matrices:
            term = (line * table * column)[0, 0]
            for k, e in raised:
                term *= powers[k][e]
            total += term
        return total

    def magnitude(self, values: Mapping[str, NDArray[np.float64]]) -> NDArray[np.float64]:
        """The sum of the absolute values of the terms of ``p / scale``, for float arrays ``values`` (all at once)."""
        if not self.names:
            return np.full(1, self.sizes.sum())
        points = [np.abs(np.asarray(values[n], dtype=float)) for n in self.names]
        terms = np.ones((len(points[0]), len(self.sizes)))
        for k, x in enumerate(points):
            top = int(self.exponents[:, k].max())
            powers = np.cumprod(np.column_stack([np.ones_like(x)] + [x] * top), axis=1)
            terms *= powers[:, self.exponents[:, k]]
        return np.asarray(terms @ self.sizes, dtype=np.float64)

    def _made(self) -> tuple[Horner, Matrices]:
        """The tables in balls: remade when the working precision changed."""
        precision = flint.ctx.prec
        if self.made[0] != precision:
            tops = self.tops + [0, 0]
            if len(self.tops) <= 2:
                (table,) = self.tables.values()
                by_row: list[dict[int, flint.fmpq]] = [{} for _ in range(tops[1] + 1)]
                for (i, j), c in table.items():
                    by_row[i][j] = c
                self.made = (precision, [_arb_poly(terms) if terms else None for terms in reversed(by_row)], [])
            else:
                self.made = (precision, [], [([(k, e) for k, e in enumerate(raised) if e],
                                              _arb_mat(table, tops[1] + 1, tops[0] + 1))
                                             for raised, table in self.tables.items()])
        return self.made[1], self.made[2]


def _scale(coefficients: Iterable[flint.fmpq | flint.fmpz]) -> flint.fmpq:
    """A power of two within a factor 2 of the largest of ``coefficients`` (1 when all are 0),
    found from their bit lengths: their floats may overflow.

    >>> _scale([flint.fmpq(3, 4), flint.fmpz(-10) ** 400]) == flint.fmpq(2) ** 1328
    True
    """
    bits = [c.p.bit_length() - c.q.bit_length() for c in map(flint.fmpq, coefficients) if c]
    return flint.fmpq(2) ** max(bits) if bits else flint.fmpq(1)


def _tables(terms: Mapping[tuple[int, ...], flint.fmpq], order: Sequence[int]) -> Tables:
    """The terms per monomial of the variables past the first two of ``order``, each
    ``{(power of order[1], power of order[0]): coefficient}``."""
    tables: defaultdict[tuple[int, ...], dict[tuple[int, int], flint.fmpq]] = defaultdict(dict)
    for monomial, coefficient in terms.items():
        exponents = [monomial[k] for k in order] + [0, 0]
        tables[tuple(exponents[2:len(order)])][exponents[1], exponents[0]] = coefficient
    return dict(tables) or {(): {}}


def _arb_mat(entries: Mapping[tuple[int, int], flint.fmpq], rows: int, columns: int) -> flint.arb_mat:
    """``entries`` as balls at the working precision in a ``rows x columns`` matrix (0 elsewhere)."""
    matrix = flint.arb_mat(rows, columns)
    for (i, j), c in entries.items():
        matrix[i, j] = ARB.number(int(c.p), int(c.q))
    return matrix


def _arb_poly(terms: Mapping[int, flint.fmpq]) -> flint.arb_poly:
    coefficients = [ARB.number(0, 1)] * (max(terms) + 1)
    for exponent, c in terms.items():
        coefficients[exponent] = ARB.number(int(c.p), int(c.q))
    return flint.arb_poly(coefficients)


def _powers(value: flint.arb, top: int) -> list[flint.arb]:
    """``[1, v, v**2, ..., v**top]`` by products (``arb ** int`` is nan on a ball around 0)."""
    powers = [flint.arb(1)]
    for _ in range(top):
        powers.append(powers[-1] * value)
    return powers
