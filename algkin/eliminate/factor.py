"""Factoring an eliminant when part of its factorization is known, and proving it irreducible.

The ``linear`` method multiplies equations by coefficients (its *multipliers*); the only
extraneous factors it can bring in are theirs. Those are small, so they are factored and
divided out by exact trial division, and only the cofactor is factored in full.
A multiplier's factor that divides the eliminant stays a candidate like any other: the
witnesses decide whether the motion lies on it.

The cofactor is often irreducible, and ``irreducibility_proof`` proves that faster than
factoring does: if the leading coefficient in some variable ``x`` is a number, no factor is
free of ``x``, and a factorization would survive substituting integers for all the other
variables with the degree in ``x`` unchanged; so an irreducible univariate specialization
proves the polynomial irreducible. The proof (the variable, the values, the degree) is
kept: an eliminant proved irreducible needs no choice of factors at the witnesses, since
it lies in the elimination ideal and the motion lies on it. When the specializations tried
factor, full factoring decides.

>>> import flint
>>> ctx = flint.fmpq_mpoly_ctx.get(("x", "y", "z"), "lex")
>>> x, y, z = ctx.gens()
>>> print(irreducibility_proof(x**3 + y*z*x + z**2 + 1))
irreducible over QQ: its leading coefficient in z is a number, and at x = 3, y = 5 it is irreducible of degree 2 in z
>>> irreducibility_proof((x**2 + y)*(x + z)) is None
True

Where a variable is of degree 2, ``quadratic_proof`` decides at once, by the discriminant in it:

>>> print(quadratic_proof(x**2*y + x*z + y + z))
irreducible over QQ: of degree 2 in x, its coefficients in x coprime and its discriminant in x not a square
>>> quadratic_proof((x*y + z)*(x + y)) is None
True
"""

import math
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from typing import cast

import flint
from flint.utils.flint_exceptions import DomainError

from .protocol import Backend, P

__all__ = ["factor_with", "irreducibility_proof", "quadratic_proof", "univariate_irreducible", "IrreducibilityProof",
           "FACTORED"]

SPECIALIZATIONS = ((3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47),
                   (-2, 9, -4, 6, -10, 15, -8, 21, -12, 25, -14, 27, -16, 33))


@dataclass(frozen=True)
class IrreducibilityProof:
    """Why a polynomial is irreducible over QQ: its leading coefficient in ``variable`` is a
    number, and with the other variables set to ``values`` it is an irreducible univariate
    polynomial of the same ``degree`` in ``variable``; or, ``by_discriminant``, it is of degree
    2 in ``variable`` with coprime coefficients and a discriminant that is not a square
    (``quadratic_proof``); or, with no ``variable``, its full factorization has one factor."""

    variable: str | None = None
    values: tuple[tuple[str, int], ...] = ()
    degree: int = 0
    by_discriminant: bool = False

    def __str__(self) -> str:
        if self.variable is None:
            return "irreducible over QQ: factored, one factor"
        if self.by_discriminant:
            return (f"irreducible over QQ: of degree 2 in {self.variable}, its coefficients in {self.variable} "
                    f"coprime and its discriminant in {self.variable} not a square")
        at = ", ".join(f"{name} = {value}" for name, value in self.values)
        return (f"irreducible over QQ: its leading coefficient in {self.variable} is a number, and at {at} "
                f"it is irreducible of degree {self.degree} in {self.variable}")


FACTORED = IrreducibilityProof()
"""The proof of a polynomial whose factorization found it irreducible."""


def factor_with(backend: Backend[P], poly: P, divisors: Sequence[P]) -> tuple[list[P], IrreducibilityProof | None]:
    """Irreducible factors of ``poly`` (each once), the factors of ``divisors`` that divide it
    first; and the proof that the last factor (the cofactor) is irreducible, when one was found."""
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
    if backend.is_constant(poly):
        return found, None
    proof = backend.irreducibility(poly)
    if proof is not None:
        return found + [poly], proof
    factors = backend.factors(poly)
    return found + factors, FACTORED if len(factors) == 1 else None


def irreducibility_proof(poly: flint.fmpq_mpoly) -> IrreducibilityProof | None:
    """A proof that the ``fmpq_mpoly`` ``poly`` is irreducible over QQ, by specialization;
    None means not proved (it may still be irreducible).

    The argument (Hilbert's irreducibility, the easy direction): let the leading coefficient
    of ``poly`` in ``x`` be a number ``c``. A factor free of ``x`` would divide ``c``, so every
    non-trivial factorization ``poly = g*h`` has ``x`` in both ``g`` and ``h``, and their
    leading coefficients in ``x`` are numbers too (their product is ``c``). Setting every other
    variable to an integer keeps both degrees in ``x``: the univariate polynomial left factors
    as well, with both factors of positive degree. So if it is irreducible of the same degree,
    ``poly`` is. (With a leading coefficient that is not a number, a factor free of ``x`` could
    vanish nowhere at the point and go unseen: such a variable is not used.) The univariate
    polynomial is proved irreducible by ``univariate_irreducible``.
    """
    degrees = poly.degrees()
    held = [i for i, d in enumerate(degrees) if d > 0]
    if len(held) < 2:
        return None  # one variable: factoring it is the proof
    leading = _Leading(poly, sorted((int(degrees[i]), i) for i in held))
    # a specialization may factor where the polynomial does not (the seed's connector, in c at
    # integer B_y and s wherever 25/4 - (B_y - s)**2 is a square): the next variable at the same
    # values, then the next values
    for values in SPECIALIZATIONS:
        for i, degree in leading:
            proof = _irreducible_at(poly, i, degree, values)
            if proof is not None:
                return proof
    return None


def quadratic_proof(poly: flint.fmpq_mpoly) -> IrreducibilityProof | None:
    """A proof that the ``fmpq_mpoly`` ``poly`` is irreducible over QQ, by its first variable of
    degree 2; None when it has none, or is reducible.

    Write ``poly = a*x**2 + b*x + c`` with ``a``, ``b``, ``c`` free of ``x``. A factor free of
    ``x`` divides all three; a factor of degree 1 in ``x`` is ``x`` less a root, and the roots
    ``(-b +- sqrt(b**2 - 4*a*c)) / 2a`` are rational functions exactly when the discriminant
    ``b**2 - 4*a*c`` is the square of a polynomial over QQ (QQ[...] is a unique factorization
    domain). So ``poly`` is irreducible exactly when ``a``, ``b``, ``c`` are coprime and the
    discriminant is not a square: a decision, at the cost of two gcds and a square root, where
    factoring costs two or three times as much (the seed's connector: about 10 against 25 us).
    """
    degrees = poly.degrees()
    if 2 not in degrees:
        return None
    i = degrees.index(2)
    c = poly.subs({i: 0})
    slope = poly.derivative(i)  # 2*a*x + b
    b, twice_a = slope.subs({i: 0}), slope.derivative(i)
    if not twice_a.is_constant():
        common = twice_a.gcd(c)
        if not common.is_constant() and not common.gcd(b).is_constant():
            return None  # a factor free of x
    try:
        (b * b - 2 * twice_a * c).sqrt()
    except DomainError:  # not a square: no factor of degree 1 in x
        return IrreducibilityProof(poly.context().names()[i], (), 2, by_discriminant=True)
    return None


class _Leading:
    """The variables (index, degree) in which ``poly``'s leading coefficient is a number, of
    the ``candidates`` (degree, index) in order, found as they are asked for: most proofs need
    the first alone, and reading the terms (when the total degree does not settle it) costs
    as much as the proof on the symbolic four-bar's 239."""

    def __init__(self, poly: flint.fmpq_mpoly, candidates: list[tuple[int, int]]) -> None:
        self.poly, self.candidates = poly, iter(candidates)
        self.total = int(poly.total_degree())
        self.found: list[tuple[int, int]] = []
        self.monomials: list[tuple[int, ...]] | None = None

    def __iter__(self) -> Iterator[tuple[int, int]]:
        yield from self.found
        for degree, i in self.candidates:
            if self._number_leads(i, degree):
                self.found.append((i, degree))
                yield i, degree

    def _number_leads(self, i: int, degree: int) -> bool:
        """At once when the total degree is the variable's (the leading terms can then hold no
        other variable), else by reading the terms, once."""
        if degree == self.total:
            return True
        if self.monomials is None:
            self.monomials = self.poly.monoms()
        top = [m for m in self.monomials if m[i] == degree]
        return len(top) == 1 and sum(top[0]) == degree


def _irreducible_at(poly: flint.fmpq_mpoly, i: int, degree: int, values: tuple[int, ...]) -> IrreducibilityProof | None:
    """The proof if ``poly`` with every variable but the ``i``-th set to ``values`` is
    irreducible (its degree in that variable cannot drop: the leading coefficient is a number)."""
    names = poly.context().names()
    held = [k for k, d in enumerate(poly.degrees()) if d > 0 and k != i]
    fixed = {k: values[n % len(values)] for n, k in enumerate(held)}
    univariate = poly.subs(cast("dict[str | int, int]", fixed))
    coefficients = univariate.coeffs()  # highest power first: one variable is left, in lex order
    if len(coefficients) == degree + 1:
        dense: list[flint.fmpq] = coefficients[::-1]
    else:
        dense = [flint.fmpq(0)] * (degree + 1)
        for exponents, coefficient in zip(univariate.monoms(), coefficients):
            dense[exponents[i]] = coefficient
    if not univariate_irreducible(dense):
        return None
    return IrreducibilityProof(names[i], tuple((names[k], value) for k, value in fixed.items()), degree)


def univariate_irreducible(coefficients: Sequence[flint.fmpq | int]) -> bool:
    """Whether the polynomial of ``coefficients`` (lowest power first, the last non-zero) is
    irreducible over QQ: a line always; a quadratic when its discriminant is not the square of
    a rational (it factors exactly when it has a rational root, ``(-b +- sqrt(D)) / 2a``);
    beyond, when python-flint's factorization over QQ has one factor, once.

    >>> univariate_irreducible([-2, 0, 1]), univariate_irreducible([-4, 0, 1])  # x**2 - 2, x**2 - 4
    (True, False)
    >>> univariate_irreducible([1, 0, 0, 0, 1]), univariate_irreducible([4, 0, 0, 0, 1])  # x**4 + 4 factors
    (True, False)
    """
    degree = len(coefficients) - 1
    if degree == 1:
        return True
    if degree == 2:
        c, b, a = (flint.fmpq(v) for v in coefficients)
        return not _rational_square(b * b - 4 * a * c)
    _, factors = flint.fmpq_poly(list(coefficients)).factor()
    return len(factors) == 1 and factors[0][1] == 1


def _rational_square(value: flint.fmpq) -> bool:
    """Whether ``value`` is the square of a rational: numerator and denominator (coprime) squares."""
    p, q = int(value.p), int(value.q)
    return p >= 0 and math.isqrt(p) ** 2 == p and math.isqrt(q) ** 2 == q
