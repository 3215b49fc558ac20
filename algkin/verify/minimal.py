"""Is an eliminant no larger than the motion it describes?

Vanishing on every true configuration does not make an eliminant right: a product with a
leftover extraneous factor (one the elimination brought in and the factor selection kept)
vanishes there too, and so does a square of a true factor. So each kept factor must vanish
*by itself* on some true configuration (the certified roots of the original system, found
without the eliminant), the kept factors must multiply to the reported polynomial, and that
polynomial must be squarefree (both decided exactly, in python-flint). Nothing from the
elimination is reused.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Mapping, Sequence

import flint
import sympy

from ..runtime.cache import BoundedCache
from ..system.convert import flint_context, to_sympy
from .residual import Polynomial, PolynomialLike, exact

__all__ = ["FactorCheck", "structure_failures"]


class FactorCheck:
    """The smallest residual of each kept factor over the certified roots seen so far.

    A factor of the true motion vanishes on the configurations of its component; one that
    vanishes on none of them was brought in by the elimination and should have been dropped.
    ``make`` turns a factor into its ``Polynomial``, unless one of ``known`` is the same.
    """

    def __init__(self, factors: Mapping[str, Sequence[PolynomialLike]] | None,
                 make: Callable[[PolynomialLike], Polynomial], known: Iterable[Polynomial] = ()) -> None:
        def polynomial(factor: PolynomialLike) -> Polynomial:
            same = [p for p in known if p.exact.context() == exact(factor).context() and p.exact == exact(factor)]
            return same[0] if same else make(factor)
        self.factors = {name: [(f, polynomial(f)) for f in fs] for name, fs in (factors or {}).items()}
        self.smallest = {name: [math.inf] * len(fs) for name, fs in self.factors.items()}

    def polynomials(self) -> list[Polynomial]:
        """The kept factors' ``Polynomial``s, each factor's, in order (the same one may come twice)."""
        return [polynomial for pairs in self.factors.values() for _, polynomial in pairs]

    def see(self, residual_of: Mapping[int, float]) -> None:
        """Take one certified root into account; ``residual_of[id(polynomial)]`` is its residual there."""
        for name, pairs in self.factors.items():
            best = self.smallest[name]
            for k, (_, polynomial) in enumerate(pairs):
                best[k] = min(best[k], residual_of[id(polynomial)])

    def failures(self, tolerance: float, evaluated: int) -> list[str]:
        """One message per kept factor that vanished on no certified root."""
        return [f"factor {_shown(factor)} of {name} vanishes on none of the {evaluated} numeric solutions "
                f"(smallest relative residual {best:.3g}): extraneous"
                for name, pairs in self.factors.items()
                for (factor, _), best in zip(pairs, self.smallest[name]) if not best <= tolerance]

    def to_json(self) -> dict[str, list[float]]:
        """Per polynomial, each kept factor's smallest residual (0 up to working precision if true)."""
        return {name: [float(v) for v in values] for name, values in self.smallest.items()}


def structure_failures(polynomials: Mapping[str, PolynomialLike],
                       factors: Mapping[str, Sequence[PolynomialLike]] | None) -> list[str]:
    """Messages for every polynomial that is not squarefree, or is not the product of its
    kept factors (when they are given). Exact and deterministic: an answer is kept for the
    same polynomials checked again."""
    failures: list[str] = []
    for name, p in polynomials.items():
        kept = (factors or {}).get(name)
        failures += _structure(name, _Keyed(p), None if kept is None else tuple(map(_Keyed, kept)))
    return failures


class _Keyed:
    """A polynomial (flint or sympy) compared and hashed by its variables and printed terms."""

    def __init__(self, polynomial: PolynomialLike) -> None:
        self.polynomial = polynomial
        names = polynomial.context().names() if hasattr(polynomial, "context") else ()
        self.key = (type(polynomial).__name__, tuple(map(str, names)), str(polynomial))

    def __eq__(self, other: object) -> bool:
        return isinstance(other, _Keyed) and self.key == other.key

    def __hash__(self) -> int:
        return hash(self.key)


def _structure(name: str, polynomial: _Keyed, factors: tuple[_Keyed, ...] | None) -> tuple[str, ...]:
    """What is wrong with the polynomial's structure (squarefree, the product of its factors),
    found once for the same polynomial and factors (``STRUCTURES``)."""
    return STRUCTURES.get((name, polynomial, factors), lambda: _structure_failures(name, polynomial, factors))


def _structure_failures(name: str, polynomial: _Keyed, factors: tuple[_Keyed, ...] | None) -> tuple[str, ...]:
    failures = [_not_squarefree(name, polynomial.polynomial)]
    if factors is not None:
        failures.append(_not_product(name, polynomial.polynomial, [f.polynomial for f in factors]))
    return tuple(f for f in failures if f)


STRUCTURES: BoundedCache[tuple[str, ...]] = BoundedCache(256, name="eliminants' structure checks")


def _shown(polynomial: PolynomialLike) -> sympy.Expr:
    """A polynomial as the user reads it (a sympy expression), only for a message."""
    if isinstance(polynomial, sympy.Basic):
        return polynomial
    return to_sympy(polynomial, polynomial.context())


def _not_squarefree(name: str, polynomial: PolynomialLike) -> str | None:
    """A repeated factor names itself: it adds degree and no points."""
    poly = exact(polynomial)
    _, parts = poly.factor_squarefree()
    repeated = [(_primitive(to_sympy(f, poly.context())), m) for f, m in parts if m > 1]
    if not repeated:
        return None
    return f"{name} is not squarefree: " + ", ".join(f"({f})**{m}" for f, m in repeated) + " divides it"


def _primitive(expr: sympy.Expr) -> sympy.Expr:
    """``expr`` with integer coefficients of gcd 1 and a positive leading one (flint's factors are monic)."""
    gens = sorted(expr.free_symbols, key=str)
    _, primitive = sympy.Poly(expr, *gens).clear_denoms()
    primitive = primitive.primitive()[1]
    return (primitive if primitive.LC() > 0 else -primitive).as_expr()


def _not_product(name: str, polynomial: PolynomialLike, factors: Sequence[PolynomialLike]) -> str | None:
    """The factors checked one by one must be the polynomial reported, up to a constant."""
    target = exact(polynomial)
    if len(factors) == 1 and _same(exact(factors[0]), target) and not target.is_zero():
        return None  # one kept factor, the polynomial itself (a sweep's irreducible curve): their product is it
    ctx = _common_context(target, *map(exact, factors))
    target = _into(target, ctx)
    product = ctx.from_dict({(0,) * len(ctx.names()): 1})
    for factor in factors:
        product *= _into(exact(factor), ctx)
    if not product.is_zero() and not target.is_zero():
        quotient, remainder = divmod(target, product)
        if remainder.is_zero() and quotient.is_constant():
            return None
    ratio = sympy.cancel(_shown(polynomial) / sympy.Mul(*map(_shown, factors)))
    return f"the kept factors of {name} do not multiply to it (quotient {ratio})"


def _same(first: flint.fmpq_mpoly | flint.fmpz_mpoly, second: flint.fmpq_mpoly | flint.fmpz_mpoly) -> bool:
    """The same polynomial in the same variables."""
    return type(first) is type(second) and first.context() == second.context() and first == second


def _common_context(*polys: flint.fmpq_mpoly | flint.fmpz_mpoly) -> flint.fmpq_mpoly_ctx:
    names = sorted({str(n) for p in polys for n, d in zip(p.context().names(), p.degrees()) if d}) or ["_"]
    return flint_context(names)


def _into(poly: flint.fmpq_mpoly | flint.fmpz_mpoly, ctx: flint.fmpq_mpoly_ctx) -> flint.fmpq_mpoly:
    """``poly`` (in its own context) in ``ctx``, which has every variable it uses."""
    names = [str(n) for n in ctx.names()]
    where = [names.index(str(n)) if d else None for n, d in zip(poly.context().names(), poly.degrees())]
    terms = {}
    for monomial, c in poly.to_dict().items():
        moved = [0] * len(names)
        for k, e in zip(where, monomial):
            if k is not None:
                moved[k] = int(e)
        terms[tuple(moved)] = c
    return ctx.from_dict(terms)
