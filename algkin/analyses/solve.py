"""Every real configuration of a scene at given inputs, certified in balls (``algkin solve``).

Each branch (one label per dyad or slider) is evaluated in python-flint ``arb`` balls at the
inputs, exact rationals (degrees for an angle, the length itself for a length input): a branch
assembles there when each of its discriminants is certified >= 0, and its points are given as
decimal strings to ``digits`` significant digits, the working precision raised until every
enclosure is that narrow. A branch whose discriminant the balls cannot sign (an input at a
toggle whose cosine is irrational) is a ComputationError, never a guess.

Points solved together (``unknown = true``, ``algkin.scene.groups``): each group's equations
are solved by ``solve_group`` (an eliminant in one unknown, the others rational in its root) with
the inputs as parameters, and its real modes at the inputs' exact values isolated and certified
(``modes``), or, where an angle's cos and sin are irrational, at their balls (``modes_in_balls``,
the precision raised until the roots are told apart, and real or not); a configuration is one mode of each group, labelled by a sign per leg (see
``_mode_labels``), and ``complex_count`` counts the complex solutions.

Nothing assembling at the inputs is a valid answer, not a failure: no configurations (exit 0).

>>> found = solve("chebyshev-lambda", at={"angle": 0}, digits=12)
>>> [(c.mode, c.points["B"]) for c in found.configurations]
[('left', ('1.5', '2.44948974278')), ('right', ('1.5', '-2.44948974278'))]
>>> solve("fourbar-nongrashof", at={"theta": 150}).configurations
()
"""

from __future__ import annotations

import math
import numbers
from collections.abc import Iterable, Mapping, Sequence
from decimal import Decimal, localcontext
from fractions import Fraction
from typing import Any

import attrs
import flint
import sympy

from ..runtime import suggest
from ..branches import Branch, closed_forms
from ..derivation.modes import Followed, follow_modes, moded_points, on_mode, resolve_modes
from ..eliminate.group import GroupSolution, Mode, modes_in_sequence, solve_group
from ..errors import ComputationError, SceneError, UsageError, written
from ..evaluate import ARB, evaluate
from ..runtime.frozen import FrozenDict, frozen
from ..runtime.validation import MAX_NUMBER_BITS, NumberTooLarge, rational
from ..runtime.exclusive import one_at_a_time
from ..scene import Compiled, Input, Scene, compile_scene
from ..scene.groups import Groups, compile_groups
from ..scene.constructions import Dyad, Slider, Unknown
from ..scene.load import as_scene
from ..system.convert import flint_context, to_flint
from ..system import input_values, symbol

__all__ = ["solve", "Solution", "Configuration", "DIGITS", "MAX_DIGITS"]

DIGITS = 30
"""Significant digits of each coordinate, by default."""
MAX_DIGITS = 1000
"""The most digits asked for: past this the balls cost more than any reader needs."""
RAISES = 5
MODE_BITS = 128
"""Working precision of the test that a configuration lies on a named mode's factor."""
"""Doublings of the working precision tried before a branch is left undecided."""


@attrs.frozen
class Configuration:
    """One configuration: its ``mode`` (the branch's label), each point's coordinates as decimal
    strings, and ``radius``, the largest radius of their enclosures."""

    mode: str
    points: FrozenDict[str, tuple[str, str]] = attrs.field(converter=frozen)
    radius: float

    def to_json(self) -> dict[str, Any]:
        return {"mode": self.mode, "points": {p: list(xy) for p, xy in self.points.items()}, "radius": self.radius}


@attrs.frozen
class Solution:
    """Every real configuration of ``scene`` at the inputs ``at`` (exact values, in the inputs'
    units); ``complex_count`` where a group of unknowns was solved together."""

    scene: str
    at: FrozenDict[str, Fraction] = attrs.field(converter=frozen)
    digits: int
    configurations: tuple[Configuration, ...]
    complex_count: int | None = None
    named_modes: tuple[str, ...] = ()  # the points whose mode the scene names by a configuration
    left_out: int = 0  # configurations certified off those modes, left out

    def to_json(self) -> dict[str, Any]:
        document: dict[str, Any] = {"scene": self.scene, "at": {n: str(v) for n, v in self.at.items()},
                                    "digits": self.digits,
                                    "configurations": [c.to_json() for c in self.configurations]}
        if self.complex_count is not None:
            document["complex_count"] = self.complex_count
        if self.named_modes:  # keys of their own: a scene naming no mode gives the document it always gave
            document["named_modes"] = list(self.named_modes)
            document["left_out"] = self.left_out
        return document


@one_at_a_time
def solve(scene: Scene | str, at: Mapping[str, Any], *, mode: str | None = None,
          digits: int = DIGITS) -> Solution:
    """Every real configuration of ``scene`` (a Scene, a catalog name or a path) at the inputs
    ``at`` (input -> an exact value: an int, a rational's string such as ``"1/3"``, a decimal),
    on every branch or on the branch labelled ``mode``, to ``digits`` significant digits.

    A UsageError names the argument: an input missing, not the scene's or out of its range,
    ``digits`` out of [1, MAX_DIGITS], a ``mode`` that is no branch label.
    """
    if isinstance(digits, bool) or not isinstance(digits, numbers.Integral) or not 1 <= digits <= MAX_DIGITS:
        raise UsageError("digits", digits, f"expected a whole number of digits in [1, {MAX_DIGITS}]")
    digits = int(digits)  # numpy's integers too
    if not isinstance(at, Mapping):
        raise UsageError("at", at, "expected a mapping of each input's name to its value, such as {'theta': 30}")
    scene = as_scene(scene)
    if scene.unknown_points:
        return _solved_together(scene, at, mode=mode, digits=digits)
    compiled = compile_scene(scene, list(scene.points))
    values = _inputs(scene, compiled.system.inputs, at)
    branches = closed_forms(compiled)
    labels = [b.label for b in branches]
    if mode is not None and mode not in labels:
        raise UsageError("mode", mode, f"not a mode of {scene.name} (modes: {', '.join(labels)})")
    named = follow_modes(resolve_modes(scene)) if moded_points(scene) else ()
    found = [(b, _configuration(compiled, b, values, digits)) for b in branches if mode in (None, b.label)]
    assembled = [(b, c) for b, c in found if c is not None]
    kept = tuple(c for b, c in assembled if _on_named(compiled, b, values, named))
    return Solution(scene.name, values, digits, kept, named_modes=tuple(m.point for m in named),
                    left_out=len(assembled) - len(kept))


def _on_named(compiled: Compiled, branch: Branch, at: Mapping[str, Fraction], named: Sequence[Followed]) -> bool:
    """Whether ``branch``'s configuration at ``at`` may lie on every named mode: False where a mode's
    factor is certified nonzero at its point there (another mode)."""
    with flint.ctx.workprec(MODE_BITS):
        values = _ball_inputs(compiled, at)
        return all(on_mode(followed, branch, values) for followed in named)


def _inputs(scene: Scene, used: Iterable[str], at: Mapping[str, Any]) -> dict[str, Fraction]:
    """``at`` as exact values, checked: every input the scene's points move with (``used``) given, each in range."""
    for name in at:
        if name not in scene.inputs:
            raise UsageError("at", name, f"not an input of {scene.name}" + suggest.known(name, scene.inputs, plural="inputs"))
    missing = [n for n in used if n not in at]
    if missing:
        raise UsageError("at", ", ".join(missing), f"no value given for {', '.join(missing)} (NAME=VALUE)")
    return {name: input_value(scene, name, value) for name, value in at.items()}


def input_value(scene: Scene, name: str, value: Any) -> Fraction:
    """An input's value, exactly, within its range (degrees for an angle)."""
    spec = scene.inputs[name]
    given = f"{name}={written(value, write=str)}"
    try:
        exact = rational(_text(value))
    except NumberTooLarge as err:
        raise UsageError("at", given, str(err)) from None
    except (ValueError, ZeroDivisionError):
        exact = None
    lo, hi = spec.span
    if exact is None or not _within(exact, spec):
        what = "a number of degrees" if spec.is_angle else "a length"
        raise UsageError("at", given, f"expected {what} in [{lo:g}, {hi:g}], exact (e.g. 30, 1/3, 0.5)")
    return exact


def _text(value: Any) -> str:
    """``value`` as the text ``rational`` reads; NumberTooLarge for a number Python will not write
    (an integer of more than 4300 digits, or a fraction of one)."""
    try:
        return str(value)
    except ValueError:
        raise NumberTooLarge(f"number too large or too precise (more than {MAX_NUMBER_BITS} bits)") from None


def _within(value: Fraction, spec: Input) -> bool:
    """Whether ``value`` (degrees for an angle) lies in the input's range: exactly, unless the range is in radians."""
    if spec.unit == "deg" or not spec.is_angle:
        return Fraction(str(spec.lo)) <= value <= Fraction(str(spec.hi))
    lo, hi = spec.span
    return lo <= value <= hi


def _configuration(compiled: Compiled, branch: Branch, at: Mapping[str, Fraction], digits: int
                   ) -> Configuration | None:
    """The configuration on ``branch`` at ``at``, or None where it does not assemble; the working
    precision doubled until the discriminants are signed and the coordinates ``digits`` narrow."""
    bits = int(digits * 3.33) + 32
    for _ in range(RAISES):
        with flint.ctx.workprec(bits):
            values = _ball_inputs(compiled, at)
            assembles = _assembles(branch, values)
            if assembles is False:
                return None
            if assembles:
                points = {p: tuple(evaluate(v.xreplace(_substitution(branch)), values, ARB) for v in xy)
                          for p, xy in compiled.coordinates.items()}
                if all(_narrow(b, digits) for xy in points.values() for b in xy):
                    return _written(branch.label, points, digits)
        bits *= 2
    raise ComputationError(f"{compiled.scene.name} at {_said(at)}: the balls could not decide whether branch "
                           f"{branch.label} assembles there at {bits // 2} bits (an input at a toggle?)")


def _assembles(branch: Branch, values: Mapping[str, flint.arb]) -> bool | None:
    """Whether every discriminant is >= 0, in order (past a negative one, a later one may hold its
    square root); None when the balls cannot tell."""
    for discriminant in branch.discriminants.values():
        sign = _sign(evaluate(discriminant, values, ARB))
        if sign is None:
            return None
        if sign < 0:
            return False
    return True


def _substitution(branch: Branch) -> dict[sympy.Symbol, sympy.Expr]:
    return {symbol(u): v for u, v in branch.values.items()}


def _ball_inputs(compiled: Compiled | Groups, at: Mapping[str, Fraction]) -> dict[str, flint.arb]:
    """Each input's variables as balls: an angle's cos and sin (exact at multiples of 90 degrees,
    where a toggle's discriminant is then exactly 0), a length as itself."""
    values: dict[str, flint.arb] = {}
    inputs = compiled.inputs if isinstance(compiled, Groups) else compiled.system.inputs
    for name, variables in inputs.items():
        if name not in at:
            continue
        value = at[name]
        if len(variables) == 1:
            values[variables[0]] = flint.arb(flint.fmpq(value.numerator, value.denominator))
        elif value % 90 == 0:  # degrees, whatever the unit the scene declares its range in
            values.update(dict(zip(variables, map(flint.arb, quarter_turn(value)))))
        else:
            radians = flint.arb.pi() * flint.fmpq(value.numerator, value.denominator) / 180
            values.update(input_values(variables, radians))
    return values


def quarter_turn(degrees: Fraction) -> tuple[int, int]:
    """cos and sin of a multiple of 90 degrees."""
    return ((1, 0), (0, 1), (-1, 0), (0, -1))[int(degrees // 90) % 4]


def _sign(ball: flint.arb) -> int | None:
    """-1, 0 or 1 when the ball tells, else None."""
    if ball.is_exact() and ball == 0:
        return 0
    if ball > 0:
        return 1
    if ball < 0:
        return -1
    return None


def _narrow(ball: flint.arb, digits: int) -> bool:
    """Whether ``ball`` is finite and fixes its ``digits`` significant digits (or is below 10**-digits),
    decided in balls (a float would overflow or underflow at a thousand digits)."""
    if not ball.is_finite():
        return False
    scale = abs(ball.mid())
    if scale < 1:
        scale = flint.arb(1)
    return bool(ball.rad() * flint.arb(10) ** (digits + 1) <= scale)


def _written(mode: str, points: Mapping[str, tuple[flint.arb, ...]], digits: int) -> Configuration:
    radii = [b.rad() for xy in points.values() for b in xy]
    largest = max((float(r) for r in radii), default=0.0)
    # rounded up: an upper bound even where the float underflows to 0
    radius = 0.0 if all(r == 0 for r in radii) else math.nextafter(largest, math.inf)
    shown = {p: (decimal_text(x, digits), decimal_text(y, digits)) for p, (x, y) in points.items()}
    return Configuration(mode, shown, radius)


def decimal_text(ball: flint.arb, digits: int) -> str:
    """The ball's midpoint rounded to ``digits`` significant digits, trailing zeros left out
    (sin 30 degrees, 1/2 in a ball, is ``0.5``), in plain notation unless very large or small.

    >>> decimal_text(flint.arb(2).sqrt(), 5), decimal_text(flint.arb(3) / 2, 30), decimal_text(flint.arb(0), 30)
    ('1.4142', '1.5', '0')
    >>> decimal_text(flint.arb(-400), 8), decimal_text(flint.arb(10) ** 9, 3), decimal_text(flint.arb(1) / 2**70, 3)
    ('-400', '1e+9', '8.47e-22')
    """
    mantissa, exponent = ball.mid().man_exp()
    with localcontext() as context:
        context.prec = max(digits, abs(int(exponent)) + len(str(mantissa))) + 10
        exact = Decimal(int(mantissa)) * Decimal(2) ** int(exponent)
        rounded = Decimal(format(exact, f".{digits}g")).normalize()
    if rounded == 0:
        return "0"
    return format(rounded, "f" if -7 <= rounded.adjusted() < digits else "e")


def _said(at: Mapping[str, Fraction]) -> str:
    return ", ".join(f"{n} = {v}" for n, v in at.items())


def _solved_together(scene: Scene, at: Mapping[str, Any], *, mode: str | None, digits: int) -> Solution:
    """``solve`` on a scene with points solved together: each group's eliminant and lifts
    (``solve_group``), its real modes at the inputs certified (``modes``), every point in balls."""
    compiled = compile_groups(scene)
    variables = {str(v) for xy in compiled.coordinates.values() for c in xy for v in sympy.sympify(c).free_symbols}
    used = [n for n, names in compiled.inputs.items() if set(names) & variables]
    values = _inputs(scene, used, at)
    exact = _exact_inputs(compiled, values)
    solutions = [_group_solution(compiled, k) for k in range(len(compiled.groups))]
    labelled = _configurations(compiled, solutions, exact, values, digits)
    labels = [label for label, _ in labelled]
    if mode is not None and mode not in labels:
        raise UsageError("mode", mode, f"not a mode of {scene.name} at {_said(values)} (modes: {', '.join(labels) or 'none'})")
    count = math.prod(s.complex_count for s in solutions)
    found = [c for label, c in labelled if mode in (None, label)]
    # an unknown point's mode, or a dyad's or slider's (a group of its own beside them)
    named = [p for p, c in scene.points.items() if isinstance(c, (Unknown, Dyad, Slider)) and c.mode is not None]
    kept = [c for c in found if all(_group_label(compiled, p, c.mode) == _named_group_label(compiled, solutions, p)
                                    for p in named)]
    return Solution(scene.name, values, digits, tuple(kept), count, named_modes=tuple(named),
                    left_out=len(found) - len(kept))


def _group_label(compiled: Groups, point: str, label: str) -> str:
    """The part of a configuration's label that is the mode of ``point``'s group."""
    index = next(k for k, g in enumerate(compiled.groups) if point in g.points)
    return label.split(" ")[index]


def _named_group_label(compiled: Groups, solutions: Sequence[GroupSolution], point: str) -> str:
    """The label of the mode of ``point``'s group that its ``mode = { at, near }`` names: at ``at``,
    the configuration whose ``point`` is close to ``near`` (within a quarter of the distance from it to
    the next configuration's ``point``), certified in balls; a SceneError naming the nearest otherwise."""
    scene = compiled.scene
    construction = scene.points[point]
    assert isinstance(construction, (Unknown, Dyad, Slider)) and construction.mode is not None
    element = f"points.{point}.mode"
    at = dict(construction.mode.at)
    try:
        values = _inputs(scene, list(at), at)
        exact = _exact_inputs(compiled, values)
    except UsageError as err:
        raise SceneError(scene.source, f"{element}.at", err.message) from None
    labelled = _configurations(compiled, solutions, exact, values, DIGITS)
    with flint.ctx.workprec(MODE_BITS):
        near = [flint.arb(flint.fmpq(int(v.p), int(v.q))) for v in construction.mode.near]
        places = [[flint.arb(f"{v} +/- {c.radius}") for v in c.points[point]] for _, c in labelled]
        distances = [_distance(p, near) for p in places]
        order = sorted(range(len(places)), key=lambda k: float(distances[k].mid()))
        if not order:
            raise SceneError(scene.source, f"{element}.at", f"no configuration of {point}'s group at {_said(values)}")
        gap = min((_distance(places[order[0]], places[k]) for k in order[1:]), key=lambda b: float(b.mid()),
                  default=None)
        if gap is not None and not distances[order[0]] * 4 < gap:
            x, y = labelled[order[0]][1].points[point]
            raise SceneError(scene.source, f"{element}.near", "[" + ", ".join(f"{float(v.mid()):g}" for v in near)
                             + f"] is not close to a configuration of {point} at {_said(values)}: the nearest is [{float(x):.6g}, "
                             f"{float(y):.6g}] ({labelled[order[0]][0]}), {float(distances[order[0]].mid()):.3g} away "
                             f"(close: within 1/4 of the {float(gap.mid()):.3g} to the next configuration's {point})")
    return _group_label(compiled, point, labelled[order[0]][0])


def _distance(p: Sequence[flint.arb], q: Sequence[flint.arb]) -> flint.arb:
    dx, dy = p[0] - q[0], p[1] - q[1]
    return (dx * dx + dy * dy).sqrt()


def _exact_inputs(compiled: Groups, at: Mapping[str, Fraction]) -> dict[str, flint.fmpq]:
    """Each used input's variables exactly where they are rational: a length as it is, an angle's
    cos and sin at multiples of 90 degrees (the eliminant's real roots are then isolated over QQ).
    Any other angle's are left out: given in balls (``_ball_inputs``), its group's roots isolated
    in balls."""
    exact: dict[str, flint.fmpq] = {}
    for name, value in at.items():
        variables = compiled.inputs[name]
        if len(variables) == 1:
            exact[variables[0]] = flint.fmpq(value.numerator, value.denominator)
        elif value % 90 == 0:
            exact.update(zip(variables, map(flint.fmpq, quarter_turn(value))))
    return exact


def _group_solution(compiled: Groups, index: int) -> GroupSolution:
    """The group's rational univariate representation; its parameters are the inputs' variables
    and the unknowns of the earlier groups its equations hold (groups solved in turn)."""
    group = compiled.groups[index]
    names = sorted({str(v) for e in group.equations for v in e.free_symbols} - set(group.unknowns))
    ctx = flint_context(group.unknowns + tuple(names))
    return solve_group([to_flint(e, ctx) for e in group.equations], group.unknowns)


def _configurations(compiled: Groups, solutions: Sequence[GroupSolution], exact: Mapping[str, flint.fmpq],
                    at: Mapping[str, Fraction], digits: int) -> list[tuple[str, Configuration]]:
    """Every real configuration (one mode per group, a later group's at each configuration of the
    earlier ones: ``modes_in_sequence``), labelled, its points ``digits`` narrow. An input not in
    ``exact`` (an angle's irrational cos and sin) is given in balls, the precision raised until its
    group's roots are told apart, and real or not."""
    bits = int(digits * 3.33) + 64
    undecided = None
    for _ in range(RAISES):
        with flint.ctx.workprec(2 * bits):  # as narrow as the eliminant's coefficients are computed (modes_in_balls)
            inputs = _ball_inputs(compiled, at)
        inexact = {v: b for v, b in inputs.items() if v not in exact}
        with flint.ctx.workprec(bits):
            try:
                combinations = modes_in_sequence(solutions, exact, balls=inexact, bits=bits)
            except ComputationError as err:
                if not inexact:
                    raise
                undecided, bits = err, bits * 2
                continue
            undecided = None
            labelled = []
            for combination in combinations:
                values = dict(inputs)
                for group_mode in combination:
                    values.update({u: v for u, v in group_mode.values.items()})
                points = {p: tuple(evaluate(v, values, ARB) for v in xy) for p, xy in compiled.coordinates.items()}
                labelled.append((combination, points, values))
            if all(_narrow(b, digits) for _, points, _ in labelled for xy in points.values() for b in xy):
                names = [_mode_labels(compiled, k, [m[k] for m, _, _ in labelled], [p for _, p, _ in labelled],
                                      [v for _, _, v in labelled])
                         for k in range(len(solutions))]
                return [(" ".join(n[i] for n in names), _written(" ".join(n[i] for n in names), points, digits))
                        for i, (_, points, _) in enumerate(labelled)]
        bits *= 2
    if undecided is not None:
        raise ComputationError(f"{compiled.scene.name} at {_said(at)}: {undecided} (at {bits // 2} bits; "
                               "an input at a toggle?)")
    raise ComputationError(f"{compiled.scene.name} at {_said(at)}: the coordinates did not narrow to {digits} "
                           f"digits at {bits // 2} bits")


def _mode_labels(compiled: Groups, index: int, group_modes: Sequence[Mode],
                 configurations: Sequence[Mapping[str, tuple[flint.arb, ...]]],
                 values: Sequence[Mapping[str, flint.arb]]) -> list[str]:
    """Each mode's label: a sign per leg (a distance from a point outside the group to one on it,
    ``+`` when the group's centroid lies left of the leg), certified; with the mode's index
    (``/k``, its rank among the real roots) where signs are undecided or do not tell it apart.
    A point built by a dyad or slider (a group of its own): its side, as the dyad's branch says
    it (``D:left``)."""
    group = compiled.groups[index]
    if len(group.points) == 1 and group.points[0] in compiled.sides:
        return [_side(compiled, group.points[0], v) or f"{group.points[0]}:?/{m.index + 1}"
                for m, v in zip(group_modes, values)]
    body = _body(compiled, index)
    legs = [c.points for name in group.constraints for c in [compiled.scene.constraints.get(name)]
            if c is not None and c.kind in ("dist", "dist2") and len({p in body for p in c.points}) == 2]
    signs = []
    for points in configurations:
        centre = [sum((points[p][k] for p in body), flint.arb(0)) / len(body) for k in (0, 1)]
        row = ""
        for first, second in legs:
            (outside, inside) = (first, second) if second in body else (second, first)
            (ax, ay), (px, py) = points[outside], points[inside]
            sign = _sign((px - ax) * (centre[1] - py) - (py - ay) * (centre[0] - px))
            row += {1: "+", -1: "-"}.get(sign or 0, "?")
        signs.append(row)
    # a mode shared by several configurations (groups after it differ) counts once
    distinct = {id(m): row for m, row in zip(group_modes, signs)}
    rows = list(distinct.values())
    told = [row and "?" not in row and rows.count(row) == 1 for row in signs]
    return [row if ok else f"{row}/{m.index + 1}".lstrip("/") for row, ok, m in zip(signs, told, group_modes)]


def _side(compiled: Groups, point: str, values: Mapping[str, flint.arb]) -> str | None:
    """``point``'s side label (its dyad's or slider's branch) at ``values``, None where the ball cannot tell."""
    indicator = compiled.sides[point]
    sign = _sign(evaluate(indicator.expr, values, ARB))
    return None if not sign else f"{point}:{indicator.positive if sign > 0 else indicator.negative}"


def _body(compiled: Groups, index: int) -> list[str]:
    """The points that move with the group alone: its own and those built on them only."""
    own = set(compiled.groups[index].unknowns)
    others = {u for g in compiled.groups for u in g.unknowns} - own
    body = []
    for name, xy in compiled.coordinates.items():
        held = {str(v) for c in xy for v in sympy.sympify(c).free_symbols}
        if held & own and not held & others:
            body.append(name)
    return body
