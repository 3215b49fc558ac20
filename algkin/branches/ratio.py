"""``tidy_ratio``'s cancellation through python-flint: the very expression ``sympy.cancel`` leads to.

``sympy.cancel`` spends most of a six-bar's closed form (a later dyad's base holds an earlier one's
square root) preparing its input (``signsimp``, ``factor_terms(radical=True)``, ``as_numer_denom``,
the expansion in ``sring``), not in its gcd. Its result depends on the input only through the
numerator and denominator ``as_numer_denom`` gives, each expanded (a root's square written as its
radicand), as polynomials with the square roots as free generators, taken to lowest terms (with
the denominator's leading coefficient positive in sympy's order of generators). ``cancelled``
computes that pair in python-flint, a root ``sqrt(b)`` a stand-in variable ``r`` reduced by
``r**2 -> b``, and returns None wherever that argument does not hold for sure: a root in a
denominator of a sum's term (the common denominator sympy picks would then matter), a root of
anything but an expanded polynomial that sympy's preparation leaves as it is, a number that is not
rational, any other function or power.
"""

import flint
import sympy
from sympy.polys.polyutils import _sort_gens
from sympy.simplify.simplify import signsimp

from ..scene.implicit.algebra import HALF, square_reduced
from ..system.convert import content, fmpq_to_rational, from_terms

__all__ = ["cancelled"]

Fraction = tuple[flint.fmpq_mpoly, flint.fmpq_mpoly]  # numerator, denominator, as as_numer_denom keeps them


class _Unsupported(Exception):
    """An expression the argument does not cover: sympy's own path then."""


def cancelled(expr: sympy.Expr) -> tuple[sympy.Rational, sympy.Expr, sympy.Expr] | None:
    """``(k, p, q)`` with ``sympy.fraction(sympy.cancel(expr))`` being ``(k1*p, k2*q)``, ``k = k1/k2``,
    ``p`` and ``q`` sums with coprime integer coefficients (their ``primitive`` parts), or ``(r, 1, 1)``
    where the ratio is a number ``r``; None where that is not sure (see the module), or where only one
    of ``p`` and ``q`` is no sum.

    >>> c, s = sympy.symbols("c s")
    >>> root = sympy.sqrt(5 - 4 * c)
    >>> cancelled((c * root - 2) / (6 * s * (root + 4)))
    (1/6, c*sqrt(5 - 4*c) - 2, s*sqrt(5 - 4*c) + 4*s)
    >>> cancelled(c / (s * root + 1) + 1) is None  # a root in a denominator of a sum's term
    True
    >>> cancelled((5 - 4 * c) / (10 - 8 * c))
    (1/2, 1, 1)
    """
    symbols = expr.free_symbols
    roots = {p for p in expr.atoms(sympy.Pow) if p.exp == HALF}
    gens = _sort_gens([*symbols, *roots])
    if not symbols or len({str(g) for g in gens}) != len(gens):  # sympy's order of two of one name: unsure
        return None
    ring = flint.fmpq_mpoly_ctx.get(tuple(f"g{k}" for k in range(len(gens))), "lex")
    walk = _Walk(dict(zip(gens, ring.gens())), ring)
    try:
        for root in roots:
            walk.add_root(root, gens)
        numerator, denominator = walk.fraction(expr)
    except _Unsupported:
        return None
    if numerator.is_zero():
        return None
    common = numerator.gcd(denominator)
    return _normalised(numerator / common, denominator / common, gens)


def _normalised(numerator: flint.fmpq_mpoly, denominator: flint.fmpq_mpoly,
                gens: list[sympy.Expr]) -> tuple[sympy.Rational, sympy.Expr, sympy.Expr] | None:
    """``(k, p, q)``: ``numerator/denominator = k*p/q``, ``p``, ``q`` primitive, ``q``'s leading
    coefficient positive (sympy's ``canonical_unit``); None unless both are sums."""
    if numerator.is_constant() and denominator.is_constant():  # sympy's cancel gives the number
        one = sympy.Integer(1)
        return fmpq_to_rational(numerator.leading_coefficient() / denominator.leading_coefficient()), one, one
    if denominator.leading_coefficient() < 0:
        numerator, denominator = -numerator, -denominator
    (kp, p), (kq, q) = (_primitive(poly) for poly in (numerator, denominator))
    if len(p) < 2 or len(q) < 2:
        return None
    return kp / kq, from_terms(p, gens), from_terms(q, gens)


def _primitive(poly: flint.fmpq_mpoly) -> tuple[sympy.Rational, dict[tuple[int, ...], int]]:
    """``(content, terms)``: ``poly = content * terms``, the terms coprime integers, the content positive."""
    terms = poly.to_dict()
    common = content(terms.values())
    return fmpq_to_rational(common), {m: int((c / common).p) for m, c in terms.items()}


class _Walk:
    """An expression's (numerator, denominator) as ``as_numer_denom`` forms them, each expanded with
    every square root's square as its radicand, as python-flint polynomials in ``variables``."""

    def __init__(self, variables: dict[sympy.Expr, flint.fmpq_mpoly], ring: flint.fmpq_mpoly_ctx) -> None:
        self.variables = variables
        self.ring = ring
        self.one = ring.from_dict({(0,) * ring.nvars(): 1})
        self.squares: list[tuple[int, flint.fmpq_mpoly]] = []  # (index of a root's stand-in, its radicand)
        self.memo: dict[sympy.Expr, Fraction] = {}

    def add_root(self, root: sympy.Pow, gens: list[sympy.Expr]) -> None:
        """Take ``root``'s stand-in's square as its radicand; _Unsupported unless sympy's preparation
        keeps the radicand as it is, an expanded polynomial sum with rational coefficients."""
        base = root.base
        if not base.is_Add or any(not p.exp.is_Integer for p in base.atoms(sympy.Pow)):
            raise _Unsupported(root)
        numerator, denominator = self.fraction(base)
        if not denominator.is_constant():
            raise _Unsupported(root)
        radicand = numerator / denominator
        if from_terms(radicand.to_dict(), gens) != base or \
                sympy.factor_terms(signsimp(root), radical=True) != root:
            raise _Unsupported(root)
        self.squares.append((list(self.variables).index(root), radicand))

    def fraction(self, node: sympy.Expr) -> Fraction:
        if node not in self.memo:
            self.memo[node] = self._fraction(node)
        return self.memo[node]

    def _fraction(self, node: sympy.Expr) -> Fraction:
        if node in self.variables:  # a symbol or a root
            return self.variables[node], self.one
        if node.is_Rational:
            return self.one * flint.fmpq(int(node.p)), self.one * flint.fmpq(int(node.q))
        if node.is_Add:
            return self._sum([self.fraction(a) for a in node.args])
        if node.is_Mul:
            parts = [self.fraction(a) for a in node.args]
            return self._product([n for n, _ in parts]), self._product([d for _, d in parts])
        if node.is_Pow and node.exp.is_Integer and node.exp != 0:
            numerator, denominator = self.fraction(node.base)
            k = int(node.exp)
            if k < 0:
                numerator, denominator, k = denominator, numerator, -k
            return self._reduced(numerator**k), self._reduced(denominator**k)
        raise _Unsupported(node)

    def _sum(self, parts: list[Fraction]) -> Fraction:
        """A sum over a common denominator: any one will do while no denominator holds a root
        (then the sum's numerator over it is the same free function)."""
        if any(self._has_root(d) for _, d in parts):
            raise _Unsupported("a root in a denominator of a sum")
        numerator, denominator = parts[0]
        for n, d in parts[1:]:
            if d == denominator:
                numerator = numerator + n
            else:
                numerator, denominator = numerator * d + n * denominator, denominator * d
        return numerator, denominator

    def _product(self, factors: list[flint.fmpq_mpoly]) -> flint.fmpq_mpoly:
        result = factors[0]
        for f in factors[1:]:
            result = self._reduced(result * f)
        return result

    def _reduced(self, poly: flint.fmpq_mpoly) -> flint.fmpq_mpoly:
        """``poly`` with each root's stand-in ``r`` of degree at most 1: ``r**2`` as its radicand."""
        for index, radicand in self.squares:
            if poly.degrees()[index] >= 2:
                poly = square_reduced(poly, index, radicand)
        return poly

    def _has_root(self, poly: flint.fmpq_mpoly) -> bool:
        degrees = poly.degrees()
        return any(degrees[index] for index, _ in self.squares)
