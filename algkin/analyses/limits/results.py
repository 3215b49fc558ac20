"""What ``limits`` answers: each limit position, the time ratio, and all of them with their JSON."""

from __future__ import annotations

from typing import Any

import attrs
import flint
import sympy

from ...runtime.frozen import FrozenDict
from ..frozen import deep_frozen, frozen_rows, thawed

__all__ = ["Json", "Limit", "TimeRatio", "Limits"]

Json = dict[str, Any]


@attrs.frozen
class Limit:
    """One limit position: the input angle (exact and certified), the point, its branch, where it is."""

    input_deg: float
    enclosure: flint.arb = attrs.field(eq=False)  # degrees, holds the exact root (balls do not hash)
    exact_deg: sympy.Expr  # the input angle in degrees, exactly (radicals, or a CRootOf)
    factor: sympy.Expr | None  # the irreducible polynomial in t = tan(theta/2) it is a root of (None: 180 deg)
    point: str
    branch: str  # the branch's label ("left", or "B:left F:right" for several dyads)
    selected: bool  # the branch the scene file asks for
    kind: str  # extended / folded (crank and coupler in line), stationary otherwise
    position: FrozenDict[str, Any] = attrs.field(converter=deep_frozen)  # x, y; angle_deg about the pivot or along the line; exact forms where sympy finds them
    certificate: str

    def to_json(self) -> Json:
        return {"input_deg": self.input_deg, "enclosure_deg": self.enclosure.str(20),
                "exact_deg": str(self.exact_deg),
                "t_factor": None if self.factor is None else str(self.factor), "point": self.point,
                "branch": self.branch, "selected": self.selected, "kind": self.kind, "position": thawed(self.position),
                "certified": True, "certificate": self.certificate}


@attrs.frozen
class TimeRatio:
    """The working and return strokes of one output on the scene's branch, in crank degrees."""

    point: str
    branch: str
    ratio: float
    enclosure: flint.arb = attrs.field(eq=False)
    exact: sympy.Expr
    strokes: tuple[FrozenDict[str, Any], ...] = attrs.field(converter=frozen_rows)  # working then return: from_deg, to_deg, crank_deg, exact
    alpha_deg: float
    stroke: FrozenDict[str, Any] = attrs.field(converter=deep_frozen)  # the output's swing (degrees about its pivot) or travel (along its line)

    def to_json(self) -> Json:
        return {"point": self.point, "branch": self.branch, "ratio": self.ratio,
                "enclosure": self.enclosure.str(20), "exact": str(self.exact),
                "strokes": thawed(self.strokes), "alpha_deg": self.alpha_deg, "stroke": thawed(self.stroke),
                "rule": "Q = (180 + alpha)/(180 - alpha): working stroke over return stroke, in crank angle"}


def _limits(limits: Any) -> tuple[Limit, ...]:
    return tuple(limits)


@attrs.frozen
class Limits:
    """Every limit position of every point with a fixed path, and the output's time ratio."""

    scene: str
    input: str
    range: tuple[float, float]
    limits: tuple[Limit, ...] = attrs.field(converter=_limits)
    time_ratio: TimeRatio | None
    time_ratio_reason: str | None  # why there is none
    dropped: tuple[FrozenDict[str, Any], ...] = attrs.field(default=(), converter=frozen_rows)  # roots that are no limit, with why
    skipped: tuple[FrozenDict[str, Any], ...] = attrs.field(default=(), converter=frozen_rows)  # points without a fixed path, with why

    def to_json(self) -> Json:
        return {"limits": [g.to_json() for g in self.limits],
                "time_ratio": None if self.time_ratio is None else self.time_ratio.to_json(),
                "time_ratio_reason": self.time_ratio_reason, "limits_dropped": thawed(self.dropped),
                "limits_skipped": thawed(self.skipped)}
