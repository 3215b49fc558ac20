"""``derive --rates`` on a scene with points solved together: every unknown's velocity and acceleration per mode.

Per group, the implicit function theorem on its own equations (``implicit``): each velocity is
``N_k / D`` and each acceleration ``M_k / D**3`` with ``D`` the Jacobian's determinant, rational
in the mode's coordinates and the input (per radian of an angle, per unit of a length): the same
forms for every mode, which differ only in where they are evaluated. At the reference input
(``derive``'s) each mode's rates are evaluated in balls at its certified configuration.

The check (``check``) is independent of every form: at seeded inputs where the groups assemble,
the group's original equations are solved at ``u - h``, ``u``, ``u + h`` by the numeric
solver (``algkin.verify.groups``: Newton from random starts, every root proved in balls) and
central differences of its roots compared with the forms. A second method, from the eliminant
alone: implicit differentiation of ``E(v, t) = 0`` gives the separating variable's rates,
compared with the forms' at every mode.

>>> found = group_rates("3rpr", samples=2)
>>> found.input, found.per, [m.label for m in found.modes[0]]
('r1', 'length', ['---', '+++'])
>>> sorted(found.forms[0].velocity), found.forms[0].velocity["P1_x"].endswith(f"/({found.forms[0].denominator})")
(['P1_x', 'P1_y', 'P2_x', 'P2_y'], True)
>>> check = found.verification
>>> check.passed, check.compared > 0, check.max_rel_error < 1e-15, check.eliminant_compared > 0
(True, True, True, True)
"""

from __future__ import annotations

import time
from collections.abc import Mapping, Sequence
from typing import Any

import attrs
import flint

from ...errors import ComputationError, UsageError
from ...runtime import validation
from ...runtime.frozen import FrozenDict, frozen
from ...scene import Scene
from ...system.convert import flint_context, to_flint
from ...verify.groups import BITS
from .check import GroupRatesCheck, check_group_rates
from .derive import GroupDerivation, derive_groups
from .implicit import ImplicitRates, implicit_rates
from .scene import GroupScene, Sample, on_circle

__all__ = ["group_rates", "rates_of_groups", "GroupRates", "GroupRateForms", "ModeRates", "implicit_of", "SMALL_TERMS"]

SMALL_TERMS = 200
"""A numerator with more terms than this is reported by its size (its value at each mode still given)."""
SAMPLES = 8  # inputs the rates are checked at by default


@attrs.frozen
class GroupRateForms:
    """One group's rate forms as text: ``denominator`` (``D``), and per unknown its ``velocity``
    (``N / D``) and ``acceleration`` (``M / D**3``), or the size of ``M`` where it is large."""

    points: tuple[str, ...]
    denominator: str
    velocity: FrozenDict[str, str] = attrs.field(converter=frozen)
    acceleration: FrozenDict[str, str] = attrs.field(converter=frozen)

    def to_json(self) -> dict[str, Any]:
        return {"points": list(self.points), "denominator": self.denominator,
                "velocity": dict(self.velocity), "acceleration": dict(self.acceleration)}


@attrs.frozen
class ModeRates:
    """One mode's rates at the reference input, as decimals: per unknown, velocity and acceleration."""

    label: str
    velocity: FrozenDict[str, str] = attrs.field(converter=frozen)
    acceleration: FrozenDict[str, str] = attrs.field(converter=frozen)

    def to_json(self) -> dict[str, dict[str, str]]:
        return {u: {"velocity": v, "acceleration": self.acceleration[u]} for u, v in self.velocity.items()}


@attrs.frozen
class GroupRates:
    """``derive --rates`` on a group scene: the ``derivation``, per group its rate ``forms`` and
    its ``modes``' rates at the reference input, the check and the timings."""

    derivation: GroupDerivation = attrs.field(eq=False)
    input: str
    per: str
    forms: tuple[GroupRateForms, ...]
    modes: tuple[tuple[ModeRates, ...], ...]
    verification: GroupRatesCheck
    timings: FrozenDict[str, float] = attrs.field(converter=frozen, eq=False)

    @property
    def passed(self) -> bool:
        return self.verification.passed or self.verification.status == "skipped"

    def to_json(self) -> dict[str, Any]:
        """The keys ``derive --rates --json`` adds to the derivation's document."""
        groups = [dict(f.to_json(), modes={m.label: m.to_json() for m in modes})
                  for f, modes in zip(self.forms, self.modes)]
        return {"rates": {"groups": groups}, "rates_input": {"name": self.input, "per": self.per},
                "rates_verification": self.verification.to_json()}


def group_rates(scene: Scene | str, *, samples: int = SAMPLES, seed: int = 0) -> GroupRates:
    """The rates of every unknown of ``scene``'s groups, per mode at the reference input, checked
    on ``samples`` seeded inputs (0 skips the check); the derivation (unchecked) is in ``.derivation``."""
    validation.count("samples", samples, validation.MAX_VERIFY_SAMPLES)
    return rates_of_groups(derive_groups(scene, samples=0, seed=seed), samples=samples, seed=seed)


def rates_of_groups(derivation: GroupDerivation, *, samples: int = SAMPLES, seed: int = 0) -> GroupRates:
    """``group_rates`` of an existing derivation."""
    prepared = derivation.prepared
    if prepared.input is None or derivation.reference is None:  # a structure: nothing moves
        raise UsageError("scene", prepared.scene.name, "rates need points that move with an input; none does")
    later = sorted(prepared.later())
    if later:  # its own equations hold the earlier groups' unknowns, which move too: the chain rule is not taken yet
        group = prepared.compiled.groups[later[0]]
        raise UsageError("scene", prepared.scene.name, f"its group of {', '.join(group.points)} is solved after "
                         "another: rates of groups solved in turn are not taken yet")
    mark = time.perf_counter()
    implicit = [implicit_of(prepared, k) for k in range(len(prepared.solutions))]
    forms = tuple(_forms(prepared, k, f) for k, f in enumerate(implicit))
    found = prepared.modes(derivation.reference, bits=BITS)
    modes = tuple(tuple(_mode_rates(f, m.label, mode.values, derivation.reference)
                        for m, mode in zip(group.modes, at))
                  for f, group, at in zip(implicit, derivation.groups, found))
    timings = {"rate_forms": time.perf_counter() - mark}
    mark = time.perf_counter()
    if samples:
        verification = check_group_rates(prepared, implicit, samples=samples, seed=seed)
    else:
        verification = GroupRatesCheck(status="skipped")
    timings["rate_check"] = time.perf_counter() - mark
    per = "radian" if prepared.input.is_angle else "length"
    return GroupRates(derivation, prepared.input.name, per, forms, modes, verification, timings)


def implicit_of(prepared: GroupScene, index: int) -> ImplicitRates:
    """Group ``index``'s rate forms from its own equations (an angle's reduced on its circle)."""
    group = prepared.compiled.groups[index]
    names = sorted({str(v) for e in group.equations for v in e.free_symbols} - set(group.unknowns))
    ctx = flint_context(group.unknowns + tuple(names))
    found = implicit_rates([to_flint(e, ctx) for e in group.equations], group.unknowns, prepared.variables)
    return _on_circle(found, prepared.variables)


def _on_circle(found: ImplicitRates, variables: Sequence[str]) -> ImplicitRates:
    def reduced(p: flint.fmpq_mpoly) -> flint.fmpq_mpoly:
        return on_circle(p, variables)

    return ImplicitRates(found.unknowns, found.variables, reduced(found.denominator),
                         {u: reduced(p) for u, p in found.velocity.items()},
                         {u: reduced(p) for u, p in found.acceleration.items()})


def _forms(prepared: GroupScene, index: int, found: ImplicitRates) -> GroupRateForms:
    d = _text(found.denominator)
    velocity = {u: f"({_text(p)})/({d})" for u, p in found.velocity.items()}
    acceleration = {u: f"({_text(p)})/({d})**3" if len(p) <= SMALL_TERMS else
                    f"({len(p)}-term polynomial in the mode's coordinates and the input)/({d})**3"
                    for u, p in found.acceleration.items()}
    return GroupRateForms(prepared.compiled.groups[index].points, d, velocity, acceleration)


def _mode_rates(found: ImplicitRates, label: str, values: Mapping[str, flint.arb], sample: Sample) -> ModeRates:
    with flint.ctx.workprec(BITS):
        rates = found.at(dict(values, **sample.balls(BITS)), sample.exact())
    return ModeRates(label, {u: _decimal(v) for u, (v, _) in rates.items()},
                     {u: _decimal(a) for u, (_, a) in rates.items()})


def _decimal(ball: flint.arb) -> str:
    if not ball.is_finite():
        raise ComputationError("a mode's rate is not finite at the reference input: modes meet there")
    return ball.str(15, radius=False)


def _text(poly: flint.fmpq_mpoly) -> str:
    return str(poly).replace("^", "**")
