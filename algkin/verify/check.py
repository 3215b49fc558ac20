"""Closed forms and eliminants checked against independent numeric solutions, proved in balls.

For a batch of sampled inputs at once: the original system is solved in floats
(``solve.solve_floats``, vectorised over samples and Newton starts; no closed form
involved); every candidate is proved to enclose exactly one root of the original equations
(``balls.BlockCertifier``, in python-flint ``arb``: the quadratic on two circles' radical axis,
else a Krawczyk test); each root is labelled by
the signs of the branch indicators on its enclosure, decided or the sample is set aside as
near a degenerate configuration; each real closed-form branch, evaluated in balls on the
same inputs, is compared with the root of the same label; and every polynomial (eliminant,
curve) is evaluated on every root's enclosure. A sample whose real branches lack a root
of their label is solved again with more starts before the check says so.
"""

from __future__ import annotations

import enum
import functools
import operator
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any, TypeAlias

import attrs
import flint
import numpy as np
import sympy
from numpy.typing import NDArray

from ..evaluate import ARB, NUMPY
from ..evaluate.program import ArrayProgram, BallProgram, Floats, compile_program
from ..runtime import progress
from ..runtime.frozen import FrozenDict, frozen
from ..system import System, input_values
from .balls import Block, BlockCertifier, certifier_of, certify_parameters
from .minimal import FactorCheck, structure_failures
from .residual import ExactValue, Polynomial, PolynomialLike, fraction, polynomial_of
from .solve import STARTS, blocks_of, solve_floats
from .tally import Tally

__all__ = ["Verification", "Status", "CheckSetup", "verify_branches", "WORKING_BITS", "real_floats", "decided_real"]

WORKING_BITS = 192
TOLERANCE = 1e-30  # relative residual a polynomial must reach on every root (the enclosures reach ~1e-50)
MAX_ERROR = 1e-27  # a closed form's largest distance from the root of its label, relative to its size
MAX_DRAWS = 50  # inputs drawn per sample asked for, looking for where the mechanism assembles
RETRY_STARTS = 8 * STARTS
CHUNK = 500  # samples solved and proved together

# (point, expression, label where it is positive, label where it is negative)
Indicator: TypeAlias = tuple[str, sympy.Expr, str, str]
# (point -> label, unknown -> closed form, name -> discriminant): real where every discriminant is positive
BranchForms: TypeAlias = tuple[Mapping[str, str], Mapping[str, sympy.Expr], Mapping[str, sympy.Expr]]
Label: TypeAlias = tuple[tuple[str, str], ...]  # (point, label) pairs, sorted by point
Root: TypeAlias = list[flint.arb]  # the unknowns' enclosures, in the system's order
_UNSET = flint.arb("nan")  # an unknown's ball before its block is proved


def _indicators(indicators: Iterable[Indicator]) -> tuple[Indicator, ...]:
    return tuple(indicators)


def _frozen_forms(branches: Iterable[BranchForms]) -> tuple[BranchForms, ...]:
    return tuple((frozen(labels), frozen(values), frozen(discriminants)) for labels, values, discriminants in branches)


@attrs.frozen(kw_only=True)
class CheckSetup:
    """What a check is of: the system with its dimensions fixed (``system``), the branch
    ``indicators`` (``(point, expression, positive label, negative label)``), the closed-form
    ``branches`` (``(labels, values, discriminants)``), each input's range in radians or its
    units (``inputs``) and a value for each symbolic parameter (``parameters``)."""

    system: System
    indicators: tuple[Indicator, ...] = attrs.field(converter=_indicators)  # typed: ``tuple`` reads as Iterable[_T_co]
    branches: tuple[BranchForms, ...] = attrs.field(converter=_frozen_forms)
    inputs: FrozenDict[str, tuple[float, float]] = attrs.field(converter=frozen)
    parameters: FrozenDict[str, ExactValue] = attrs.field(converter=frozen)


class Status(str, enum.Enum):
    """How a check ended: its JSON strings (``passed``, ``failed``, ``skipped``)."""

    PASSED = "passed"
    FAILED = "failed"
    SKIPPED = "skipped"  # no samples asked for


@attrs.frozen
class Verification:
    """What the check found: the largest error and how it ended (an immutable, hashable value).

    ``status`` is ``Status.PASSED``, ``FAILED`` or ``SKIPPED`` (no samples asked for); a check
    that compared nothing never passes.

    >>> Verification.skipped().passed, Verification.skipped().status.value
    (False, 'skipped')
    """

    samples: int
    max_abs_error: float
    status: Status
    compared: int = 0
    near_degenerate: int = 0
    max_polynomial_residual: FrozenDict[str, float] = attrs.field(factory=FrozenDict, converter=frozen)
    failures: tuple[str, ...] = ()
    evaluated: int = 0  # numeric solutions the polynomials were evaluated at
    # per polynomial, per kept factor
    smallest_factor_residual: FrozenDict[str, tuple[float, ...]] = attrs.field(factory=FrozenDict,
                                                                              converter=frozen)
    max_rel_error: float = 0.0  # the largest error over the size of its configuration: scale-free

    @property
    def passed(self) -> bool:
        return self.status is Status.PASSED

    @classmethod
    def skipped(cls) -> Verification:
        """No verification was asked for (zero samples)."""
        return cls(0, 0.0, Status.SKIPPED)

    def to_json(self) -> dict[str, Any]:
        return {
            "samples": self.samples,
            "status": self.status.value,
            "max_abs_error": self.max_abs_error,
            "max_rel_error": self.max_rel_error,
            "passed": self.passed,
            "compared": self.compared,
            "evaluated": self.evaluated,
            "near_degenerate": self.near_degenerate,
            "max_polynomial_residual": dict(self.max_polynomial_residual),
            "smallest_factor_residual": {k: list(v) for k, v in self.smallest_factor_residual.items()},
            "failures": list(self.failures[:10]),
            "method": ("Newton multistart on the original system (floats, all samples at once), "
                       f"every root proved in arb at {WORKING_BITS} bits: two circles by the quadratic on their "
                       "radical axis, other blocks by a Krawczyk test"),
        }


def _verification(report: Tally, residuals: Mapping[str, float],
                  factors: Mapping[str, Sequence[float]]) -> Verification:
    """The check's result, passed when nothing failed and every error is within its tolerance."""
    passed = (not report.failures and report.max_rel_error <= MAX_ERROR
              and all(v <= TOLERANCE for v in residuals.values()))
    return Verification(report.samples, report.max_abs_error, Status.PASSED if passed else Status.FAILED,
                        compared=report.compared, near_degenerate=report.near_degenerate,
                        max_polynomial_residual=dict(residuals), failures=tuple(report.failures),
                        evaluated=report.evaluated,
                        smallest_factor_residual={k: tuple(v) for k, v in factors.items()},
                        max_rel_error=report.max_rel_error)


class _Plan:
    """Everything compiled once per check: solver, certifier, indicators, branches, polynomials."""

    def __init__(self, setup: CheckSetup, *, polynomials: Mapping[str, PolynomialLike] | None,
                 factors: Mapping[str, Sequence[PolynomialLike]] | None) -> None:
        system, indicators, branches, parameters = setup.system, setup.indicators, setup.branches, setup.parameters
        self.system = system
        self.blocks = blocks_of(system)
        self.certifiers: list[tuple[Block, BlockCertifier, list[str]]] = [
            (block, certifier_of(block), certify_parameters(block)) for block in self.blocks.blocks]
        self.known = [v for v in system.variables if v not in system.unknowns]
        self.parameters = {n: fraction(v) for n, v in parameters.items()}
        self._balls_made: tuple[int | None, dict[str, flint.arb]] = (None, {})
        # a polynomial may keep the dimensions symbolic: they take their exact values in it
        dimensions = {n: v for n, v in self.parameters.items() if n not in system.variables}
        names = list(system.unknowns) + self.known
        self.labels = [(point, positive, negative) for point, _, positive, negative in indicators]
        self.indicators: BallProgram = compile_program([expr for _, expr, _, _ in indicators], names, ARB)
        self.branches = [_Branch(labels, values, discriminants, self.known, unknowns=system.unknowns)
                         for labels, values, discriminants in branches]
        # every branch's discriminants and closed forms in one program: they share subexpressions
        self.closed: BallProgram = compile_program([e for b in self.branches for e in b.discriminants + b.values],
                                                   self.known, ARB)
        # where each branch's discriminants start, its closed forms start and end in ``closed``'s values
        ends = np.cumsum([0] + [len(b.discriminants) + len(b.values) for b in self.branches]).tolist()
        self.spans = [(start, start + len(b.discriminants), end) for b, start, end in zip(self.branches, ends, ends[1:])]
        self.polynomials = {n: polynomial_of(p, names, dimensions) for n, p in (polynomials or {}).items()}
        self.factors = FactorCheck(factors, lambda f: polynomial_of(f, names, dimensions), self.polynomials.values())
        self.index = {u: k for k, u in enumerate(system.unknowns)}
        # A sample's balls are one list, ``names`` in order (its root, then its known values): each
        # block certified reads its parameters from it by position and writes its unknowns into it.
        slot = {n: k for k, n in enumerate(names)}
        self.steps = [(certify, _picker([slot[n] for n in parameters]), [slot[n] for n in block.names])
                      for block, certify, parameters in self.certifiers]
        self.nonnegative = [self.index[n] for n in system.nonnegative]
        # every polynomial evaluated on a root, once however many names it has (a kept factor may be
        # the polynomial itself)
        self.evaluated = list({id(p): p for p in [*self.polynomials.values(), *self.factors.polynomials()]}.values())
        self.ids = [id(p) for p in self.evaluated]
        self.used = {n for p in self.evaluated for n in p.names}  # the variables their magnitudes read
        self.worst = [(n, self.ids.index(id(p))) for n, p in self.polynomials.items()]

    def floats(self, angles: Mapping[str, Floats]) -> dict[str, Floats]:
        """The known variables as float arrays over the samples (``angles``: input -> radians, or lengths)."""
        count = len(next(iter(angles.values()), [0]))
        values = {n: np.full(count, float(v)) for n, v in self.parameters.items()}
        for name, angle in angles.items():
            values.update(input_values(self.system.inputs[name], angle))
        return values

    def balls(self, angles: Mapping[str, Floats], count: int) -> list[list[flint.arb]]:
        """The known variables of each of the ``count`` samples as balls, in ``self.known`` order."""
        parameters = self._parameter_balls()
        inputs = [(self.system.inputs[name], angle.tolist()) for name, angle in angles.items()]
        samples = []
        for k in range(count):
            values = dict(parameters)
            for variables, angle in inputs:
                values.update(input_values(variables, flint.arb(angle[k])))
            samples.append([values[n] for n in self.known])
        return samples

    def _parameter_balls(self) -> dict[str, flint.arb]:
        """The parameters' exact values as balls at the working precision, made once per precision."""
        precision = flint.ctx.prec
        if self._balls_made[0] != precision:
            self._balls_made = (precision, {n: ARB.number(v.numerator, v.denominator)
                                            for n, v in self.parameters.items()})
        return self._balls_made[1]

    def any_real(self, floats: Mapping[str, Floats]) -> NDArray[np.bool_]:
        """Per sample, whether some branch's discriminants are all positive (where to sample)."""
        real = np.zeros(len(next(iter(floats.values()))), dtype=bool)
        for branch in self.branches:
            real |= branch.real_floats(floats, self.known)
        return real


def _picker(slots: list[int]) -> Callable[[list[flint.arb]], Sequence[flint.arb]]:
    """The values at ``slots`` of a list, in their order: ``operator.itemgetter``, a tuple always.

    >>> _picker([2, 0])("abc"), _picker([1])("abc"), _picker([])("abc")
    (('c', 'a'), ('b',), ())
    """
    if len(slots) > 1:
        return operator.itemgetter(*slots)
    return (lambda values: (values[slots[0]],)) if slots else (lambda values: ())


class _Branch:
    def __init__(self, labels: Mapping[str, str], values: Mapping[str, sympy.Expr],
                 discriminants: Mapping[str, sympy.Expr], known: list[str], *, unknowns: Sequence[str]) -> None:
        self.key = tuple(sorted(labels.items()))
        self.said = f"branch {dict(self.key)}"  # how its failures name it
        self.said_off = f"{self.said}: its closed form is"  # how an error past its tolerance is said
        self.unknowns = list(values)
        self.slots = [list(unknowns).index(u) for u in self.unknowns]  # where each value's unknown is in a root
        self.values, self.discriminants = list(values.values()), list(discriminants.values())
        self.discriminant_floats: ArrayProgram = compile_program(self.discriminants, known, NUMPY)

    def real_floats(self, floats: Mapping[str, Floats], known: Sequence[str]) -> NDArray[np.bool_]:
        return real_floats(self.discriminant_floats, floats, known)


def real_floats(discriminants: ArrayProgram, floats: Mapping[str, Floats], known: Sequence[str]) -> NDArray[np.bool_]:
    """Per sample, whether every discriminant (a numpy program of ``known``) is positive in floats; True
    where floats cannot say (a coefficient past a float's range: dimensions given as ratios of 60-digit
    integers), the balls deciding there."""
    count = len(next(iter(floats.values())))
    try:
        with np.errstate(all="ignore"):  # a later discriminant holds an earlier one's sqrt: nan where that is negative
            values = discriminants(*(floats.get(n, np.zeros(count)) for n in known))
    except OverflowError:  # an integer of the program made a float
        return np.ones(count, bool)
    return np.all([np.broadcast_to(v, (count,)) > 0 for v in values], axis=0) if values else np.ones(count, bool)


def verify_branches(setup: CheckSetup, *, samples: int = 50, seed: int = 0,
                    polynomials: Mapping[str, PolynomialLike] | None = None,
                    factors: Mapping[str, Sequence[PolynomialLike]] | None = None,
                    where: Mapping[str, Sequence[tuple[float, float]]] | None = None) -> Verification:
    """Check ``setup``'s branches on ``samples`` inputs where something could be compared.

    ``polynomials`` (name -> expression) must vanish on every root and be
    squarefree. ``factors`` (name -> the polynomial's kept factors) must multiply to it, and
    each must vanish by itself on some root: otherwise it is extraneous (see ``minimal``).
    ``where`` (input -> intervals within its range, in its units) confines the samples to where
    something may assemble, when that is a small part of the range (``algkin.derivation.assembles``).
    """
    spans = {n: list((where or {}).get(n) or [span]) for n, span in setup.inputs.items()}
    if not spans:  # outputs of fixed points alone: one configuration, checked once
        samples = min(samples, 1)
    rng = np.random.default_rng(seed)
    report = Tally()
    useful = drawn = 0
    with flint.ctx.workprec(WORKING_BITS), progress.counting(samples, "samples"):
        # the plan's exact dimensions become balls at this working precision
        plan = _Plan(setup, polynomials=polynomials, factors=factors)
        worst = {n: 0.0 for n in plan.polynomials}
        # An input where the mechanism does not assemble compares nothing. The first ``samples``
        # inputs are solved wherever they fall (the numeric solution must then find nothing
        # either); after those, more are drawn, and solved only where some branch is real, until
        # ``samples`` inputs have compared something (at most twice as many solved in all).
        while useful < samples and drawn < samples * MAX_DRAWS and report.samples < 2 * samples:
            angles, drawn = _batch(plan, spans, rng, drawn=drawn, needed=samples - useful,
                                   solvable=2 * samples - report.samples, most=samples * MAX_DRAWS, first=not drawn)
            count = len(next(iter(angles.values()), [None]))
            if not count:
                break
            for start in range(0, count, CHUNK):  # in chunks, so that progress shows on long runs
                useful += _check_batch(report, plan, {n: a[start:start + CHUNK] for n, a in angles.items()},
                                       rng=rng, worst=worst)
    _require_comparisons(report, branches=bool(setup.branches), polynomials=bool(plan.polynomials))
    report.failures += plan.factors.failures(TOLERANCE, report.evaluated)
    report.failures += structure_failures(polynomials or {}, factors)
    return _verification(report, worst, plan.factors.to_json())


def _batch(plan: _Plan, spans: Mapping[str, Sequence[tuple[float, float]]], rng: np.random.Generator, *,
           drawn: int, needed: int, solvable: int, most: int, first: bool) -> tuple[dict[str, Floats], int]:
    """The next inputs to solve (input -> radians) and the draws counted so far."""
    if first:
        return {n: _uniform(rng, pieces, needed) for n, pieces in spans.items()}, needed
    pool = min(most - drawn, max(8 * needed, 64))
    angles = {n: _uniform(rng, pieces, pool) for n, pieces in spans.items()}
    chosen = np.flatnonzero(plan.any_real(plan.floats(angles)))[:min(needed, solvable)]
    used = int(chosen[-1]) + 1 if len(chosen) == min(needed, solvable) and len(chosen) else pool
    return {n: a[chosen] for n, a in angles.items()}, drawn + used


def _uniform(rng: np.random.Generator, pieces: Sequence[tuple[float, float]], count: int) -> Floats:
    """``count`` draws uniform on the union of the disjoint intervals ``pieces`` (one interval: numpy's own).

    >>> draws = _uniform(np.random.default_rng(0), [(0.0, 1.0), (3.0, 4.0)], 1000)
    >>> bool(np.all((draws <= 1) | (draws >= 3))), bool(200 < np.sum(draws < 2) < 800)
    (True, True)
    """
    if len(pieces) == 1:
        (lo, hi), = pieces
        return rng.uniform(lo, hi, count)
    widths = np.array([hi - lo for lo, hi in pieces])
    ends = np.cumsum(widths)
    along = rng.uniform(0.0, float(ends[-1]), count)
    index = np.minimum(np.searchsorted(ends, along, side="right"), len(pieces) - 1)
    starts = np.array([lo for lo, _ in pieces])
    return np.asarray(starts[index] + along - (ends[index] - widths[index]), dtype=np.float64)


def _check_batch(report: Tally, plan: _Plan, angles: Mapping[str, Floats], *, rng: np.random.Generator,
                 worst: dict[str, float]) -> int:
    """Solve, prove and compare every sample of the batch; how many compared something."""
    count = len(next(iter(angles.values()), [None]))
    samples = [_Sample(known) for known in plan.balls(angles, count)]
    floats = plan.floats(angles)
    _certified(plan, floats, samples, rng=rng, starts=STARTS)
    missing = [k for k, sample in enumerate(samples) if sample.lacks_a_root(plan)]
    if missing:  # Newton's random starts may miss a root: those samples again, with more starts
        _certified(plan, {n: v[missing] for n, v in floats.items()}, [samples[k] for k in missing], rng=rng,
                   starts=RETRY_STARTS)
    magnitudes = _magnitudes(plan, floats, samples)
    useful = 0
    for sample, sizes in zip(samples, magnitudes):
        before = (report.compared, report.evaluated)
        _check_sample(report, plan, sample, magnitudes=sizes, worst=worst)
        if (report.compared, report.evaluated) != before:
            useful += 1
            progress.step()
    return useful


@dataclass
class _Sample:
    """One input: its known values in balls, its proved roots, their labels, its real branches."""

    known: list[flint.arb]
    roots: list[Root] = field(default_factory=list)
    doubtful: bool = False  # some candidate could not be proved: near a degenerate configuration
    # per root, ``None`` where an indicator's sign is undecided
    labels: list[Label | None] = field(default_factory=list)
    real: list[bool | None] = field(default_factory=list)  # per branch: True, False, or None near its boundary
    values: list[list[flint.arb | int]] = field(default_factory=list)  # per branch, its closed forms in balls

    def classify(self, plan: _Plan) -> None:
        self.labels = [_labels(plan, root, self.known) for root in self.roots]
        closed = plan.closed(*self.known)
        self.real = [decided_real(closed[start:middle]) for start, middle, _ in plan.spans]
        self.values = [closed[middle:end] for _, middle, end in plan.spans]

    def lacks_a_root(self, plan: _Plan) -> bool:
        """Whether some branch decided real has no root of its label (Newton may have missed it)."""
        if self.doubtful or None in self.labels:
            return False
        return any(real and branch.key not in self.labels for branch, real in zip(plan.branches, self.real))


def _certified(plan: _Plan, floats: Mapping[str, Floats], samples: list[_Sample], *, rng: np.random.Generator,
               starts: int) -> None:
    """Set each sample's proved roots (and whether some candidate could not be proved); ``floats``
    holds the known variables' float arrays over the samples."""
    candidates = solve_floats(plan.blocks, floats, rng, starts)
    rows = [np.stack([candidates.values[n] for n in block.names], axis=1).tolist() for block, _, _ in plan.certifiers]
    lineage = [row.tolist() for row in candidates.lineage]
    # (block, partial solution) -> its unknowns' balls: candidates share their first blocks
    proved: dict[tuple[int, int], list[flint.arb] | None] = {}
    found: list[tuple[list[Root], bool]] = [([], False) for _ in samples]
    unset = [_UNSET] * len(plan.index)
    for row, k in enumerate(candidates.owner.tolist()):
        balls = unset + samples[k].known  # the root's unknowns, each set by its block, then the known values
        enclosure: list[flint.arb] | None = None
        for b, (certify, parameters, slots) in enumerate(plan.steps):
            key = (b, lineage[b][row])
            if key in proved:
                enclosure = proved[key]
            else:
                # the Jacobian's inverse made only if the proof comes to it
                enclosure = proved[key] = certify(rows[b][row], parameters(balls),
                                                  functools.partial(candidates.inverses.at, *key))
            if enclosure is None:
                break
            for i, ball in zip(slots, enclosure):
                balls[i] = ball
        roots, doubtful = found[k]
        if enclosure is None:
            found[k] = roots, True
        else:
            root = balls[:len(unset)]
            for other in roots:
                if all(map(flint.arb.overlaps, root, other)):
                    break  # a root found already
            else:
                roots.append(root)
    for sample, (roots, doubtful) in zip(samples, found):
        sample.roots, sample.doubtful = _nonnegative(plan, roots, doubtful)
        sample.classify(plan)


def _nonnegative(plan: _Plan, roots: list[Root], doubtful: bool) -> tuple[list[Root], bool]:
    """Roots whose distances are not negative (a distance that might be either way is doubtful)."""
    kept = []
    for root in roots:
        signs = [root[k] for k in plan.nonnegative]
        if all(v >= 0 for v in signs):
            kept.append(root)
        elif not any(v < 0 for v in signs):
            doubtful = True
    return kept, doubtful


def _labels(plan: _Plan, root: Root, known: list[flint.arb]) -> Label | None:
    """The root's label per point, or ``None`` where an indicator's sign is undecided."""
    labels = {}
    for (point, positive, negative), value in zip(plan.labels, plan.indicators(*root, *known)):
        if value > 0:
            labels[point] = positive
        elif value < 0:
            labels[point] = negative
        else:
            return None
    return tuple(sorted(labels.items()))


def decided_real(values: Sequence[flint.arb | int]) -> bool | None:
    """``True`` or ``False`` where the branch (its discriminants' ``values``) is decided real or not,
    ``None`` near its boundary."""
    if all(v > 0 for v in values):
        return True
    return False if any(v < 0 for v in values) else None


def _magnitudes(plan: _Plan, floats: Mapping[str, Floats], samples: list[_Sample]) -> list[list[list[float]]]:
    """Per sample, per root, per polynomial of ``plan.evaluated``: the sum of its terms' absolute
    values (floats, one pass)."""
    owners = [k for k, sample in enumerate(samples) for _ in sample.roots]
    if not owners or not plan.polynomials:
        return [[[] for _ in sample.roots] for sample in samples]
    floats = {n: v[owners] for n, v in floats.items() if n in plan.used}
    flat = [root for sample in samples for root in sample.roots]
    for u, k in plan.index.items():
        if u in plan.used:
            floats[u] = np.array([float(root[k]) for root in flat])
    sizes = np.stack([np.broadcast_to(p.magnitude(floats), (len(flat),)) for p in plan.evaluated], axis=1).tolist()
    rows, start = [], 0
    for sample in samples:
        rows.append(sizes[start:start + len(sample.roots)])
        start += len(sample.roots)
    return rows


def _check_sample(report: Tally, plan: _Plan, sample: _Sample, *, magnitudes: list[list[float]],
                  worst: dict[str, float]) -> None:
    """Evaluate the polynomials on the sample's roots and compare its branches."""
    report.samples += 1
    for root, sizes in zip(sample.roots, magnitudes):
        residuals = _residuals(plan.evaluated, root + sample.known, sizes)
        for name, k in plan.worst:
            worst[name] = max(worst[name], residuals[k])
        plan.factors.see(dict(zip(plan.ids, residuals)))
    report.evaluated += len(sample.roots) if plan.polynomials else 0
    if sample.doubtful or None in sample.labels or None in sample.real:
        report.near_degenerate += 1
        return
    _compare(report, plan, sample)


def _residuals(polynomials: Sequence[Polynomial], values: Sequence[flint.arb], sizes: Sequence[float]) -> list[float]:
    """``|p(K)| / sum |terms|`` of each polynomial at one root (``values``: its balls and the known
    values', as the polynomials' names), given each one's ``sizes``."""
    residuals = []
    for polynomial, size in zip(polynomials, sizes):
        upper = float(polynomial.at(values).abs_upper())  # the upper bound of |p(K)|
        residuals.append(upper / size if size else upper)
    return residuals


def _compare(report: Tally, plan: _Plan, sample: _Sample) -> None:
    by_label: dict[Label | None, list[Root]] = {}
    for labels, root in zip(sample.labels, sample.roots):
        by_label.setdefault(labels, []).append(root)
    for branch, real, values in zip(plan.branches, sample.real, sample.values):
        if not real:
            continue
        matches = by_label.pop(branch.key, [])
        if len(matches) != 1:
            report.failures.append(f"{branch.said}: {len(matches)} numeric solutions with its label")
            continue
        error, size = _error(branch, values, matches[0]), _size(matches[0])
        # the detail is only read past the tolerance: written only there
        detail = "" if error <= MAX_ERROR * size else \
            f"{error:.3g} from the root of its label (relative {error / size:.3g})"
        report.error(error, scale=size, tolerance=MAX_ERROR, said=branch.said_off, detail=detail)
        report.compared += 1
    for key in by_label:
        # every label is decided here (_check_sample compares no sample with an undecided one)
        labelled = dict(key)  # type: ignore[arg-type]
        report.failures.append(f"numeric solution labelled {labelled} has no real closed-form branch")


def _size(root: Root) -> float:
    """The configuration's size: its largest coordinate (1 where all are 0)."""
    return max(map(abs, map(float, root))) or 1.0


def _error(branch: _Branch, values: list[flint.arb | int], root: Root) -> float:
    """The largest distance between the closed form and the root it must equal (an upper bound)."""
    error = 0.0
    for k, value in zip(branch.slots, values):
        gap = value - root[k]
        error = max(error, float(gap.abs_upper()) if gap.is_finite() else float("inf"))  # the upper bound of |gap|
    return error


def _require_comparisons(report: Tally, *, branches: bool, polynomials: bool) -> None:
    """A check that compared nothing fails, saying why, rather than passing vacuously."""
    if not (branches or polynomials):
        report.failures.append("nothing to compare: no branch and no polynomial was given")
    if branches:
        report.require_compared("branch value")
    if polynomials and not report.evaluated:
        report.failures.append(f"no numeric solution to evaluate the polynomials at on {report.samples} samples")
