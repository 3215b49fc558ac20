"""A backend over a word-size prime field: the same methods, on residues.

``ModularBackend`` implements the backend protocol on python-flint's ``nmod_mpoly``: the
elimination methods run on it unchanged, with coefficients mod a prime. It is the engine of
``interpolate`` (a family's eliminant rebuilt from cheap specialisations); polynomials enter
as ``fmpq_mpoly`` reduced mod the prime (``reduce``), never through sympy. ``terms`` gives
every coefficient as a residue over 1, and ``primitive`` makes a polynomial monic (the
lex-leading coefficient 1): the normalisation a modular image is compared and
interpolated under.

>>> import flint
>>> ctx = flint.fmpq_mpoly_ctx.get(("x", "y"), "lex")
>>> x, y = ctx.gens()
>>> backend = ModularBackend(("x", "y"), 101)
>>> f, g = backend.reduce(x**2 + y**2 - 1), backend.reduce(x - y / 2)
>>> backend.resultant(f, g, "x")   # 5/4 y**2 - 1: 5/4 is 77 mod 101 (4 * 77 = 308 = 3*101 + 5)
77*y^2 + 100
>>> backend.primitive(backend.resultant(f, g, "x"))   # y**2 - 4/5: -4/5 is 80 mod 101 (5 * 80 = 400 = 4*101 - 4)
y^2 + 80
"""

from collections.abc import Mapping, Sequence

import flint
import sympy

from .backends import FlintMpolys
from .protocol import Term

__all__ = ["ModularBackend", "PRIMES", "Shape", "shape"]

Shape = tuple[tuple[int, ...], int]
"""A factor's degree in each variable and its number of terms: at generic values of the
parameters, the same for every image of one factor of the family (and as a rule different
for two factors of the same degrees)."""


def shape(poly: flint.nmod_mpoly | flint.fmpq_mpoly) -> Shape:
    """``poly``'s ``Shape``."""
    return tuple(int(d) for d in poly.degrees()), len(poly)


def _primes_below(bound: int, count: int) -> tuple[int, ...]:
    found: list[int] = []
    candidate = bound - 1
    while len(found) < count:
        if flint.fmpz(candidate).is_prime():
            found.append(candidate)
        candidate -= 2
    return tuple(found)


# below 2**31: python-flint 0.9 fails sorting the factors of an nmod_mpoly whose coefficients
# pass a C int (an OverflowError in its sort key), so larger word-size primes cannot be used
PRIMES = _primes_below(2**31, 64)
"""Primes below 2**31, largest first: one modular image each."""


class ModularBackend(FlintMpolys[flint.nmod_mpoly]):
    """python-flint ``nmod_mpoly`` over ``names``, modulo the prime ``modulus``; ``drop``: the
    shapes of factors ``factors`` leaves out (learned where witnesses chose)."""

    name = "nmod"

    def __init__(self, names: Sequence[str], modulus: int, drop: frozenset[Shape] = frozenset()) -> None:
        super().__init__(names)
        self.modulus = modulus
        self.drop = drop
        self.ctx = flint.nmod_mpoly_ctx.get(self.names, modulus=modulus, ordering="lex")

    def reduce(self, poly: flint.fmpq_mpoly) -> flint.nmod_mpoly:
        """The rational polynomial ``poly`` (same names) mod the prime; a ZeroDivisionError if
        the prime divides a denominator."""
        p = self.modulus
        return self.ctx.from_dict({m: int(c.p) * pow(int(c.q), -1, p) % p for m, c in poly.to_dict().items()})

    def from_rational(self, poly: flint.fmpq_mpoly) -> flint.nmod_mpoly:
        return self.reduce(poly)

    def from_sympy(self, expr: sympy.Expr) -> flint.nmod_mpoly:
        from ..system.convert import flint_context, to_flint  # sympy enters through convert only

        return self.reduce(to_flint(expr, flint_context(self.names)))

    def to_sympy(self, poly: flint.nmod_mpoly) -> sympy.Expr:
        raise TypeError("a modular image has no sympy form: lift it first")

    def coefficient_bits(self, poly: flint.nmod_mpoly) -> int:
        return self.modulus.bit_length()

    def factors(self, poly: flint.nmod_mpoly) -> list[flint.nmod_mpoly]:
        """Where a factor of a shape of ``drop`` (factors known not to hold the motion) may
        divide ``poly``: the irreducible factors but those, unless that leaves none. Elsewhere: the
        squarefree parts, not the irreducible factors: without witnesses the methods keep
        every factor, and their product, the radical, is the same (a third faster).
        ``irreducible`` factors in full."""
        if self._may_divide(poly):
            found = self.irreducible(poly)
            kept = [f for f in found if shape(f) not in self.drop]
            return kept or found
        _, parts = poly.factor_squarefree()
        return [f for f, _ in parts]

    def _may_divide(self, poly: flint.nmod_mpoly) -> bool:
        """False where no factor of a shape of ``drop`` divides ``poly``: none fits in its
        degrees, or those that fit hold fewer variables, and would divide ``poly``'s values at
        any values of the others, and two such values have no common factor (a gcd costs a
        fraction of factoring)."""
        held = poly.degrees()
        fitting = {tuple(n for n, d, e in zip(self.names, degrees, held) if e and not d)
                   for degrees, _ in self.drop if all(d <= e for d, e in zip(degrees, held))}
        if () in fitting:
            return True
        for others in fitting:
            # any values: such a factor divides both (keys typed as python-flint's stub wants them)
            first: dict[str | int, int] = {n: 2 + i for i, n in enumerate(others)}
            second: dict[str | int, int] = {n: 5 + 3 * i for i, n in enumerate(others)}
            common = poly.subs(first).gcd(poly.subs(second))
            if common.is_zero() or not common.is_constant():
                return True
        return False

    def irreducible(self, poly: flint.nmod_mpoly) -> list[flint.nmod_mpoly]:
        """The distinct irreducible factors of ``poly``."""
        _, factors = poly.factor()
        return [f for f, _ in factors]

    def specialize(self, poly: flint.nmod_mpoly, values: Mapping[str, flint.fmpq]) -> flint.nmod_mpoly:
        p = self.modulus
        return poly.subs({n: int(v.p) * pow(int(v.q), -1, p) % p for n, v in values.items()})

    def scale(self, poly: flint.nmod_mpoly, numerator: int, denominator: int) -> flint.nmod_mpoly:
        return poly * (numerator * pow(denominator, -1, self.modulus) % self.modulus)

    def terms(self, poly: flint.nmod_mpoly) -> list[Term]:
        return [(m, int(c), 1) for m, c in zip(poly.monoms(), poly.coeffs())]

    def divide(self, f: flint.nmod_mpoly, g: flint.nmod_mpoly) -> flint.nmod_mpoly:
        quotient, _ = divmod(f, g)
        return quotient

    def primitive(self, poly: flint.nmod_mpoly) -> flint.nmod_mpoly:
        """``poly`` made monic: its lex-leading coefficient 1."""
        if poly.is_zero():
            return poly
        return poly * pow(int(poly.coeffs()[0]), -1, self.modulus)

    def groebner_lex(self, polys: Sequence[flint.nmod_mpoly], order: Sequence[str]) -> list[flint.nmod_mpoly]:
        raise TypeError("no Gröbner bases mod a prime: the modular backend runs resultants and linear steps")
