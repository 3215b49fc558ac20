"""Certified branch labels: input intervals where ball arithmetic proves the label holds.

A branch is real, and its label (the side of each dyad) means one thing, while every
dyad discriminant stays positive. Over an input interval given as one arb ball, the
discriminants evaluated in balls either exclude zero (the label is *certified* on the
whole interval, or the branch provably does *not assemble* there) or the interval is
split. Intervals that shrink below ``MIN_WIDTH_DEG`` undecided get one more try at four
times the precision; what is still undecided is reported as ``undecided`` (a toggle lies
there, or the balls are too wide), never guessed.

>>> from algkin.scene import load_scene, compile_scene
>>> from algkin.branches import closed_forms
>>> compiled = compile_scene(load_scene("chebyshev-lambda"), ["B"])
>>> left = closed_forms(compiled)[0]
>>> certify_label(left, "c_angle", "s_angle", 0, 360, {})
[{'from_deg': 0.0, 'to_deg': 360.0, 'status': 'certified'}]
"""

import heapq
from collections.abc import Mapping, Sequence
from typing import TypedDict

import flint
import sympy

from ..evaluate import ARB, evaluate
from .closed_form import Branch

__all__ = ["certify_label", "Interval", "MIN_WIDTH_DEG"]

MIN_WIDTH_DEG = 1e-7
# Each interval splits until decided or narrower than MIN_WIDTH_DEG; where a discriminant stays
# within rounding of zero over a stretch (a branch that touches its boundary without crossing),
# that would be millions of intervals: past this many evaluations the rest is undecided.
MAX_EVALUATIONS = 5_000
BITS = 64


class Interval(TypedDict):
    """Input angles in degrees and what holds there: ``certified``, ``no-assembly`` or ``undecided``."""

    from_deg: float
    to_deg: float
    status: str


def _status(discriminants: Sequence[sympy.Expr], c_name: str, s_name: str, lo: float, hi: float,
            parameters: Mapping[str, flint.arb]) -> str | None:
    middle, radius = (flint.arb(lo) + flint.arb(hi)) / 2, (flint.arb(hi) - flint.arb(lo)) / 2
    angle = flint.arb(middle.mid(), radius.mid() + radius.rad()) * flint.arb.pi() / 180
    values = dict(parameters, **{c_name: angle.cos(), s_name: angle.sin()})
    balls = [evaluate(d, values, ARB) for d in discriminants]
    if any(b < 0 for b in balls):
        return "no-assembly"
    if all(b > 0 for b in balls):
        return "certified"
    return None


def certify_label(branch: Branch, c_name: str, s_name: str, lo_deg: float, hi_deg: float,
                  parameters: Mapping[str, flint.arb]) -> list[Interval]:
    """[{from_deg, to_deg, status}] covering ``[lo_deg, hi_deg]``, merged by status.

    ``parameters``: name -> arb for every dimension in the discriminants.
    """
    discriminants = list(branch.discriminants.values())
    if not discriminants:
        return [{"from_deg": float(lo_deg), "to_deg": float(hi_deg), "status": "certified"}]
    pieces: list[tuple[float, float, str]] = []
    # widest first: if the evaluations run out, what is left undecided is the finest part
    queue = [(-(float(hi_deg) - float(lo_deg)), float(lo_deg), float(hi_deg))]
    evaluations = 0
    with flint.ctx.workprec(BITS):
        while queue:
            _, lo, hi = heapq.heappop(queue)
            evaluations += 1
            if evaluations > MAX_EVALUATIONS:  # a discriminant flat at zero over a stretch: left undecided
                pieces += [(lo, hi, "undecided")] + [(a, b, "undecided") for _, a, b in queue]
                break
            status = _status(discriminants, c_name, s_name, lo, hi, parameters)
            if status is None and hi - lo < MIN_WIDTH_DEG:
                with flint.ctx.workprec(4 * BITS):
                    status = _status(discriminants, c_name, s_name, lo, hi, parameters) or "undecided"
            if status is None:
                middle = (lo + hi) / 2
                heapq.heappush(queue, (lo - middle, lo, middle))
                heapq.heappush(queue, (middle - hi, middle, hi))
            else:
                pieces.append((lo, hi, status))
    return _merged(pieces)


def _merged(pieces: Sequence[tuple[float, float, str]]) -> list[Interval]:
    merged: list[Interval] = []
    for lo, hi, status in sorted(pieces):
        if merged and merged[-1]["status"] == status and merged[-1]["to_deg"] == lo:
            merged[-1]["to_deg"] = hi
        else:
            merged.append({"from_deg": lo, "to_deg": hi, "status": status})
    return merged
