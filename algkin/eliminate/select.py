"""Keep the factors the true motion satisfies, decided by ball arithmetic at witnesses.

A *witness* is a configuration of the mechanism (every variable's value as a python-flint
``arb`` ball; a ``Witness`` also holds the coordinates known exactly, such as rational
inputs and dimensions, which are substituted exactly before the rest is evaluated in
balls); witnesses come in groups, one group per branch. A factor is kept when its
ball contains zero at every witness of some group, and dropped when that fails: at some
witness of every group its ball excludes zero, which proves it non-zero there.

Each factor is evaluated at the witnesses' own precision plus its coefficients' bits and
its degree times the witnesses' magnitude, not at python-flint's default of 53 bits: at 53
bits a degree-30 factor with 160-bit coefficients gives a ball of width 1e38 around every
value, and would be kept for "containing" zero.

>>> import flint
>>> point = {"x": flint.arb(2).sqrt(), "y": flint.arb(3)}
>>> evaluator = Evaluator([((2, 0), 1, 1), ((0, 0), -2, 1)], ("x", "y"), 128)  # x**2 - 2
>>> evaluator.bits  # 128, + 3 for the coefficient -2/1 (2 + 1 bits), + 2 for degree 2 times 1 bit
133
>>> evaluator(point).contains(0), Evaluator([((0, 1), 1, 1)], ("x", "y"), 128)(point).contains(0)
(True, False)
"""

import math
from collections.abc import Callable, Collection, Iterable, Mapping, Sequence
import flint

from ..errors import ComputationError
from ..system.roots import real_roots
from .protocol import Backend, P, Term

__all__ = ["Witness", "Point", "WitnessGroups", "Evaluator", "Horner", "select_factors", "vanishes_at", "unreal_factors", "unreal",
           "NOT_THE_MOTION"]

MARGIN_BITS = 64
NOT_THE_MOTION = "no kept factor vanishes at a witness configuration: the eliminant does not describe the motion"

Point = Mapping[str, flint.arb]
"""A configuration: every variable's value as a ball (a ``Witness``, or a plain dict)."""

WitnessGroups = Sequence[Sequence[Point]]
"""Configurations in groups, one group per branch."""


class Witness(dict[str, flint.arb]):
    """A configuration: name -> arb ball, ``exact``: name -> fmpq for the coordinates known
    exactly (their balls enclose these values), and ``scale`` (see ``_scale``), worked out
    when it is made, for every elimination that uses it."""

    def __init__(self, balls: Mapping[str, flint.arb] | Iterable[tuple[str, flint.arb]] = (),
                 exact: Mapping[str, flint.fmpq] | None = None) -> None:
        super().__init__(balls)
        self.exact = dict(exact or {})
        self.scale = _scale(self)


def _scale(point: Point) -> tuple[int, float]:
    """``(bits, magnitude)``: the most mantissa bits of the balls (the precision they were
    computed at) and the largest absolute midpoint."""
    return (max((_bits(v) for v in point.values()), default=0),
            max((float(abs(v).mid()) for v in point.values()), default=0.0))


class Evaluator:
    """The ball value of one polynomial, given by its ``terms`` (exponents, numerator,
    denominator) over ``names``, at ``base_bits`` of precision plus its coefficients' bits
    plus its degree times ``magnitude_bits`` (the witnesses' size).

    Compiled once into a straight-line program: coefficients made balls, and every product of
    powers shared by terms with the same leading exponents (in the terms' lexicographic
    order) computed once: on the Stephenson III curve, 180 products instead of the 324 of a
    term-by-term loop.
    """

    def __init__(self, terms: Sequence[Term], names: Sequence[str], base_bits: int, magnitude_bits: int = 1) -> None:
        self.names = names
        highest: dict[int, int] = {}  # variable -> highest power
        degree, coefficient_bits = 0, 0
        nodes: dict[tuple[int, int, int], int] = {}  # (parent, variable, power) -> node; node 0 is 1
        steps: list[tuple[int, int, int, int]] = []
        self.ends: list[int] = []
        for exponents, p, q in terms:
            coefficient_bits = max(coefficient_bits, p.bit_length() + q.bit_length())
            node, total = 0, 0
            for i, e in enumerate(exponents):
                if not e:
                    continue
                total += e
                if e > highest.get(i, 0):
                    highest[i] = e
                known = nodes.get((node, i, e))
                if known is None:
                    known = nodes[node, i, e] = len(nodes) + 1
                    steps.append((known, node, i, e))
                node = known
            degree = max(degree, total)
            self.ends.append(node)
        self.bits = base_bits + coefficient_bits + degree * magnitude_bits
        self.used = sorted(highest.items())  # (variable, highest power): the slots, in order
        first, slot = {}, 0
        for i, top in self.used:
            first[i], slot = slot - 1, slot + top
        self.steps = [(node, parent, first[i] + e) for node, parent, i, e in steps]
        self.size = len(nodes) + 1
        with flint.ctx.workprec(self.bits):
            self.coefficients = [flint.arb(p) / q if q != 1 else flint.arb(p) for _, p, q in terms]

    def __call__(self, point: Point) -> flint.arb:
        with flint.ctx.workprec(self.bits):
            powers = []
            for i, top in self.used:
                value = power = point[self.names[i]]
                powers.append(power)
                for _ in range(top - 1):
                    power = power * value
                    powers.append(power)
            products = [flint.arb(1)] * self.size  # node 0 is 1; every other is set before it is read
            for node, parent, slot in self.steps:
                products[node] = powers[slot] if parent == 0 else products[parent] * powers[slot]
            total = flint.arb(0)
            for coefficient, end in zip(self.coefficients, self.ends):
                total += coefficient if end == 0 else coefficient * products[end]
            return total


class Horner:
    """The ball value of a polynomial in the one variable ``names[variable]`` (a factor its
    witness's exact values left univariate), given by its ``terms`` as for ``Evaluator``, at the
    precision ``Evaluator`` would take: by Horner's rule in C (python-flint's ``arb_poly``), one
    call where the ``Evaluator``'s program takes a Python step a term, and no program to compile.

    >>> point = {"x": flint.arb(2).sqrt(), "y": flint.arb(3)}
    >>> line = Horner([((1, 0), 1, 1), ((0, 0), -1, 1)], ("x", "y"), 128, variable=0)  # x - 1
    >>> line.bits, (line(point) - point["x"] + 1).contains(0)
    (131, True)
    """

    def __init__(self, terms: Sequence[Term], names: Sequence[str], base_bits: int, magnitude_bits: int = 1, *,
                 variable: int) -> None:
        degree = max(exponents[variable] for exponents, _, _ in terms)
        self.bits = base_bits + max(p.bit_length() + q.bit_length() for _, p, q in terms) + degree * magnitude_bits
        self.name = names[variable]
        dense = [flint.fmpq(0)] * (degree + 1)
        for exponents, p, q in terms:
            dense[exponents[variable]] = flint.fmpq(p, q)
        with flint.ctx.workprec(self.bits):
            self.poly = flint.arb_poly(dense)  # each coefficient rounded to a ball that holds it

    def __call__(self, point: Point) -> flint.arb:
        with flint.ctx.workprec(self.bits):
            return self.poly(point[self.name])


def unreal_factors(backend: Backend[P], factors: Sequence[P], parameters: Collection[str]
                   ) -> tuple[list[P], list[P]]:
    """Split ``factors`` into (kept, dropped): dropped, those in the ``parameters`` alone
    (dimensions, a derivation's inputs) that have no real zero, proved by ``unreal``.

    Such a factor is content (free of the unknowns) that no real mechanism makes vanish,
    so the true motion never lies on it: ``b**2 + 160000`` in the arm's value polynomial
    comes from the half-angle substitution's ``t = -+i`` at ``b = +-400i``, not from any
    configuration. Witnesses would drop it too, but eliminations without witnesses (the
    extremum's stationary and value polynomials) have only this test. A parameter factor
    with a real zero is left to the witnesses.
    """
    kept: list[P] = []
    dropped: list[P] = []
    for factor in factors:
        alone = backend.variables(factor) <= set(parameters)
        (dropped if alone and unreal(backend.terms(factor)) else kept).append(factor)
    return kept, dropped


def unreal(terms: Sequence[Term]) -> bool:
    """True when the polynomial of ``terms`` (exponents, numerator, denominator) is proved to
    have no real zero: a nonzero constant; a sum of positive multiples of even powers plus a
    positive number (every exponent even, every coefficient of one sign, the constant term
    there); in one variable, when python-flint's certified roots are all off the real line.
    False means not proved.

    >>> unreal([((2,), 1, 1), ((0,), 160000, 1)]), unreal([((3,), 1, 1), ((0,), 1, 1)])
    (True, False)
    >>> unreal([((4,), 1, 1), ((1,), 1, 1), ((0,), 1, 1)])  # x**4 + x + 1: no real root, by its roots
    True
    """
    used = sorted({i for exponents, _, _ in terms for i, e in enumerate(exponents) if e})
    if not used:
        return any(p for _, p, _ in terms)
    signs = {p > 0 for _, p, _ in terms}
    constant = any(not any(e) for e, _, _ in terms)
    if len(signs) == 1 and constant and all(e % 2 == 0 for exponents, _, _ in terms for e in exponents):
        return True
    if len(used) > 1:
        return False
    coefficients: list[flint.fmpq] = [flint.fmpq(0)] * (max(e[used[0]] for e, _, _ in terms) + 1)
    for exponents, p, q in terms:
        coefficients[exponents[used[0]]] = flint.fmpq(p, q)
    return not real_roots(flint.fmpq_poly(coefficients))


def select_factors(backend: Backend[P], factors: Sequence[P], witness_groups: WitnessGroups, check: bool = True
                   ) -> tuple[list[P], list[P]]:
    """Split ``factors`` into (kept, dropped) by the witnesses; keep all without witnesses.

    With ``check``, every witness must also have a kept factor vanishing there (else a
    ComputationError: the eliminant does not describe the motion). Intermediate eliminants
    skip it; the final one answers for them.
    """
    groups = [g for g in witness_groups if g]
    if not groups or not factors:
        return list(factors), []
    return _select(factors, groups, _values(backend, factors, groups, *_precision(groups)), check)


def vanishes_at(backend: Backend[P], factor: P, points: Sequence[Point]) -> bool:
    """Whether ``factor``'s ball contains zero at every one of ``points``, evaluated as
    ``select_factors`` evaluates: its one factor kept at every point, without its bookkeeping
    of groups and factors.

    >>> import flint
    >>> from algkin.eliminate.backends import FlintBackend
    >>> engine = FlintBackend(("x", "y"))
    >>> x, y = engine.ctx.gens()
    >>> points = [{"x": flint.arb(2).sqrt(), "y": flint.arb(2)}, {"x": -flint.arb(2).sqrt(), "y": flint.arb(2)}]
    >>> vanishes_at(engine, x**2 - y, points), vanishes_at(engine, x - y + 2, points)
    (True, False)
    """
    if not points:
        return True
    value = _values(backend, [factor], [points], *_precision([points]))
    return all(value(0, point).contains(0) for point in points)


def _precision(groups: WitnessGroups) -> tuple[int, int]:
    """``(base bits, magnitude bits)`` of the witnesses: enough for a factor's own coefficients
    and powers on top of the witnesses' precision (``Evaluator``)."""
    scales = [point.scale if isinstance(point, Witness) else _scale(point) for group in groups for point in group]
    witness_bits = max(bits for bits, _ in scales)
    magnitude_bits = max(1, math.ceil(math.log2(1 + max(magnitude for _, magnitude in scales))))
    return MARGIN_BITS + witness_bits, magnitude_bits


def _values(backend: Backend[P], factors: Sequence[P], groups: WitnessGroups, base_bits: int, magnitude_bits: int
            ) -> Callable[[int, Point], flint.arb]:
    """``(i, point) -> ball of factor i at point``, its exactly known coordinates substituted
    exactly first: one evaluator per factor and set of exact values, which branches share at
    the same input (on the symbolic four-bar's curve, the dimensions take 239 terms down to
    25). Exact values can only sharpen a ball: a factor that vanishes there still does."""
    held = [backend.variables(f) for f in factors]
    assignments, which = [], {}  # the distinct exact assignments, and each witness's
    for point in (p for group in groups for p in group):
        exact = _exact(point)
        if exact not in assignments:  # compared, not hashed: fmpq hashes in Python
            assignments.append(exact)
        which[id(point)] = assignments.index(exact)
    evaluators: dict[tuple[int, int | None], Evaluator | Horner] = {}

    def value(i: int, point: Point) -> flint.arb:
        fixed = {n: v for n, v in assignments[which[id(point)]].items() if n in held[i]}
        key = (i, which[id(point)] if fixed else None)
        if key not in evaluators:
            poly = backend.specialize(factors[i], fixed) if fixed else factors[i]
            free = held[i] - fixed.keys()
            evaluators[key] = Horner(backend.terms(poly), backend.names, base_bits, magnitude_bits,
                                     variable=backend.names.index(next(iter(free)))) if len(free) == 1 else \
                Evaluator(backend.terms(poly), backend.names, base_bits, magnitude_bits)
        return evaluators[key](point)

    return value


def _exact(point: Point) -> Mapping[str, flint.fmpq]:
    """The coordinates of ``point`` known exactly (none for a plain dict of balls)."""
    return getattr(point, "exact", {})


def _bits(ball: flint.arb) -> int:
    """Bits of the ball's midpoint mantissa: the precision it was computed at."""
    return int(ball.mid().man_exp()[0]).bit_length() if ball.mid() != 0 else 0


def _select(factors: Sequence[P], groups: WitnessGroups, value: Callable[[int, Point], flint.arb], check: bool
            ) -> tuple[list[P], list[P]]:
    known: dict[tuple[int, int, int], bool] = {}

    def vanishes(i: int, g: int, w: int) -> bool:
        if (i, g, w) not in known:
            known[i, g, w] = value(i, groups[g][w]).contains(0)
        return known[i, g, w]

    kept: list[int] = []  # indices
    dropped: list[P] = []
    for i, factor in enumerate(factors):
        if any(all(vanishes(i, g, w) for w in range(len(group))) for g, group in enumerate(groups)):
            kept.append(i)
        else:
            dropped.append(factor)
    for g, group in enumerate(groups) if check else ():
        for w in range(len(group)):
            if not any(vanishes(i, g, w) for i in kept):
                raise ComputationError(NOT_THE_MOTION)
    return [factors[i] for i in kept], dropped
