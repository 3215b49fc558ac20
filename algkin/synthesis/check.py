"""A synthesized four-bar checked by algkin's own derivation, and its defects certified.

The design's scene is loaded like any other and solved (``algkin.analyses.solve``, certified
balls) at the crank angle of each precision position: the dyad's mode there is the one the
design puts ``B`` on, and its ``A`` and ``B`` must be where the synthesis wants them, within
the scene's digits (``deviation`` is the largest distance found). Then the defects a designer
trips over, each decided exactly or in certified balls:

- ``branch``: the positions are not all on one assembly mode of the dyad, or a toggle (a dead
  centre, ``algkin.analyses.toggles``) lies on the crank's way from one position to the next;
- ``circuit``: the modes of the positions are on different circuits (a Grashof four-bar whose
  crank turns fully: its two modes never meet), so no motion joins them;
- ``order``: the crank, turning one way, meets the positions in another order;
- ``transmission``: the transmission angle (at ``B``, between the coupler and the rocker)
  leaves [``min_transmission``, 180 - ``min_transmission``] between the first and last position.

A design is ``usable`` when it has none of them.
"""

from __future__ import annotations

from collections.abc import Sequence
from fractions import Fraction
from typing import Any

import attrs
import flint

from ..analyses.extremum import extremum
from ..analyses.solve import solve
from ..analyses.toggles import grashof, toggles
from ..errors import ComputationError
from ..scene import Scene, compile_scene
from ..scene.load import load_scene_text
from .fourbar import BITS, DIGITS, FourBar, scene_text

__all__ = ["Checked", "check_design", "MIN_TRANSMISSION", "TRANSMISSION"]

MIN_TRANSMISSION = 30
"""Degrees: a transmission angle below it (or above 180 minus it) is a defect, by default."""
TRANSMISSION = "angle(A, B, D)"
"""The transmission angle: at the coupler-rocker joint B, between the crank tip A and the rocker's pivot D."""
TOLERANCE = flint.arb(10) ** -20
"""Largest relative distance from a wanted position: a scene to 40 digits misses by about 1e-38."""


@attrs.frozen
class Checked:
    """A design checked: its ``scene`` text, the mode of each position (``modes``), the crank
    angle of each (degrees), whether algkin's solve put it at every position (``reached``, the
    largest distance ``deviation``), the Grashof class, the transmission angle's range between
    the first and last position (degrees, in the crank's turning ``direction``: +1 counter-
    clockwise), and the ``defects`` (each a kind and why)."""

    name: str
    scene: str
    modes: tuple[str | None, ...]
    crank_angles: tuple[float, ...]
    reached: bool
    deviation: float
    grashof: str | None
    direction: int | None
    transmission_range: tuple[float, float] | None
    defects: tuple[tuple[str, str], ...]

    @property
    def usable(self) -> bool:
        return self.reached and not self.defects

    def to_json(self) -> dict[str, Any]:
        return {"name": self.name, "modes": list(self.modes), "crank_angles_deg": list(self.crank_angles),
                "reached": self.reached, "deviation": self.deviation, "grashof": self.grashof,
                "direction": self.direction,
                "transmission_range": None if self.transmission_range is None else list(self.transmission_range),
                "defects": [{"kind": k, "why": w} for k, w in self.defects], "usable": self.usable}


def check_design(design: FourBar, *, min_transmission: float = MIN_TRANSMISSION, digits: int = DIGITS) -> Checked:
    """``design`` written as a scene, solved at each position, and its defects found."""
    modes = tuple(design.branch_at(i) for i in range(len(design.positions)))
    if modes[0] is None:
        raise ComputationError(f"{design.name}: the first position is at a dead centre (A, B and the rocker's "
                               "pivot in line): no assembly mode to write")
    text = scene_text(design, branch=modes[0], digits=digits)
    scene = load_scene_text(text, design.name + ".toml")
    angles = tuple(_degrees(design.crank_angle(i)) for i in range(len(design.positions)))
    deviation = max(_deviation(design, scene, i, angle=angles[i], mode=mode) for i, mode in enumerate(modes))
    kind = _grashof(scene)
    defects = _mode_defects(modes, kind)
    direction, order_why = _direction(angles)
    if order_why:
        defects.append(("order", order_why))
    span = None
    if direction is not None and len(set(modes)) == 1:
        toggle_why = _toggle_between(scene, angles, direction)
        if toggle_why:
            defects.append(("branch", toggle_why))
        else:
            span = _transmission(scene, angles, direction)
            if span[0] < min_transmission or span[1] > 180 - min_transmission:
                defects.append(("transmission", f"the transmission angle ranges over [{span[0]:.4g}, {span[1]:.4g}] "
                                                f"degrees, outside [{min_transmission:g}, {180 - min_transmission:g}]"))
    scale = max(abs(float(c.mid())) for c in (*design.crank_pivot, *design.rocker_pivot)) + 1
    return Checked(design.name, text, modes, tuple(float(a) for a in angles), deviation < float(TOLERANCE.mid()) * scale,
                   deviation, kind, direction, span, tuple(defects))


def _degrees(angle: flint.arb) -> Fraction:
    """An angle in [0, 360), to 40 digits, as the exact decimal ``solve`` takes."""
    text = (angle if angle >= 0 else angle + 360).mid().str(40, radius=False)
    return Fraction(*_ratio(text))


def _ratio(text: str) -> tuple[int, int]:
    from decimal import Decimal

    return Decimal(text).as_integer_ratio()


def _deviation(design: FourBar, scene: Scene, index: int, *, angle: Fraction, mode: str | None) -> float:
    """The largest distance of A and B, as algkin solves the scene on ``mode``, from where the
    design wants them at position ``index`` (infinity where that mode does not assemble)."""
    if mode is None:
        return float("inf")
    found = solve(scene, at={"theta": str(angle)}, mode=mode, digits=45)
    if not found.configurations:
        return float("inf")
    points = found.configurations[0].points
    wanted = design.positions[index]
    with flint.ctx.workprec(BITS):
        gaps = [abs(flint.arb(points[name][k]) - want[k]) for name, want in (("A", wanted.crank_tip),
                                                                           ("B", wanted.rocker_tip)) for k in (0, 1)]
    return max(float(g.upper()) for g in gaps)


def _grashof(scene: Scene) -> str | None:
    found = grashof(compile_scene(scene, ["B"]))
    return None if found is None else str(found["class"])


def _mode_defects(modes: Sequence[str | None], kind: str | None) -> list[tuple[str, str]]:
    if None in modes:
        return [("branch", f"position {modes.index(None) + 1} is at a dead centre")]
    if len(set(modes)) == 1:
        return []
    first = modes[0]
    other = next(i for i, m in enumerate(modes) if m != first)
    why = f"position 1 is on the {first} mode, position {other + 1} on the {modes[other]}"
    if kind in ("crank-rocker", "double crank"):  # the crank turns fully: each mode is a circuit
        return [("circuit", why + f"; a {kind}'s two modes never meet")]
    return [("branch", why)]


def _direction(angles: Sequence[Fraction]) -> tuple[int | None, str]:
    """The crank's turning direction (+1 counterclockwise) that meets the positions in their
    order within one turn, and why neither does (empty when one does)."""
    for direction in (1, -1):
        offsets = [(direction * (a - angles[0])) % 360 for a in angles[1:]]
        if all(x < y for x, y in zip([Fraction(0)] + offsets, offsets)):
            return direction, ""
    shown = ", ".join(f"{float(a):.4g}" for a in angles)
    return None, f"the crank meets the positions in another order, turning either way (crank angles {shown} degrees)"


def _toggle_between(scene: Scene, angles: Sequence[Fraction], direction: int) -> str:
    """Why the crank's way from the first position to the last crosses a dead centre (empty: it does not)."""
    last = (direction * (angles[-1] - angles[0])) % 360
    for toggle in toggles(scene, artefacts=False).toggles:
        offset = (direction * (Fraction(*_ratio(toggle.enclosure.mid().str(40, radius=False))) - angles[0])) % 360
        if 0 < offset < last:
            return f"a dead centre of B ({toggle.kind}) at crank angle {toggle.input_deg:.6g} degrees lies between " \
                   "the first and the last position"
    return ""


def _transmission(scene: Scene, angles: Sequence[Fraction], direction: int) -> tuple[float, float]:
    """The transmission angle's least and greatest value on the crank's way through the positions."""
    sweep = (direction * (angles[-1] - angles[0])) % 360
    start = angles[0] if direction > 0 else angles[0] - sweep
    found = extremum(scene, TRANSMISSION, angle_range=(float(start), float(start + sweep)))
    return float(found.minimum.value), float(found.maximum.value)
