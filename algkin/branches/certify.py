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
>>> certify_label(left, ("c_angle", "s_angle"), 0, 360, {})
[{'from_deg': 0.0, 'to_deg': 360.0, 'status': 'certified'}]

A length input's intervals are lengths, under the keys ``from_length`` and ``to_length``.
"""

import heapq
from collections.abc import Mapping, Sequence
from typing import TypedDict

import flint
import numpy as np
from numpy.typing import NDArray

from ..evaluate import ARB
from ..evaluate.program import BallProgram, compile_program
from ..system import input_values
from .closed_form import Branch

__all__ = ["certify_label", "Interval", "MIN_WIDTH_DEG", "interval_keys", "uncertified"]

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


def interval_keys(turning: bool) -> tuple[str, str]:
    """The keys of an interval's ends: degrees for a turning input, a length as it is."""
    return ("from_deg", "to_deg") if turning else ("from_length", "to_length")


def _status(discriminants: BallProgram, variables: tuple[str, ...], lo: float, hi: float,
            parameters: Mapping[str, flint.arb]) -> str | None:
    """Over ``[lo, hi]``: ``no-assembly`` if a discriminant (a program of the variables, then the
    parameters) is negative throughout, ``certified`` if all are positive throughout, else None."""
    middle, radius = (flint.arb(lo) + flint.arb(hi)) / 2, (flint.arb(hi) - flint.arb(lo)) / 2
    value = flint.arb(middle.mid(), radius.mid() + radius.rad())
    if len(variables) == 2:
        value *= flint.arb.pi() / 180
    at = input_values(variables, value)
    balls = discriminants(*(at[v] for v in variables), *parameters.values())
    if any(b < 0 for b in balls):
        return "no-assembly"
    if all(b > 0 for b in balls):
        return "certified"
    return None


def certify_label(branch: Branch, variables: tuple[str, ...], lo_deg: float, hi_deg: float,
                  parameters: Mapping[str, flint.arb]) -> list[Interval]:
    """[{from_deg, to_deg, status}] covering ``[lo_deg, hi_deg]``, merged by status.

    ``variables``: the input's, an angle's (cos, sin) (the range in degrees) or a length's one
    (the range in lengths, the keys ``from_length``, ``to_length``); ``parameters``: name -> arb for every
    dimension in the discriminants.
    """
    if not branch.discriminants:
        return _merged([(float(lo_deg), float(hi_deg), "certified")], variables)
    # compiled once: the interval's splits evaluate them hundreds of times
    discriminants = compile_program(branch.discriminants.values(), [*variables, *parameters], ARB)
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
            status = _status(discriminants, variables, lo, hi, parameters)
            if status is None and hi - lo < MIN_WIDTH_DEG:
                with flint.ctx.workprec(4 * BITS):
                    status = _status(discriminants, variables, lo, hi, parameters) or "undecided"
            if status is None:
                middle = (lo + hi) / 2
                heapq.heappush(queue, (lo - middle, lo, middle))
                heapq.heappush(queue, (middle - hi, middle, hi))
            else:
                pieces.append((lo, hi, status))
    return _merged(pieces, variables)


def uncertified(intervals: Sequence[Interval], shown: NDArray[np.float64], turning: bool) -> NDArray[np.bool_]:
    """Where the inputs ``shown`` (degrees, or lengths) fall in an interval of ``intervals`` that is
    not ``certified`` (``undecided`` at a toggle, or ``no-assembly``): where a float evaluation must
    say nothing. An angle is taken a turn at a time into the intervals' range when they cover a
    whole turn; an input outside their range is not held against them.

    >>> pieces = [{"from_deg": 0.0, "to_deg": 10.0, "status": "certified"},
    ...           {"from_deg": 10.0, "to_deg": 20.0, "status": "undecided"}]
    >>> uncertified(pieces, np.array([5.0, 15.0, 375.0, 30.0]), turning=True).tolist()
    [False, True, False, False]
    """
    start, end = interval_keys(turning)
    lows = np.array([i[start] for i in intervals], dtype=np.float64)  # type: ignore[literal-required]
    highs = np.array([i[end] for i in intervals], dtype=np.float64)  # type: ignore[literal-required]
    values = np.asarray(shown, dtype=np.float64)
    if turning and highs[-1] - lows[0] >= 360:
        values = lows[0] + np.mod(values - lows[0], 360.0)
    index = np.clip(np.searchsorted(highs, values, side="left"), 0, len(intervals) - 1)
    inside = (values >= lows[0]) & (values <= highs[-1])
    bad = np.array([i["status"] != "certified" for i in intervals], dtype=np.bool_)
    unproved: NDArray[np.bool_] = inside & bad[index]  # numpy types an array's comparison with its item as Any
    return unproved


def _merged(pieces: Sequence[tuple[float, float, str]], variables: Sequence[str]) -> list[Interval]:
    start, end = interval_keys(len(variables) == 2)
    merged: list[dict[str, float | str]] = []
    for lo, hi, status in sorted(pieces):
        if merged and merged[-1]["status"] == status and merged[-1][end] == lo:
            merged[-1][end] = hi
        else:
            merged.append({start: lo, end: hi, "status": status})
    return merged  # type: ignore[return-value]  # an angle's keys, or a length's
