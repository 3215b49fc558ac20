"""Elimination behind one interface: methods and backends chosen by name.

>>> import sympy
>>> x, y, c, s = [sympy.Symbol(n, real=True) for n in "xycs"]
>>> circles = [(x - c)**2 + (y - s)**2 - 4, x**2 + y**2 - 1]
>>> result = eliminate(circles, eliminate=["x"], keep=["y", "c", "s"], method="groebner")
>>> result.degree, result.terms
(4, 11)
>>> eliminate(circles, ["x"], ["y", "c", "s"], method="magic")
Traceback (most recent call last):
...
algkin.errors.UsageError: method='magic': unknown elimination method; valid: groebner, resultant
"""

import time
from dataclasses import dataclass, field

from ..errors import ComputationError, UsageError
from .backends import BACKENDS
from .methods import METHODS, prepare
from .select import select_factors

__all__ = ["eliminate", "Elimination", "METHODS", "BACKENDS", "method_names", "backend_names"]


def method_names():
    return sorted(METHODS)


def backend_names():
    return sorted(BACKENDS)


@dataclass
class Elimination:
    """An eliminant: primitive, squarefree, its factors kept and dropped, and its figures."""

    polynomial: object  # sympy expression
    variables: tuple
    factors: list
    dropped: list
    method: str
    backend: str
    degree: int
    terms: int
    bits: int
    seconds: float
    log: list = field(default_factory=list)


def _lookup(table, kind, name):
    if name not in table:
        raise UsageError(kind, name, f"unknown elimination {kind}; valid: {', '.join(sorted(table))}")
    return table[name]


def _consistent(engine, polys):
    """Drop zero polynomials; a non-zero constant means there is no solution at all."""
    polys = [p for p in polys if not engine.is_zero(p)]
    if any(not engine.variables(p) for p in polys):
        raise ComputationError("the equations are inconsistent: elimination reached a non-zero constant")
    return polys


def eliminate(equations, eliminate, keep, method="resultant", backend="flint", witnesses=()):
    """Eliminate the variables ``eliminate`` from ``equations`` (sympy polynomials over QQ).

    Returns the polynomial left in the variables ``keep``, with factors the witnesses
    (groups of configurations, name -> arb) do not satisfy dropped and reported.
    """
    run = _lookup(METHODS, "method", method)
    engine = _lookup(BACKENDS, "backend", backend)(tuple(eliminate) + tuple(keep))
    start = time.perf_counter()
    polys = [engine.from_sympy(eq) for eq in equations]
    log, dropped = [], []
    polys = _consistent(engine, prepare(engine, polys, list(eliminate), log))
    left = _consistent(engine, run(engine, polys, list(eliminate), witnesses, dropped, log))
    if not left:
        raise ComputationError(f"nothing left after eliminating {', '.join(eliminate)}")
    eliminant = left[0]
    for poly in left[1:]:
        eliminant = engine.gcd(eliminant, poly)
    if not engine.variables(eliminant):
        eliminant = min(left, key=lambda p: (engine.total_degree(p), engine.nterms(p)))
    kept, lost = select_factors(engine, engine.factors(eliminant), witnesses)
    dropped.extend(lost)
    product = kept[0]
    for factor in kept[1:]:
        product = product * factor
    product = engine.primitive(product)
    seconds = time.perf_counter() - start
    return Elimination(
        polynomial=engine.to_sympy(product),
        variables=tuple(keep),
        factors=[engine.to_sympy(engine.primitive(f)) for f in kept],
        dropped=[engine.to_sympy(engine.primitive(f)) for f in dropped],
        method=method,
        backend=backend,
        degree=engine.total_degree(product),
        terms=engine.nterms(product),
        bits=engine.coefficient_bits(product),
        seconds=seconds,
    )
