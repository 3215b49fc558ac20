"""Witness configurations: per branch, a few configurations in ball arithmetic at exact rational inputs.

An elimination keeps the factors of an eliminant that vanish at some branch's witnesses
(``algkin.eliminate.select``). Each witness is the branch's closed forms evaluated in balls
(``WITNESS_BITS``) at exact inputs spread over the range (or over where the scene assembles,
``algkin.derivation.assembles``) and at the symbolic dimensions nudged off their defaults.

>>> from algkin.scene import compile_scene, load_scene
>>> from algkin.branches import closed_forms
>>> compiled = compile_scene(load_scene("fourbar"), ["B"])
>>> groups = witnesses(compiled, closed_forms(compiled))
>>> [len(group) for group in groups]
[3, 3]
>>> sorted(groups[0][0])
['B_x', 'B_y', 'c_theta', 's_theta']
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from fractions import Fraction

import flint

from ..branches import Branch
from ..eliminate import Witness
from ..evaluate import ARB
from ..evaluate.program import BallProgram, compile_program
from ..scene import Compiled
from ..scene.model import Input
from .assembles import Pieces, where_assembled

__all__ = ["witnesses", "sampled_witnesses", "exact_samples", "WITNESS_BITS", "WITNESSES_PER_BRANCH"]

WITNESS_BITS = 256
WITNESSES_PER_BRANCH = 3

Sample = tuple[Fraction, ...]  # an angle's exact (cos, sin), or a length's (length,)
Groups = tuple[tuple[Witness, ...], ...]  # per branch, its witnesses


def witnesses(compiled: Compiled, branches: Sequence[Branch]) -> Groups:
    """Per branch, configurations in ball arithmetic at exact rational inputs (where it may assemble)."""
    return sampled_witnesses(compiled, branches, where_assembled(compiled, branches))


def sampled_witnesses(compiled: Compiled, branches: Sequence[Branch], where: Mapping[str, Pieces] | None) -> Groups:
    """``witnesses``, the inputs drawn from ``where`` (``where_assembled``'s answer, found already)."""
    where = where or {}
    spread = {n: exact_samples(compiled.scene.inputs[n], WITNESSES_PER_BRANCH * 3, where.get(n))
              for n in compiled.system.inputs}
    count = len(next(iter(spread.values()), [()]))
    names = _exact_names(compiled)
    groups = []
    with flint.ctx.workprec(WITNESS_BITS):
        for branch in branches:
            # compiled once a branch (a six-bar's closed forms are long: walking them per sample was most of this)
            programs = (compile_program(list(branch.discriminants.values()), names, ARB),
                        compile_program(list(branch.values.values()), names, ARB))
            group: list[Witness] = []
            for k in range(count):
                point = _witness(compiled, branch, programs, spread, k)
                if point is not None:
                    group.append(point)
                if len(group) == WITNESSES_PER_BRANCH:
                    break
            groups.append(tuple(group))
    return tuple(groups)


def exact_samples(spec: Input, count: int, pieces: Pieces | None = None) -> list[Sample]:
    """``4 * count`` exact rational inputs spread over the input's range (or over ``pieces`` of it, in
    radians or lengths: where something assembles), the same number for every input: an angle's as an
    exact point ``(cos, sin)`` on the unit circle, a length's as ``(length,)``.

    >>> points = exact_samples(Input("t", 179, 181, "deg"), 2)
    >>> len(points), all(c * c + s * s == 1 and c < 0 for c, s in points)
    (8, True)
    """
    pieces = pieces or [(float(spec.to_radians(spec.lo)), float(spec.to_radians(spec.hi)))]
    values: list[Sample] = []
    for k in range(4 * count):
        value = _along(pieces, (k + 0.5) / (4 * count))
        values.append(_on_circle(value) if spec.is_angle else (Fraction(value).limit_denominator(97),))
    # Interleave so that the first few samples already spread over the range.
    return values[::4] + values[1::4] + values[2::4] + values[3::4]


def _along(pieces: Pieces, share: float) -> float:
    """The point ``share`` (0 to 1) of the way along the intervals ``pieces`` put end to end."""
    left = share * sum(hi - lo for lo, hi in pieces)
    for lo, hi in pieces:
        if left <= hi - lo:
            return lo + left
        left -= hi - lo
    return pieces[-1][1]


def _on_circle(angle: float) -> Sample:
    """An exact rational point ``(cos, sin)`` on the unit circle near ``angle`` (radians), from the
    rational half-angle tangent ``t`` (or, near a half turn where ``t`` is unbounded, its cotangent ``u``).

    >>> _on_circle(0.0), _on_circle(math.pi)
    ((Fraction(1, 1), Fraction(0, 1)), (Fraction(-1, 1), Fraction(0, 1)))
    """
    if abs(math.cos(angle / 2)) >= abs(math.sin(angle / 2)):
        t = Fraction(math.tan(angle / 2)).limit_denominator(97)
        return (1 - t * t) / (1 + t * t), 2 * t / (1 + t * t)
    u = Fraction(1 / math.tan(angle / 2)).limit_denominator(97)
    return (u * u - 1) / (u * u + 1), 2 * u / (u * u + 1)


def _exact_names(compiled: Compiled) -> list[str]:
    """The variables a witness holds exactly, the programs' arguments: the inputs' and the dimensions."""
    return sorted([*(v for variables in compiled.system.inputs.values() for v in variables),
                   *compiled.system.parameters])


def _witness(compiled: Compiled, branch: Branch, programs: tuple[BallProgram, BallProgram],
             spread: Mapping[str, list[Sample]], k: int) -> Witness | None:
    """The configuration of ``branch`` at sample ``k``, where it assembles: ``programs`` give its
    discriminants and its closed forms in the inputs' variables and the dimensions, sorted by name."""
    exact: dict[str, Fraction] = {}  # the inputs' cos and sin (or lengths) and the dimensions are rational: kept exactly too
    for name, variables in compiled.system.inputs.items():
        exact.update(zip(variables, spread[name][k]))
    for n in compiled.system.parameters:
        default = Fraction(str(compiled.parameter_values[n]))
        exact[n] = default * (1 + Fraction(k + 1, 211)) if default else Fraction(k + 1, 211)
    names = _exact_names(compiled)
    balls = [ARB.number(exact[n].numerator, exact[n].denominator) for n in names]
    discriminants, closed_forms = programs
    if not all(d > 0 for d in discriminants(*balls)):
        return None
    closed = closed_forms(*balls)
    if not all(flint.arb(v).is_finite() for v in closed):
        return None
    values = dict(zip(names, balls)) | {u: flint.arb(v) for u, v in zip(branch.values, closed)}
    return Witness(values, {n: flint.fmpq(v.numerator, v.denominator) for n, v in exact.items()})
