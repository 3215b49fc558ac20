"""Velocities and accelerations of a scene's outputs as closed forms per branch, checked by finite differences.

Each output coordinate's first and second derivatives in the input angle (per radian: the
velocity and acceleration for a unit input rate; per unit of a length input) come from its branch closed form by the
chain rule (``forms``), and are checked against central differences of the original
system's roots, solved and proved independently of every closed form (``check``).

>>> found = rates("chebyshev-lambda", outputs=["P"], samples=4)
>>> [b.label for b in found.branches]
['left', 'right']
>>> found.branches[0].velocity["P_y"]
c_angle*s_angle*(8*c_angle + 5)/(sqrt((5 - 4*c_angle)*(c_angle + 5))*(4*c_angle - 5))
>>> found.verification.passed, found.verification.max_rel_error < 1e-30
(True, True)
"""

from __future__ import annotations

import time
from typing import TYPE_CHECKING, Any

import attrs
import sympy

from ...derivation.pipeline import derive
from ...derivation.checking import check_setup
from ...derivation.prepared import Prepared
from ...derivation.results import Derivation
from ...eliminate import DEFAULT_METHOD
from ...errors import UsageError
from ...runtime import validation
from ...runtime.frozen import FrozenDict, frozen
from ...runtime.exclusive import one_at_a_time
from ...scene.load import SceneLike, as_scene
from ...system import symbol
from .check import RatesCheck, check_rates
from .forms import Rate, rates_of_values
from .text import text

if TYPE_CHECKING:
    from ..groups.rates import GroupRates

__all__ = ["rates", "rates_of", "check_forms", "Rates", "BranchRates", "RatesCheck", "Rate"]

SAMPLES = 20  # inputs the rates are checked at by default


@attrs.frozen
class BranchRates:
    """One branch's velocity and acceleration closed forms, per output coordinate (unknown)."""

    label: str
    selected: bool
    velocity: FrozenDict[str, sympy.Expr] = attrs.field(converter=frozen)
    acceleration: FrozenDict[str, sympy.Expr] = attrs.field(converter=frozen)

    def to_json(self) -> dict[str, dict[str, str]]:
        return {u: {"velocity": text(v), "acceleration": text(self.acceleration[u])} for u, v in self.velocity.items()}


def _branches(branches: Any) -> tuple[BranchRates, ...]:
    return tuple(branches)


@attrs.frozen
class Rates:
    """The rates of a derivation's outputs: per branch closed forms, and their check."""

    derivation: Derivation
    input: str  # the input the derivatives are taken in
    branches: tuple[BranchRates, ...] = attrs.field(converter=_branches)
    verification: RatesCheck
    timings: FrozenDict[str, float] = attrs.field(converter=frozen, eq=False)  # how long, not what
    per: str = "radian"  # "radian" for an input angle, "length" for a length input

    def to_json(self) -> dict[str, Any]:
        """The keys ``derive --rates --json`` adds to the derivation's document."""
        return {"rates": {b.label: b.to_json() for b in self.branches},
                "rates_input": {"name": self.input, "per": self.per},
                "rates_verification": self.verification.to_json()}


@one_at_a_time
def rates(scene: SceneLike | Prepared, outputs: list[str] | None = None, params: tuple[str, ...] | list[str] = (),
          samples: int = SAMPLES, seed: int = 0, method: str = DEFAULT_METHOD, backend: str = "flint",
          set: dict[str, Any] | None = None) -> Rates | GroupRates:  # noqa: A002 - ``set=`` as in derive
    """Velocity and acceleration of every coordinate of ``outputs`` of a one-input ``scene``, per
    branch, checked on ``samples`` inputs (0 skips the check); the positions' derivation and its
    own verification are in ``.derivation``. ``scene`` may be a ``Prepared`` one (``prepare``).

    A scene with points solved together (``unknown = true``) has every unknown's rates per mode
    instead (``algkin.analyses.groups.rates.GroupRates``; ``outputs``, ``params``, ``method`` and
    ``backend`` are the dyads' and are refused there)."""
    validation.count("samples", samples, validation.MAX_VERIFY_SAMPLES)
    if not isinstance(scene, Prepared) and as_scene(scene).unknown_points:
        return _group_rates(scene, outputs=outputs, params=params, method=method, values=set, samples=samples,
                            seed=seed)
    derivation = derive(scene, outputs, method=method, backend=backend, params=params, samples=samples, seed=seed,
                        set=set)
    return rates_of(derivation, samples, seed)


def _group_rates(scene: SceneLike, *, outputs: list[str] | None, params: tuple[str, ...] | list[str], method: str,
                 values: dict[str, Any] | None, samples: int, seed: int) -> GroupRates:
    """``rates`` of a scene with points solved together: its dyads' options refused, by name."""
    from ..groups.rates import group_rates

    dyads = (("outputs", outputs), ("params", params), ("method", None if method == DEFAULT_METHOD else method),
             ("set", values))
    for name, given in dyads:
        if given:
            raise UsageError(name, given, "is not taken with points solved together (unknown = true) yet")
    return group_rates(as_scene(scene), samples=samples, seed=seed)


def rates_of(derivation: Derivation, samples: int = SAMPLES, seed: int = 0) -> Rates:
    """``rates`` of an existing derivation."""
    compiled: Any = derivation.compiled
    if len(compiled.system.inputs) != 1:  # a derivative needs one input to be taken in
        inputs = compiled.system.inputs
        raise UsageError("scene", compiled.scene.name, f"rates need outputs moved by one input angle; they move with "
                         f"{len(inputs)}" + (f" ({', '.join(inputs)})" if inputs else ""))
    (name, variables), = compiled.system.inputs.items()
    unknowns = [u for names in compiled.outputs.values() for u in names]
    mark = time.perf_counter()
    forms = [rates_of_values(b.values, unknowns, tuple(symbol(v) for v in variables)) for b in derivation.branches]
    branches = [BranchRates(b.label, b.selected, {u: r.velocity for u, r in f.items()},
                            {u: r.acceleration for u, r in f.items()}) for b, f in zip(derivation.branches, forms)]
    timings = {"rate_forms": time.perf_counter() - mark}
    mark = time.perf_counter()
    verification = check_forms(derivation, forms, samples, seed)
    timings["rate_check"] = time.perf_counter() - mark
    return Rates(derivation, name, branches, verification, timings, "radian" if len(variables) == 2 else "length")


def check_forms(derivation: Derivation, forms: list[dict[str, Rate]], samples: int = SAMPLES,
                seed: int = 0) -> RatesCheck:
    """``forms`` (per branch of ``derivation``, unknown -> ``Rate``) against central differences,
    symbolic dimensions at their defaults; a test hands it wrong forms to see them caught."""
    compiled: Any = derivation.compiled
    setup = check_setup(compiled, derivation.branches)
    system, indicators, branches, spans = setup.system, setup.indicators, setup.branches, setup.inputs
    defaults = {symbol(n): compiled.parameter_values[n] for n in compiled.system.parameters}
    checked = [(labels, {u: (r.velocity.xreplace(defaults), r.acceleration.xreplace(defaults)) for u, r in f.items()},
                discriminants) for (labels, _, discriminants), f in zip(branches, forms)]
    (span,) = spans.values()
    return check_rates(system, indicators, checked, span, samples, seed)
