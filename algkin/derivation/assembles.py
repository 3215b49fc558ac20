"""Where a one-input scene assembles: the intervals its verification samples, and structures refused.

A design may assemble on a short stretch of its input's range only, or at isolated inputs (a
four-bar with ``d - a = l + m`` reaches across only at ``theta = 0``): a structure, not a
motion. A float grid of the branches' discriminants (``GRID`` inputs, as ``check_assembly``'s)
tells the common case, a branch real on much of the range, at once; only when some branch is
real on less than ``NARROW`` of the grid are the labels certified in balls
(``algkin.branches.certify_label``), which proves where no branch assembles: the
verification then draws its samples in the rest, and a scene whose own branch is certified
nowhere (its undecided stretches together narrower than ``STILL`` of the range) is refused.

>>> from algkin.scene import load_scene, compile_scene
>>> from algkin.scene.settings import with_values
>>> from algkin.branches import closed_forms
>>> compiled = compile_scene(load_scene("fourbar"), ["P"])
>>> where_assembled(compiled, closed_forms(compiled)) is None   # a crank-rocker: the whole turn
True
>>> compiled = compile_scene(with_values(load_scene("fourbar"), {"a": "5/6", "d": "22/3"}), ["P"])
>>> where_assembled(compiled, closed_forms(compiled))
Traceback (most recent call last):
...
algkin.errors.SceneError: fourbar.toml: points.B: assembles only at theta = 0° (with a=5/6, d=22/3, l=3, m=7/2): a structure, not a motion
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from fractions import Fraction

import attrs
import flint
import numpy as np
import sympy

from ..branches import Branch, certify_label
from ..branches.certify import Interval, interval_keys
from ..errors import SceneError
from ..evaluate import ARB, NUMPY
from ..evaluate.program import compile_program
from ..scene import Compiled
from ..system import input_values, symbol
from ..verify.check import real_floats

__all__ = ["where_assembled", "certify_labels", "Pieces", "STRUCTURE", "GRID", "NARROW", "STILL"]

GRID = 721  # inputs of the float grid over the range, as check_assembly's
NARROW = 1 / 4  # a branch real on less of the grid: its labels are certified, the samples drawn where it may be
STILL = 1e-4  # undecided stretches together narrower than this part of the range, nothing certified: no motion
STRUCTURE = "a structure, not a motion"  # what a structure's error says (the sweep's status reads it)

Pieces = Sequence[tuple[float, float]]  # stretches of an input's range: (lo, hi) in radians, or lengths


def certify_labels(compiled: Compiled, branches: Sequence[Branch]) -> list[list[Interval] | None]:
    """Per branch, the input intervals where its label is certified (dimensions at defaults)."""
    if len(compiled.system.inputs) != 1:
        return [None] * len(branches)
    (name, variables), = compiled.system.inputs.items()
    lo, hi = compiled.scene.inputs[name].span
    return [certify_label(b, variables, lo, hi, _balls(compiled)) for b in branches]


def _balls(compiled: Compiled) -> dict[str, flint.arb]:
    return {n: ARB.number(Fraction(str(v)).numerator, Fraction(str(v)).denominator)
            for n, v in compiled.parameter_values.items()}


def where_assembled(compiled: Compiled, branches: Sequence[Branch]) -> dict[str, list[tuple[float, float]]] | None:
    """``{input: [(lo, hi), ...]}`` (radians, or lengths) outside which no branch assembles, when
    some branch is real on a narrow part of the range only; ``None`` when the whole range is to be
    sampled. SceneError when the scene's own branch assembles at isolated inputs only.

    ``algkin.derivation.prepare`` finds it once, for the witnesses and the verification."""
    if len(compiled.system.inputs) != 1 or not branches:
        return None
    (name, variables), = compiled.system.inputs.items()
    spec = compiled.scene.inputs[name]
    lo, hi = spec.span
    if not hi > lo:
        return None
    real = _real(compiled, branches, variables, np.linspace(lo, hi, GRID), spec.is_angle)
    chosen = next(k for k, b in enumerate(branches) if b.selected)
    balls = _balls(compiled)
    if real[chosen].mean() < NARROW:
        _refuse_structure(compiled, branches[chosen], certify_label(branches[chosen], variables, lo, hi, balls),
                          (lo, hi))
    if np.any(real, axis=0).mean() >= NARROW:  # drawn on the whole range, enough samples fall where it assembles
        return None
    start, end = interval_keys(spec.is_angle)
    pieces = _joined(sorted((i[start], i[end]) for b in branches  # type: ignore[literal-required]
                            for i in certify_label(b, variables, lo, hi, balls) if i["status"] != "no-assembly"))
    if not pieces or sum(b - a for a, b in pieces) >= NARROW * (hi - lo):
        return None
    scale = math.pi / 180 if spec.is_angle else 1.0
    return {name: [(a * scale, b * scale) for a, b in pieces]}


def _real(compiled: Compiled, branches: Sequence[Branch], variables: tuple[str, ...],
          grid: np.ndarray, angle: bool) -> np.ndarray:
    """Per branch, per input of the grid, whether every discriminant is positive in floats; all True
    (nothing narrowed, nothing refused) where a dimension's rationals leave a float's range."""
    defaults = {symbol(n): v for n, v in compiled.parameter_values.items()}
    floats = input_values(variables, np.radians(grid) if angle else grid)
    rows = []
    for branch in branches:
        program = compile_program([d.xreplace(defaults) for d in branch.discriminants.values()], list(variables), NUMPY)
        rows.append(real_floats(program, floats, list(variables)))
    return np.array(rows)


def _joined(pieces: list[tuple[float, float]]) -> list[tuple[float, float]]:
    """Sorted intervals, those that touch or overlap made one."""
    if not pieces:
        return []
    joined = [pieces[0]]
    for a, b in pieces[1:]:
        if a <= joined[-1][1]:
            joined[-1] = (joined[-1][0], max(joined[-1][1], b))
        else:
            joined.append((a, b))
    return joined


def _refuse_structure(compiled: Compiled, branch: Branch, intervals: list[Interval], span: tuple[float, float]) -> None:
    """SceneError naming where ``branch`` assembles if it is certified nowhere and what is undecided is
    narrower than ``STILL`` of the range (a touch of its discriminant's zero, not a stretch of motion)."""
    start, end = interval_keys("from_deg" in intervals[0])
    if any(i["status"] == "certified" for i in intervals):
        return
    undecided = [(i[start], i[end]) for i in intervals if i["status"] == "undecided"]  # type: ignore[literal-required]
    if not undecided or sum(b - a for a, b in undecided) >= STILL * (span[1] - span[0]):
        return
    (name, _), = compiled.system.inputs.items()
    spec = compiled.scene.inputs[name]
    places = _places(_joined(sorted(undecided)), span, full_turn=spec.is_angle and span[1] - span[0] >= 360)
    at = " and ".join(f"{name} = {spec.shown(p)}" for p in places)
    point = _culprit(branch, compiled)
    dimensions = _dimensions(compiled, point)  # none where the file gives every length as a number
    raise SceneError(compiled.scene.source, f"points.{point}",
                     f"assembles only at {at}{f' (with {dimensions})' if dimensions else ''}: {STRUCTURE}")


def _places(stretches: list[tuple[float, float]], span: tuple[float, float], full_turn: bool) -> list[float]:
    """The middle of each stretch, rounded to a thousandth; on a full turn its two ends are one place."""
    if full_turn and len(stretches) > 1 and stretches[0][0] <= span[0] and stretches[-1][1] >= span[1]:
        first, last = stretches[0], stretches[-1]
        stretches = [(last[0] - 360, first[1])] + stretches[1:-1]
    places = []
    for a, b in stretches:
        middle = round((a + b) / 2, 3)
        middle = middle % 360 if full_turn else middle
        places.append(middle + 0.0 if middle else 0.0)  # no "-0"
    return places


def _culprit(branch: Branch, compiled: Compiled) -> str:
    """The first point whose discriminant alone is certified nowhere (the first point, if none)."""
    (_, variables), = compiled.system.inputs.items()
    lo, hi = compiled.scene.inputs[next(iter(compiled.system.inputs))].span
    for point, discriminant in branch.discriminants.items():
        alone = attrs.evolve(branch, discriminants={point: discriminant})
        if not any(i["status"] == "certified" for i in certify_label(alone, variables, lo, hi, _balls(compiled))):
            return point
    return next(iter(branch.discriminants))


def _dimensions(compiled: Compiled, point: str) -> str:
    """``a=5/6, d=22/3, ...``: the dimensions ``point`` is built from, its bases' included, in the scene's order."""
    points, held, pending, seen = compiled.scene.points, set(), [point], set()
    while pending:
        name = pending.pop()
        if name in seen or name not in points:
            continue
        seen.add(name)
        for value in vars(points[name]).values():
            for item in value if isinstance(value, tuple) else (value,):
                if isinstance(item, str):
                    pending.append(item)  # a base, a centre (or a label, an input: not points)
                elif isinstance(item, sympy.Basic):
                    held |= {str(s) for s in item.free_symbols}
    return ", ".join(f"{n}={v}" for n, v in compiled.parameter_values.items() if n in held)
