"""Closed forms and eliminants checked against independent numeric solutions.

For each sampled input the original system is solved numerically (``solve.solve_all``,
no closed form involved), every solution is labelled by the sign of the branch
indicators, and each real closed-form branch is compared with the solution of the same
label. Polynomials (eliminants, curves) are evaluated at every solution.
"""

from dataclasses import dataclass, field

import mpmath
import numpy as np

from ..evaluate import MPMATH, evaluate
from .minimal import FactorCheck, relative_residual, structure_failures
from .solve import Blocks, solve_all

__all__ = ["Verification", "verify_branches", "WORKING_DIGITS"]

WORKING_DIGITS = 50
TOLERANCE_DIGITS = 30
MAX_DRAWS = 50  # inputs drawn per sample asked for, looking for where the mechanism assembles


@dataclass
class Verification:
    """What the check found: the largest error and whether every branch matched.

    ``status`` is ``passed``, ``failed`` or ``skipped`` (no samples asked for); a check
    that compared nothing never passes.

    >>> Verification.skipped().passed, Verification.skipped().status
    (False, 'skipped')
    """

    samples: int
    max_abs_error: float
    passed: bool
    compared: int = 0
    near_degenerate: int = 0
    max_polynomial_residual: dict = field(default_factory=dict)
    failures: list = field(default_factory=list)
    evaluated: int = 0  # numeric solutions the polynomials were evaluated at
    status: str = "failed"
    smallest_factor_residual: dict = field(default_factory=dict)  # per polynomial, per kept factor

    @classmethod
    def skipped(cls):
        """No verification was asked for (zero samples)."""
        return cls(0, 0.0, False, status="skipped")

    def to_json(self):
        return {
            "samples": self.samples,
            "status": self.status,
            "max_abs_error": self.max_abs_error,
            "passed": self.passed,
            "compared": self.compared,
            "evaluated": self.evaluated,
            "near_degenerate": self.near_degenerate,
            "max_polynomial_residual": self.max_polynomial_residual,
            "smallest_factor_residual": self.smallest_factor_residual,
            "failures": self.failures[:10],
            "method": f"Newton multistart on the original system, {WORKING_DIGITS} digits",
        }


def _label(indicators, solution, scale):
    labels = {}
    for point, expr, positive, negative in indicators:
        value = evaluate(expr, solution, MPMATH)
        if abs(value) <= mpmath.mpf(10) ** (-12) * scale**2:
            return None
        labels[point] = positive if value > 0 else negative
    return labels


def verify_branches(system, indicators, branches, inputs, parameters, samples=50, seed=0,
                    polynomials=None, factors=None):
    """Check ``branches`` (list of ``(labels, values, discriminants)``) on ``samples`` inputs
    where something could be compared.

    ``inputs`` maps an input name to its range in radians; ``parameters`` gives a value
    to each symbolic parameter; ``polynomials`` (name -> expression) must vanish on every
    numeric solution and be squarefree. ``factors`` (name -> the polynomial's kept factors)
    must multiply to it, and each must vanish by itself on some numeric solution: otherwise
    it is extraneous (see ``minimal``).
    """
    rng = np.random.default_rng(seed)
    blocks = Blocks(system)
    report = Verification(0, 0.0, False)
    polynomial_terms = {n: list(p.expand().as_ordered_terms()) for n, p in (polynomials or {}).items()}
    worst = {n: mpmath.mpf(0) for n in polynomial_terms}
    kept = FactorCheck(factors)
    useful = drawn = 0
    with mpmath.workdps(WORKING_DIGITS):
        # An input where the mechanism does not assemble compares nothing. The first
        # ``samples`` inputs are solved wherever they fall (the numeric solution must then
        # find nothing either); after those, more are drawn, and solved only where some
        # branch is real, until ``samples`` inputs have compared something (at most twice
        # as many solved in all).
        while useful < samples and drawn < samples * MAX_DRAWS and report.samples < 2 * samples:
            drawn += 1
            values = _draw(system, inputs, parameters, rng)
            if drawn > samples and not _any_real(branches, values):
                continue
            before = (report.compared, report.evaluated)
            _sample(report, blocks, indicators, branches, values, rng, polynomial_terms, worst, kept)
            useful += (report.compared, report.evaluated) != before
    tolerance = 10.0 ** (-TOLERANCE_DIGITS)
    report.max_polynomial_residual = {n: float(v) for n, v in worst.items()}
    _require_comparisons(report, bool(branches), bool(polynomial_terms))
    report.smallest_factor_residual = kept.to_json()
    report.failures += kept.failures(tolerance, report.evaluated) + structure_failures(polynomials or {}, factors)
    report.passed = (not report.failures and report.max_abs_error <= tolerance * 1e3
                     and all(v <= tolerance for v in report.max_polynomial_residual.values()))
    report.status = "passed" if report.passed else "failed"
    return report


def _draw(system, inputs, parameters, rng):
    """The known values at one random input: parameters, and each input's cos and sin."""
    values = {n: mpmath.mpf(v) for n, v in parameters.items()}
    for name, (lo, hi) in inputs.items():
        angle = mpmath.mpf(float(rng.uniform(lo, hi)))
        cos_name, sin_name = system.inputs[name]
        values[cos_name], values[sin_name] = mpmath.cos(angle), mpmath.sin(angle)
    return values


def _any_real(branches, values):
    """Whether some branch's discriminants are all positive at ``values`` (where to sample)."""
    return any(all(evaluate(d, values, MPMATH) > 0 for d in discriminants.values())
               for _, _, discriminants in branches)


def _sample(report, blocks, indicators, branches, values, rng, polynomial_terms, worst, kept):
    """Solve the system at one input and compare what it gives."""
    report.samples += 1
    scale = 1 + max(abs(v) for v in values.values())
    solutions = solve_all(blocks, values, rng)
    for solution in solutions:
        for name, terms in polynomial_terms.items():
            worst[name] = max(worst[name], relative_residual(terms, solution))
        kept.see(solution)
    report.evaluated += len(solutions) if polynomial_terms else 0
    _compare(report, indicators, branches, values, solutions, scale)


def _require_comparisons(report, branches, polynomials):
    """A check that compared nothing fails, saying why, rather than passing vacuously."""
    if not (branches or polynomials):
        report.failures.append("nothing to compare: no branch and no polynomial was given")
    if branches and not report.compared:
        report.failures.append(f"no branch value compared on {report.samples} samples "
                               f"({report.near_degenerate} near a degenerate configuration)")
    if polynomials and not report.evaluated:
        report.failures.append(f"no numeric solution to evaluate the polynomials at on {report.samples} samples")


def _compare(report, indicators, branches, values, solutions, scale):
    by_label = {}
    for solution in solutions:
        labels = _label(indicators, solution, scale)
        if labels is None:
            report.near_degenerate += 1
            return
        by_label.setdefault(tuple(sorted(labels.items())), []).append(solution)
    real = []
    for labels, closed, discriminants in branches:
        discs = [evaluate(d, values, MPMATH) for d in discriminants.values()]
        if any(abs(d) <= mpmath.mpf(10) ** (-12) * scale**4 for d in discs):
            report.near_degenerate += 1
            return
        if all(d > 0 for d in discs):
            real.append((tuple(sorted(labels.items())), closed))
    for key, closed in real:
        matches = by_label.pop(key, [])
        if len(matches) != 1:
            report.failures.append(f"branch {dict(key)}: {len(matches)} numeric solutions with its label")
            continue
        error = max(abs(evaluate(expr, values, MPMATH) - matches[0][name]) for name, expr in closed.items())
        report.max_abs_error = max(report.max_abs_error, float(error))
        report.compared += 1
    for key in by_label:
        report.failures.append(f"numeric solution labelled {dict(key)} has no real closed-form branch")
