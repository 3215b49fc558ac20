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
algkin.errors.UsageError: method='magic': unknown elimination method; valid: groebner, linear, resultant
>>> eliminate(circles, ["x"], ["y", "c", "s"], method="resultant", budget=Budget(terms=5))
Traceback (most recent call last):
...
algkin.errors.BudgetExceeded: max_terms=5: the resultant in x has 11 terms, while eliminating x (keeping y, c, s) by resultant on flint
"""

import functools
import time
from dataclasses import dataclass, field

from ..errors import ComputationError, UsageError
from ..runtime.budget import Budget, current
from ..system.convert import flint_context, to_flint
from .backends import BACKENDS
from .linear import linear_elimination
from .methods import groebner_basis, prepare, resultant_chain
from .factor import factor_with
from .select import Witness, select_factors, unreal_factors

__all__ = ["eliminate", "Elimination", "Witness", "Budget", "current", "METHODS", "DEFAULT_METHOD", "BACKENDS",
           "method_names", "backend_names"]


METHODS = {"resultant": resultant_chain, "groebner": groebner_basis, "linear": linear_elimination}
DEFAULT_METHOD = "linear"  # measured fastest on every catalog problem: ``algkin bench``


def method_names():
    return sorted(METHODS)


def backend_names():
    return sorted(BACKENDS)


@dataclass
class Elimination:
    """An eliminant: primitive, squarefree, its factors kept and dropped, and its figures.

    The polynomials stay in the backend until first asked for as sympy expressions
    (``polynomial``, ``factors``, ``dropped``): converting is the slow edge, and a
    benchmark or a budget check needs only the figures.
    """

    engine: object
    raw: object  # the eliminant in the backend's type
    raw_factors: list
    raw_dropped: list
    variables: tuple
    method: str
    backend: str
    degree: int
    terms: int
    bits: int
    seconds: float
    log: list = field(default_factory=list)

    @functools.cached_property
    def polynomial(self):
        return self.engine.to_sympy(self.raw)

    @functools.cached_property
    def factors(self):
        return [self.engine.to_sympy(self.engine.primitive(f)) for f in self.raw_factors]

    @functools.cached_property
    def dropped(self):
        return [self.engine.to_sympy(self.engine.primitive(f)) for f in self.raw_dropped]

    @functools.cached_property
    def exact(self):
        """``(polynomial, kept factors)`` as python-flint ``fmpq_mpoly``: on the flint backend,
        straight from the elimination, with no sympy on the way (a verification needs no more)."""
        if self.engine is not None and self.engine.name == "flint":
            return self.raw, [self.engine.primitive(f) for f in self.raw_factors]
        ctx = flint_context(sorted({str(v) for e in [self.polynomial, *self.factors] for v in e.free_symbols}) or ["_"])
        return to_flint(self.polynomial, ctx), [to_flint(f, ctx) for f in self.factors]

    def __getstate__(self):
        """Out of a budget's child process an elimination travels as sympy: the backend's
        polynomials do not pickle."""
        state = dict(self.__dict__, polynomial=self.polynomial, factors=self.factors, dropped=self.dropped)
        state.pop("exact", None)
        return dict(state, engine=None, raw=None, raw_factors=None, raw_dropped=None)


def _lookup(table, kind, name):
    if name not in table:
        raise UsageError(kind, name, f"unknown elimination {kind}; valid: {', '.join(sorted(table))}")
    return table[name]


def _consistent(engine, polys):
    """Drop zero polynomials; a non-zero constant means there is no solution at all."""
    polys = [p for p in polys if not engine.is_zero(p)]
    if any(engine.is_constant(p) for p in polys):
        raise ComputationError("the equations are inconsistent: elimination reached a non-zero constant")
    return polys


def eliminate(equations, eliminate, keep, method=DEFAULT_METHOD, backend="flint", witnesses=(), parameters=(),
              budget=None):
    """Eliminate the variables ``eliminate`` from ``equations`` (sympy polynomials over QQ).

    Returns the polynomial left in the variables ``keep``, with factors the witnesses
    (groups of configurations, name -> arb) do not satisfy dropped and reported.
    ``parameters`` (a subset of ``keep``: dimensions, and a derivation's inputs) may appear
    in the multipliers of the ``linear`` method. A ``Budget`` bounds the time and the terms of every intermediate
    eliminant (by default, the budget of the ``Budget.run()`` under way, if any).
    """
    run = _lookup(METHODS, "method", method)
    engine = _lookup(BACKENDS, "backend", backend)(tuple(eliminate) + tuple(keep))
    budget = budget or current()
    budget.note(f"eliminating {', '.join(map(str, eliminate)) or 'nothing'} "
                f"(keeping {', '.join(map(str, keep))}) by {method} on {backend}")
    work = functools.partial(_eliminate, engine, method, run, equations, list(eliminate), list(keep),
                             witnesses, parameters, budget)
    return budget.run(work)


def _eliminate(engine, method, run, equations, eliminate, keep, witnesses, parameters, budget):
    start = time.perf_counter()
    polys = [engine.from_sympy(eq) for eq in equations]
    log, dropped, multipliers = [], [], []
    polys = _consistent(engine, prepare(engine, polys, eliminate, log))
    left = _consistent(engine, run(engine, polys, eliminate, witnesses, dropped, log, parameters, budget,
                                   multipliers))
    if not left:
        raise ComputationError(f"nothing left after eliminating {', '.join(eliminate)}")
    eliminant = left[0]
    for poly in left[1:]:
        eliminant = engine.gcd(eliminant, poly)
    if engine.is_constant(eliminant):
        eliminant = min(left, key=lambda p: (engine.total_degree(p), engine.nterms(p)))
    real, unreal = unreal_factors(engine, factor_with(engine, eliminant, multipliers), parameters)
    kept, lost = select_factors(engine, real, witnesses)
    dropped.extend(unreal + lost)
    product = kept[0]
    for factor in kept[1:]:
        product = product * factor
    product = engine.primitive(product)
    return Elimination(
        engine=engine,
        raw=product,
        raw_factors=kept,
        raw_dropped=dropped,
        variables=tuple(keep),
        method=method,
        backend=engine.name,
        degree=engine.total_degree(product),
        terms=engine.nterms(product),
        bits=engine.coefficient_bits(product),
        seconds=time.perf_counter() - start,
        log=log,
    )
