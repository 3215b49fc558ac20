"""A group's rates checked against central differences of independent numeric solutions, and its eliminant.

At seeded inputs where every group assembles (exact: a rational length, or an angle whose
half-angle tangent ``u`` is rational), each group's own equations are solved at ``u - h``,
``u``, ``u + h`` (``h = 2**-STEP_BITS``, exact points of the circle for an angle) by
``algkin.verify.groups.real_solutions``, which never sees the eliminant or a rate form: Newton
from random starts, each root proved in balls. The root at ``u`` that a mode's certified ball
meets is that mode's; at ``u +- h`` its nearest root. Then

    X_u  ~ (X(u + h) - X(u - h)) / (2 h),   X_uu ~ (X(u + h) - 2 X(u) + X(u - h)) / h**2

in balls, and for an angle ``t = 2 atan(u)``: ``X_t = X_u / t_u``, ``X_tt = (X_uu - X_t t_uu) / t_u**2``
with ``t_u = 2 / (1 + u**2)``, ``t_uu = -4 u / (1 + u**2)**2``. The truncation error
(``h**2 X'''/6``, about 1e-22 of the motion's scale away from a toggle) is not in the balls:
a numerical check, to ``MAX_REL_ERROR`` of the larger of the configuration's size and its largest rate.

The second method: implicit differentiation of the eliminant ``E(v, t) = 0`` gives the separating
variable ``v``'s rates at each mode (``v' = -E_t / E_v``, and so on), compared in balls with the
forms' (a linear form's, where ``v`` is one). A check that compared nothing fails.
"""

from __future__ import annotations

import random
from collections.abc import Mapping, Sequence
from fractions import Fraction
from typing import Any

import attrs
import flint
import numpy as np

from ...eliminate.group import GroupSolution
from ...errors import ComputationError
from ...verify.groups import BITS, STARTS, real_solutions
from ...verify.tally import Tally
from .curve import assembling
from .implicit import ImplicitRates, implicit_rates
from .scene import GroupScene, Sample

__all__ = ["GroupRatesCheck", "check_group_rates", "shifted", "STEP_BITS", "MAX_REL_ERROR"]

STEP_BITS = 36
"""h = 2**-36: truncation ~h**2 = 1e-22; the proved roots' width (~1e-45) over h**2 far below."""
MAX_REL_ERROR = 1e-15
RETRY = 4  # times as many Newton starts where a mode's root was not found
METHOD = (f"central differences with h = 2^-{STEP_BITS} (in a length, or in the tangent of half an angle) of "
          f"the group's own equations' roots, found by Newton from random starts and proved in arb balls at "
          f"{BITS} bits; and the separating variable's rates by implicit differentiation of the eliminant; "
          f"tolerance {MAX_REL_ERROR:g} relative")


@attrs.frozen
class GroupRatesCheck:
    """The rates against central differences of independent numeric solutions (``compared``:
    modes compared, a velocity and an acceleration per unknown each), and against the eliminant's
    implicit derivative (``eliminant_compared``: modes).

    >>> GroupRatesCheck(status="skipped").to_json()["status"]
    'skipped'
    """

    samples: int = 0
    compared: int = 0
    eliminant_compared: int = 0
    max_rel_error: float = 0.0
    max_abs_error: float = 0.0
    near_degenerate: int = 0
    failures: tuple[str, ...] = ()
    status: str = "failed"

    @property
    def passed(self) -> bool:
        return self.status == "passed"

    def to_json(self) -> dict[str, Any]:
        return {"samples": self.samples, "status": self.status, "passed": self.passed, "compared": self.compared,
                "eliminant_compared": self.eliminant_compared, "max_rel_error": self.max_rel_error,
                "max_abs_error": self.max_abs_error, "near_degenerate": self.near_degenerate,
                "failures": list(self.failures[:10]), "method": METHOD}


def check_group_rates(prepared: GroupScene, forms: Sequence[ImplicitRates], *, samples: int,
                      seed: int = 0) -> GroupRatesCheck:
    """Each group's rate ``forms`` (by position) on ``samples`` seeded inputs where the groups assemble."""
    tally = Tally()
    eliminant = [0]
    drawn = assembling(prepared, samples, random.Random(seed))
    inputs = {n: v for n, v in prepared.compiled.inputs.items() if set(v) & set(prepared.variables)}
    rng = np.random.default_rng(seed)
    by_eliminant = [implicit_rates([s.eliminant.to_flint()], (s.variable,), prepared.variables)
                    for s in prepared.solutions]  # the second method: the eliminant alone
    for sample in drawn:
        tally.samples += 1
        moved = [shifted(prepared, sample, Fraction(k, 2**STEP_BITS)) for k in (-1, 0, 1)]
        if any(m is None for m in moved):  # a half turn: its tangent is infinite
            tally.near_degenerate += 1
            continue
        points = [m for m in moved if m is not None]
        try:
            found = prepared.modes(points[1][0], bits=BITS)
        except ComputationError:  # modes meet there
            tally.near_degenerate += 1
            continue
        for index, (group, modes) in enumerate(zip(prepared.compiled.groups, found)):
            roots = _roots(group.unknowns, group.equations, inputs, [p for p, _ in points], rng)
            for mode in modes:
                values = dict(mode.values, **points[1][0].balls(BITS))
                with flint.ctx.workprec(BITS):
                    closed = forms[index].at(values, points[1][0].exact())
                    _compare(tally, prepared, group.unknowns, mode.values, closed, roots, at=points[1][1],
                             where=f"group {', '.join(group.points)} mode {mode.index + 1} at {sample.shown}")
                    eliminant[0] += _compare_eliminant(tally, prepared.solutions[index], by_eliminant[index],
                                                       values, closed, points[1][0].exact(),
                                                       where=f"group {', '.join(group.points)} mode "
                                                             f"{mode.index + 1} at {sample.shown}")
    tally.require_compared("mode's rates")
    passed = not tally.failures and tally.max_rel_error <= MAX_REL_ERROR
    return GroupRatesCheck(tally.samples, tally.compared, eliminant[0], tally.max_rel_error, tally.max_abs_error,
                           tally.near_degenerate, tuple(tally.failures), "passed" if passed else "failed")


def shifted(prepared: GroupScene, sample: Sample, step: Fraction) -> tuple[Sample, Fraction] | None:
    """``sample`` moved by ``step`` in its input (a length), or in the tangent ``u`` of half its
    angle (an exact point of the circle), with the length or ``u`` it is at; None at a half turn.

    >>> from .scene import prepare_groups
    >>> prepared = prepare_groups("stephenson-iii-triad")
    >>> moved, u = shifted(prepared, prepared.sample(90), Fraction(1, 2))
    >>> u, {n: str(v) for n, v in moved.values.items()}
    (Fraction(3, 2), {'c_theta': '-5/13', 's_theta': '12/13'})
    """
    assert prepared.input is not None
    values = {n: Fraction(v) for n, v in sample.values.items()}
    if not prepared.input.is_angle:
        (name,) = prepared.variables
        length = values[name] + step
        return Sample({name: length}, float(length), f"{float(length):g}"), length
    c, s = prepared.variables
    if values[c] == -1:
        return None
    u = values[s] / (1 + values[c]) + step
    return Sample({c: (1 - u * u) / (1 + u * u), s: 2 * u / (1 + u * u)}, sample.value, sample.shown), u


def _roots(unknowns: Sequence[str], equations: Sequence[Any], inputs: Mapping[str, tuple[str, ...]],
           points: Sequence[Sample], rng: np.random.Generator) -> list[list[dict[str, flint.arb]]]:
    """The group's proved real roots at each of ``points``; where fewer are found at one than at
    another (Newton's starts missed one), that point again with more starts."""
    found = real_solutions(unknowns, equations, inputs, [p.exact() for p in points], rng)
    most = max(len(f) for f in found)
    return [f if len(f) == most else real_solutions(unknowns, equations, inputs, [p.exact()], rng,
                                                    starts=STARTS * RETRY)[0]
            for f, p in zip(found, points)]


def _compare(tally: Tally, prepared: GroupScene, unknowns: Sequence[str], mode: Mapping[str, flint.arb],
             closed: Mapping[str, tuple[flint.arb, flint.arb]], roots: Sequence[Sequence[Mapping[str, flint.arb]]],
             *, at: Fraction, where: str) -> None:
    """One mode's forms (``closed``) against the central differences of its roots."""
    owners = [r for r in roots[1] if all(mode[u].overlaps(r[u]) for u in unknowns)]
    if len(owners) != 1:
        tally.failures.append(f"{where}: {len(owners)} proved numeric solutions meet the mode")
        return
    centre = owners[0]
    low, high = (_nearest(centre, r, unknowns) for r in (roots[0], roots[2]))
    if low is None or high is None:
        tally.failures.append(f"{where}: no proved numeric solution next to the mode at u - h or u + h")
        return
    h = flint.arb(2) ** -STEP_BITS
    differences = {u: ((high[u] - low[u]) / (2 * h), (high[u] - 2 * centre[u] + low[u]) / (h * h)) for u in unknowns}
    if prepared.input is not None and prepared.input.is_angle:
        differences = {u: _per_radian(*d, u=flint.arb(at.numerator) / at.denominator) for u, d in differences.items()}
    size = max(abs(float(centre[u].mid())) for u in unknowns) or 1.0
    for which, what in enumerate(("velocity", "acceleration")):
        scale = max([size] + [abs(float(closed[u][which].mid())) for u in unknowns])
        for u in unknowns:
            gap = abs(differences[u][which] - closed[u][which])
            error = float(gap.upper()) if gap.is_finite() else float("inf")
            tally.error(error, scale=scale, tolerance=MAX_REL_ERROR, said=f"{where}: the {what} of {u}",
                        detail=f"is {error / scale:.3g} (relative) from its central difference")
    tally.compared += 1


def _nearest(centre: Mapping[str, flint.arb], roots: Sequence[Mapping[str, flint.arb]],
             unknowns: Sequence[str]) -> Mapping[str, flint.arb] | None:
    """The root nearest ``centre``, where it is nearer than half the way to any other."""
    def distance(root: Mapping[str, flint.arb]) -> float:
        return max(abs(float((root[u] - centre[u]).mid())) for u in unknowns)

    ranked = sorted(roots, key=distance)
    if not ranked or (len(ranked) > 1 and 2 * distance(ranked[0]) >= distance(ranked[1])):
        return None
    return ranked[0]


def _per_radian(x_u: flint.arb, x_uu: flint.arb, *, u: flint.arb) -> tuple[flint.arb, flint.arb]:
    """Derivatives in the half-angle tangent ``u`` as derivatives in the angle ``t = 2 atan(u)``."""
    t_u = 2 / (1 + u * u)
    t_uu = -4 * u / (1 + u * u) ** 2
    x_t = x_u / t_u
    return x_t, (x_uu - x_t * t_uu) / (t_u * t_u)


def _compare_eliminant(tally: Tally, solution: GroupSolution, eliminant: ImplicitRates,
                       values: Mapping[str, flint.arb], closed: Mapping[str, tuple[flint.arb, flint.arb]],
                       exact: Mapping[str, flint.fmpq], *, where: str) -> int:
    """The separating variable's rates from the eliminant (``eliminant``: its implicit rates)
    against the forms' (1 where compared)."""
    variable = solution.variable
    by_eliminant = eliminant.at(values, exact)
    weights = dict(solution.form) if solution.form else {variable: 1}
    scale = max(abs(float(values[variable].mid())), 1.0)
    for which, what in enumerate(("velocity", "acceleration")):
        of_forms = sum((w * closed[u][which] for u, w in weights.items()), flint.arb(0))
        expected = by_eliminant[variable][which]
        gap = abs(of_forms - expected)
        error = float(gap.upper()) if gap.is_finite() else float("inf")
        tally.error(error, scale=max(scale, abs(float(expected.mid()))), tolerance=MAX_REL_ERROR,
                    said=f"{where}: the {what} of {variable}",
                    detail="differs from the eliminant's implicit derivative")
    return 1
