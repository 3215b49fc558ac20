"""Limit positions of an output and the time ratio of its strokes, exact and certified.

An implicit point X (a dyad, a slider) whose own equations include one in X alone, ``C(X) = 0``
(a circle about a ground pivot: a rocker; a fixed line: a slider), moves along that curve as
the input turns. It is at a *limit position* where it stops there and turns back: where
``dX/dtheta = 0``. X's other equation ``G(X, u, c, s) = 0`` ties it to the moving points
(``u``: earlier points' unknowns, ``c, s``: the input's cosine and sine). Differentiating
both, ``grad C . X' = 0`` and ``grad G . X' + dG/dtheta = 0`` with ``dG/dtheta`` the derivative of
G *with X held*; where the point is not at a dead centre (``grad C``, ``grad G`` independent)
``X' = 0`` exactly where

    dG/dtheta|X held  =  c G_s - s G_c + G_u . u'  =  0,   with  u' = -J_u^-1 (c F_s - s F_c)

the earlier points' velocities by the implicit function theorem (``F``: their equations,
``J_u``: their Jacobian). Times ``det J_u`` this is a polynomial, the *stationarity condition*;
with the unknowns eliminated (resultants), a polynomial in ``c, s`` whose real roots, in the
half-angle ``t``, python-flint isolates with certified enclosures. For a four-bar (X = B on
the crank tip A and the ground pivot D) it is ``(B - A) . A' = 0``: crank and coupler in
line, ``|OB| = l + a`` (*extended*) or ``|OB| = l - a`` (*folded*); for a slider-crank the same.

Each root is certified, branch by branch: the closed form of the branch assembles over an
interval around the root (every discriminant > 0 in ball arithmetic), the condition evaluated
on it changes sign across the interval (so it has a zero there: the output turns back) and
the eliminant has no other root in it (so that zero is the exact root reported). Roots that
no branch certifies are listed as dropped, with why (an extraneous factor of the elimination,
where every branch's condition is bounded away from zero).

The *time ratio* of a crank-rocker or an offset slider-crank: with the input turning fully
(no dead centre in the range) and the output on the scene's branch turning back exactly twice
per turn, at crank angles ``theta1 < theta2``, the output takes ``theta2 - theta1`` of crank
angle one way and ``360 - (theta2 - theta1)`` the other. The working stroke is the slower one
(the larger angle, ``180 + alpha``), the return the quicker (``180 - alpha``), and
``Q = (180 + alpha) / (180 - alpha)``. The stroke of the output is the rocker's swing (the angle
between its limit positions about its pivot) or the slider's travel.

>>> found = limits("slider-crank")
>>> [(round(g.input_deg, 6), g.kind, g.branch) for g in found.limits if g.selected]
[(7.180756, 'extended', 'ahead'), (194.477512, 'folded', 'ahead')]
>>> round(found.time_ratio.ratio, 12), found.time_ratio.stroke["exact"]
(1.084500513743, '(-sqrt(15) + 3*sqrt(7))/2')
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import flint
import sympy

from ..branches import Branch
from ..derivation.prepared import prepare
from ..eliminate import eliminate
from ..errors import UsageError
from ..evaluate import ARB, evaluate
from ..scene import Compiled, load_scene
from ..scene.constructions import Crank, Fixed
from ..scene.model import Scene
from ..scene.settings import with_values
from ..system import symbol
from ..system.angles import half_angle_poly, tangent_to_degrees, vanishes_at_half_turn
from .toggles import single_input
from ..system.convert import fmpq_to_rational

__all__ = ["limits", "stationary_condition", "Limit", "Limits", "TimeRatio"]

ROOT_BITS = 128  # root isolation: enclosures about 1e-36 deg wide
CHECK_BITS = 320  # ball arithmetic of the certificates, far finer than the interval they check
HALF_WIDTH_DEG = sympy.Rational(1, 10**20)  # half the interval each certificate covers, at most
TIDY_OPS = 80  # an exact position longer than this (sympy's count_ops) is left out

Json = dict[str, Any]


@dataclass
class Limit:
    """One limit position: the input angle (exact and certified), the point, its branch, where it is."""

    input_deg: float
    enclosure: flint.arb  # degrees, holds the exact root
    exact_deg: sympy.Expr  # the input angle in degrees, exactly (radicals, or a CRootOf)
    factor: sympy.Expr | None  # the irreducible polynomial in t = tan(theta/2) it is a root of (None: 180 deg)
    point: str
    branch: str  # the branch's label ("left", or "B:left F:right" for several dyads)
    selected: bool  # the branch the scene file asks for
    kind: str  # extended / folded (crank and coupler in line), stationary otherwise
    position: Json  # x, y; angle_deg about the pivot or along the line; exact forms where sympy finds them
    certificate: str

    def to_json(self) -> Json:
        return {"input_deg": self.input_deg, "enclosure_deg": self.enclosure.str(20),
                "exact_deg": str(self.exact_deg),
                "t_factor": None if self.factor is None else str(self.factor), "point": self.point,
                "branch": self.branch, "selected": self.selected, "kind": self.kind, "position": self.position,
                "certified": True, "certificate": self.certificate}


@dataclass
class TimeRatio:
    """The working and return strokes of one output on the scene's branch, in crank degrees."""

    point: str
    branch: str
    ratio: float
    enclosure: flint.arb
    exact: sympy.Expr
    strokes: list[Json]  # working then return: from_deg, to_deg, crank_deg, exact
    alpha_deg: float
    stroke: Json  # the output's swing (degrees about its pivot) or travel (along its line)

    def to_json(self) -> Json:
        return {"point": self.point, "branch": self.branch, "ratio": self.ratio,
                "enclosure": self.enclosure.str(20), "exact": str(self.exact),
                "strokes": self.strokes, "alpha_deg": self.alpha_deg, "stroke": self.stroke,
                "rule": "Q = (180 + alpha)/(180 - alpha): working stroke over return stroke, in crank angle"}


@dataclass
class Limits:
    """Every limit position of every point with a fixed path, and the output's time ratio."""

    scene: str
    input: str
    range: tuple[float, float]
    limits: list[Limit]
    time_ratio: TimeRatio | None
    time_ratio_reason: str | None  # why there is none
    dropped: list[Json] = field(default_factory=list)  # roots that are no limit, with why
    skipped: list[Json] = field(default_factory=list)  # points without a fixed path, with why

    def to_json(self) -> Json:
        return {"limits": [g.to_json() for g in self.limits],
                "time_ratio": None if self.time_ratio is None else self.time_ratio.to_json(),
                "time_ratio_reason": self.time_ratio_reason, "limits_dropped": self.dropped,
                "limits_skipped": self.skipped}


@dataclass(frozen=True)
class Path:
    """The curve an implicit point moves on, ``C(X) = 0``: a circle about a centre, or a line."""

    equation: sympy.Expr
    centre: tuple[sympy.Expr, sympy.Expr] | None  # a circle's
    direction: tuple[sympy.Expr, sympy.Expr] | None  # a line's


@dataclass(frozen=True)
class Stationary:
    """What the limit positions of one point are computed from."""

    point: str
    unknowns: tuple[sympy.Symbol, sympy.Symbol]
    path: Path
    coupling: sympy.Expr  # X's other equation
    condition: sympy.Expr  # zero where X stops on its path (polynomial in X, earlier unknowns, c, s)
    earlier: tuple[sympy.Expr, ...]  # the earlier points' equations
    earlier_unknowns: tuple[sympy.Symbol, ...]


def _along_theta(f: sympy.Expr, c: sympy.Symbol, s: sympy.Symbol) -> sympy.Expr:
    """``d f / d theta`` through ``c = cos(theta)``, ``s = sin(theta)`` alone (``c' = -s``, ``s' = c``)."""
    return sympy.expand(c * sympy.diff(f, s) - s * sympy.diff(f, c))


def _path(equation: sympy.Expr, x: sympy.Symbol, y: sympy.Symbol) -> Path | None:
    """``equation`` as a circle (centre) or a line (direction); None for any other curve."""
    poly = sympy.Poly(equation, x, y)
    if poly.total_degree() == 1:
        a, b = poly.coeff_monomial(x), poly.coeff_monomial(y)
        return Path(equation, None, (b, -a))  # a x + b y + k = 0 runs along (b, -a)
    quadratic = poly.coeff_monomial(x**2)
    if (poly.total_degree() == 2 and quadratic != 0 and poly.coeff_monomial(y**2) == quadratic
            and poly.coeff_monomial(x * y) == 0):
        return Path(equation, (-poly.coeff_monomial(x) / (2 * quadratic), -poly.coeff_monomial(y) / (2 * quadratic)),
                    None)
    return None


def stationary_condition(compiled: Compiled, point: str) -> Stationary | str:
    """The stationarity condition of ``point`` (see the module's text), or why it has none.

    ``compiled`` holds ``point`` and what it is built on; dimensions are at their defaults.
    """
    (c_name, s_name), = compiled.system.inputs.values()
    c, s = symbol(c_name), symbol(s_name)
    spec = next(p for p in compiled.implicit if p.point == point)
    x, y = (symbol(u) for u in spec.unknowns)
    equations = [e for e in compiled.system.equations if e.free_symbols - {c, s}]  # not the circle's
    own = [e for e in equations if e.has(x) or e.has(y)]
    fixed = [e for e in own if e.free_symbols <= {x, y}]
    if len(own) != 2 or len(fixed) != 1:
        return ("its path is not fixed: both its equations involve moving points" if not fixed
                else "it does not move")
    path = _path(fixed[0], x, y)
    if path is None:
        return "its path is neither a circle nor a line"
    coupling = next(e for e in own if e is not fixed[0])
    earlier = [e for e in equations if not (e.has(x) or e.has(y))]
    unknowns = [symbol(u) for u in compiled.system.unknowns if u not in spec.unknowns]
    condition = _along_theta(coupling, c, s)
    if unknowns:
        # u' = -adj(J) r / det(J); times det(J), the condition stays a polynomial
        jacobian = sympy.Matrix([[sympy.diff(f, u) for u in unknowns] for f in earlier])
        rates = sympy.Matrix([_along_theta(f, c, s) for f in earlier])
        gradient = sympy.Matrix([[sympy.diff(coupling, u) for u in unknowns]])
        determinant = jacobian.det(method="berkowitz")
        condition = sympy.expand(determinant * condition
                                 - (gradient * jacobian.adjugate(method="berkowitz") * rates)[0])
    return Stationary(point, (x, y), path, coupling, condition, tuple(earlier), tuple(unknowns))


def _eliminant(stationary: Stationary, c: sympy.Symbol, s: sympy.Symbol) -> tuple[sympy.Expr, list[sympy.Expr]]:
    """The condition with every unknown eliminated, and the factors the elimination dropped (in ``c, s``)."""
    equations = [stationary.condition, stationary.coupling, stationary.path.equation, *stationary.earlier]
    names = [str(u) for u in (*stationary.unknowns, *stationary.earlier_unknowns)]
    result = eliminate(equations, names, [str(c), str(s)])
    dropped = [f for f in result.dropped if f.free_symbols <= {c, s} and f.free_symbols]
    return result.polynomial, dropped


@dataclass(frozen=True)
class Root:
    """A real root of an eliminant: its enclosure in degrees, the factor in t and its exact angle."""

    degrees: flint.arb
    factor: sympy.Expr | None  # None at 180 deg (t at infinity)
    exact_deg: sympy.Expr
    t_value: sympy.Expr | None  # the root in radicals (factor of degree <= 2), None otherwise or at 180


def _roots(polys: Sequence[sympy.Expr], c: sympy.Symbol, s: sympy.Symbol, t: sympy.Symbol) -> list[Root]:
    """Every real root (as an angle) of every polynomial in ``c, s``, each with its factor."""
    found: list[Root] = []
    for poly in polys:
        numerator = half_angle_poly(poly, c, s)
        if vanishes_at_half_turn(poly, c, s):
            found.append(Root(flint.arb(180), None, sympy.Integer(180), None))
        if numerator.degree() < 1:
            continue
        for factor, _ in numerator.factor()[1]:
            pairs: Any = factor.complex_roots()  # python-flint 0.9: (root, multiplicity) pairs
            real = sorted((r.real for r, _ in pairs if r.imag.is_zero()), key=lambda r: float(r.mid()))
            if not real:
                continue
            expr = sympy.Add(*[fmpq_to_rational(a) * t**k for k, a in enumerate(factor.coeffs())])
            radicals = _radical_roots(expr, t) if factor.degree() <= 2 else []
            for index, root in enumerate(real):
                value = next((r for r in radicals if root.overlaps(flint.arb(str(sympy.N(r, 60))))), None)
                exact = sympy.CRootOf(expr, index) if value is None else value
                found.append(Root(tangent_to_degrees(root), expr, 360 * sympy.atan(exact) / sympy.pi, value))
    return found


def _radical_roots(expr: sympy.Expr, t: sympy.Symbol) -> list[sympy.Expr]:
    return [sympy.radsimp(r) for r in sympy.roots(sympy.Poly(expr, t)) if r.is_real]


def _interval(root: Root, others: Sequence[flint.arb]) -> tuple[flint.arb, flint.arb] | None:
    """``(lo, hi)`` in degrees around ``root`` holding no other root; None if it cannot be had."""
    middle = root.degrees.mid()
    half = flint.arb(str(HALF_WIDTH_DEG))
    for other in others:
        if other.overlaps(root.degrees):  # itself, or the same root of another polynomial
            continue
        gap = abs(other - middle)
        gap = 360 - gap if gap > 180 else gap
        if not gap > 0:
            return None
        half = min(half, gap.lower() / 4, key=float)
    lo, hi = middle - half, middle + half
    if not (lo < root.degrees.lower() and root.degrees.upper() < hi) or not half > 0:
        return None
    return lo, hi


def _angle_values(degrees: flint.arb, c: str, s: str) -> dict[str, flint.arb]:
    radians = degrees * flint.arb.pi() / 180
    return {c: radians.cos(), s: radians.sin()}


def _certify(condition: sympy.Expr, branch: Branch, interval: tuple[flint.arb, flint.arb],
             c: str, s: str) -> tuple[str, str]:
    """``(verdict, why)``: is the condition, on ``branch``, zero inside ``interval``?"""
    lo, hi = interval
    whole = _angle_values(lo.union(hi), c, s)  # a ball holding the whole interval
    discriminants = [evaluate(d, whole, ARB) for d in branch.discriminants.values()]
    if any(d < 0 for d in discriminants):
        return "no", "the branch does not assemble there"
    if not all(d > 0 for d in discriminants):
        return "undecided", "a dead centre is in the interval"
    on_branch = condition.xreplace({symbol(u): v for u, v in branch.values.items()})
    ends = [evaluate(on_branch, _angle_values(end, c, s), ARB) for end in interval]
    if (ends[0] < 0 and ends[1] > 0) or (ends[0] > 0 and ends[1] < 0):
        return "yes", "changes sign"
    value = evaluate(on_branch, whole, ARB)
    if value > 0 or value < 0:
        return "no", "bounded away from zero"
    return "undecided", "no sign change shown"


def _kind(scene: Scene, compiled: Compiled, point: str, values: Mapping[str, flint.arb]) -> str:
    """extended / folded when the point hangs on a crank tip P about a ground pivot O (the sign of
    ``(X - P) . (P - O)``: the coupler along the crank or back over it), else stationary."""
    cranks = {}
    for reference in scene.points[point].references:
        crank = scene.points[reference]
        if isinstance(crank, Crank) and isinstance(scene.points[crank.center], Fixed):
            cranks[reference] = crank.center
    if len(cranks) != 1:
        return "stationary"
    (tip, pivot), = cranks.items()
    (x, y), (px, py), (ox, oy) = (compiled.coordinates[p] for p in (point, tip, pivot))
    along = evaluate((x - px) * (px - ox) + (y - py) * (py - oy), values, ARB)
    return "extended" if along > 0 else "folded" if along < 0 else "stationary"


def _float(ball: flint.arb) -> float:
    return float(ball.mid())


def _position(path: Path, xy: tuple[flint.arb, flint.arb], exact: tuple[sympy.Expr, sympy.Expr] | None,
              centre_name: str | None) -> Json:
    """Where the point is: x, y and its angle about its path's centre or its place along its line."""
    x, y = xy
    position: Json = {"x": _float(x), "y": _float(y)}
    exact_position: Json = {}
    if exact is not None:
        exact_position = {"x": str(exact[0]), "y": str(exact[1])}
        position.update(x=float(exact[0]), y=float(exact[1]))  # 0, not the middle of a ball around it
    if path.centre is not None:
        qx, qy = (flint.arb(str(sympy.N(v, 60))) for v in path.centre)
        position["angle_deg"] = _float(flint.arb.atan2(y - qy, x - qx) * 180 / flint.arb.pi())
        position["about"] = centre_name or f"({path.centre[0]}, {path.centre[1]})"
        if exact is not None:
            exact_position["angle_deg"] = str(_tidy(180 * sympy.atan2(exact[1] - path.centre[1],
                                                                      exact[0] - path.centre[0]) / sympy.pi))
    else:
        assert path.direction is not None
        dx, dy = path.direction
        norm = sympy.sqrt(dx**2 + dy**2)
        ux, uy = (flint.arb(str(sympy.N(v / norm, 60))) for v in (dx, dy))
        position["along"] = _float(x * ux + y * uy)
        position["direction"] = [str(dx / norm), str(dy / norm)]
        if exact is not None:
            exact_position["along"] = str(_tidy((exact[0] * dx + exact[1] * dy) / norm))
    if exact is not None:
        position["exact"] = exact_position
    return position


def _tidy(expr: sympy.Expr) -> sympy.Expr:
    """The shortest of a few equal forms of ``expr`` (rewritings that keep its value); a root of a
    polynomial of degree above 2 (``CRootOf``) is left as it is."""
    if expr.has(sympy.CRootOf) or sympy.count_ops(expr) > 4 * TIDY_OPS:
        return expr
    forms = [expr]
    for rewrite in (sympy.radsimp, sympy.sqrtdenest, sympy.simplify):
        forms.append(rewrite(expr))
    return min(forms, key=sympy.count_ops)


def _exact_point(branch: Branch, unknowns: tuple[sympy.Symbol, sympy.Symbol], root: Root, c: sympy.Symbol,
                 s: sympy.Symbol) -> tuple[sympy.Expr, sympy.Expr] | None:
    """The point's coordinates at the root in radicals, when its angle has them and they stay short."""
    if root.t_value is None and root.factor is not None:
        return None
    if root.factor is None:  # theta = 180
        cosine, sine = sympy.Integer(-1), sympy.Integer(0)
    else:
        t = root.t_value
        assert t is not None
        cosine, sine = sympy.radsimp((1 - t**2) / (1 + t**2)), sympy.radsimp(2 * t / (1 + t**2))
    coordinates = tuple(_tidy(branch.values[str(u)].xreplace({c: cosine, s: sine})) for u in unknowns)
    if any(sympy.count_ops(v) > TIDY_OPS for v in coordinates):
        return None
    return coordinates[0], coordinates[1]


def _centre_name(scene: Scene, compiled: Compiled, path: Path) -> str | None:
    if path.centre is None:
        return None
    return next((n for n, (x, y) in compiled.coordinates.items()
                 if isinstance(scene.points[n], Fixed) and (x, y) == path.centre), None)


@dataclass
class PointLimits:
    """One point's limit positions on every branch, the roots that are none, or why it has none."""

    point: str
    compiled: Compiled
    stationary: Stationary | None
    branches: list[Branch]
    limits: list[Limit]
    dropped: list[Json]
    skipped: str | None  # why the point has no limit positions to look for


def _point_limits(scene: Scene, point: str, lo: float, hi: float) -> PointLimits:
    """The limits of one point (every branch), the roots dropped, or why the point has none."""
    prepared = prepare(scene, outputs=[point])
    compiled = prepared.compiled
    _, line = single_input(compiled, "limit positions")
    c, s = line.variables
    stationary = stationary_condition(compiled, point)
    if isinstance(stationary, str):
        return PointLimits(point, compiled, None, [], [], [], stationary)
    eliminant, dropped_factors = _eliminant(stationary, c, s)
    t = sympy.Symbol("t")
    with flint.ctx.workprec(ROOT_BITS):
        roots = _roots([eliminant], c, s, t)
        others = [r.degrees for r in roots] + [r.degrees for r in _roots(dropped_factors, c, s, t)]
    branches = list(prepared.branches)
    centre = _centre_name(scene, compiled, stationary.path)
    found: list[Limit] = []
    dropped: list[Json] = []
    with flint.ctx.workprec(CHECK_BITS):
        for root in roots:
            middle = _float(root.degrees)
            turns = [turn for turn in (-360, 0, 360) if lo <= middle + turn <= hi]
            if not turns:
                continue
            interval = _interval(root, others)
            verdicts = [(b, "undecided", "another root of the eliminant is too close") for b in branches] \
                if interval is None else \
                [(b, *_certify(stationary.condition, b, interval, str(c), str(s))) for b in branches]
            for branch, verdict, _ in verdicts:
                if verdict != "yes":
                    continue
                assert interval is not None
                width = float((interval[1] - interval[0]).upper())
                values = _angle_values(root.degrees, str(c), str(s))
                values.update({u: evaluate(v, values, ARB) for u, v in branch.values.items()})
                x, y = (values[str(u)] for u in stationary.unknowns)
                position = _position(stationary.path, (x, y), _exact_point(branch, stationary.unknowns, root, c, s),
                                     centre)
                certificate = (f"on branch {branch.label} every discriminant is > 0 and the stationarity "
                               f"condition changes sign across a {width:.1e} deg interval holding no other "
                               "root of the eliminant (ball arithmetic)")
                kind = _kind(scene, compiled, point, values)
                found += [Limit(middle + turn, root.degrees + turn, root.exact_deg + turn, root.factor, point,
                                branch.label, branch.selected, kind, position, certificate) for turn in turns]
            if not any(v == "yes" for _, v, _ in verdicts):
                reasons = "; ".join(sorted({f"{b.label}: {why}" for b, _, why in verdicts}))
                verdict = "undecided: " if any(v == "undecided" for _, v, _ in verdicts) else "not a limit (certified): "
                dropped += [{"point": point, "input_deg": middle + turn,
                             "t_factor": None if root.factor is None else str(root.factor), "why": verdict + reasons}
                            for turn in turns]
    return PointLimits(point, compiled, stationary, branches, found, dropped, None)


def _turns_fully(compiled: Compiled, lo: float, hi: float) -> str | None:
    """None when the input turns fully with every point the output needs assembled; else why not."""
    from .toggles import toggle_conditions

    if hi - lo < 360:
        return f"the input's range [{lo:g}, {hi:g}] deg is less than a full turn"
    _, line = single_input(compiled, "limit positions")
    with flint.ctx.workprec(ROOT_BITS):
        for spec in compiled.implicit:
            for kind, condition in toggle_conditions(compiled, spec).items():
                balls = line.roots(condition)
                if balls:
                    angles = ", ".join(f"{float(b.mid()):.6g}" for b in balls)
                    return f"the input does not turn fully: {spec.point} has dead centres ({kind}) at {angles} deg"
    return None


def _time_ratio(found: PointLimits, lo: float, hi: float) -> tuple[TimeRatio | None, str | None]:
    point, compiled, stationary = found.point, found.compiled, found.stationary
    assert stationary is not None
    why = _turns_fully(compiled, lo, hi)
    if why is not None:
        return None, why
    branch = next(b for b in found.branches if b.selected)
    _, line = single_input(compiled, "limit positions")
    c, s = line.variables
    with flint.ctx.workprec(CHECK_BITS):
        if not all(evaluate(d, _angle_values(flint.arb(lo), str(c), str(s)), ARB) > 0
                   for d in branch.discriminants.values()):
            return None, f"the scene's branch {branch.label} does not assemble"
    mine = {round(g.input_deg % 360, 9): g for g in found.limits if g.selected}
    if len(mine) != 2:
        what = "none: it turns without stopping" if not mine else f"{len(mine)} per turn"
        return None, f"{point} on branch {branch.label} has limit positions {what}, not exactly two"
    first, second = sorted(mine.values(), key=lambda g: g.input_deg % 360)
    with flint.ctx.workprec(CHECK_BITS):
        (a1, b1, e1), (a2, b2, e2) = (_per_turn(g) for g in (first, second))
        forward = {"from_deg": a1, "to_deg": a2, "from_kind": first.kind, "to_kind": second.kind,
                   "crank_deg": b2 - b1, "exact": e2 - e1}
        backward = {"from_deg": a2, "to_deg": a1 + 360, "from_kind": second.kind, "to_kind": first.kind,
                    "crank_deg": 360 - (b2 - b1), "exact": 360 - (e2 - e1)}
        working, quick = (forward, backward) if a2 - a1 >= 180 else (backward, forward)
        ratio = working["crank_deg"] / quick["crank_deg"]
    strokes = [{**stroke, "stroke": name, "crank_deg": _float(stroke["crank_deg"]),
                "enclosure_deg": stroke["crank_deg"].str(20), "exact": str(_tidy(stroke["exact"]))}
               for name, stroke in (("working", working), ("return", quick))]
    return TimeRatio(point, branch.label, _float(ratio), ratio, _tidy(working["exact"] / quick["exact"]), strokes,
                     _float(working["crank_deg"]) - 180, _stroke(stationary.path, first, second)), None


def _per_turn(limit: Limit) -> tuple[float, flint.arb, sympy.Expr]:
    """The limit's input angle in [0, 360) deg: a float, its enclosure, exactly."""
    turns = 360 * math.floor(limit.input_deg / 360)
    return limit.input_deg - turns, limit.enclosure - turns, limit.exact_deg - turns


def _stroke(path: Path, first: Limit, second: Limit) -> Json:
    """The output's swing about its pivot (degrees) or its travel along its line."""
    one, two = first.position, second.position
    exact_one, exact_two = one.get("exact"), two.get("exact")
    if path.centre is not None:
        swing = abs(two["angle_deg"] - one["angle_deg"])
        swing = min(swing, 360 - swing)
        exact = None
        if exact_one and exact_two:
            difference = sympy.sympify(exact_two["angle_deg"]) - sympy.sympify(exact_one["angle_deg"])
            difference = difference if float(difference) >= 0 else -difference
            exact = str(_tidy(difference if float(difference) <= 180 else 360 - difference))  # as the float
        return {"kind": "swing", "about": one["about"], "angle_deg": swing, "exact": exact}
    travel = abs(two["along"] - one["along"])
    exact = None
    if exact_one and exact_two:
        difference = sympy.sympify(exact_two["along"]) - sympy.sympify(exact_one["along"])
        exact = str(_tidy(difference if float(difference) >= 0 else -difference))
    return {"kind": "travel", "length": travel, "exact": exact}


def limits(scene: Scene | str, set: Mapping[str, object] | None = None) -> Limits:  # noqa: A002 - the public name (the command line's --set)
    """Every limit position of every dyad and slider with a fixed path, certified, and the time
    ratio of the last of them (the output) on the scene's branch."""
    scene = with_values(scene if not isinstance(scene, str) else load_scene(scene), dict(set) if set else None)
    implicit = [n for n, p in scene.points.items() if p.labels]
    if not implicit:
        raise UsageError("scene", scene.name, "has no dyad or slider, so no output to stop and turn back")
    name = next(iter(scene.inputs)) if len(scene.inputs) == 1 else None
    if name is None:
        raise UsageError("scene", scene.name, "limit positions are computed for one-input scenes")
    if not scene.inputs[name].is_angle:
        raise UsageError("scene", scene.name, f"limit positions and the time ratio are for a turning input; "
                                              f"{name} is a length (its toggles end the strokes)")
    lo, hi = scene.inputs[name].span
    points = [_point_limits(scene, point, lo, hi) for point in implicit]
    found = sorted((g for p in points for g in p.limits), key=lambda g: (g.input_deg, g.point, g.branch))
    dropped = [d for p in points for d in p.dropped]
    skipped = [{"point": p.point, "why": p.skipped} for p in points if p.skipped]
    moving = [p for p in points if p.stationary is not None]
    if not moving:
        return Limits(scene.name, name, (lo, hi), found, None, "no dyad or slider moves on a fixed path", dropped,
                      skipped)
    ratio, reason = _time_ratio(moving[-1], lo, hi)
    return Limits(scene.name, name, (lo, hi), found, ratio, reason, dropped, skipped)
