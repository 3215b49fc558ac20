"""A mode followed along an input by certified continuation (``algkin follow``).

The start is the configuration ``algkin solve`` gives at the start input on the mode ``mode``
(a branch label such as ``left`` or ``B:left F:right`` for points built by dyads and sliders,
a mode's label at the start for points solved together); from there the scene's ORIGINAL
equations (each dyad's two circles, each group's constraints: no eliminant, no closed form) are
followed along the input, every step proved in balls (``algkin.verify.follow``): for each input
in the step exactly one configuration in a box around the predicted path, so the mode can never
jump to another. The path ends at the stop input, or where the mode meets another (a toggle,
where the Jacobian of the equations is singular): that meeting is reported, never crossed.

Inputs are exact values in the input's unit (degrees for an angle), as with ``solve``; the
samples are the proven steps' ends, each point's coordinates as decimal strings.

>>> path = follow("chebyshev-lambda", mode="left", start={"angle": 0}, stop=360, digits=8)
>>> path.ended, path.samples[0].points["B"], path.samples[-1].points["B"]
('reached', ('1.5', '2.4494897'), ('1.5', '2.4494897'))
>>> meets = follow("fourbar-nongrashof", mode="left", start={"theta": 0}, stop=180, digits=6)
>>> meets.ended, meets.meeting["from"], meets.meeting["to"], meets.meeting["holds_zero"]
('meets', '131.49', '131.491', True)
"""

from __future__ import annotations

import math
import numbers
from collections.abc import Mapping, Sequence
from decimal import ROUND_CEILING, ROUND_FLOOR, Decimal, localcontext
from fractions import Fraction
from typing import Any

import attrs
import flint
import sympy

from ..errors import ComputationError, UsageError
from ..evaluate import ARB, evaluate
from ..runtime import suggest
from ..runtime.budget import Budget, Deadline, started
from ..runtime.frozen import FrozenDict, frozen
from ..runtime import validation
from ..runtime.validation import NumberTooLarge, rational
from ..runtime.exclusive import one_at_a_time
from ..scene import Scene, compile_scene
from ..scene.groups import compile_groups
from ..scene.load import as_scene
from ..scene.implicit.base import Point
from ..system import symbol
from ..verify.follow import BITS, Follower, Path
from .frozen import deep_frozen, thawed
from .solve import DIGITS, MAX_DIGITS, decimal_text, input_value, quarter_turn, solve

__all__ = ["follow", "Followed", "FollowedSample"]

MAX_INPUT_DIGITS = 40
"""The most digits an input value is written with to tell it from its neighbours (a step is
never shorter than 2^-36 of the span)."""
MAX_STEPS = 100_000
"""The most steps a ``max_step`` may ask for: each is a sample kept and shown."""


@attrs.frozen
class FollowedSample:
    """The mode at the input ``at`` (a decimal string): each point's coordinates as decimal strings,
    ``radius`` the largest radius of their enclosures, ``values`` each unknown's ball."""

    at: str
    points: FrozenDict[str, tuple[str, str]] = attrs.field(converter=frozen)
    radius: float
    values: FrozenDict[str, flint.arb] = attrs.field(converter=frozen, eq=False, repr=False)

    def to_json(self) -> dict[str, Any]:
        return {"at": self.at, "points": {p: list(xy) for p, xy in self.points.items()}, "radius": self.radius}


def _frozen_meeting(meeting: Mapping[str, Any] | None) -> FrozenDict[str, Any] | None:
    return None if meeting is None else deep_frozen(meeting)


@attrs.frozen
class Followed:
    """The mode ``mode`` of ``scene`` followed along ``input`` from ``start`` toward ``stop``:
    ``ended`` is ``reached`` or ``meets`` (another mode, for an input in ``meeting``'s
    [``from``, ``to``], where ``determinant`` of the Jacobian holds 0), after ``steps`` proven steps."""

    scene: str
    mode: str
    input: str
    start: Fraction
    stop: Fraction
    digits: int
    samples: tuple[FollowedSample, ...]
    steps: int
    ended: str
    meeting: FrozenDict[str, Any] | None = attrs.field(converter=_frozen_meeting)

    def to_json(self) -> dict[str, Any]:
        return {"scene": self.scene, "mode": self.mode, "input": self.input, "from": str(self.start),
                "to": str(self.stop), "digits": self.digits, "ended": self.ended, "steps": self.steps,
                "meeting": thawed(self.meeting), "samples": [s.to_json() for s in self.samples]}


@attrs.frozen
class _Equations:
    """What is followed: the unknowns, their original equations, every point's coordinates in them."""

    unknowns: tuple[str, ...]
    equations: tuple[sympy.Expr, ...]
    coordinates: Mapping[str, Point]


@one_at_a_time
def follow(scene: Scene | str, *, mode: str, start: Mapping[str, Any], stop: Any, at: Mapping[str, Any] | None = None,
           digits: int = DIGITS, max_step: Any = None, deadline: Budget | Deadline | None = None) -> Followed:
    """The mode ``mode`` of ``scene`` followed from ``start`` (``{input: value}``, one input) to
    ``stop`` (a value of that input), the scene's other inputs at ``at``; ``max_step`` the largest
    step (the input's unit), ``deadline`` (a ``Budget``, started here, or one running) kept between steps.

    A UsageError names the argument: a ``mode`` that is not one (its message lists the modes), or
    that does not assemble at the start; an input that is not the scene's; a value out of its range.
    """
    if isinstance(digits, bool) or not isinstance(digits, numbers.Integral) or not 1 <= digits <= MAX_DIGITS:
        raise UsageError("digits", digits, f"expected a whole number of digits in [1, {MAX_DIGITS}]")
    digits = int(digits)  # numpy's integers too
    if not isinstance(mode, str):  # None would take solve's meaning, every branch, and follow the first
        raise UsageError("mode", mode, "expected a mode's label, such as 'left'")
    deadline = None if deadline is None else started(validation.budget(deadline, "deadline"))
    if at is not None and not isinstance(at, Mapping):
        raise UsageError("at", at, "expected a mapping of each other input's name to its value, such as {'phi': 30}")
    scene = as_scene(scene)
    name, t0, t1 = _span(scene, start, stop)
    others = dict(at or {})
    if name in others:
        raise UsageError("at", name, "is the input followed: give its value as the start only")
    found = solve(scene, {**others, name: t0}, mode=mode, digits=30)
    if not found.configurations:
        raise UsageError("mode", mode, f"does not assemble at {name} = {t0}")
    fixed = {n: v for n, v in found.at.items() if n != name}
    system = _equations(scene)
    variables = _input_variables(scene, name)
    parameters, known = _fixed(scene, fixed, exclude=name)
    held = {str(v) for e in system.equations for v in e.free_symbols}
    if not held & set(variables):
        raise UsageError("start", name, f"the points of {scene.name} do not move with {name}")
    follower = Follower(system.unknowns, system.equations, variables, parameters)
    configuration = found.configurations[0]
    guess = [float(configuration.points[u[:-2]][u.endswith("_y")]) for u in system.unknowns]
    step = None if max_step is None else _step(max_step, t0, t1)
    path = follower.follow(guess, t0, t1, known=[known[p] for p in parameters], max_step=step, deadline=deadline)
    inputs = _input_texts([sample.t for sample in path.samples], digits)
    samples = tuple(_sample(system, variables, path, k, known, digits, at=inputs[k]) for k in range(len(path.samples)))
    meeting = None if path.meeting is None else _meeting(path, digits)
    return Followed(scene.name, configuration.mode, name, t0, t1, digits, samples, path.steps,
                    "reached" if meeting is None else "meets", meeting)


def _span(scene: Scene, start: Mapping[str, Any], stop: Any) -> tuple[str, Fraction, Fraction]:
    """The followed input and its start and stop values, exact and in its range."""
    if not isinstance(start, Mapping) or len(start) != 1:
        raise UsageError("start", start, "expected one input and its value, e.g. {'theta': 0}")
    (name, value), = start.items()
    if name not in scene.inputs:
        raise UsageError("start", name, f"not an input of {scene.name}" + suggest.known(name, scene.inputs, plural="inputs"))
    return name, _checked(scene, name, value, "start"), _checked(scene, name, stop, "stop")


def _checked(scene: Scene, name: str, value: Any, argument: str) -> Fraction:
    """``solve``'s check of an input value, its error naming ``argument``."""
    try:
        return input_value(scene, name, value)
    except UsageError as err:
        raise UsageError(argument, err.value, err.message) from None


def _step(value: Any, t0: Fraction, t1: Fraction) -> Fraction:
    """``max_step`` as an exact positive number, no shorter than the way from ``t0`` to ``t1`` over ``MAX_STEPS``."""
    span = abs(t1 - t0)
    try:
        step = rational(str(value))
    except NumberTooLarge as err:
        raise UsageError("max_step", value, str(err)) from None
    except (ValueError, ZeroDivisionError):
        step = Fraction(0)
    if step <= 0:
        raise UsageError("max_step", value, "expected a positive number (the input's unit)")
    if span > step * MAX_STEPS:
        raise UsageError("max_step", value, f"would take over {MAX_STEPS} steps from {float(t0):g} to {float(t1):g}; "
                                            f"give at least {float(span / MAX_STEPS):.3g}")
    return step


def _equations(scene: Scene) -> _Equations:
    """The unknowns followed and their original equations: each group's for points solved together,
    else each dyad's and slider's point (the other points are explicit in them)."""
    if scene.unknown_points:
        groups = compile_groups(scene)
        unknowns = tuple(u for g in groups.groups for u in g.unknowns)
        equations = tuple(e for g in groups.groups for e in g.equations)
        return _Equations(unknowns, equations, groups.coordinates)
    compiled = compile_scene(scene, list(scene.points))
    unknowns = tuple(f"{spec.point}_{axis}" for spec in compiled.implicit for axis in "xy")
    names = {symbol(u) for u in unknowns}
    system_unknowns = {symbol(u) for u in compiled.system.unknowns}
    equations = tuple(e for e in compiled.system.equations
                      if e.free_symbols & names and not (e.free_symbols & system_unknowns) - names)
    if len(equations) != len(unknowns):
        raise ComputationError(f"{scene.name}: {len(equations)} equations for the {len(unknowns)} unknowns "
                               f"{', '.join(unknowns)} of its dyads and sliders")
    return _Equations(unknowns, equations, compiled.coordinates)


def _input_variables(scene: Scene, name: str) -> tuple[str, ...]:
    return tuple(str(s) for s in scene.inputs[name].symbols)


def _fixed(scene: Scene, at: Mapping[str, Fraction], *, exclude: str) -> tuple[list[str], dict[str, flint.arb]]:
    """The other inputs' variables and their balls (at the follower's precision)."""
    names: list[str] = []
    values: dict[str, flint.arb] = {}
    with flint.ctx.workprec(BITS):
        for name, value in at.items():
            if name != exclude:
                variables = _input_variables(scene, name)
                names += variables
                values.update(_input_balls(variables, value))
    return names, values


def _input_balls(variables: tuple[str, ...], value: Fraction) -> dict[str, flint.arb]:
    """An input's variables at ``value`` (degrees for an angle), in balls."""
    ball = flint.arb(flint.fmpq(value.numerator, value.denominator))
    if len(variables) == 1:
        return {variables[0]: ball}
    if value % 90 == 0:  # exact, as solve gives them: a crank at 90 degrees is at x = 0
        return dict(zip(variables, map(flint.arb, quarter_turn(value))))
    radians = ball * flint.arb.pi() / 180
    return {variables[0]: radians.cos(), variables[1]: radians.sin()}


def _input_texts(values: Sequence[Fraction], digits: int) -> list[str]:
    """Each input value (exact) in decimal: ``digits`` significant digits, more where two
    neighbours (steps near a meeting are short) would read the same.

    >>> _input_texts([Fraction(6), Fraction(7922781, 10**6), Fraction(7922782, 10**6)], 6)
    ['6', '7.922781', '7.922782']
    """
    def text(value: Fraction, shown: int) -> str:
        return decimal_text(flint.arb(flint.fmpq(value.numerator, value.denominator)), shown)

    texts = []
    for k, value in enumerate(values):
        neighbours = [v for v in values[max(k - 1, 0):k + 2] if v != value]
        shown = digits
        while shown < MAX_INPUT_DIGITS and any(text(v, shown) == text(value, shown) for v in neighbours):
            shown += 1
        texts.append(text(value, shown))
    return texts


def _sample(system: _Equations, variables: tuple[str, ...], path: Path, index: int,
            known: Mapping[str, flint.arb], digits: int, *, at: str) -> FollowedSample:
    """A sample's points in balls from its unknowns' enclosures and the input, written to ``digits``."""
    sample = path.samples[index]
    with flint.ctx.workprec(BITS):
        values = {**known, **_input_balls(variables, sample.t), **sample.values}
        points = {p: tuple(evaluate(sympy.sympify(v), values, ARB) for v in xy)
                  for p, xy in system.coordinates.items()}
    radii = [float(b.rad()) for xy in points.values() for b in xy]
    radius = math.nextafter(max(radii, default=0.0), math.inf) if any(radii) else 0.0
    shown = {p: (decimal_text(x, digits), decimal_text(y, digits)) for p, (x, y) in points.items()}
    return FollowedSample(at, shown, radius, sample.values)


def _meeting(path: Path, digits: int) -> dict[str, Any]:
    """Where the mode meets another: the input interval rounded outward, the determinant's ball."""
    meeting = path.meeting
    assert meeting is not None
    return {"from": _outward(meeting.lo, digits, ROUND_FLOOR), "to": _outward(meeting.hi, digits, ROUND_CEILING),
            "determinant": meeting.determinant.str(5, radius=True), "holds_zero": meeting.determinant.contains(0),
            "proved": meeting.fold}


def _outward(value: Fraction, digits: int, rounding: str) -> str:
    """``value`` to ``digits`` significant digits, rounded toward ``rounding``'s side.

    >>> _outward(Fraction(1, 3), 3, ROUND_FLOOR), _outward(Fraction(1, 3), 3, ROUND_CEILING), _outward(Fraction(90), 3, ROUND_FLOOR)
    ('0.333', '0.334', '90')
    >>> _outward(Fraction(10**40 + 1, 10**40), 35, ROUND_CEILING)  # past Decimal's own 28 digits
    '1.0000000000000000000000000000000001'
    """
    with localcontext() as context:
        context.prec, context.rounding = digits, rounding
        rounded = (Decimal(value.numerator) / Decimal(value.denominator)).normalize()
    return format(rounded, "f")
