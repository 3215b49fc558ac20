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
algkin.errors.UsageError: method='magic': unknown elimination method (valid: groebner, interpolate, linear, resultant)
>>> eliminate(circles, ["x"], ["y", "c", "s"], method="resultant", budget=Budget(terms=5))
Traceback (most recent call last):
...
algkin.errors.BudgetExceeded: max_terms=5: the resultant in x has 11 terms, while eliminating x (keeping y, c, s) by resultant on flint
"""

import functools
import time
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any, Generic, TypeVar, cast

import flint
import sympy

from ..runtime import suggest
from ..errors import ComputationError, UsageError
from ..runtime.budget import Budget, Deadline, started
from ..system.convert import flint_context, to_flint
from .backends import BACKENDS
from .interpolate import interpolation
from .linear import linear_elimination
from .methods import groebner_basis, prepare, resultant_chain
from .factor import IrreducibilityProof, factor_with
from .protocol import Backend, P
from .request import EliminationRequest, LogEntry, Method, MethodOutcome
from .select import NOT_THE_MOTION, Witness, WitnessGroups, select_factors, unreal_factors, vanishes_at

__all__ = ["eliminate", "eliminate_each", "Elimination", "Witness", "Budget", "Deadline", "METHODS", "DEFAULT_METHOD", "BACKENDS",
           "method_names", "backend_names"]


METHODS: dict[str, Method] = {"resultant": resultant_chain, "groebner": groebner_basis, "linear": linear_elimination,
                             "interpolate": interpolation}
DEFAULT_METHOD = "linear"  # measured fastest on every catalog problem: ``algkin bench``
PREPARING = frozenset({"interpolate"})
"""Methods given the equations unprepared: they prepare each specialisation of them themselves."""
OUTSIDE_THE_IDEAL = frozenset({
    "stripped",  # an equation divided by a multiplier's factor: only the ideal's saturation holds it
    "interpolated",  # images cut to the factors a signature read at one witness chose
})
"""Steps after which an eliminant is no longer known to lie in the elimination ideal itself."""

_T = TypeVar("_T")


def method_names() -> list[str]:
    return sorted(METHODS)


def backend_names() -> list[str]:
    return sorted(BACKENDS)


@dataclass(frozen=True, eq=False)  # hashed by identity: its polynomials live in a backend
class Elimination(Generic[P]):
    """An eliminant: primitive, squarefree, its factors kept and dropped, and its figures.

    The polynomials stay in the backend until first asked for as sympy expressions
    (``polynomial``, ``factors``, ``dropped``): converting is the slow edge, and a
    benchmark or a budget check needs only the figures.
    """

    engine: Backend[P] | None  # None once pickled (``__getstate__``), as the three below
    raw: P | None  # the eliminant in the backend's type
    raw_factors: list[P] | None
    raw_dropped: list[P] | None
    variables: tuple[str, ...]
    method: str
    backend: str
    degree: int
    terms: int
    seconds: float
    log: list[LogEntry] = field(default_factory=list)
    proof: IrreducibilityProof | None = None  # why the one kept factor needed no choosing, if it did not

    @functools.cached_property
    def bits(self) -> int:
        """The most bits of a coefficient (numerator and denominator): worked out when asked."""
        engine, raw, _, _ = self._live()
        return engine.coefficient_bits(raw)

    @functools.cached_property
    def text(self) -> str:
        """The eliminant as text in sympy's syntax (``sympy.parse_expr`` reads it back): from
        python-flint on the flint backend, which prints a curve of 7,000 terms in milliseconds
        where sympy's conversion and printing take seconds.

        >>> import sympy
        >>> x, y = sympy.symbols("x y")
        >>> result = eliminate([x**2 + y**2 - 4, x - 1], ["x"], ["y"])
        >>> result.text, str(result.polynomial)
        ('y**2 - 3', 'y**2 - 3')
        """
        if self.engine is not None and self.engine.name == "flint":
            return str(self.raw).replace("^", "**")
        return str(self.polynomial)

    @functools.cached_property
    def polynomial(self) -> sympy.Expr:
        engine, raw, _, _ = self._live()
        return engine.to_sympy(raw)

    @functools.cached_property
    def factors(self) -> list[sympy.Expr]:
        engine, _, kept, _ = self._live()
        return [engine.to_sympy(engine.primitive(f)) for f in kept]

    @functools.cached_property
    def dropped(self) -> list[sympy.Expr]:
        engine, _, _, dropped = self._live()
        return [engine.to_sympy(engine.primitive(f)) for f in dropped]

    @functools.cached_property
    def exact(self) -> tuple[flint.fmpq_mpoly, list[flint.fmpq_mpoly]]:
        """``(polynomial, kept factors)`` as python-flint ``fmpq_mpoly``: on the flint backend,
        straight from the elimination, with no sympy on the way (a verification needs no more)."""
        if self.engine is not None and self.engine.name == "flint":
            engine, raw, kept, _ = self._live()
            exact = (raw, [engine.primitive(f) for f in kept])
            return cast(tuple[flint.fmpq_mpoly, list[flint.fmpq_mpoly]], exact)  # the flint backend's P
        ctx = flint_context(sorted({str(v) for e in [self.polynomial, *self.factors] for v in e.free_symbols}) or ["_"])
        return to_flint(self.polynomial, ctx), [to_flint(f, ctx) for f in self.factors]

    def _live(self) -> tuple[Backend[P], P, list[P], list[P]]:
        """The backend and its polynomials, held until pickled: the sympy forms, worked out
        before pickling, are all a pickled elimination is asked for."""
        assert self.engine is not None and self.raw is not None, "a pickled elimination has only its sympy forms"
        assert self.raw_factors is not None and self.raw_dropped is not None
        return self.engine, self.raw, self.raw_factors, self.raw_dropped

    def __getstate__(self) -> dict[str, Any]:
        """Out of a budget's child process an elimination travels as sympy: the backend's
        polynomials do not pickle."""
        state = dict(self.__dict__, polynomial=self.polynomial, factors=self.factors, dropped=self.dropped,
                     bits=self.bits, text=self.text)
        state.pop("exact", None)
        return dict(state, engine=None, raw=None, raw_factors=None, raw_dropped=None)


def _lookup(table: dict[str, _T], kind: str, name: str) -> _T:
    if not isinstance(name, str) or name not in table:  # a list or a dict would not even hash
        raise UsageError(kind, name, f"unknown elimination {kind}" + suggest.known(str(name), sorted(table), plural="valid"))
    return table[name]


def _consistent(engine: Backend[P], polys: list[P]) -> list[P]:
    """Drop zero polynomials; a non-zero constant means there is no solution at all."""
    polys = [p for p in polys if not engine.is_zero(p)]
    if any(engine.is_constant(p) for p in polys):
        raise ComputationError("the equations are inconsistent: elimination reached a non-zero constant")
    return polys


def eliminate(equations: Sequence[sympy.Expr | flint.fmpq_mpoly], eliminate: Sequence[str], keep: Sequence[str], *,
              method: str = DEFAULT_METHOD, backend: str = "flint", witnesses: WitnessGroups = (),
              parameters: Sequence[str] = (), budget: Budget | Deadline | None = None
              ) -> Elimination[flint.fmpq_mpoly] | Elimination[sympy.Poly]:
    """Eliminate the variables ``eliminate`` from ``equations`` (polynomials over QQ: sympy
    expressions, or python-flint ``fmpq_mpoly`` over any names, matched by name).

    Returns the polynomial left in the variables ``keep``, with factors the witnesses
    (groups of configurations, name -> arb) do not satisfy dropped and reported.
    ``parameters`` (a subset of ``keep``: dimensions, and a derivation's inputs) may appear
    in the multipliers of the ``linear`` method. A ``Budget`` bounds the time and the terms of every intermediate
    eliminant; or the ``Deadline`` of one already running, which the elimination then counts against (by
    default, no bound).
    """
    run = _lookup(METHODS, "method", method)
    engine = _lookup(BACKENDS, "backend", backend)(tuple(eliminate) + tuple(keep))
    deadline = started(budget)
    deadline.note(f"eliminating {', '.join(map(str, eliminate)) or 'nothing'} "
                  f"(keeping {', '.join(map(str, keep))}) by {method} on {backend}")
    request = EliminationRequest(tuple(eliminate), witnesses, tuple(parameters), deadline)

    def converted_and_eliminated() -> Elimination[Any]:
        start = time.perf_counter()
        return _eliminate(engine, method, run, _converted(engine, equations), tuple(keep), request, start=start)

    try:
        return deadline.run(converted_and_eliminated)
    finally:
        engine.forget()  # the result holds the backend: not the intermediate polynomials with it


def eliminate_each(equations: Sequence[sympy.Expr | flint.fmpq_mpoly], eliminate: Sequence[str],
                   keep: Sequence[str], *, at: Sequence[Mapping[str, flint.fmpq | int]],
                   witnesses: Sequence[WitnessGroups] = (), method: str = DEFAULT_METHOD, backend: str = "flint",
                   parameters: Sequence[str] = (), budget: Budget | Deadline | None = None
                   ) -> list[Elimination[flint.fmpq_mpoly]] | list[Elimination[sympy.Poly]]:
    """``eliminate`` at each specialization of one system, in one call: ``at`` gives each one's
    values (name -> rational) of some of the ``keep`` variables (a scene's dimensions, for a
    sweep or a property-based run), ``witnesses`` each one's witness groups (none by default).
    The backend and the equations' conversion are shared, the rest is ``eliminate``'s, item by
    item: each result is the one ``eliminate`` gives on the specialized equations. One budget
    bounds the whole batch.

    >>> import sympy
    >>> x, y, r = sympy.symbols("x y r")
    >>> circles = [x**2 + y**2 - r**2, (x - 1)**2 + y**2 - 1]  # the unit circle about (1, 0) and one of radius r
    >>> [str(e.polynomial) for e in eliminate_each(circles, ["x"], ["y", "r"], at=[{"r": 1}, {"r": 2}])]
    ['4*y**2 - 3', 'y']

    (at ``r = 2`` the circles touch at (2, 0): ``y**2``, made squarefree.)
    """
    if witnesses and len(witnesses) != len(at):
        raise UsageError("witnesses", len(witnesses), f"expected one set of witness groups for each of the {len(at)} "
                                                      "specializations")
    stray = sorted({name for values in at for name in values} - set(keep))
    if stray:
        raise UsageError("at", stray[0], f"not a kept variable (kept: {', '.join(keep)})")
    run = _lookup(METHODS, "method", method)
    engine = _lookup(BACKENDS, "backend", backend)(tuple(eliminate) + tuple(keep))
    deadline = started(budget)
    deadline.note(f"eliminating {', '.join(map(str, eliminate)) or 'nothing'} (keeping {', '.join(map(str, keep))}) "
                  f"by {method} on {backend}, at {len(at)} specializations")
    requests = [EliminationRequest(tuple(eliminate), witnesses[k] if witnesses else (), tuple(parameters), deadline)
                for k in range(len(at))]

    def each() -> list[Elimination[Any]]:
        polys = _converted(engine, equations)
        done = []
        for values, request in zip(at, requests):
            start = time.perf_counter()
            exact = {name: flint.fmpq(value) for name, value in values.items()}
            specialized = [engine.specialize(p, exact) for p in polys]
            done.append(_eliminate(engine, method, run, specialized, tuple(keep), request, start=start))
            engine.forget()
        return done

    try:
        return deadline.run(each)
    finally:
        engine.forget()


def _converted(engine: Backend[P], equations: Sequence[sympy.Expr | flint.fmpq_mpoly]) -> list[P]:
    return [engine.from_flint(e) if isinstance(e, flint.fmpq_mpoly) else engine.from_sympy(e) for e in equations]


def _eliminate(engine: Backend[P], method: str, run: Method, polys: list[P], keep: tuple[str, ...],
               request: EliminationRequest, *, start: float) -> Elimination[P]:
    prepared = MethodOutcome(polys) if method in PREPARING else prepare(engine, polys, request.eliminate)
    outcome = prepared.then(run(engine, _consistent(engine, prepared.left), request))
    left = _consistent(engine, outcome.left)
    if not left:
        raise ComputationError(f"nothing left after eliminating {', '.join(request.eliminate)}")
    eliminant = left[0]
    for poly in left[1:]:
        eliminant = engine.gcd(eliminant, poly)
    coprime = engine.is_constant(eliminant)
    member = len(left) == 1 or coprime  # an element of the ideal, not a gcd of some
    if coprime:
        eliminant = min(left, key=lambda p: (engine.total_degree(p), engine.nterms(p)))
    factors, proof = factor_with(engine, eliminant, outcome.multipliers)
    # in the elimination ideal itself: no factor chosen, no equation divided, on the way
    in_ideal = member and not outcome.dropped and not any(kind in OUTSIDE_THE_IDEAL for kind, _ in outcome.log)
    kept, lost, proof = _choose(engine, factors, proof=proof, in_ideal=in_ideal, request=request)
    log = outcome.log + ([("proved-irreducible", proof.variable or "factored")] if proof else [])
    product = kept[0]
    for factor in kept[1:]:
        product = product * factor
    product = engine.primitive(product)
    return Elimination(
        engine=engine,
        raw=product,
        raw_factors=kept,
        raw_dropped=outcome.dropped + lost,
        variables=keep,
        method=method,
        backend=engine.name,
        degree=engine.total_degree(product),
        terms=engine.nterms(product),
        seconds=time.perf_counter() - start,
        log=log,
        proof=proof,
    )


def _choose(engine: Backend[P], factors: list[P], *, proof: IrreducibilityProof | None, in_ideal: bool,
            request: EliminationRequest) -> tuple[list[P], list[P], IrreducibilityProof | None]:
    """``(kept, dropped, proof)``: the factors the motion lies on, chosen at the witnesses.

    When the eliminant is in the elimination ideal (``in_ideal``: no factor was chosen and
    no equation divided on the way) and its last factor is proved irreducible (``proof``),
    the motion lies on that factor once every other factor is shown not to vanish on it:
    the others are evaluated at every witness, the last at one witness a branch (a
    ComputationError if it does not vanish there), and the proof is returned as the reason
    the last needed no choosing.
    """
    real, unreal = unreal_factors(engine, factors, request.parameters)
    last = factors[-1]
    if proof is not None and in_ideal and real and real[-1] is last and \
            engine.variables(last) - set(request.parameters):
        others_kept, others_lost = select_factors(engine, real[:-1], request.witnesses, check=False)
        if not others_kept:
            # the proof says the motion lies on it; one witness a branch still checks the
            # witnesses against it (all of them: the verification's sampled configurations)
            if not vanishes_at(engine, last, [group[0] for group in request.witnesses if group]):
                raise ComputationError(NOT_THE_MOTION)
            return [last], unreal + others_lost, proof
    kept, lost = select_factors(engine, real, request.witnesses)
    return kept, unreal + lost, None
