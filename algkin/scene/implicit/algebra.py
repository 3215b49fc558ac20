"""Reduction on the inputs' unit circles: the normal form compiling and the closed forms share."""

from collections.abc import Sequence

import flint
import sympy

from ...system.convert import from_terms, to_flint

__all__ = ["Circles", "reduce_on_circles", "reduce_exact_on_circles", "square_reduced"]

HALF = sympy.Rational(1, 2)

Circles = Sequence[tuple[sympy.Symbol, sympy.Symbol]]  # each input's (cos, sin) symbols


def reduce_on_circles(expr: sympy.Expr, inputs: Circles) -> sympy.Expr:
    """Normal form of a polynomial modulo ``c**2 + s**2 - 1`` for each input (s**2 -> 1 - c**2);
    anything else expanded.

    A polynomial is reduced in python-flint (``reduce_exact_on_circles``): sympy's ``rem`` builds a
    ``Poly`` per input, most of a dyad's closed form. The result is sympy's, the same expression.

    >>> c, s, x = sympy.symbols("c s x")
    >>> reduce_on_circles((s * x + c) ** 2, [(c, s)]), reduce_on_circles(s / x, [(c, s)])
    (-c**2*x**2 + c**2 + 2*c*s*x + x**2, s/x)
    """
    if _expanded_already(expr):  # no polynomial, and what ``sympy.expand`` gives back as it is
        return expr
    reduced = _reduced_in_flint(expr, inputs)
    return reduced if reduced is not None else _reduced_in_sympy(expr, inputs)


def _expanded_already(expr: sympy.Expr) -> bool:
    """Whether ``expr`` is a sum that is no polynomial and that ``sympy.expand`` leaves as it is (a
    later dyad's closed form, reduced once, then shifted by a number): each term a number times
    powers of symbols, roots of sums of such monomials, and at most one reciprocal of one such sum,
    the number then an integer (``expand`` would move its denominator into the sum's).

    >>> c, s = sympy.symbols("c s")
    >>> root = sympy.sqrt(5 - 4 * c)
    >>> _expanded_already(3 * c**2 / (8 * c - 17) + s * root / 2 - 1)
    True
    >>> half = c / 2 / (8 * c - 17)
    >>> _expanded_already(half + s), sympy.expand(half + s)
    (False, c/(16*c - 34) + s)
    """
    if not expr.is_Add:
        return False
    polynomial = True
    for term in expr.args:
        coefficient, factors = term.as_coeff_mul()
        roots = [f for f in factors if f.is_Pow and f.exp == HALF and _monomial_sum(f.base)]
        reciprocals = [f for f in factors if f.is_Pow and f.exp == -1 and _monomial_sum(f.base)]
        if len(roots) + len(reciprocals) + sum(1 for f in factors if _monomial(f)) != len(factors):
            return False
        if not coefficient.is_Rational or len(reciprocals) > 1 or (reciprocals and not coefficient.is_Integer):
            return False
        polynomial = polynomial and not roots and not reciprocals
    return not polynomial


def _monomial(factor: sympy.Expr) -> bool:
    """A symbol or its positive integer power."""
    return bool(factor.is_Symbol or (factor.is_Pow and factor.base.is_Symbol and factor.exp.is_Integer
                                     and factor.exp > 0))


def _monomial_sum(expr: sympy.Expr) -> bool:
    """A sum of rational multiples of products of ``_monomial`` factors (what ``expand`` gives back)."""
    return bool(expr.is_Add) and all(
        k.is_Rational and all(_monomial(f) for f in rest) for k, rest in (t.as_coeff_mul() for t in expr.args))


def _reduced_in_sympy(expr: sympy.Expr, inputs: Circles) -> sympy.Expr:
    expr = sympy.expand(expr)
    if not expr.is_polynomial():
        return expr
    for c, s in inputs:
        expr = sympy.expand(sympy.rem(expr, s**2 + c**2 - 1, s)) if expr.has(s) else expr
    return expr


def _reduced_in_flint(expr: sympy.Expr, inputs: Circles) -> sympy.Expr | None:
    """``reduce_on_circles`` of a polynomial with rational coefficients, through python-flint; None
    for anything else (a root, a quotient by a polynomial, two symbols of one name: a ``Dummy`` and a
    ``Symbol``, or a real symbol and a plain one)."""
    if any(not p.exp.is_Integer for p in expr.atoms(sympy.Pow)):  # a root: ``to_flint`` would refuse it, after
        return None  # evaluating the rest (most of a later dyad's closed form, in vain)
    every = expr.free_symbols | {v for circle in inputs for v in circle}
    symbols = {v.name: v for v in every}  # the names python-flint's ring and ``to_flint`` know them by
    if len(symbols) != len(every):
        return None
    names = sorted(symbols)
    ring = flint.fmpq_mpoly_ctx.get(tuple(names), "lex")
    try:
        poly = to_flint(expr, ring)
    except TypeError:  # a root, an absolute value, a quotient that is not exact
        return None
    reduced = reduce_exact_on_circles(poly, inputs)
    if reduced is None:
        return None
    return from_terms(reduced.to_dict(), [symbols[n] for n in names])


def reduce_exact_on_circles(poly: flint.fmpq_mpoly, inputs: Circles) -> flint.fmpq_mpoly | None:
    """``reduce_on_circles`` on a python-flint polynomial, in its own ring: each ``s**k`` as
    ``s**(k % 2) * (1 - c**2)**(k // 2)``, the remainder by ``s**2 + c**2 - 1`` in ``s``. None
    where an input's sine is in the ring but not its cosine (sympy's reduction then).

    >>> ring = flint.fmpq_mpoly_ctx.get(("c", "s", "x"), "lex")
    >>> c, s, x = ring.gens()
    >>> reduce_exact_on_circles(s**3 * x + c * s**2 - 1, [sympy.symbols("c s")])
    -c^3 - c^2*s*x + c + s*x - 1
    """
    ring = poly.context()
    names = [str(n) for n in ring.names()]
    for c, s in inputs:
        if str(s) not in names:
            continue
        if str(c) not in names:
            return None
        poly = square_reduced(poly, names.index(str(s)), 1 - ring.gens()[names.index(str(c))] ** 2)
    return poly


def square_reduced(poly: flint.fmpq_mpoly, at: int, square: flint.fmpq_mpoly) -> flint.fmpq_mpoly:
    """``poly`` with its variable number ``at`` (``v``) of degree at most 1, ``v**2`` taken as
    ``square``: each ``v**k`` as ``v**(k % 2) * square**(k // 2)``.

    >>> ring = flint.fmpq_mpoly_ctx.get(("r", "x"), "lex")
    >>> r, x = ring.gens()
    >>> square_reduced(r**3 + r**2 * x, 0, x + 1)
    r*x + r + x^2 + x
    """
    ring = poly.context()
    name, v = ring.names()[at], ring.gens()[at]
    even, odd = ring.from_dict({}), ring.from_dict({})
    power = ring.from_dict({(0,) * ring.nvars(): 1})
    coefficients = _coefficients_in(poly, at, name)
    for k in range(0, len(coefficients), 2):  # c_k v**k + c_(k+1) v**(k+1) as (c_k + c_(k+1) v) square**(k/2)
        even += coefficients[k] * power
        if k + 1 < len(coefficients):
            odd += coefficients[k + 1] * power
        power *= square
    return even + v * odd


def _coefficients_in(poly: flint.fmpq_mpoly, at: int, name: str) -> list[flint.fmpq_mpoly]:
    """``poly``'s coefficients in its variable number ``at``, lowest power first: Taylor's, a few
    calls into python-flint (splitting its terms in Python cost three times as much)."""
    coefficients, factorial = [], 1
    for k in range(max(poly.degrees()[at], 0) + 1):
        coefficients.append(poly.subs({name: 0}) / factorial)
        poly = poly.derivative(at)
        factorial *= k + 1
    return coefficients
