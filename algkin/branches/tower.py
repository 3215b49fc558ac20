"""Closed forms over square roots, in python-flint: the algebra of a point built on another's closed form.

A later dyad's base holds an earlier dyad's square root ``r = sqrt(R)``. Expanded by sympy, its
algebra writes each term over a denominator of its own and leaves ``s**2`` unreduced under the
new root (9,000 characters a coordinate on Stephenson III, a fifth of a second to build). Here
it is done in the ring ``Q[symbols, roots]`` modulo ``s**2 = 1 - c**2`` for each input and
``r**2 = R`` for each root, in python-flint: every value a fraction ``N/D`` of reduced
polynomials, written back as one sum over ``D`` grouped by the roots it holds.

>>> c, s = sympy.symbols("c s")
>>> root = sympy.sqrt(5 - 4 * c)
>>> tower = Tower([s * root, c / root], [(c, s)])
>>> value = tower.value(s * root) * tower.value(s * root) + tower.value(c / root)
>>> tower.expr(value)  # s**2 * (5 - 4*c) with s**2 = 1 - c**2
(c + sqrt(5 - 4*c)*(4*c**3 - 5*c**2 - 4*c + 5))/sqrt(5 - 4*c)
"""

from collections.abc import Callable, Mapping, Sequence

import flint
import sympy
from sympy.core.mul import _keep_coeff

from ..scene.implicit.algebra import HALF, Circles, square_reduced
from ..system.convert import content, fmpq_to_rational, from_terms
from .algebra import product, total

__all__ = ["Tower", "Value", "Unsupported", "roots_in", "varying_radicands", "root_free"]


class Unsupported(Exception):
    """An expression outside the tower's vocabulary (sums, products, integer powers, square roots of
    polynomials, rational numbers, symbols of distinct names): sympy's own path then."""


def roots_in(exprs: Sequence[sympy.Expr]) -> set[sympy.Pow]:
    """The square roots in ``exprs`` (``x**(k/2)`` holds ``sqrt(x)``), nested ones too."""
    return {sympy.sqrt(p.base) for e in exprs for p in e.atoms(sympy.Pow) if p.exp.is_Rational and p.exp.q == 2}


def varying_radicands(expr: sympy.Expr) -> int:
    """How many distinct radicands with symbols ``expr``'s square roots and absolute values have: at
    least as many as the varying roots a ``Tower`` of it counts (``roots_in`` makes each root anew,
    sympy's ``sqrt`` asking each factor's sign; two radicands may give one root, never one two).

    >>> c = sympy.Symbol("c")
    >>> varying_radicands(c * sympy.sqrt(5 - 4 * c) + sympy.sqrt(2) / sympy.sqrt(5 - 4 * c)), varying_radicands(c)
    (1, 0)
    """
    radicands = {p.base for p in expr.atoms(sympy.Pow) if p.exp.is_Rational and p.exp.q == 2}
    return sum(1 for r in radicands if r.free_symbols) + sum(1 for a in _absolutes([expr]) if a.free_symbols)


def _absolutes(exprs: Sequence[sympy.Expr]) -> set[sympy.Expr]:
    """The absolute values in ``exprs``: sympy writes ``sqrt(x**2)`` of a real ``x`` as ``Abs(x)``
    (a symbolic length's), which the tower takes back as the root of ``x**2``."""
    return {a for e in exprs for a in e.atoms(sympy.Abs)}


def root_free(expr: sympy.Expr) -> sympy.Expr:
    """``expr`` times its conjugates over its square roots (``Tower.norm``): a rational function, zero
    wherever ``expr`` is (and where a conjugate is); ``expr`` itself when it holds no root.

    >>> c = sympy.Symbol("c")
    >>> root_free((c - sympy.sqrt(c + 2)) * 3)
    9*(c**2 - c - 2)
    """
    if not roots_in([expr]) and not _absolutes([expr]):
        return expr
    tower = Tower([expr], [])
    return tower.expr(tower.norm(tower.value(expr)))


class Tower:
    """The ring of ``exprs``' symbols and square roots, with room for ``new_roots`` more, each
    input's sine and each root of degree at most one (their squares replaced)."""

    def __init__(self, exprs: Sequence[sympy.Expr], inputs: Circles, *, new_roots: int = 0) -> None:
        symbols = set().union(*(e.free_symbols for e in exprs))
        circles = [(c, s) for c, s in inputs if c in symbols or s in symbols]
        symbols |= {v for circle in circles for v in circle}
        self.symbols = sorted(symbols, key=lambda v: v.name)
        if len({v.name for v in self.symbols}) != len(self.symbols):
            raise Unsupported("two symbols of one name")
        roots = roots_in(exprs) | _absolutes(exprs)
        size = len(self.symbols) + len(roots) + new_roots
        self.ring = flint.fmpq_mpoly_ctx.get(tuple(f"g{k}" for k in range(size)), "lex")
        gens = self.ring.gens()
        self.one = self.ring.from_dict({(0,) * size: 1})
        self.shown: list[sympy.Expr] = list(self.symbols)  # each variable as sympy writes it
        self._squares: list[tuple[int, flint.fmpq_mpoly]] = []  # (root's index, its radicand), innermost first
        self._circles = [(self.symbols.index(s), 1 - gens[self.symbols.index(c)] ** 2) for c, s in circles]
        self._memo: dict[sympy.Expr, Value] = {v: Value(self, g, self.one) for v, g in zip(self.symbols, gens)}
        self._written: list[tuple[flint.fmpq_mpoly, tuple[sympy.Rational, sympy.Expr]]] = []
        self.roots = sum(1 for r in roots if r.free_symbols)  # those of ``exprs`` that vary (not sqrt(5))

    def new_root(self, radicand: "Value", shown: sympy.Expr) -> "Value":
        """The next free variable ``r`` with ``r**2 = radicand`` (a polynomial), written ``shown``."""
        index = len(self.shown)
        if index >= self.ring.nvars():
            raise Unsupported("no room for another root in this tower")
        if not radicand.denominator.is_constant():
            raise Unsupported("a root of a fraction")
        self._squares.append((index, radicand.numerator / radicand.denominator))
        self.shown.append(shown)
        return Value(self, self.ring.gens()[index], self.one)

    def over_common(self, values: Sequence["Value"]) -> tuple[list["Value"], "Value"]:
        """``(numerators, denominator)``: each of ``values`` is its numerator over the one denominator."""
        common = values[0].denominator
        for value in values[1:]:
            if value.denominator != common:
                common = common * (value.denominator / common.gcd(value.denominator))
        numerators = [Value(self, self.reduced(v.numerator * (common / v.denominator)), self.one) for v in values]
        return numerators, Value(self, self.reduced(common), self.one)

    def primitive(self, value: "Value") -> tuple[sympy.Rational, sympy.Expr]:
        """``(k, p)`` with ``value = k * p``, ``p`` a sum with coprime integer coefficients; ``value``'s
        denominator a number."""
        if not value.denominator.is_constant():
            raise Unsupported("a fraction")
        k, part = self.written(value.numerator)
        return k / fmpq_to_rational(value.denominator.leading_coefficient()), part

    def norm(self, value: "Value") -> "Value":
        """The product of ``value``'s conjugates (each root's sign in turn, the outermost first): free
        of roots, and zero wherever ``value`` is.

        >>> c = sympy.Symbol("c")
        >>> tower = Tower([c + sympy.sqrt(c + 2)], [])
        >>> tower.expr(tower.norm(tower.value(c + sympy.sqrt(c + 2))))
        c**2 - c - 2
        """
        for index, _ in reversed(self._squares):
            gens = list(self.ring.gens())
            gens[index] = -gens[index]
            value = value * Value(self, value.numerator.compose(*gens), value.denominator.compose(*gens))
        return value

    def reduced(self, poly: flint.fmpq_mpoly) -> flint.fmpq_mpoly:
        """``poly`` with each root and each sine of degree at most one: the outermost root first
        (its radicand may hold the inner ones), the sines last."""
        for index, square in [*reversed(self._squares), *self._circles]:
            if poly.degrees()[index] >= 2:
                poly = square_reduced(poly, index, square)
        return poly

    def value(self, expr: sympy.Expr) -> "Value":
        """``expr`` in the tower; Unsupported outside its vocabulary."""
        found = self._memo.get(expr)
        if found is None:
            found = self._memo[expr] = self._value(expr, self.value)
        return found

    def value_given(self, expr: sympy.Expr, given: Mapping[sympy.Symbol, "Value"]) -> "Value":
        """``expr`` with ``given``'s symbols standing for their values (a definition in the unknowns,
        the unknowns' closed forms met in this tower already), remembered for this call only."""
        local: dict[sympy.Expr, Value] = dict(given)

        def value(node: sympy.Expr) -> Value:
            found = local.get(node)
            if found is None:
                found = local[node] = self._value(node, value) if node.free_symbols & given.keys() \
                    else self.value(node)
            return found
        return value(expr)

    def _value(self, expr: sympy.Expr, value: Callable[[sympy.Expr], "Value"]) -> "Value":
        if expr.is_Rational:
            return Value(self, self.one * flint.fmpq(int(expr.p), int(expr.q)), self.one)
        if expr.is_Add or expr.is_Mul:
            parts = [value(a) for a in expr.args]
            total = parts[0]
            for part in parts[1:]:
                total = total + part if expr.is_Add else total * part
            return total
        if expr.is_Pow and expr.exp == HALF:  # a root's variable comes after those in its radicand
            return self.new_root(value(expr.base), expr)
        if isinstance(expr, sympy.Abs):  # |x| = sqrt(x**2)
            return self.new_root(value(expr.args[0] ** 2), expr)
        if expr.is_Pow and expr.exp.is_Rational and expr.exp.q in (1, 2):
            root = expr.exp.q == 2  # x**(k/2) as sqrt(x)**k
            base, power = value(sympy.sqrt(expr.base) if root else expr.base), int(expr.exp.p)
            if power < 0:
                base, power = base.inverse(), -power
            result = base
            for _ in range(power - 1):
                result = result * base
            return result
        raise Unsupported(expr)

    def expr(self, value: "Value", *, remember: bool = False) -> sympy.Expr:
        """``value`` as ``k * a / q``: ``a`` and ``q`` with coprime integer coefficients, each
        grouped by the roots it holds (``a0 + a1*r``), ``q``'s leading coefficient positive;
        ``remember``: the expression is ``value`` when met again in this tower."""
        numerator, denominator = value.lowest()
        if denominator.leading_coefficient() < 0:
            numerator, denominator = -numerator, -denominator
        (above, a), (below, q) = self.written(numerator), self.written(denominator)
        expr = _keep_coeff(above / below, product(a, 1 / q))
        if remember:
            self._memo[expr] = value
        return expr

    def written(self, poly: flint.fmpq_mpoly) -> tuple[sympy.Rational, sympy.Expr]:
        """``(k, p)`` with ``poly = k * p``, ``p`` with coprime integer coefficients and the roots'
        coefficients apart: ``(c + 1)*sqrt(5 - 4*c) + 3*c``, each root written once a product."""
        for known, found in self._written:  # a dyad's denominator is both coordinates' in both modes
            if known == poly:
                return found
        found = self._write(poly)
        self._written.append((poly, found))
        return found

    def _write(self, poly: flint.fmpq_mpoly) -> tuple[sympy.Rational, sympy.Expr]:
        terms = poly.to_dict()
        if not terms:
            return sympy.Integer(1), sympy.Integer(0)
        common = content(terms.values())
        split = len(self.symbols)
        by_roots: dict[tuple[int, ...], dict[tuple[int, ...], flint.fmpq]] = {}
        for exponents, coefficient in terms.items():
            by_roots.setdefault(exponents[split:], {})[exponents[:split]] = coefficient / common
        return fmpq_to_rational(common), total(*[
            product(from_terms(part, self.symbols), *[r**e for r, e in zip(self.shown[split:], exponents) if e])
            for exponents, part in by_roots.items()])


class Value:
    """A fraction ``numerator / denominator`` of a tower's reduced polynomials."""

    __slots__ = ("tower", "numerator", "denominator")

    def __init__(self, tower: Tower, numerator: flint.fmpq_mpoly, denominator: flint.fmpq_mpoly) -> None:
        self.tower, self.numerator, self.denominator = tower, numerator, denominator

    def _of(self, other: "Value | int") -> "Value":
        return other if isinstance(other, Value) else Value(self.tower, self.tower.one * other, self.tower.one)

    def __add__(self, other: "Value | int") -> "Value":
        other = self._of(other)
        if self.denominator == other.denominator:
            return Value(self.tower, self.numerator + other.numerator, self.denominator)
        common = self.denominator.gcd(other.denominator)
        mine, theirs = self.denominator / common, other.denominator / common
        reduced = self.tower.reduced
        return Value(self.tower, reduced(self.numerator * theirs + other.numerator * mine),
                     reduced(mine * other.denominator))

    def __radd__(self, other: int) -> "Value":
        return self + other

    def __neg__(self) -> "Value":
        return Value(self.tower, -self.numerator, self.denominator)

    def __sub__(self, other: "Value | int") -> "Value":
        return self + -self._of(other)

    def __rsub__(self, other: int) -> "Value":
        return -self + other

    def __mul__(self, other: "Value | int") -> "Value":
        other = self._of(other)
        reduced = self.tower.reduced
        if other.denominator == self.tower.one:
            return Value(self.tower, reduced(self.numerator * other.numerator), self.denominator)
        return Value(self.tower, reduced(self.numerator * other.numerator),
                     reduced(self.denominator * other.denominator))

    __rmul__ = __mul__

    def inverse(self) -> "Value":
        return Value(self.tower, self.denominator, self.numerator)

    def __truediv__(self, other: "Value | int") -> "Value":
        return self * self._of(other).inverse()

    def lowest(self) -> tuple[flint.fmpq_mpoly, flint.fmpq_mpoly]:
        """``(numerator, denominator)`` without their common factor (as polynomials: where it is
        not zero, the same function)."""
        common = self.numerator.gcd(self.denominator)
        return self.numerator / common, self.denominator / common
