"""Angle outputs in the extremum machinery: a scalar monotone in the angle stands for it.

The machinery finds the critical points of one unknown ``u`` from its eliminant
``F(u, c, s)``. An angle output has no such unknown of its own, so a scalar that moves
with the angle, one to one, stands for it (its *via*):

- the angle at a point (``angle(P, Q, R)``, in [0, 180] degrees) through its cosine, the
  unknown the system already has: the angle is ``acos(u)``, decreasing in ``u``, so the
  smallest angle is where the cosine is largest;
- a direction (``angle(P, Q)``) through the tangent of its half-angle from a quarter-turn
  reference ``k*90`` degrees: ``w = tan((phi - k*90)/2)``, increasing in ``phi`` on the
  open turn around ``k*90``. Of the four references, the one whose opposite direction the
  motion (sampled over the range) stays farthest from is chosen; a direction that turns
  (nearly) full circle has no least or greatest value and is refused. The eliminant of
  ``w`` is the system's, with the direction's cosine and sine written in ``w`` (rational,
  so no extraneous branch), its other unknowns eliminated.

Values are reported in degrees; ``AngleScale`` maps the via's values and closed forms there.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import flint
import mpmath
import numpy as np
from numpy.typing import NDArray
import sympy

from ...derivation.witnesses import Groups, witnesses as drawn
from ...derivation.tasks import equations_for
from ...eliminate import Witness, eliminate
from ...runtime.budget import Deadline
from ...errors import ComputationError, UsageError
from ...evaluate import NUMPY, evaluate
from ...system import input_values, symbol
from ...system.angles import Parametrisation
from .critical import DIGITS, Problem, stretches_of

if TYPE_CHECKING:
    from ...branches import Branch
    from ...derivation.results import Derivation
    from ...scene.compile import AngleOutput

__all__ = ["AngleScale", "direction_problem", "SAMPLES", "MARGIN_DEG"]

SAMPLES = 1441  # inputs at which a direction's motion is sampled to choose its reference
MARGIN_DEG = 1.0  # the least room, in degrees, between the sampled motion and the chosen cut


@dataclass(frozen=True)
class AngleScale:
    """How an angle output's degrees follow from the scalar ``via`` that stands for it.

    ``quarter_turns`` is None for an angle at a point (degrees = acos(via)), else the
    reference k of a direction (degrees = 90*k + 2*atan(via)).
    """

    via: str
    quarter_turns: int | None

    @property
    def decreasing(self) -> bool:
        """Whether the angle falls as ``via`` grows (an angle at a point, through its cosine)."""
        return self.quarter_turns is None

    def degrees(self, value: mpmath.mpf) -> mpmath.mpf:
        """The angle in degrees at a value of ``via`` (nan stays nan), at the critical points' own
        precision whatever the caller's (mpmath's is process-wide)."""
        with mpmath.workdps(DIGITS):
            value = mpmath.mpf(value)
            if value != value:
                return value
            if self.quarter_turns is None:
                return mpmath.degrees(mpmath.acos(min(max(value, -1), 1)))  # rounding may step past +-1
            return 90 * self.quarter_turns + 2 * mpmath.degrees(mpmath.atan(value))

    def expr(self, value: sympy.Expr) -> sympy.Expr:
        """The angle in degrees as an expression in ``via``'s expression ``value``."""
        if self.quarter_turns is None:
            return 180 * sympy.acos(value) / sympy.pi
        return 90 * self.quarter_turns + 360 * sympy.atan(value) / sympy.pi

    def to_json(self) -> dict[str, object]:
        return {"unit": "deg", "via": self.via, "degrees": str(self.expr(symbol(self.via))),
                "kind": "at a point" if self.quarter_turns is None else "direction"}


def _rotated(cos: Any, sin: Any, quarter_turns: int) -> tuple[Any, Any]:
    """``(cos, sin)`` (expressions or balls) of the angle turned by ``quarter_turns`` * 90 degrees."""
    for _ in range(quarter_turns % 4):
        cos, sin = -sin, cos
    return cos, sin


def _reference(cos_form: sympy.Expr, sin_form: sympy.Expr, line: Parametrisation,
               defaults: Mapping[str, sympy.Expr], lo: float, hi: float, output: str) -> int:
    """The quarter-turn reference k whose opposite direction the sampled motion stays farthest from."""
    angles = np.linspace(float(lo), float(hi), SAMPLES)
    values: dict[str, float | NDArray[np.float64]] = {n: float(sympy.Rational(str(v))) for n, v in defaults.items()}
    names = tuple(v.name for v in line.variables)
    values.update(input_values(names, np.radians(angles) if line.is_angle else angles))
    with np.errstate(invalid="ignore", divide="ignore"):
        x, y = (np.broadcast_to(evaluate(f, values, NUMPY), angles.shape) for f in (cos_form, sin_form))
    phi = np.degrees(np.arctan2(y, x))
    real = np.isfinite(phi)
    if not real.any():
        raise ComputationError(f"{output} is not real anywhere on the range")
    steps = np.abs((np.diff(phi) + 180) % 360 - 180)
    step = float(np.nanmax(steps)) if np.isfinite(steps).any() else 0.0
    room = {k: float(np.min(np.abs((phi[real] - (90 * k + 180) + 180) % 360 - 180))) for k in range(4)}
    best = max(room, key=lambda k: (room[k], -abs(k - 1)))  # ties: 90 deg, the upper half-plane, first
    if room[best] <= max(MARGIN_DEG, 2 * step):
        raise UsageError("output", output, f"the direction turns through (nearly) a full circle over "
                         f"[{float(lo):g}, {float(hi):g}] deg, so it has no least or greatest value there; "
                         "narrow the range")
    return best


def _fresh(name: str, taken: set[str]) -> sympy.Symbol:
    while name in taken:
        name += "_"
    return symbol(name)


def direction_problem(derived: Derivation, angle: AngleOutput, line: Parametrisation,
                      parameters: tuple[sympy.Symbol, ...], lo: float, hi: float, output: str, *,
                      witnesses: Groups | None = None, deadline: Deadline | None = None) -> Problem:
    """The ``Problem`` of a direction output: ``w = tan((phi - k*90)/2)`` on the chosen branch,
    and its eliminant in ``w``, the input's variables and the symbolic dimensions (the factors
    kept by the derivation's ``witnesses``, drawn again if not given; the elimination keeping to
    ``deadline``, if any)."""
    compiled = derived.compiled
    system = compiled.system
    chosen = next(b for b in derived.branches if b.selected)
    assert angle.sin is not None, "a direction has a sine"
    cos_form, sin_form = chosen.values[angle.cos], chosen.values[angle.sin]
    k = _reference(cos_form, sin_form, line, compiled.parameter_values, lo, hi, output)
    taken = set(system.variables) | set(compiled.parameter_values)
    w = _fresh(f"tan_half_{angle.name}", taken)
    groups = witnesses if witnesses is not None else drawn(derived.compiled, derived.branches)
    eliminant = _eliminant(derived, angle, k, w, groups, deadline)
    return Problem(eliminant, _via(chosen, angle, k), w, line, parameters, AngleScale(w.name, k),
                   tuple(chosen.discriminants.values()),
                   stretches_of(derived, chosen, lambda branch: _via(branch, angle, k), output))


def _via(branch: Branch, angle: AngleOutput, k: int) -> sympy.Expr:
    """``w = tan((phi - k*90)/2)`` on ``branch``, from its cosine and sine of ``phi``."""
    assert angle.sin is not None, "a direction has a sine"
    turned_cos, turned_sin = _rotated(branch.values[angle.cos], branch.values[angle.sin], -k)
    return turned_sin / (1 + turned_cos)


def _eliminant(derived: Derivation, angle: AngleOutput, k: int, w: sympy.Symbol, groups: Groups,
               deadline: Deadline | None) -> sympy.Expr:
    """``w``'s polynomial: the equations the direction's cosine and sine need, with those two
    written in ``w`` (times ``1 + w**2``), every other unknown eliminated; the factors the
    branches' witnesses vanish on kept."""
    system = derived.compiled.system
    assert angle.sin is not None, "a direction has a sine"
    cos, sin = symbol(angle.cos), symbol(angle.sin)
    in_w = _rotated((1 - w**2) / (1 + w**2), 2 * w / (1 + w**2), k)
    equations: list[sympy.Expr] = []
    unknowns: list[str] = []
    for unknown in (angle.cos, angle.sin):
        chosen, names = equations_for(system, unknown)
        equations += [e for e in chosen if e not in equations]
        unknowns += [u for u in names if u not in unknowns]
    written = [sympy.expand(sympy.numer(sympy.together(e.xreplace({cos: in_w[0], sin: in_w[1]}))))
               for e in equations]
    others = [u for u in system.unknowns if u in unknowns and u not in (angle.cos, angle.sin)]
    keep_always = tuple(system.input_variables) + tuple(system.parameters)
    try:
        result = eliminate(written, others, (w.name,) + keep_always, method="linear", backend="flint",
                           witnesses=_witnesses(groups, angle, k, w), parameters=keep_always, budget=deadline)
    except ComputationError as err:
        raise ComputationError(f"no polynomial for the direction {angle.name}: {err}") from None
    return result.polynomial


def _witnesses(groups: Groups, angle: AngleOutput, k: int, w: sympy.Symbol) -> list[list[Witness]]:
    """The derivation's witness configurations with ``w`` added, where it is finite."""
    assert angle.sin is not None, "a direction has a sine"
    extended_groups: list[list[Witness]] = []
    with flint.ctx.workprec(256):
        for group in groups:
            extended: list[Witness] = []
            for point in group:
                turned_cos, turned_sin = _rotated(point[angle.cos], point[angle.sin], -k)
                denominator = 1 + turned_cos
                if not denominator.contains(0):
                    extended.append(Witness({**point, w.name: turned_sin / denominator}, point.exact))
            extended_groups.append(extended)
    return extended_groups
