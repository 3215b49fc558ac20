"""The one crossing between sympy and python-flint: convert in, compute, convert out.

>>> import sympy
>>> x, y = sympy.symbols("x y")
>>> ctx = flint_context(["x", "y"])
>>> p = to_flint(x**2 - y/3, ctx)
>>> p
x^2 - 1/3*y
>>> to_sympy(p * p, ctx)
x**4 - 2*x**2*y/3 + y**2/9
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping, Sequence
from typing import NoReturn

import flint
import sympy
from flint.utils.flint_exceptions import DomainError
from sympy.core.add import _addsort
from sympy.core.mul import _mulsort

from ..evaluate import NumberKind, evaluate
from .core import symbol

__all__ = ["flint_context", "to_flint", "rational_polynomial", "expanded", "coefficients", "from_terms", "to_sympy", "sympy_text", "to_flint_integer", "integer_factors", "factored_over_rationals", "fmpq_to_rational", "univariate", "content"]


def flint_context(names: Iterable[str], ordering: str = "lex") -> flint.fmpq_mpoly_ctx:
    """A python-flint rational polynomial context over ``names`` (order matters for lex)."""
    return flint.fmpq_mpoly_ctx.get(tuple(names), ordering)


def to_flint(expr: sympy.Expr | sympy.Poly, ctx: flint.fmpq_mpoly_ctx) -> flint.fmpq_mpoly:
    """A sympy polynomial (expression or Poly) as an ``fmpq_mpoly`` in ``ctx``; TypeError where
    ``expr`` is none (a root, an absolute value, a quotient by a polynomial).

    The expression tree is evaluated with flint's own arithmetic (``evaluate``): building a
    sympy ``Poly`` first costs milliseconds on a dozen generators, more than most
    eliminations.

    >>> x = sympy.Symbol("x")
    >>> to_flint(1 / x, flint_context(["x"]))
    Traceback (most recent call last):
    ...
    TypeError: not a polynomial: 1/x
    """
    zero = ctx.from_dict({})
    kind = NumberKind("flint polynomial", number=lambda p, q: zero + flint.fmpq(p, q),
                      sqrt=lambda v: _not_polynomial(f"sqrt({v})"), absolute=lambda v: _not_polynomial(f"Abs({v})"))
    expr = expr.as_expr() if isinstance(expr, sympy.Poly) else expr
    try:
        return evaluate(expr, dict(zip((str(n) for n in ctx.names()), ctx.gens())), kind)
    except DomainError:  # python-flint's quotient that is not exact
        _not_polynomial(str(expr))


def rational_polynomial(expr: sympy.Expr) -> bool:
    """Whether ``expr``, as written, is a polynomial with rational coefficients (python-flint takes
    it: no ``sympy.Poly`` and its domain built to ask).

    >>> x = symbol("x")
    >>> rational_polynomial(x**2 / 3 - 1), rational_polynomial(sympy.sqrt(2) * x), rational_polynomial(x / 2.5)
    (True, False, False)
    """
    try:
        to_flint(expr, flint_context(sorted({v.name for v in expr.free_symbols}) or ["_"]))
    except TypeError:  # a root, a float, a quotient, an unknown function
        return False
    return True


def expanded(expr: sympy.Expr) -> sympy.Expr:
    """``sympy.expand(expr)``, the same expression: through python-flint where ``expr`` is a
    polynomial with rational coefficients (``from_terms`` writes sympy's canonical sum of its terms,
    without sympy's expansion, a few hundred microseconds a small equation in a cold process);
    sympy's own elsewhere (a root, a float, two symbols of one name).

    >>> x, y = symbol("x"), symbol("y")
    >>> expanded((x - y / 2) ** 2 - 1), expanded(sympy.sqrt(2) * (x + 1)), expanded((x**2 - 1) / (x - 1))
    (x**2 - x*y + y**2/4 - 1, sqrt(2)*x + sqrt(2), x**2/(x - 1) - 1/(x - 1))
    """
    if expr.is_Rational:
        return expr
    symbols = sorted(expr.free_symbols, key=lambda v: v.name)
    names = [v.name for v in symbols]
    # a quotient by a polynomial stays one in sympy's expansion, even where python-flint divides exactly
    if len(set(names)) != len(names) or any(p.exp.is_negative for p in expr.atoms(sympy.Pow)):
        return sympy.expand(expr)
    try:
        poly = to_flint(expr, flint_context(names or ["_"]))
    except TypeError:  # a root, a float, a quotient: not a polynomial over the rationals
        return sympy.expand(expr)
    return from_terms(poly.to_dict(), symbols)


def coefficients(expr: sympy.Expr, gens: Sequence[sympy.Symbol]) -> dict[tuple[int, ...], sympy.Expr]:
    """``expr`` as a polynomial in ``gens``, its coefficients polynomials with rational coefficients
    in its other symbols: {exponents of ``gens``: coefficient}, the terms of ``sympy.Poly(expr,
    *gens)`` (the same expressions) through python-flint, without sympy's domain construction.
    TypeError where ``expr`` is none, or has two symbols of one name.

    >>> x, y, a = sympy.symbols("x y a")
    >>> coefficients((a * x + y) ** 2 - x / 2, [x, y])
    {(2, 0): a**2, (1, 1): 2*a, (1, 0): -1/2, (0, 2): 1}
    """
    others = sorted(expr.free_symbols - set(gens), key=lambda v: v.name)
    names = [v.name for v in [*gens, *others]]
    if len(set(names)) != len(names):
        raise TypeError(f"two symbols of one name in {expr}")
    split: dict[tuple[int, ...], dict[tuple[int, ...], flint.fmpq]] = {}
    for exponents, coefficient in to_flint(expr, flint_context(names)).to_dict().items():
        split.setdefault(exponents[:len(gens)], {})[exponents[len(gens):]] = coefficient
    return {exponents: from_terms(terms, others) for exponents, terms in split.items()}


def from_terms(terms: Mapping[tuple[int, ...], flint.fmpq | flint.fmpz | int], gens: Sequence[sympy.Symbol]) -> sympy.Expr:
    """The sum of ``terms`` ({exponents of ``gens``: rational coefficient}) as a sympy expression:
    what ``sympy.Poly.from_dict(terms, *gens).as_expr()`` gives (the same expression), without a Poly.

    >>> x, y = sympy.symbols("x y")
    >>> from_terms({(2, 0): flint.fmpq(1, 2), (0, 1): -3}, [x, y])
    x**2/2 - 3*y
    """
    # Built in sympy's canonical form directly (its constructors' sorting, no flattening and no
    # questions asked of the terms): a curve's sum of hundreds of terms costs a tenth as much.
    constant, products = None, []
    for exponents, coefficient in terms.items():
        if not coefficient:
            continue
        rational = fmpq_to_rational(coefficient)
        powers = [g if e == 1 else sympy.Pow(g, sympy.Integer(e), evaluate=False)
                  for g, e in zip(gens, exponents) if e]
        if not powers:
            constant = rational
            continue
        _mulsort(powers)
        factors = powers if rational == 1 else [rational, *powers]
        products.append(factors[0] if len(factors) == 1 else sympy.Mul._from_args(factors, is_commutative=True))
    _addsort(products)
    summands = products if constant is None else [constant, *products]
    if len(summands) <= 1:
        return summands[0] if summands else sympy.S.Zero
    return sympy.Add._from_args(summands, is_commutative=True)


def _not_polynomial(value: str) -> NoReturn:
    raise TypeError(f"not a polynomial: {value}")


def to_flint_integer(poly: flint.fmpq_mpoly, ctx: flint.fmpz_mpoly_ctx) -> flint.fmpz_mpoly:
    """An ``fmpq_mpoly`` with denominators cleared, as an ``fmpz_mpoly`` in ``ctx``."""
    terms = poly.to_dict()
    if not terms:
        return ctx.from_dict({})
    lcm = math.lcm(*(int(c.q) for c in terms.values()))
    return ctx.from_dict({m: int(c.p) * (lcm // int(c.q)) for m, c in terms.items()})


def integer_factors(poly: flint.fmpz_mpoly) -> list[tuple[flint.fmpz_mpoly, int]]:
    """``poly.factor()[1]``: its irreducible factors, primitive with a positive leading coefficient, and
    their multiplicities, in python-flint's order. python-flint 0.9 orders two factors whose terms tie
    up to a coefficient by converting the coefficients to C ints: past 2**31 it raises OverflowError
    (dimensions of a dozen digits reach that). The factors are then FLINT's over the rationals, made
    integral again and put in the order python-flint means.

    >>> ctx = flint.fmpz_mpoly_ctx.get(("t",), "lex")
    >>> t, = ctx.gens()
    >>> integer_factors((t + 2**40) * (3 - t) ** 2 * (t + 3))
    [(t + 3, 1), (t + 1099511627776, 1), (t - 3, 2)]
    """
    try:
        return list(poly.factor()[1])
    except OverflowError:
        return factored_over_rationals(poly)


def factored_over_rationals(poly: flint.fmpz_mpoly) -> list[tuple[flint.fmpz_mpoly, int]]:
    """``integer_factors`` from FLINT's factoring over the rationals, in python-flint's order: by
    multiplicity, then term by term by exponents and coefficient, then the shorter first."""
    ctx = poly.context()
    rational = flint_context(ctx.names(), ctx.ordering().name).from_dict(poly.to_dict())
    factors = [(_primitive(factor, ctx), int(multiplicity)) for factor, multiplicity in rational.factor()[1]]
    return sorted(factors, key=lambda pair: (pair[1], [(m, int(c)) for m, c in zip(pair[0].monoms(), pair[0].coeffs())]))


def _primitive(factor: flint.fmpq_mpoly, ctx: flint.fmpz_mpoly_ctx) -> flint.fmpz_mpoly:
    """``factor``'s integral primitive multiple in ``ctx`` with a positive leading coefficient."""
    integral = to_flint_integer(factor, ctx)
    primitive = integral / math.gcd(*(int(c) for c in integral.coeffs()))
    return -primitive if primitive.leading_coefficient() < 0 else primitive


def content(coefficients: Iterable[flint.fmpq | flint.fmpz | int]) -> flint.fmpq:
    """The positive rational whose quotients with ``coefficients`` are coprime integers (1 where all
    are 0). FLINT keeps them, as one univariate polynomial, as integers over their common denominator,
    whose content is the numerators' gcd: in C, a fraction of Python's lcm and gcd of each.

    >>> content([flint.fmpq(-3, 4), flint.fmpq(-9, 2), 0])
    3/4
    """
    numbers = flint.fmpq_poly(list(coefficients))
    if numbers.is_zero():
        return flint.fmpq(1)
    return flint.fmpq(numbers.numer().content(), numbers.denom())


def fmpq_to_rational(value: flint.fmpq | flint.fmpz | int) -> sympy.Rational:
    """A python-flint rational (or integer) as a sympy Rational."""
    value = flint.fmpq(value)
    return sympy.Rational(int(value.p), int(value.q))


def to_sympy(poly: flint.fmpq_mpoly | flint.fmpz_mpoly,
             ctx: flint.fmpq_mpoly_ctx | flint.fmpz_mpoly_ctx) -> sympy.Expr:
    """An ``fmpq_mpoly`` or ``fmpz_mpoly`` of ``ctx`` as a sympy expression."""
    return from_terms(poly.to_dict(), [symbol(str(n)) for n in ctx.names()])


def sympy_text(poly: flint.fmpq_mpoly | flint.fmpz_mpoly, ctx: flint.fmpq_mpoly_ctx | flint.fmpz_mpoly_ctx) -> str:
    """``str(to_sympy(poly, ctx))``, written directly: sympy's terms in lex order of its sorted symbols,
    each a product its rational coefficient's numerator begins and its denominator ends (``2*x**2*y/3``),
    without building and printing the expression, a few milliseconds on a sextic. Where the ring is lex
    in sympy's order and the coefficients integers, FLINT's own text is sympy's (but its ``^``), but
    for sympy's one exception of two terms.

    >>> ctx = flint_context(["y", "x"])
    >>> y, x = ctx.gens()
    >>> sympy_text(3*x**2*y - x*y**3 + 5 - y, ctx), str(to_sympy(3*x**2*y - x*y**3 + 5 - y, ctx))
    ('3*x**2*y - x*y**3 - y + 5', '3*x**2*y - x*y**3 - y + 5')
    >>> sympy_text(x**2/3 - 2*x*y/5 - flint.fmpq(1, 2), ctx)
    'x**2/3 - 2*x*y/5 - 1/2'
    """
    names = [str(n) for n in ctx.names()]
    order = sorted(range(len(names)), key=lambda k: symbol(names[k]).sort_key())  # sympy's order of symbols
    if order == sorted(order) and ctx.ordering() == flint.Ordering.lex and len(poly) != 2:
        written = str(poly)  # FLINT's terms in sympy's order: in C, a tenth of the time of the loop below
        if "/" not in written:  # integer coefficients, written as sympy writes them (but powers, ^)
            return written.replace("^", "**")
    terms = poly.to_dict()
    if not terms:
        return "0"
    ordered = sorted(((tuple(int(m[k]) for k in order), flint.fmpq(c)) for m, c in terms.items()),
                     key=lambda term: term[0], reverse=True)
    if len(ordered) == 2 and not any(ordered[1][0]) and ordered[1][1] > 0 and ordered[0][1] < 0 \
            and sum(1 for e in ordered[0][0] if e) == 1:
        ordered.reverse()  # sympy's one exception: ``1 - 2*x``, a positive number before a negative multiple
    text: list[str] = []
    for exponents, coefficient in ordered:
        factors = [names[k] if e == 1 else f"{names[k]}**{e}" for k, e in zip(order, exponents) if e]
        numerator, denominator = abs(int(coefficient.p)), int(coefficient.q)
        term = "*".join(([str(numerator)] if numerator != 1 or not factors else []) + factors)
        term += f"/{denominator}" if denominator != 1 else ""
        sign = "-" if coefficient < 0 else "+"
        text.append((" - " if sign == "-" else " + ") + term if text else ("-" if sign == "-" else "") + term)
    return "".join(text)


def univariate(expr: sympy.Expr, var: sympy.Symbol) -> flint.fmpq_poly:
    """A sympy polynomial in ``var`` alone, with rational coefficients, as an ``fmpq_poly``.

    >>> t = sympy.Symbol("t")
    >>> univariate(t**2 / 2 - 3, t)
    1/2*x^2 + (-3)
    """
    coefficients = sympy.Poly(expr, var).all_coeffs()
    return flint.fmpq_poly([_fmpq(sympy.Rational(a)) for a in reversed(coefficients)])


def _fmpq(value: sympy.Rational) -> flint.fmpq:
    return flint.fmpq(int(value.p), int(value.q))
