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

import itertools
import math
from collections.abc import Mapping, Sequence
from fractions import Fraction

import flint

from ..branches import Branch
from ..eliminate import Witness
from ..evaluate import ARB
from ..evaluate.program import compile_program
from ..scene import Compiled
from ..scene.model import Input
from .assembles import Pieces, where_assembled

__all__ = ["witnesses", "sampled_witnesses", "exact_sample", "WITNESS_BITS", "WITNESSES_PER_BRANCH"]

WITNESS_BITS = 256
WITNESSES_PER_BRANCH = 3
SPREAD = WITNESSES_PER_BRANCH * 3  # exact_sample's count: at most 4 * SPREAD samples are tried

Sample = tuple[Fraction, ...]  # an angle's exact (cos, sin), or a length's (length,)
Groups = tuple[tuple[Witness, ...], ...]  # per branch, its witnesses


def witnesses(compiled: Compiled, branches: Sequence[Branch]) -> Groups:
    """Per branch, configurations in ball arithmetic at exact rational inputs (where it may assemble)."""
    return sampled_witnesses(compiled, branches, where_assembled(compiled, branches))


def sampled_witnesses(compiled: Compiled, branches: Sequence[Branch], where: Mapping[str, Pieces] | None) -> Groups:
    """``witnesses``, the inputs drawn from ``where`` (``where_assembled``'s answer, found already).

    Each sample is evaluated for every branch at once, in one program of every branch's
    discriminants and closed forms: the verification's (``algkin.verify.check``), compiled once
    for both where no dimension is fixed for the check. A sample's exact inputs are made when it
    is first evaluated (most scenes need the first three)."""
    where = where or {}
    spans = {n: where.get(n) or _whole(compiled.scene.inputs[n]) for n in compiled.system.inputs}
    count = 4 * SPREAD if compiled.system.inputs else 1
    names, known = _exact_names(compiled), _known_names(compiled)
    # a six-bar's closed forms are long: compiled once, not walked per sample
    program = compile_program([e for b in branches for e in (*b.discriminants.values(), *b.values.values())],
                              known, ARB)
    ends = list(itertools.accumulate([len(b.discriminants) + len(b.values) for b in branches], initial=0))
    groups: list[list[Witness]] = [[] for _ in branches]
    with flint.ctx.workprec(WITNESS_BITS):
        for k in range(count):
            exact = _exact_values(compiled, spans, k)
            balls = {n: ARB.number(exact[n].numerator, exact[n].denominator) for n in names}
            values = program(*(balls[n] for n in known))
            for branch, group, start, end in zip(branches, groups, ends, ends[1:]):
                if len(group) < WITNESSES_PER_BRANCH:
                    found = _witness(branch, values[start:end], balls, exact)
                    if found is not None:
                        group.append(found)
            if all(len(group) == WITNESSES_PER_BRANCH for group in groups):
                break
    return tuple(tuple(group) for group in groups)


def exact_sample(spec: Input, count: int, pieces: Pieces | None, k: int) -> Sample:
    """The ``k``-th of ``4 * count`` exact rational inputs spread evenly over the input's range (or
    over ``pieces`` of it, in radians or lengths: where something assembles), taken every fourth
    first so that the first few already spread over it: an angle's as an exact point ``(cos, sin)``
    on the unit circle, a length's as ``(length,)``.

    >>> points = [exact_sample(Input("t", 179, 181, "deg"), 2, None, k) for k in range(8)]
    >>> len(points), all(c * c + s * s == 1 and c < 0 for c, s in points)
    (8, True)
    """
    value = _along(pieces or _whole(spec), (4 * (k % count) + k // count + 0.5) / (4 * count))
    return _on_circle(value) if spec.is_angle else (Fraction(value).limit_denominator(97),)


def _whole(spec: Input) -> Pieces:
    """The input's whole range, in radians or lengths."""
    return [(spec.radians(spec.lo), spec.radians(spec.hi))]


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
    """The variables a witness holds exactly: the inputs' and the dimensions, sorted by name."""
    return sorted(_known_names(compiled))


def _known_names(compiled: Compiled) -> list[str]:
    """The program's arguments, the variables that are not unknowns in the system's order (the
    verification's ``known``)."""
    return [*compiled.system.input_variables, *compiled.system.parameters]


def _exact_values(compiled: Compiled, spans: Mapping[str, Pieces], k: int) -> dict[str, Fraction]:
    """Sample ``k``'s exact inputs (cos and sin, or lengths) drawn from ``spans`` (input -> pieces of
    its range) and dimensions (nudged off their defaults)."""
    exact: dict[str, Fraction] = {}
    for name, variables in compiled.system.inputs.items():
        exact.update(zip(variables, exact_sample(compiled.scene.inputs[name], SPREAD, spans[name], k)))
    for n in compiled.system.parameters:
        default = Fraction(str(compiled.parameter_values[n]))
        exact[n] = default * (1 + Fraction(k + 1, 211)) if default else Fraction(k + 1, 211)
    return exact


def _witness(branch: Branch, values: Sequence[flint.arb | int], balls: Mapping[str, flint.arb],
             exact: Mapping[str, Fraction]) -> Witness | None:
    """The configuration of ``branch`` at a sample, where it assembles: ``values`` are its
    discriminants then its closed forms there, ``balls`` and ``exact`` the sample's inputs and dimensions."""
    discriminants, closed = values[:len(branch.discriminants)], values[len(branch.discriminants):]
    if not all(d > 0 for d in discriminants):
        return None
    if not all(flint.arb(v).is_finite() for v in closed):
        return None
    return Witness(dict(balls) | {u: flint.arb(v) for u, v in zip(branch.values, closed)},
                   {n: flint.fmpq(v.numerator, v.denominator) for n, v in exact.items()})
