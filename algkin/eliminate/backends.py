"""Polynomial arithmetic backends: python-flint (default, fast) and sympy (the seeds' tool).

Both expose the same small set of operations on opaque polynomial objects, so every
elimination method runs on either. Polynomials enter as python-flint polynomials over any
names (``from_flint``: a compiled system's, ``System.polynomials``) or as sympy
expressions, and leave as sympy expressions, through ``algkin.system.convert``.
"""

import functools
from collections.abc import Mapping, Sequence, Set as AbstractSet
from typing import Generic, Protocol, TypeVar, cast

import flint
import sympy

from ..errors import ComputationError
from ..system import symbol
from .factor import IrreducibilityProof, irreducibility_proof, quadratic_proof
from .protocol import BackendFactory, Term
from ..system.convert import content, flint_context, to_flint, to_flint_integer, to_sympy

__all__ = ["FlintBackend", "FlintMpolys", "SympyBackend", "BACKENDS"]

M = TypeVar("M", flint.fmpq_mpoly, flint.nmod_mpoly)
MEMO = 256  # polynomials whose degrees a backend keeps (``FlintMpolys._reading``)  # the polynomials of a python-flint backend
_M_co = TypeVar("_M_co", covariant=True)


class _Context(Protocol[_M_co]):
    """What the shared operations ask of a python-flint polynomial context."""

    def gens(self) -> tuple[_M_co, ...]: ...
    def from_dict(self, d: Mapping[tuple[int, ...], int], /) -> _M_co: ...


class FlintMpolys(Generic[M]):
    """What python-flint's multivariate polynomials answer alike over the rationals
    (``fmpq_mpoly``) and modulo a prime (``nmod_mpoly``): the two backends share these, each
    adding what its coefficients decide (conversion, factoring, scaling, normalisation).
    ``self.ctx`` is the subclass's polynomial context over ``names``."""

    ctx: _Context[M]

    def __init__(self, names: Sequence[str]) -> None:
        self.names = tuple(names)
        self.index = {n: i for i, n in enumerate(self.names)}
        self.rational = flint_context(self.names)  # where ``from_flint`` projects to
        self._read: dict[int, tuple[M, tuple[int, ...], frozenset[str]]] = {}
        self._sources: dict[int, tuple[flint.fmpq_mpoly_ctx, tuple[flint.fmpq_mpoly, ...] | None]] = {}

    def _reading(self, poly: M) -> tuple[M, tuple[int, ...], frozenset[str]]:
        """``poly``, its degree in each variable and the variables it holds, read once per
        polynomial: python-flint builds the tuple of degrees anew at each call (1 us), and the
        methods ask dozens of times of the same few polynomials (the lambda's coupler: 110
        times of a dozen). Kept by identity, the polynomial held with them (python-flint's
        polynomials are never changed in place), at most ``MEMO`` of them, until ``forget``."""
        known = self._read.get(id(poly))
        if known is None or known[0] is not poly:
            if len(self._read) >= MEMO:
                self._read.clear()
            degrees = tuple(map(int, poly.degrees()))  # fmpz: Python ints compare faster
            held = frozenset(n for n, d in zip(self.names, degrees) if d > 0)
            known = self._read[id(poly)] = (poly, degrees, held)
        return known

    def forget(self) -> None:
        """Let go of the polynomials ``_reading`` holds (an elimination is over)."""
        self._read.clear()

    def variables(self, poly: M) -> AbstractSet[str]:
        known = self._read.get(id(poly))  # ``_reading``'s memo first: a call less where it holds (most asks)
        return (known if known is not None and known[0] is poly else self._reading(poly))[2]

    def from_flint(self, poly: flint.fmpq_mpoly) -> M:
        """``poly`` (over any names) in this backend's ring, its variables matched by name."""
        source = poly.context()
        if source is not self.rational:
            images = self._images(source)
            if images is None:  # the source ring has names this one lacks: refused if the polynomial holds one
                _refuse_strays(self.names, poly)
                poly = poly.project_to_context(self.rational)
            else:
                poly = poly.compose(*images, ctx=self.rational)
        return self.from_rational(poly)

    def _images(self, source: flint.fmpq_mpoly_ctx) -> tuple[flint.fmpq_mpoly, ...] | None:
        """The generators of this ring that ``source``'s go to, when all its names are here
        (a compiled system's ring, for each of its equations: the names compared once, not the
        degrees of every equation); None otherwise."""
        known = self._sources.get(id(source))
        if known is None or known[0] is not source:
            names = source.names()
            gens = self.rational.gens()
            images = tuple(gens[self.index[n]] for n in names) if set(names) <= self.index.keys() else None
            known = self._sources[id(source)] = (source, images)
        return known[1]

    def from_rational(self, poly: flint.fmpq_mpoly) -> M:
        """An ``fmpq_mpoly`` over ``names`` as this backend's polynomial."""
        raise NotImplementedError

    def irreducibility(self, poly: M) -> IrreducibilityProof | None:
        """A proof that ``poly`` is irreducible, found more cheaply than factoring; None if not found."""
        return None

    def degree(self, poly: M, var: str) -> int:
        known = self._read.get(id(poly))  # as ``variables``
        return (known if known is not None and known[0] is poly else self._reading(poly))[1][self.index[var]]

    def is_constant(self, poly: M) -> bool:
        # flint's is_constant scans every term for the total degree; a constant has one term, of
        # total degree 0 (the zero polynomial's is -1)
        return len(poly) <= 1 and poly.total_degree() == 0

    def total_degree(self, poly: M) -> int:
        return int(poly.total_degree())

    def nterms(self, poly: M) -> int:
        return len(poly)

    def is_zero(self, poly: M) -> bool:
        return bool(poly.is_zero())

    def resultant(self, f: M, g: M, var: str) -> M:
        # nmod_mpoly's stub takes Self from typing, which is Any on Python 3.10: the type said here
        resultant: M = f.resultant(g, var)
        return resultant

    def gcd(self, f: M, g: M) -> M:
        return f.gcd(g)

    def derivative(self, poly: M, var: str) -> M:
        return poly.derivative(self.index[var])  # by index: python-flint looks a name up in Python

    def scale(self, poly: M, numerator: int, denominator: int) -> M:
        """``poly * numerator / denominator``: what the coefficients' ring says (each backend's own)."""
        raise NotImplementedError

    def substitute(self, poly: M, var: str, value: M) -> M:
        """``poly`` with ``var`` replaced by the polynomial ``value``: one composition in C."""
        gens = list(self._constants[2])
        gens[self.index[var]] = value
        return poly.compose(*gens)

    def zero(self) -> M:
        return self._constants[0]

    def one(self) -> M:
        return self._constants[1]

    @functools.cached_property
    def _constants(self) -> tuple[M, M, tuple[M, ...]]:
        """Zero, one and the generators, made once (python-flint's polynomials are values; the
        generators alone cost 2.6 us a call)."""
        return self.ctx.from_dict({}), self.ctx.from_dict({(0,) * len(self.names): 1}), tuple(self.ctx.gens())

    def quotient(self, f: M, g: M) -> M | None:
        """``f / g`` if ``g`` divides ``f``, else None."""
        quotient, remainder = divmod(f, g)
        return quotient if remainder.is_zero() else None

    def split(self, poly: M, variables: Sequence[str]) -> dict[tuple[int, ...], M]:
        """``{exponents in variables: coefficient free of them}``, in C: the coefficient of
        ``x**k`` is the ``k``-th derivative at ``x = 0`` over ``k!`` (a Python loop over
        the terms is ten times slower; modulo a prime above every degree ``k!`` is invertible)."""
        if not variables:
            return {(): poly}
        index, factorial, top = self.index[variables[0]], 1, self.degree(poly, variables[0])
        parts: dict[tuple[int, ...], M] = {}
        for degree in range(top + 1):
            part = poly.subs({index: 0}) if degree < top else poly
            if not part.is_zero():
                scaled = self.scale(part, 1, factorial) if factorial > 1 else part
                for key, value in self.split(scaled, variables[1:]).items():
                    parts[(degree,) + key] = value
            if degree < top:
                poly, factorial = poly.derivative(index), factorial * (degree + 1)
        return parts

    def join(self, parts: Mapping[tuple[int, ...], M], variables: Sequence[str]) -> M:
        """The inverse of ``split``."""
        gens = self._constants[2]
        where = [gens[self.index[v]] for v in variables]
        total = self.zero()
        for exponents, coefficient in parts.items():
            for gen, e in zip(where, exponents):
                coefficient = coefficient * gen**e
            total = total + coefficient
        return total


def _refuse_strays(names: Sequence[str], poly: flint.fmpq_mpoly) -> None:
    """A ComputationError if ``poly`` holds a variable not in ``names`` (a projection onto
    them would set it to zero)."""
    stray = [n for n, d in zip(poly.context().names(), poly.degrees()) if d and n not in names]
    if stray:
        raise ComputationError(f"an equation holds {', '.join(stray)}, neither eliminated nor kept")


class FlintBackend(FlintMpolys[flint.fmpq_mpoly]):
    """python-flint ``fmpq_mpoly``: resultants, factoring and Buchberger in C."""

    name = "flint"
    ctx: flint.fmpq_mpoly_ctx

    def __init__(self, names: Sequence[str]) -> None:
        super().__init__(names)
        self.ctx = self.rational  # the ring ``from_flint`` projects to is this backend's own

    def from_sympy(self, expr: sympy.Expr) -> flint.fmpq_mpoly:
        return to_flint(expr, self.ctx)

    def from_rational(self, poly: flint.fmpq_mpoly) -> flint.fmpq_mpoly:
        return poly

    def to_sympy(self, poly: flint.fmpq_mpoly) -> sympy.Expr:
        return to_sympy(poly, self.ctx)

    def coefficient_bits(self, poly: flint.fmpq_mpoly) -> int:
        return max((int(c.p).bit_length() + int(c.q).bit_length() for c in poly.coeffs()), default=0)

    def factors(self, poly: flint.fmpq_mpoly) -> list[flint.fmpq_mpoly]:
        if poly.total_degree() == 1:  # a line is irreducible: flint's factoring costs 20 us to say so
            return [self.primitive(poly)]
        _, factors = poly.factor()
        return [f for f, _ in factors]

    def irreducibility(self, poly: flint.fmpq_mpoly) -> IrreducibilityProof | None:
        # beyond three variables, specializing to one proves irreducibility faster than flint's
        # multivariate factoring (benchmarks/bench_ideas.py). In three, about as fast (an attempt:
        # 5 us to specialize, 10 us for flint's univariate factoring of a quartic, against 26 us
        # for the seed's connector, where the first values tried factor); but a variable of degree
        # 2 decides by its discriminant in 10 us (the connector's B_y). In two (a curve), 5
        # against 40 us, but flint's factoring stays: its proof is what ``curve`` reports.
        held = len(self.variables(poly))
        if held > 3:
            return irreducibility_proof(poly)
        return quadratic_proof(poly) if held == 3 else None

    def specialize(self, poly: flint.fmpq_mpoly, values: Mapping[str, flint.fmpq]) -> flint.fmpq_mpoly:
        """``poly`` with the variables of ``values`` (name -> fmpq) replaced by them."""
        # by index: python-flint looks a name up in Python (3.7 against 2.3 us for two values); its
        # stub takes names or indices, in a Mapping invariant in its keys
        return poly.subs(cast("Mapping[str | int, flint.fmpq]", {self.index[n]: v for n, v in values.items()}))

    def scale(self, poly: flint.fmpq_mpoly, numerator: int, denominator: int) -> flint.fmpq_mpoly:
        return poly * flint.fmpq(numerator, denominator)

    def terms(self, poly: flint.fmpq_mpoly) -> list[Term]:
        """``(exponents, numerator, denominator)`` per term, for evaluation at witnesses."""
        return [(m, int(c.p), int(c.q)) for m, c in zip(poly.monoms(), poly.coeffs())]

    def divide(self, f: flint.fmpq_mpoly, g: flint.fmpq_mpoly) -> flint.fmpq_mpoly:
        """``f / g``, exact."""
        return f / g

    def primitive(self, poly: flint.fmpq_mpoly) -> flint.fmpq_mpoly:
        """Integer coefficients with gcd 1, positive leading coefficient (lex)."""
        if poly.is_zero():
            return poly
        scaled = poly / content(poly.coeffs())  # 3 against 5.6 us for 17 terms by Python's lcm and gcd
        return -scaled if scaled.leading_coefficient() < 0 else scaled

    def groebner_lex(self, polys: Sequence[flint.fmpq_mpoly], order: Sequence[str]) -> list[flint.fmpq_mpoly]:
        """Reduced lex Gröbner basis with variables ordered as ``order`` (first is largest)."""
        zctx = flint.fmpz_mpoly_ctx.get(tuple(order), "lex")
        qctx = flint_context(order, "lex")
        moved = [to_flint_integer(to_flint(self.to_sympy(p), qctx), zctx) for p in polys]
        basis = flint.fmpz_mpoly_vec(moved, zctx).buchberger_naive().autoreduction()
        return [self.from_sympy(to_sympy(g, zctx)) for g in basis]


class SympyBackend:
    """sympy ``Poly`` over QQ: the reference the seeds used, for comparison."""

    name = "sympy"

    def __init__(self, names: Sequence[str]) -> None:
        self.names = tuple(names)
        self.index = {n: i for i, n in enumerate(self.names)}
        self.gens = [symbol(n) for n in self.names]

    def from_sympy(self, expr: sympy.Expr) -> sympy.Poly:
        expr = sympy.sympify(expr).xreplace({sympy.Symbol(n): g for n, g in zip(self.names, self.gens)})
        return sympy.Poly(expr, *self.gens, domain=sympy.QQ)

    def from_flint(self, poly: flint.fmpq_mpoly) -> sympy.Poly:
        _refuse_strays(self.names, poly)
        return self.from_sympy(to_sympy(poly, poly.context()))

    def to_sympy(self, poly: sympy.Poly) -> sympy.Expr:
        return poly.as_expr()

    def forget(self) -> None:
        """Nothing kept: sympy's ``Poly`` reads its degrees itself."""

    def variables(self, poly: sympy.Poly) -> AbstractSet[str]:
        return {n for n, d in zip(self.names, poly.degree_list()) if d > 0}

    def degree(self, poly: sympy.Poly, var: str) -> int:
        return int(poly.degree(self.gens[self.index[var]]))

    def is_constant(self, poly: sympy.Poly) -> bool:
        return bool(poly.is_ground)

    def total_degree(self, poly: sympy.Poly) -> int:
        return int(poly.total_degree())

    def nterms(self, poly: sympy.Poly) -> int:
        return len(poly.terms())

    def coefficient_bits(self, poly: sympy.Poly) -> int:
        return max((int(c.p).bit_length() + int(c.q).bit_length() for c in poly.coeffs()), default=0)

    def is_zero(self, poly: sympy.Poly) -> bool:
        return bool(poly.is_zero)

    def resultant(self, f: sympy.Poly, g: sympy.Poly, var: str) -> sympy.Poly:
        gen = self.gens[self.names.index(var)]
        result = sympy.resultant(f.as_expr(), g.as_expr(), gen)
        return self.from_sympy(result)

    def factors(self, poly: sympy.Poly) -> list[sympy.Poly]:
        _, factors = poly.factor_list()
        return [f for f, _ in factors]

    def irreducibility(self, poly: sympy.Poly) -> IrreducibilityProof | None:
        return None  # sympy, the seeds' tool, factors

    def gcd(self, f: sympy.Poly, g: sympy.Poly) -> sympy.Poly:
        return f.gcd(g)

    def derivative(self, poly: sympy.Poly, var: str) -> sympy.Poly:
        return poly.diff(self.gens[self.names.index(var)])

    def specialize(self, poly: sympy.Poly, values: Mapping[str, flint.fmpq]) -> sympy.Poly:
        replaced = poly.as_expr().xreplace({self.gens[self.names.index(n)]: sympy.Rational(int(v.p), int(v.q))
                                            for n, v in values.items()})
        return self.from_sympy(replaced)

    def scale(self, poly: sympy.Poly, numerator: int, denominator: int) -> sympy.Poly:
        return poly * sympy.Rational(numerator, denominator)

    def substitute(self, poly: sympy.Poly, var: str, value: sympy.Poly) -> sympy.Poly:
        return self.from_sympy(poly.as_expr().xreplace({self.gens[self.names.index(var)]: value.as_expr()}))

    def terms(self, poly: sympy.Poly) -> list[Term]:
        return [(m, int(c.p), int(c.q)) for m, c in poly.terms()]

    def zero(self) -> sympy.Poly:
        return sympy.Poly(0, *self.gens, domain=sympy.QQ)

    def one(self) -> sympy.Poly:
        return sympy.Poly(1, *self.gens, domain=sympy.QQ)

    def divide(self, f: sympy.Poly, g: sympy.Poly) -> sympy.Poly:
        return f.exquo(g)

    def quotient(self, f: sympy.Poly, g: sympy.Poly) -> sympy.Poly | None:
        quotient, remainder = f.div(g)
        return quotient if remainder.is_zero else None

    def split(self, poly: sympy.Poly, variables: Sequence[str]) -> dict[tuple[int, ...], sympy.Poly]:
        where = [self.names.index(v) for v in variables]
        groups: dict[tuple[int, ...], dict[tuple[int, ...], sympy.Rational]] = {}
        for monomial, coefficient in poly.as_dict().items():
            key = tuple(monomial[i] for i in where)
            rest = tuple(0 if i in where else e for i, e in enumerate(monomial))
            groups.setdefault(key, {})[rest] = coefficient
        return {key: sympy.Poly.from_dict(terms, *self.gens, domain=sympy.QQ) for key, terms in groups.items()}

    def join(self, parts: Mapping[tuple[int, ...], sympy.Poly], variables: Sequence[str]) -> sympy.Poly:
        total = self.zero()
        for exponents, coefficient in parts.items():
            monomial = sympy.Mul(*(self.gens[self.names.index(v)] ** e for v, e in zip(variables, exponents)))
            total = total + coefficient * sympy.Poly(monomial, *self.gens, domain=sympy.QQ)
        return total

    def primitive(self, poly: sympy.Poly) -> sympy.Poly:
        if poly.is_zero:
            return poly
        _, prim = poly.clear_denoms(convert=True)[1].primitive()
        prim = prim.to_field()
        return -prim if prim.LC() < 0 else prim

    def groebner_lex(self, polys: Sequence[sympy.Poly], order: Sequence[str]) -> list[sympy.Poly]:
        gens = [symbol(n) for n in order]
        basis = sympy.groebner([p.as_expr() for p in polys], *gens, order="lex", domain=sympy.QQ)
        return [self.from_sympy(g) for g in basis.exprs]


BACKENDS: dict[str, BackendFactory] = {"flint": FlintBackend, "sympy": SympyBackend}
