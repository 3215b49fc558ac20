"""Modes named by a configuration (``mode = { at = .., near = [x, y] }``), followed along the input.

A dyad's side label (``left``/``right``) is a sign that may flip along the motion while the
mechanism stays in one assembly mode: where the configuration curve is reducible (an
antiparallelogram's crossed and parallelogram components), two components cross at a
configuration where the dyad's two circles touch, its discriminant having a zero of even order
along the motion, and past it the mode goes on with the other label. A label cannot say "stay
crossed"; a configuration can.

**Naming.** At the inputs ``at`` (the other points on their own branches), the point's two
configurations are evaluated in balls (``BITS``); ``near`` names the one it is *close* to:
within a quarter of the distance between the two (so at least three times nearer to it than to
the other), certified in balls. Anything else is refused, naming the nearest configuration;
so is an ``at`` where the point does not assemble or where its two configurations meet.
``resolve_modes`` writes the label found into the point's ``branch``: at ``at``, every command
takes the named mode.

**Following** (one-input scenes), exactly:

1. *The mode as a factor.* The point's implicit curve (everything else eliminated, the
   dimensions at their values) is factored over the rationals; the mode is the irreducible
   factor ``f`` that vanishes at the named configuration (its ball holds 0, every other
   factor's excludes it). A component of the configuration curve traces one factor.
2. *Where labels may change.* Every dyad's and slider's discriminant on the chain that builds
   the point vanishes only at the real roots of its toggle conditions (``|PQ| = l1 + l2`` or
   ``|l1 - l2|``, a slider's tangency), earlier points eliminated (resultants), in the
   half-angle ``t = tan(input/2)``: exact irreducible polynomials, roots isolated in balls.
   Those roots where the chain is not certified apart cut the range into *pieces*; inside one
   no discriminant vanishes, so the point's two configurations are two disjoint arcs, each on
   one component: on a piece the mode keeps one label.
3. *The label per piece.* At a point inside each piece, ``f`` is evaluated in balls at the two
   configurations: the mode is the one where the ball holds 0 while the other's excludes it
   (certified); where both exclude 0 the mode is absent from that piece, where neither does it
   is undecided. A piece where the chain does not assemble (a discriminant certified negative)
   has none.
4. *Change points.* A cut between two assembled pieces whose labels differ is a change point:
   the mode crosses the other there and goes on with the other label. It is given exactly, as
   its irreducible polynomial in ``t`` and its certified enclosure in the input's unit.

Where the point's curve is irreducible, no factor tells two modes apart: the named label holds
on every piece (no change points), as a ``branch`` would; so it does, not followed, on a point
that moves with several inputs.

**Using it.** ``derive`` reports each named mode (``follow_modes``) with the branch that is the
mode on each piece; ``curve`` takes its witness configurations from the mode's pieces alone
(``mode_witnesses``), so the elimination keeps the factors the mode traces and drops the others
(``other_modes`` tells those from extraneous ones); ``algkin solve`` leaves out the
configurations certified off the factor (``on_mode``).

>>> from algkin.scene import load_scene
>>> followed = follow_modes(resolve_modes(load_scene("hart-inversor")))
>>> [(p.labels["C"], round(p.lo, 2), round(p.hi, 2)) for p in followed[0].pieces if p.status == "mode"]
[('left', 0.0, 75.52), ('right', 284.48, 300.0), ('left', 300.0, 360.0)]
>>> [(c.enclosure.str(8), c.polynomial) for c in followed[0].change_points]
[('[300.00000 +/- 1e-10]', '3*t_angle**2 - 1')]
"""

from __future__ import annotations

import dataclasses
from collections.abc import Collection, Mapping, Sequence
from fractions import Fraction
from typing import Any

import attrs
import flint
import sympy

from ..branches import Branch, closed_forms
from ..branches.constructions import algebra_of
from ..eliminate import DEFAULT_METHOD, eliminate
from ..eliminate.select import select_factors
from ..errors import SceneError
from ..evaluate import ARB, evaluate
from ..runtime.budget import Deadline
from ..runtime.frozen import FrozenDict, frozen
from ..scene import Compiled, Scene, compile_scene
from ..scene.constructions import Dyad, Mode, Slider
from ..scene.implicit import ImplicitSpec
from ..system import input_values, symbol
from ..system.angles import Parametrisation
from ..system.convert import univariate
from ..system.roots import real_roots
from .tasks import Eliminant
from .witnesses import Groups, sampled_witnesses

__all__ = ["resolve_modes", "follow_modes", "Followed", "Piece", "ChangePoint", "moded_points", "mode_witnesses",
           "other_modes", "on_mode", "BITS"]

BITS = 128
CLOSE = 4  # near is close to a configuration within 1/CLOSE of the distance between the two


def moded_points(scene: Scene) -> list[str]:
    """The dyads and sliders of ``scene`` that name their mode by a configuration, in file order."""
    return [n for n, c in scene.points.items() if isinstance(c, (Dyad, Slider)) and c.mode is not None]


# -- naming -----------------------------------------------------------------------------------

def resolve_modes(scene: Scene) -> Scene:
    """``scene`` with each named mode's label at its ``at`` written into the point's ``branch``
    (earlier points first, so a later one is named on their modes); SceneError on a bad ``near``.

    >>> from algkin.scene import load_scene
    >>> scene = resolve_modes(load_scene("hart-inversor"))
    >>> scene.points["C"].branch, scene.points["C"].mode.near
    ('left', (-1, 17/10))
    """
    for name in moded_points(scene):
        construction = scene.points[name]
        assert isinstance(construction, (Dyad, Slider)) and construction.mode is not None
        label = _named_label(scene, name, construction.mode)
        scene = attrs.evolve(scene, points={**scene.points, name: dataclasses.replace(construction, branch=label)})
    return scene


def _named_label(scene: Scene, point: str, mode: Mode) -> str:
    compiled = compile_scene(scene, [point])
    spec = _spec(compiled, point)
    element = f"points.{point}.mode"
    if not spec.labels:  # the other intersection of two circles through an earlier point: no choice to name
        raise SceneError(scene.source, element, f"{point}'s circles pass through an earlier point: it is their other "
                         "intersection, with no mode of its own to name (give its branch)")
    pair = _pair(compiled, closed_forms(compiled), point)
    at = dict(mode.at)
    shown = ", ".join(f"{n} = {scene.inputs[n].shown(float(v))}" for n, v in mode.at)
    with flint.ctx.workprec(BITS):
        values = _values(compiled, {n: _ball(compiled, n, v) for n, v in at.items() if n in compiled.system.inputs})
        status = _assembles(pair[0], values)
        if status != "yes":
            why = "does not assemble" if status == "no" else "is at a toggle (its two configurations meet)"
            raise SceneError(scene.source, f"{element}.at", f"{point} {why} at {shown}: name the mode at another input")
        places = [_place(b, spec, values) for b in pair]
        near = (flint.arb(Fraction(mode.near[0]).numerator) / Fraction(mode.near[0]).denominator,
                flint.arb(Fraction(mode.near[1]).numerator) / Fraction(mode.near[1]).denominator)
        gap = _distance(*places)
        distances = [_distance(p, near) for p in places]
        for branch, distance in zip(pair, distances):
            if distance * CLOSE < gap:
                return branch.labels[point]
    nearest = min(range(2), key=lambda k: float(distances[k].mid()))
    x, y = (float(c.mid()) for c in places[nearest])
    raise SceneError(scene.source, f"{element}.near", f"[{float(near[0].mid()):g}, {float(near[1].mid()):g}] is "
                     f"not close to a configuration of {point} at {shown}: the nearest is [{x:.6g}, {y:.6g}] "
                     f"({pair[nearest].labels[point]}), {float(distances[nearest].mid()):.3g} away (close: within "
                     f"1/{CLOSE} of the {float(gap.mid()):.3g} between its two configurations)")


def _spec(compiled: Compiled, point: str) -> ImplicitSpec:
    return next(s for s in compiled.implicit if s.point == point)


def _pair(compiled: Compiled, branches: Sequence[Branch], point: str) -> tuple[Branch, Branch]:
    """The two branches on the scene's labels for every point but ``point``: its two labels, in order."""
    chosen = {s.point: s.branch for s in compiled.implicit if s.labels and s.point != point}
    pair = [b for b in branches if all(b.labels[p] == l for p, l in chosen.items())]
    labels = _spec(compiled, point).labels
    first, second = sorted(pair, key=lambda b: labels.index(b.labels[point]))
    return first, second


def _ball(compiled: Compiled, name: str, value: sympy.Rational) -> flint.arb:
    """An input's value as the system takes it: radians for an angle (a ball), a length as it is."""
    spec = compiled.scene.inputs[name]
    number = flint.arb(int(value.p)) / int(value.q)
    return number * flint.arb.pi() / 180 if spec.unit == "deg" else number


def _values(compiled: Compiled, inputs: Mapping[str, flint.arb]) -> dict[str, flint.arb]:
    """Every dimension at its value and each input's variables at ``inputs``, in balls."""
    values = {n: flint.arb(Fraction(str(v)).numerator) / Fraction(str(v)).denominator
              for n, v in compiled.parameter_values.items()}
    for name, variables in compiled.system.inputs.items():
        values.update(input_values(variables, inputs[name]))
    return values


def _assembles(branch: Branch, values: Mapping[str, flint.arb]) -> str:
    """'yes' (every discriminant certified positive), 'no' (one certified negative), or 'undecided'."""
    balls = [evaluate(d, values, ARB) for d in branch.discriminants.values()]
    if any(b < 0 for b in balls):
        return "no"
    return "yes" if all(b > 0 for b in balls) else "undecided"


def _place(branch: Branch, spec: ImplicitSpec, values: Mapping[str, flint.arb]) -> tuple[flint.arb, flint.arb]:
    x, y = (evaluate(branch.values[u], values, ARB) for u in spec.unknowns)
    return x, y


def _distance(p: tuple[flint.arb, flint.arb], q: tuple[flint.arb, flint.arb]) -> flint.arb:
    dx, dy = p[0] - q[0], p[1] - q[1]
    return (dx * dx + dy * dy).sqrt()


# -- following --------------------------------------------------------------------------------

@attrs.frozen
class ChangePoint:
    """Where the named mode crosses the point's other mode, its label flipping: exactly the root of
    ``polynomial`` (irreducible, in the half-angle ``t_<input>``, or the length) in ``enclosure``."""

    input: float  # degrees (or the length)
    enclosure: flint.arb = attrs.field(eq=False)
    polynomial: str
    before: str
    after: str

    def to_json(self, unit: str) -> dict[str, object]:
        key = "deg" if unit != "length" else "length"
        return {f"input_{key}": self.input, f"enclosure_{key}": self.enclosure.str(20), "polynomial": self.polynomial,
                "from": self.before, "to": self.after, "certified": True}


@attrs.frozen
class Piece:
    """A stretch of the input (degrees, or lengths) between cuts: ``status`` 'mode' (the named mode
    is the branch with ``labels`` there), 'absent' (it is not there), 'no-assembly' or 'undecided'."""

    lo: float
    hi: float
    status: str
    labels: FrozenDict[str, str] = attrs.field(converter=frozen)  # the chain's points -> label, on 'mode'

    def to_json(self, unit: str) -> dict[str, object]:
        start, end = ("from_deg", "to_deg") if unit != "length" else ("from_length", "to_length")
        return {start: self.lo, end: self.hi, "status": self.status, "labels": dict(self.labels)}


@attrs.frozen
class Followed:
    """A named mode followed: its point, where it was named and its ``label`` there, the factor of
    the point's curve it traces (None where no factor tells the two modes apart: an irreducible
    curve, or several inputs), and its pieces and change points over the input's range (none with
    several inputs)."""

    point: str
    mode: Mode
    label: str
    factor: sympy.Expr | None  # in the point's coordinates, the dimensions at their values
    pieces: tuple[Piece, ...]
    change_points: tuple[ChangePoint, ...]
    unit: str

    def branch_of(self, piece: Piece, branches: Sequence[Branch]) -> Branch | None:
        """The branch of ``branches`` that is the mode on ``piece``: its labels there, the scene's elsewhere."""
        chosen = next((b for b in branches if b.selected), None)
        if chosen is None:
            return None
        return next((b for b in branches if all(label == piece.labels.get(p, chosen.labels[p])
                                                for p, label in b.labels.items())), None)

    def to_json(self) -> dict[str, Any]:
        at = {n: str(v) for n, v in self.mode.at}
        factor = None if self.factor is None else str(self.factor)
        return {"point": self.point, "at": at, "near": [str(v) for v in self.mode.near], "label_at": self.label,
                "factor": factor,
                "pieces": [p.to_json(self.unit) for p in self.pieces if p.status != "no-assembly"],
                "change_points": [c.to_json(self.unit) for c in self.change_points]}


def follow_modes(scene: Scene, points: Collection[str] | None = None, *,
                 deadline: Deadline | None = None) -> tuple[Followed, ...]:
    """Each named mode of ``scene`` (resolved: ``resolve_modes``) followed along its one input; of
    the dyads and sliders in ``points`` alone if given."""
    return tuple(_follow(scene, point, deadline) for point in moded_points(scene) if points is None or point in points)


def _follow(scene: Scene, point: str, deadline: Deadline | None) -> Followed:
    compiled = compile_scene(scene, [point])
    construction = scene.points[point]
    assert isinstance(construction, (Dyad, Slider)) and construction.mode is not None
    mode, label = construction.mode, construction.branch
    if len(compiled.system.inputs) != 1:  # a region, not a curve: the mode is its label at ``at``
        return Followed(point, mode, label, None, (), (), "deg")
    branches = closed_forms(compiled)
    pair = _pair(compiled, branches, point)
    factors = _curve_factors(compiled, branches, point, deadline)
    with flint.ctx.workprec(BITS):
        values = _values(compiled, {n: _ball(compiled, n, v) for n, v in mode.at if n in compiled.system.inputs})
        named = next(b for b in pair if b.labels[point] == label)
        factor = _factor_at(factors, named, _spec(compiled, point), values, scene.source) if len(factors) > 1 else None
        (name, variables), = compiled.system.inputs.items()
        line = Parametrisation(tuple(symbol(v) for v in variables),
                               symbol(f"t_{name}") if len(variables) == 2 else symbol(name))
        spec = scene.inputs[name]
        cuts = _cuts(compiled, pair[0], line, spec.span, deadline)
        pieces = [_piece(compiled, pair, point, factor or label, lo, hi) for (lo, _), (hi, _) in zip(cuts, cuts[1:])]
    merged, changes = _joined(pieces, cuts, point)
    return Followed(point, mode, label, factor, tuple(merged), tuple(changes), spec.unit)


def on_mode(followed: Followed, branch: Branch, values: Mapping[str, flint.arb]) -> bool:
    """Whether ``branch``'s configuration at ``values`` (the inputs' variables and the dimensions,
    in balls) may be on the named mode: False where the ball of the mode's factor at its point
    excludes 0 (certified off it); without a factor, whether the branch has the named label."""
    if followed.factor is None:
        return branch.labels[followed.point] == followed.label
    x, y = (f"{followed.point}_{c}" for c in "xy")
    point = dict(values, **{x: evaluate(branch.values[x], values, ARB), y: evaluate(branch.values[y], values, ARB)})
    return bool(evaluate(followed.factor, point, ARB).contains(0))


def _curve_factors(compiled: Compiled, branches: Sequence[Branch], point: str,
                   deadline: Deadline | None) -> list[sympy.Expr]:
    """The irreducible factors of ``point``'s implicit curve (every branch's witnesses keep theirs)."""
    system = compiled.system
    variables = (f"{point}_x", f"{point}_y")
    others = [u for u in system.unknowns if u not in variables] + list(system.input_variables)
    groups = sampled_witnesses(compiled, branches, None)
    result = eliminate(system.polynomials or system.equations, others, variables, method=DEFAULT_METHOD,
                       witnesses=groups, budget=deadline)
    return list(result.factors)


def _factor_at(factors: Sequence[sympy.Expr], branch: Branch, spec: ImplicitSpec,
               values: Mapping[str, flint.arb], source: str) -> sympy.Expr:
    """The one factor whose ball at the branch's point holds 0 (every other's excludes it)."""
    x, y = _place(branch, spec, values)
    at = dict(values, **{spec.unknowns[0]: x, spec.unknowns[1]: y})
    holding = [f for f in factors if evaluate(f, at, ARB).contains(0)]
    if len(holding) != 1:
        raise SceneError(source, f"points.{spec.point}.mode",
                         f"{len(holding)} factors of {spec.point}'s curve vanish at the named configuration: "
                         "name it at another input")
    return holding[0]


def _cuts(compiled: Compiled, branch: Branch, line: Parametrisation, span: tuple[float, float],
          deadline: Deadline | None) -> list[tuple[float, ChangeRoot | None]]:
    """The range's ends and, between them, every root of the chain's toggle conditions where the
    chain is not certified apart, ascending: (input, its root) pairs, the ends' root None."""
    lo, hi = span
    found: dict[tuple[str, int, int], ChangeRoot] = {}  # (polynomial, rank among its real roots, turn) -> cut
    for spec in compiled.implicit:
        if not spec.labels:
            continue
        for condition in algebra_of(spec).toggle_conditions().values():
            polynomial = _eliminated(compiled, condition, spec, deadline)
            numerator = line.numerator(polynomial)
            roots = [(line.shown(r.refined(2 * BITS).ball), _in_t(r.coefficients, line.t), r.index)
                     for r in real_roots(univariate(numerator, line.t))] if numerator.has(line.t) else []
            roots += [(ball, f"{line.t} = oo (a half turn)", 0) for ball in line.at_infinity(polynomial)]
            for ball, exact, index in roots:
                for turn in line.turns:
                    shown = ball + turn
                    if lo < float(shown.mid()) < hi and _assembles(branch, _at(compiled, shown, line)) != "no":
                        found[exact, index, turn] = ChangeRoot(shown, exact)
    cuts: list[tuple[float, ChangeRoot | None]] = [(lo, None)]
    cuts += sorted(((float(root.ball.mid()), root) for root in found.values()), key=lambda cut: cut[0])
    return cuts + [(hi, None)]


def _in_t(coefficients: Sequence[int], t: sympy.Symbol) -> str:
    """An irreducible polynomial (coefficients low to high) as text in ``t``."""
    return str(sympy.Poly(list(reversed(coefficients)), t).as_expr())


@attrs.frozen
class ChangeRoot:
    """A cut: its enclosure (as users read the input) and the irreducible polynomial it is a root of."""

    ball: flint.arb = attrs.field(eq=False)
    polynomial: str


def _at(compiled: Compiled, shown: flint.arb, line: Parametrisation) -> dict[str, flint.arb]:
    value = shown * flint.arb.pi() / 180 if line.is_angle else shown
    (name, _), = compiled.system.inputs.items()
    return _values(compiled, {name: value})


def _eliminated(compiled: Compiled, condition: sympy.Expr, spec: ImplicitSpec, deadline: Deadline | None) -> sympy.Expr:
    """``condition`` (in the spec's bases) with the earlier points' unknowns eliminated: a
    polynomial in the input's variables, the dimensions at their values."""
    defaults = {symbol(n): v for n, v in compiled.parameter_values.items()}
    condition = sympy.expand(condition.xreplace(defaults))
    unknowns = set(compiled.system.unknowns) - set(spec.unknowns)
    names = lambda e: {str(v) for v in e.free_symbols}  # noqa: E731
    earlier = names(condition) & unknowns
    if not earlier:
        return condition
    system = [sympy.expand(e.xreplace(defaults)) for e in compiled.system.equations if not names(e) & set(spec.unknowns)]
    while True:  # every unknown the equations of those named bring in
        grown = earlier.union(*(names(e) & unknowns for e in system if names(e) & earlier))
        if grown == earlier:
            break
        earlier = grown
    equations = [e for e in system if names(e) & earlier]
    (variables,) = compiled.system.inputs.values()
    return eliminate([condition] + equations, sorted(earlier), list(variables), method="resultant",
                     budget=deadline).polynomial


def _piece(compiled: Compiled, pair: tuple[Branch, Branch], point: str, factor: sympy.Expr | str,
           lo: float, hi: float) -> Piece:
    """The piece between two cuts, decided at its middle: the branch whose point lies on the mode's
    ``factor`` there, or (where no factor tells the modes apart) the one with the named label."""
    spec = _spec(compiled, point)
    (name, _), = compiled.system.inputs.items()
    middle = flint.arb((lo + hi) / 2)
    values = _values(compiled, {name: middle * flint.arb.pi() / 180 if compiled.scene.inputs[name].is_angle
                                else middle})
    status = _assembles(pair[0], values)
    if status != "yes":
        return Piece(lo, hi, "no-assembly" if status == "no" else "undecided", {})
    chain = {s.point for s in compiled.implicit if s.labels}
    if isinstance(factor, str):
        named = next(b for b in pair if b.labels[point] == factor)
        return Piece(lo, hi, "mode", {p: l for p, l in named.labels.items() if p in chain})
    on = []
    for branch in pair:
        x, y = _place(branch, spec, values)
        on.append(evaluate(factor, dict(values, **{spec.unknowns[0]: x, spec.unknowns[1]: y}), ARB))
    holds = [b.contains(0) for b in on]
    if holds == [False, False]:
        return Piece(lo, hi, "absent", {})
    if holds == [True, True]:
        return Piece(lo, hi, "undecided", {})
    chosen = pair[holds.index(True)]
    return Piece(lo, hi, "mode", {p: l for p, l in chosen.labels.items() if p in chain})


def _joined(pieces: Sequence[Piece], cuts: Sequence[tuple[float, ChangeRoot | None]], point: str
            ) -> tuple[list[Piece], list[ChangePoint]]:
    """Neighbouring pieces with the same status and labels made one; the cuts between two 'mode'
    pieces whose labels differ, as change points."""
    merged: list[Piece] = []
    changes: list[ChangePoint] = []
    for piece, (_, root) in zip(pieces, cuts):
        if merged and (merged[-1].status, merged[-1].labels) == (piece.status, piece.labels):
            merged[-1] = attrs.evolve(merged[-1], hi=piece.hi)
            continue
        if merged and merged[-1].status == piece.status == "mode" and root is not None:
            changes.append(ChangePoint(float(root.ball.mid()), root.ball, root.polynomial,
                                       merged[-1].labels[point], piece.labels[point]))
        merged.append(piece)
    return merged, changes


def mode_witnesses(compiled: Compiled, branches: Sequence[Branch], followed: Followed) -> Groups:
    """Witness configurations on the named mode alone, a group per piece (of ``branches``,
    ``compiled``'s, the one with the piece's labels, the other points on their own): the curve
    keeps the mode's factors."""
    (name, _), = compiled.system.inputs.items()
    spec = compiled.scene.inputs[name]
    scale = float(sympy.pi / 180) if spec.is_angle else 1.0
    chosen = {s.point: s.branch for s in compiled.implicit if s.labels}
    groups: list[tuple] = []
    for piece in followed.pieces:
        if piece.status != "mode":
            continue
        labels = dict(chosen, **{p: l for p, l in piece.labels.items() if p in chosen})
        branch = next(b for b in branches if dict(b.labels) == labels)
        groups += sampled_witnesses(compiled, [branch], {name: [(piece.lo * scale, piece.hi * scale)]})
    return tuple(groups)


def other_modes(elimination: Eliminant, groups: Groups) -> tuple[sympy.Expr, ...]:
    """The factors a curve on a named mode dropped that vanish at some branch's witnesses in
    ``groups`` (the scene's every branch): those the other modes trace, not extraneous ones."""
    engine, dropped = elimination.engine, elimination.raw_dropped
    if engine is None or not dropped:
        return ()
    traced, _ = select_factors(engine, dropped, groups, check=False)
    return tuple(engine.to_sympy(engine.primitive(f)) for f in traced)
