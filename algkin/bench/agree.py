"""Do two eliminants describe the same curve? Compared exactly, in python-flint.

Polynomials travel between processes as ``(names, [(exponents, numerator, denominator)])``
and are rebuilt over the kept variables. Two results agree when they are equal up to a
constant; when one carries extraneous factors (a resultant chain's, a peer's), they agree
with a note if their gcd holds every kept variable the reference holds; when the problem
has side relations (``c**2 + s**2 - 1``), equality modulo them also counts.

>>> import flint
>>> ctx = flint.fmpq_mpoly_ctx.get(("x", "y"), "lex")
>>> x, y = ctx.gens()
>>> agreement(2 * (x**2 + y**2 - 1), x**2 + y**2 - 1), agreement(x * (x**2 + y**2 - 1), x**2 + y**2 - 1)
('yes', 'yes, extra deg 1/0')
>>> agreement(x**2 + y**2 - 2, x**2 + y**2 - 1)
'NO'
"""

import flint
import sympy

from ..system import symbol
from ..system.convert import flint_context, to_flint, to_sympy

__all__ = ["agreement", "rebuild", "portable"]


def portable(engine, poly):
    """A picklable form of a backend polynomial."""
    return engine.names, engine.terms(poly)


def rebuild(form, keep):
    """The polynomial of ``portable`` over the variables ``keep``."""
    names, terms = form
    ctx = flint_context(keep)
    where = [names.index(n) if n in names else None for n in keep]
    dictionary = {}
    for exponents, numerator, denominator in terms:
        key = tuple(exponents[i] if i is not None else 0 for i in where)
        dictionary[key] = dictionary.get(key, 0) + flint.fmpq(numerator, denominator)
    return ctx.from_dict(dictionary)


def from_sympy(expr, keep):
    return to_flint(expr, flint_context(keep))


def agreement(poly, reference, side=()):
    """'yes', 'yes, extra deg P/R', 'yes, mod side rel.' or 'NO' (flint polynomials in one context)."""
    if _proportional(poly, reference):
        return "yes"
    shared = poly.gcd(reference)
    needed = [d > 0 for d in reference.degrees()]
    if all(d > 0 for d, need in zip(shared.degrees(), needed) if need):
        return f"yes, extra deg {poly.total_degree() - shared.total_degree()}/" \
               f"{reference.total_degree() - shared.total_degree()}"
    if side and _proportional(*(_reduced(p, side) for p in (poly, reference))):
        return "yes, mod side rel."
    return "NO"


def _proportional(p, q):
    if p.is_zero() or q.is_zero():
        return p.is_zero() and q.is_zero()
    return p * q.leading_coefficient() == q * p.leading_coefficient()


def _reduced(poly, side):
    """``poly`` reduced modulo the side relations (a Gröbner basis of them, in sympy)."""
    ctx = poly.context()
    gens = [symbol(str(n)) for n in ctx.names()]
    basis = sympy.groebner([to_sympy(s, ctx) for s in side], *gens, order="grevlex")
    _, remainder = basis.reduce(to_sympy(poly, ctx))
    return to_flint(remainder, ctx)
