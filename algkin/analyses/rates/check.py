"""Velocities and accelerations checked against central differences of independent numeric solutions.

At seeded random inputs ``theta`` (or lengths, for a length input) the original system is solved, with no closed form, at
``theta - h``, ``theta`` and ``theta + h`` (``h = 2**-60``): in floats once at ``theta``
(``verify.solve``), then each candidate is proved in python-flint balls at each of the
three inputs (``verify.balls``, block by block) and tightened by Krawczyk steps on the
whole system to the working precision (448 bits). Each root is labelled by the branch
indicators, as ``verify`` does, and paired with the branch of its label at all three
inputs. Then, per coordinate ``x``,

    velocity     ~ (x(theta + h) - x(theta - h)) / (2 h)
    acceleration ~ (x(theta + h) - 2 x(theta) + x(theta - h)) / h**2

in balls, compared with the derivative closed forms evaluated in balls at ``theta``. The
balls bound the rounding; the differences' truncation error, ``h**2/6 x'''`` and
``h**2/12 x''''`` (about 1e-37 of the motion's scale, away from a toggle), is not in the
bound, so this is a numerical check, not a proof: an error must stay below
``MAX_REL_ERROR`` of the larger of the configuration's size and the largest rate of its
branch there. A check that compared nothing never passes.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any, TypeAlias

import attrs
import flint
import numpy as np
import sympy
from flint import arb, arb_mat

from ...evaluate import ARB, NUMPY
from ...evaluate.program import BallProgram, compile_program
from ...system import System, input_values, symbol
from ...verify.balls import certifier_of, certify_parameters
from ...verify.check import Status, decided_real, real_floats
from ...verify.solve import STARTS, blocks_of, solve_floats
from ...verify.tally import Tally

__all__ = ["RatesCheck", "check_rates", "WORKING_BITS", "STEP_BITS", "MAX_REL_ERROR"]

WORKING_BITS = 448
STEP_BITS = 60  # h = 2**-60: truncation ~h**2 = 1e-36; rounding ~2**-440 / h**2, far below
MAX_REL_ERROR = 1e-24  # what a rate may miss its central difference by, relative to its scale
MAX_DRAWS = 50  # inputs drawn per sample asked for, looking for where some branch is real
RETRY_STARTS = 8 * STARTS
REFINEMENTS = 3  # Krawczyk steps on the whole system: each squares the enclosure's width
SHIFTS = (-1, 0, 1)  # theta - h, theta, theta + h

# (point -> label, unknown -> (velocity, acceleration), point -> discriminant), dimensions at values
RateForms: TypeAlias = tuple[Mapping[str, str], Mapping[str, tuple[sympy.Expr, sympy.Expr]], Mapping[str, sympy.Expr]]
# (point, expression, label where it is positive, label where it is negative)
Indicator: TypeAlias = tuple[str, sympy.Expr, str, str]
Label: TypeAlias = tuple[tuple[str, str], ...]


@attrs.frozen
class RatesCheck:
    """The largest error of the rates against central differences, and how the check ended
    (an immutable, hashable value).

    >>> RatesCheck.skipped().to_json()["status"]
    'skipped'
    """

    samples: int = 0
    compared: int = 0  # branch rates compared, a velocity and an acceleration per coordinate each
    max_rel_error: float = 0.0
    max_abs_error: float = 0.0
    near_degenerate: int = 0  # samples set aside: a label or a branch's reality undecided
    failures: tuple[str, ...] = ()
    status: Status = Status.FAILED

    @property
    def passed(self) -> bool:
        return self.status is Status.PASSED

    @classmethod
    def skipped(cls) -> RatesCheck:
        """No check was asked for (zero samples): not passed, not failed."""
        return cls(status=Status.SKIPPED)

    def to_json(self) -> dict[str, Any]:
        return {"samples": self.samples, "status": self.status.value, "passed": self.passed,
                "compared": self.compared, "max_rel_error": self.max_rel_error, "max_abs_error": self.max_abs_error,
                "near_degenerate": self.near_degenerate, "failures": list(self.failures[:10]),
                "method": (f"central differences with h = 2^-{STEP_BITS} of the original system's roots, found "
                           f"in floats and proved and refined in arb at {WORKING_BITS} bits; "
                           f"tolerance {MAX_REL_ERROR:g} relative")}


def _result(report: Tally) -> RatesCheck:
    passed = not report.failures and report.max_rel_error <= MAX_REL_ERROR
    return RatesCheck(report.samples, report.compared, report.max_rel_error, report.max_abs_error,
                      report.near_degenerate, tuple(report.failures), Status.PASSED if passed else Status.FAILED)


def check_rates(system: System, indicators: Sequence[Indicator], branches: Sequence[RateForms],
                span: tuple[float, float], samples: int = 20, seed: int = 0) -> RatesCheck:
    """Check each branch's rates (``branches``) on ``samples`` inputs in ``span`` (radians) where
    some branch is real; ``system`` has one input and no symbolic dimension left."""
    if not samples:
        return RatesCheck.skipped()
    report = Tally()
    rng = np.random.default_rng(seed)
    with flint.ctx.workprec(WORKING_BITS):
        plan = _Plan(system, indicators, branches)
        angles = plan.draw(rng, span, samples)
        for theta, roots in zip(angles, plan.roots(angles, rng, STARTS)):
            if plan.lacks_a_root(theta, roots):  # Newton's random starts may miss one
                roots = plan.roots(np.array([theta]), rng, RETRY_STARTS)[0]
            _compare(report, plan, theta, roots)
    report.require_compared("branch rate")
    return _result(report)


class _Plan:
    """What is compiled once: the blocks and their certifiers, the whole system, indicators, branches."""

    def __init__(self, system: System, indicators: Sequence[Indicator], branches: Sequence[RateForms]) -> None:
        (self.variables,) = system.inputs.values()  # an angle's (cos, sin), or a length's one
        self.system = system
        self.blocks = blocks_of(system)
        self.certifiers = [(block, certifier_of(block), certify_parameters(block)) for block in self.blocks.blocks]
        self.unknowns = list(system.unknowns)
        names = self.unknowns + list(self.variables)
        equations = self.blocks.equations  # square: one per unknown, block-triangular
        self.residual: BallProgram = compile_program(equations, names, ARB)
        jacobian = sympy.Matrix(equations).jacobian([symbol(u) for u in self.unknowns])
        self.jacobian: BallProgram = compile_program(list(jacobian), names, ARB)
        self.labels = [(point, positive, negative) for point, _, positive, negative in indicators]
        self.indicators: BallProgram = compile_program([e for _, e, _, _ in indicators], names, ARB)
        self.branches = [_Branch(labels, rates, discriminants, list(self.variables))
                         for labels, rates, discriminants in branches]
        self.nonnegative = [self.unknowns.index(n) for n in system.nonnegative]

    def draw(self, rng: np.random.Generator, span: tuple[float, float], samples: int) -> np.ndarray:
        """``samples`` inputs where some branch is real in floats (fewer if few are found)."""
        pool = rng.uniform(span[0], span[1], samples * MAX_DRAWS)
        known = input_values(self.variables, pool)
        real = np.zeros(len(pool), dtype=bool)
        for branch in self.branches:
            real |= branch.real_floats(known)
        return pool[real][:samples]

    def known(self, theta: float, shift: int) -> dict[str, arb]:
        """The input's cos and sin (or length) in balls at ``theta + shift * h`` (exact in the working precision)."""
        return input_values(self.variables, arb(theta) + shift * arb(2) ** -STEP_BITS)

    def roots(self, angles: np.ndarray, rng: np.random.Generator, starts: int) -> list[list[list[_Root]]]:
        """Per input, per shift, the proved roots there (from the float candidates at ``theta``)."""
        candidates = solve_floats(self.blocks, input_values(self.variables, angles), rng, starts)
        owners = candidates.owner.tolist()
        rows = [[[float(candidates.values[n][k]) for n in block.names] for k in range(len(owners))]
                for block, _, _ in self.certifiers]
        found: list[list[list[_Root]]] = [[[] for _ in SHIFTS] for _ in angles]
        for j, shift in enumerate(SHIFTS):
            knowns = [self.known(float(theta), shift) for theta in angles]
            proved: dict[tuple[int, int], list[arb] | None] = {}  # candidates share their first blocks
            for row, k in enumerate(owners):
                root = self._prove(rows, candidates.lineage, row, knowns[k], proved)
                if root is not None and not any(root.same(r) for r in found[k][j]):
                    found[k][j].append(root)
        return found

    def _prove(self, rows: list[list[list[float]]], lineage: list[np.ndarray], row: int, known: dict[str, arb],
               proved: dict[tuple[int, int], list[arb] | None]) -> _Root | None:
        balls = dict(known)
        for b, (block, certify, parameters) in enumerate(self.certifiers):
            key = (b, int(lineage[b][row]))
            if key not in proved:
                proved[key] = certify(rows[b][row], [balls[n] for n in parameters])
            enclosure = proved[key]
            if enclosure is None:
                return None
            balls.update(zip(block.names, enclosure))
        values = self._refined([balls[u] for u in self.unknowns], known)
        if values is None or any(values[i] < 0 for i in self.nonnegative):
            return None
        return _Root(values, self._label(values, known), known)

    def _refined(self, root: list[arb], known: dict[str, arb]) -> list[arb] | None:
        """The root's enclosure tightened: ``K(X) = m - Y F(m) + (I - Y J(X)) (X - m)`` holds
        every root in ``X``, whatever ``Y``; ``X`` holds exactly one (the blocks' proof)."""
        n, given = len(root), [known[v] for v in self.variables]
        identity = arb_mat([[int(i == j) for j in range(n)] for i in range(n)])
        for _ in range(REFINEMENTS):
            middle = [arb(v.mid()) for v in root]
            try:
                inverse = arb_mat(n, n, self.jacobian(*middle, *given)).mid().inv().mid()
            except ZeroDivisionError:
                return root
            residual = arb_mat(n, 1, self.residual(*middle, *given))
            spread = arb_mat(n, 1, [x - m for x, m in zip(root, middle)])
            k = arb_mat(n, 1, middle) - inverse * residual + \
                (identity - inverse * arb_mat(n, n, self.jacobian(*root, *given))) * spread
            if not all(k[i, 0].overlaps(root[i]) for i in range(n)):
                return None  # cannot happen for a proved root: a sign of a wrong proof, so no root
            root = [k[i, 0].intersection(root[i]) for i in range(n)]
        return root

    def _label(self, values: list[arb], known: dict[str, arb]) -> Label | None:
        labels = {}
        given = [known[v] for v in self.variables]
        for (point, positive, negative), value in zip(self.labels, self.indicators(*values, *given)):
            if not (value > 0 or value < 0):
                return None
            labels[point] = positive if value > 0 else negative
        return tuple(sorted(labels.items()))

    def lacks_a_root(self, theta: float, roots: list[list[_Root]]) -> bool:
        """Whether a branch real at ``theta`` has, at some shift, no root of its label."""
        known = self.known(theta, 0)
        return any(branch.real(known) and any(branch.key not in [r.label for r in at] for at in roots)
                   for branch in self.branches)


@dataclass
class _Root:
    """A proved root at one input: its unknowns' balls and its label."""

    values: list[arb]
    label: Label | None
    known: dict[str, arb]

    def same(self, other: _Root) -> bool:
        return all(a.overlaps(b) for a, b in zip(self.values, other.values))


class _Branch:
    def __init__(self, labels: Mapping[str, str], rates: Mapping[str, tuple[sympy.Expr, sympy.Expr]],
                 discriminants: Mapping[str, sympy.Expr], known: list[str]) -> None:
        self.key = tuple(sorted(labels.items()))
        self.unknowns = list(rates)
        # compiled once (shared subexpressions computed once: a six-bar's forms share most of theirs)
        self.rates: BallProgram = compile_program([f for pair in rates.values() for f in pair], known, ARB)
        self.discriminants: BallProgram = compile_program(list(discriminants.values()), known, ARB)
        self.discriminant_floats = compile_program(list(discriminants.values()), known, NUMPY)
        self.known = known

    def real_floats(self, known: Mapping[str, np.ndarray]) -> np.ndarray:
        return real_floats(self.discriminant_floats, known, self.known)

    def real(self, known: Mapping[str, arb]) -> bool | None:
        """``True`` or ``False`` where decided in balls, ``None`` near the branch's edge (a toggle)."""
        return decided_real(self.discriminants(*(known[n] for n in self.known)))

    def values(self, known: Mapping[str, arb]) -> dict[str, tuple[arb, arb]]:
        """Each coordinate's velocity and acceleration closed forms, in balls at ``known``."""
        values = [arb(v) for v in self.rates(*(known[n] for n in self.known))]
        return {u: (values[2 * k], values[2 * k + 1]) for k, u in enumerate(self.unknowns)}


def _compare(report: Tally, plan: _Plan, theta: float, roots: list[list[_Root]]) -> None:
    """Compare every branch real at all three inputs with its roots' central differences."""
    report.samples += 1
    knowns = [plan.known(theta, shift) for shift in SHIFTS]
    reality = [[branch.real(known) for known in knowns] for branch in plan.branches]
    if any(r.label is None for at in roots for r in at) or any(None in row for row in reality):
        report.near_degenerate += 1
        return
    for branch, real in zip(plan.branches, reality):
        if not all(real):
            continue
        matches = [[r for r in at if r.label == branch.key] for at in roots]
        if any(len(m) != 1 for m in matches):
            counts = ", ".join(str(len(m)) for m in matches)
            report.failures.append(f"branch {dict(branch.key)} at {theta:.17g} rad: {counts} numeric solutions "
                                   "with its label at theta - h, theta, theta + h")
            continue
        _compare_branch(report, plan, branch, theta, [m[0] for m in matches])


def _compare_branch(report: Tally, plan: _Plan, branch: _Branch, theta: float, roots: list[_Root]) -> None:
    h = arb(2) ** -STEP_BITS
    rates = branch.values(roots[1].known)
    if not rates:
        return
    size = max(abs(float(v.mid())) for v in roots[1].values) or 1.0
    for which, (order, scale) in enumerate(((1, _largest(rates, 0, size)), (2, _largest(rates, 1, size)))):
        for unknown, closed in rates.items():
            k = plan.unknowns.index(unknown)
            low, middle, high = (root.values[k] for root in roots)
            difference = (high - low) / (2 * h) if order == 1 else (high - 2 * middle + low) / (h * h)
            gap = abs(difference - closed[which])
            error = float(gap.upper().mid()) if gap.is_finite() else float("inf")
            what = "velocity" if order == 1 else "acceleration"
            report.error(error, scale=scale, tolerance=MAX_REL_ERROR,
                         said=f"branch {dict(branch.key)}: the {what} of {unknown}",
                         detail=f"is {error / scale:.3g} (relative) from its central difference at {theta:.17g} rad")
    report.compared += 1


def _largest(rates: Mapping[str, tuple[arb, arb]], which: int, size: float) -> float:
    """The scale an error is measured against: the configuration's size or the largest rate."""
    return max([size] + [abs(float(r[which].mid())) for r in rates.values()])
