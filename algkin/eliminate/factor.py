"""Factoring an eliminant when part of its factorization is known.

The ``linear`` method multiplies equations by coefficients (its *multipliers*); the only
extraneous factors it can bring in are theirs. Those are small, so they are factored and
divided out by exact trial division, and only the cofactor is factored in full. A
multiplier's factor that divides the eliminant stays a candidate like any other: the
witnesses decide whether the motion lies on it.

The cofactor is often irreducible. Over python-flint, when it has more than two variables,
``certified_irreducible`` proves that faster than multivariate factoring does: if the
leading coefficient in some variable ``x`` is a number, no factor is free of ``x``, and a
factorization would survive substituting integers for all the other variables with the
degree in ``x`` unchanged; so an irreducible specialization proves the polynomial
irreducible. When the specializations tried factor, full factoring decides.

>>> import flint
>>> ctx = flint.fmpq_mpoly_ctx.get(("x", "y", "z"), "lex")
>>> x, y, z = ctx.gens()
>>> certified_irreducible(x**3 + y*z*x + z**2 + 1), certified_irreducible((x**2 + y)*(x + z))
(True, False)
"""

from collections.abc import Sequence

import flint

from .protocol import Backend, P

__all__ = ["factor_with", "certified_irreducible"]

SPECIALIZATIONS = ((3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47),
                   (-2, 9, -4, 6, -10, 15, -8, 21, -12, 25, -14, 27, -16, 33))


def factor_with(backend: Backend[P], poly: P, divisors: Sequence[P]) -> list[P]:
    """Irreducible factors of ``poly`` (each once), the factors of ``divisors`` that divide it first."""
    candidates: list[P] = []
    for divisor in divisors:
        for factor in backend.factors(divisor):
            factor = backend.primitive(factor)
            if factor not in candidates:
                candidates.append(factor)
    found: list[P] = []
    for factor in candidates:
        quotient = backend.quotient(poly, factor)
        if quotient is not None:
            while quotient is not None:
                poly, quotient = quotient, backend.quotient(quotient, factor)
            found.append(factor)
    return found + ([] if backend.is_constant(poly) else backend.factors(poly))


def certified_irreducible(poly: flint.fmpq_mpoly) -> bool:
    """True when the ``fmpq_mpoly`` ``poly`` is proved irreducible over QQ by specialization;
    False means not proved (it may still be irreducible)."""
    degrees = poly.degrees()
    for degree, i in sorted((d, i) for i, d in enumerate(degrees) if d > 0):
        power = tuple(degree if k == i else 0 for k in range(len(degrees)))
        lead = poly[power]  # the coefficient of x**degree: the leading one, if no other term reaches it
        if lead == 0 or (poly - poly.context().term(lead, power)).degrees()[i] == degree:
            continue
        return any(_irreducible_at(poly, i, degree, values) for values in SPECIALIZATIONS)
    return False


def _irreducible_at(poly: flint.fmpq_mpoly, i: int, degree: int, values: tuple[int, ...]) -> bool:
    """Whether ``poly`` with every variable but the ``i``-th set to ``values`` is irreducible
    (its degree in that variable cannot drop: the leading coefficient is a number)."""
    names = poly.context().names()
    cycled = values * (len(names) // len(values) + 1)
    fixed: dict[str | int, int] = {n: v for k, (n, v) in enumerate(zip(names, cycled)) if k != i}
    univariate = poly.subs(fixed)
    coefficients: list[flint.fmpq | int] = [0] * (int(degree) + 1)
    for exponents, coefficient in zip(univariate.monoms(), univariate.coeffs()):
        coefficients[exponents[i]] = coefficient
    _, factors = flint.fmpq_poly(coefficients).factor()
    return len(factors) == 1 and factors[0][1] == 1
