"""Do two eliminants describe the same curve? Compared exactly, in python-flint, with a typed verdict.

Polynomials travel between processes as ``(names, [(exponents, numerator, denominator)])``
and are rebuilt over the kept variables. Only two verdicts count as agreeing: ``equal`` (up
to a nonzero constant) and ``equal mod side relations`` (equal once reduced modulo
``c**2 + s**2 - 1`` and the like). A third, ``equal up to content``, also agrees, and only
when the two differ by factors in the parameters (the dimensions) alone that have no real
zero, such as ``b**2 + 160000``: at every real choice of the dimensions that factor is a
nonzero constant, so the two are equal up to a nonzero constant on every real mechanism;
it is the factor algkin's elimination drops (``algkin.eliminate.select.unreal_factors``)
and a peer's Gröbner basis keeps. Everything else disagrees, and says how: ``extra
factor`` (the row carries a factor the reference does not), ``missing factor`` (the
reverse), ``different`` (neither divides the other). A resultant chain's extraneous
factors are an ``extra factor``: the row's eliminant is not the curve.

>>> import flint
>>> ctx = flint.fmpq_mpoly_ctx.get(("x", "y"), "lex")
>>> x, y = ctx.gens()
>>> circle = x**2 + y**2 - 1
>>> str(agreement(2 * circle, circle)), str(agreement(x * circle, circle)), str(agreement(circle, x * circle))
('equal', 'extra factor', 'missing factor')
>>> agreement(x * circle, circle).detail
'extra factor x (degree 1, 1 terms)'
>>> agreement(x**2 + y**2 - 2, circle).agrees
False
"""

import enum
from collections.abc import Iterable, Sequence
from dataclasses import dataclass

import flint
import sympy

from ..eliminate.protocol import Backend, P, Term
from ..eliminate.select import unreal
from ..system import symbol
from ..system.convert import flint_context, to_flint, to_sympy

__all__ = ["Agreement", "AGREEING", "PASSING", "Verdict", "agreement", "rebuild", "portable", "from_sympy", "describe"]

# A peer's or a backend's eliminant, portable: (variable names, [(exponents, numerator, denominator)])
PortableForm = tuple[tuple[str, ...], list[Term]]

SHOWN = 80  # characters of a factor written out in a verdict's detail


class Agreement(enum.Enum):
    EQUAL = "equal"
    EQUAL_MOD_SIDE = "equal mod side relations"
    EQUAL_UP_TO_CONTENT = "equal up to content"
    EXTRA_FACTOR = "extra factor"
    MISSING_FACTOR = "missing factor"
    DIFFERENT = "different"
    REFERENCE = "reference"
    NOT_COMPARED = "not compared"

    def __str__(self) -> str:
        return self.value


AGREEING = {Agreement.EQUAL, Agreement.EQUAL_MOD_SIDE, Agreement.EQUAL_UP_TO_CONTENT}
PASSING = AGREEING | {Agreement.REFERENCE}  # what a bench row may read for ``algkin bench`` to exit 0


@dataclass(frozen=True)
class Verdict:
    """An ``Agreement`` and what it rests on (the factor in excess or missing, the content)."""

    kind: Agreement
    detail: str = ""

    @property
    def agrees(self) -> bool:
        return self.kind in AGREEING

    def __str__(self) -> str:
        return str(self.kind)


def portable(engine: Backend[P], poly: P) -> PortableForm:
    """A picklable form of a backend polynomial."""
    return engine.names, engine.terms(poly)


def rebuild(form: PortableForm, keep: Sequence[str]) -> flint.fmpq_mpoly:
    """The polynomial of ``portable`` over the variables ``keep``."""
    names, terms = form
    ctx = flint_context(keep)
    where = [names.index(n) if n in names else None for n in keep]
    dictionary: dict[tuple[int, ...], flint.fmpq] = {}
    for exponents, numerator, denominator in terms:
        key = tuple(exponents[i] if i is not None else 0 for i in where)
        dictionary[key] = dictionary.get(key, 0) + flint.fmpq(numerator, denominator)
    return ctx.from_dict(dictionary)


def from_sympy(expr: sympy.Expr, keep: Sequence[str]) -> flint.fmpq_mpoly:
    return to_flint(expr, flint_context(keep))


def agreement(poly: flint.fmpq_mpoly, reference: flint.fmpq_mpoly, side: Sequence[flint.fmpq_mpoly] = (),
              parameters: Iterable[str] = ()) -> Verdict:
    """The ``Verdict`` of ``poly`` against ``reference`` (flint polynomials in one context);
    ``side``: the side relations; ``parameters``: names of the dimensions, for content."""
    if _proportional(poly, reference):
        return Verdict(Agreement.EQUAL)
    if side and _proportional(*(_reduced(p, side) for p in (poly, reference))):
        return Verdict(Agreement.EQUAL_MOD_SIDE)
    if poly.is_zero() or reference.is_zero():
        return Verdict(Agreement.DIFFERENT, "one of them is zero")
    shared = poly.gcd(reference)
    extra, missing = poly / shared, reference / shared
    if _content(extra, parameters) and _content(missing, parameters):
        return Verdict(Agreement.EQUAL_UP_TO_CONTENT, "; ".join(
            f"{where} content {_text(f)} (no real zero)" for where, f in (("row's", extra), ("reference's", missing))
            if not _constant(f)))
    if _constant(missing):
        return Verdict(Agreement.EXTRA_FACTOR, f"extra factor {describe(extra)}")
    if _constant(extra):
        return Verdict(Agreement.MISSING_FACTOR, f"missing factor {describe(missing)}")
    return Verdict(Agreement.DIFFERENT, f"{describe(extra)} in the row against {describe(missing)} in the reference")


def describe(poly: flint.fmpq_mpoly) -> str:
    """A factor as a reader checks it: written out when short, with its degree and terms."""
    text, figures = _text(poly), f"degree {poly.total_degree()}, {len(poly)} terms"
    return f"{text} ({figures})" if len(text) <= SHOWN else f"of {figures}"


def _text(poly: flint.fmpq_mpoly) -> str:
    return str(to_sympy(poly, poly.context()).factor())


def _constant(poly: flint.fmpq_mpoly) -> bool:
    return not any(poly.degrees())


def _content(poly: flint.fmpq_mpoly, parameters: Iterable[str]) -> bool:
    """Whether ``poly`` is a constant or a product of factors in the ``parameters`` alone
    with no real zero (a nonzero constant at every real choice of them)."""
    if _constant(poly):
        return True
    names = poly.context().names()
    held = {n for n, d in zip(names, poly.degrees()) if d > 0}
    if not held <= set(parameters):
        return False
    _, factors = poly.factor()
    terms = lambda f: [(m, int(c.p), int(c.q)) for m, c in zip(f.monoms(), f.coeffs())]  # noqa: E731
    return all(unreal(terms(f)) for f, _ in factors)


def _proportional(p: flint.fmpq_mpoly, q: flint.fmpq_mpoly) -> bool:
    if p.is_zero() or q.is_zero():
        return p.is_zero() and q.is_zero()
    return p * q.leading_coefficient() == q * p.leading_coefficient()


def _reduced(poly: flint.fmpq_mpoly, side: Sequence[flint.fmpq_mpoly]) -> flint.fmpq_mpoly:
    """``poly`` reduced modulo the side relations (a Gröbner basis of them, in sympy)."""
    ctx = poly.context()
    gens = [symbol(str(n)) for n in ctx.names()]
    basis = sympy.groebner([to_sympy(s, ctx) for s in side], *gens, order="grevlex")
    _, remainder = basis.reduce(to_sympy(poly, ctx))
    return to_flint(remainder, ctx)
