"""Toggles (dead centres): where an implicit point's two assembly modes meet, certified.

Each implicit point's branch algebra gives its conditions (``algkin.branches.constructions``). A dyad on
bases P, Q with lengths l1, l2 toggles where ``|PQ| = l1 + l2`` (*extended*:
both bars in line, pointing apart) or ``|PQ| = |l1 - l2|`` (*folded*: in line, one over the
other). A slider (on the line through P with direction d, at distance l from Q) toggles
where the circle about Q is *tangent* to the line: ``cross(d, Q - P)**2 = l**2 |d|**2``.
``|PQ|**2`` and ``cross(d, Q - P)`` are polynomials in the input's ``c, s`` (earlier
points' unknowns eliminated), so each condition becomes, in the half-angle ``t``, a
polynomial whose real roots python-flint isolates with certified enclosures.

The discriminant of an eliminant (of ``B_y``, say) has more factors than these: where the
two modes have the same ``y`` but are different points. Those *artefacts* of the
projection are recognised, with a certificate (ball arithmetic shows the two modes'
points apart at every real root), and reported as dropped.

>>> result = toggles("chebyshev-lambda")
>>> result.toggles, result.grashof["class"]
((), 'crank-rocker')
"""

from collections.abc import Mapping, Sequence
from typing import Any, TypedDict

import attrs
import flint
import sympy
from sympy.polys.polytools import _sorted_factors
from sympy.polys.polyutils import _sort_gens

from ..branches import Branch
from ..derivation.prepared import Prepared, given, prepared_from
from ..branches.constructions import algebra_of
from ..eliminate import eliminate
from ..errors import UsageError
from ..runtime.budget import Budget, Deadline, started
from ..evaluate import ARB, evaluate
from ..scene import Compiled, compile_scene
from ..scene.compile import refuse_solved_together
from ..scene.constructions import Crank, Dyad, Fixed
from ..scene.implicit import DyadSpec, ImplicitSpec
from ..scene.load import SceneLike, Values, as_scene
from ..scene.settings import with_values
from ..system import input_values, symbol
from ..system.angles import Parametrisation
from ..system.convert import flint_context, to_flint
from ..runtime.frozen import FrozenDict
from ..runtime.exclusive import one_at_a_time
from .frozen import deep_frozen, frozen_rows, thawed

__all__ = ["toggles", "Toggle", "Toggles", "grashof", "single_input"]

ROOT_BITS = 128


# A four-bar's Grashof class, its bars' lengths and the margin that decides it (as text);
# "class" is a keyword: the functional form
Grashof = TypedDict("Grashof", {"class": str, "bars": dict[str, str], "margin": str, "rule": str})


class Artefact(TypedDict):
    """A factor of an eliminant's discriminant that is no toggle, and why (certified)."""

    eliminant: str
    factor: str
    why: str


@attrs.frozen
class Toggle:
    input_deg: float  # a length input's value, for a length
    enclosure: flint.arb = attrs.field(eq=False)  # degrees (or the length); balls do not hash
    point: str  # the dyad or slider
    kind: str  # extended / folded (dyad), tangent (slider)
    angle: bool = True  # False: the input is a length, its keys have no _deg

    def to_json(self) -> dict[str, object]:
        suffix = "_deg" if self.angle else "_length"
        return {f"input{suffix}": self.input_deg, f"enclosure{suffix}": self.enclosure.str(20), "point": self.point,
                "kind": self.kind, "certified": True}


def _toggles(toggles: Any) -> tuple[Toggle, ...]:
    return tuple(toggles)


@attrs.frozen
class Toggles:
    scene: str
    input: str
    range: tuple[float, float]
    toggles: tuple[Toggle, ...] = attrs.field(converter=_toggles)
    grashof: FrozenDict[str, Any] | None = attrs.field(default=None, converter=deep_frozen)  # a Grashof, frozen
    artefacts: tuple[FrozenDict[str, str], ...] = attrs.field(default=(), converter=frozen_rows)  # dropped
    # discriminant factors (Artefact rows), with why
    unit: str = "deg"  # the range's and the toggles' unit: "deg", or "length" for a length input

    def to_json(self) -> dict[str, object]:
        return {"scene": self.scene, "input": self.input, "unit": self.unit, "range": list(self.range),
                "toggles": [t.to_json() for t in self.toggles], "grashof": thawed(self.grashof),
                "artefacts": thawed(self.artefacts)}


def _defaults(compiled: Compiled) -> dict[sympy.Symbol, sympy.Expr]:
    return {symbol(n): compiled.parameter_values[n] for n in compiled.system.parameters}


def toggle_conditions(compiled: Compiled, spec: ImplicitSpec, *, deadline: Deadline | None = None
                      ) -> dict[str, sympy.Expr]:
    """{kind: poly} in the input's c, s (earlier points eliminated, keeping to ``deadline`` if any),
    for a dyad or a slider."""
    defaults = _defaults(compiled)
    return {kind: _eliminate_earlier(compiled, sympy.expand(e.xreplace(defaults)), spec, deadline)
            for kind, e in algebra_of(spec).toggle_conditions().items()}


def _eliminate_earlier(compiled: Compiled, condition: sympy.Expr, spec: ImplicitSpec, deadline: Deadline | None
                       ) -> sympy.Expr:
    """The condition with earlier points' unknowns eliminated (a polynomial in c, s): those it
    names, and every unknown their equations bring in (a slider on a horizontal guide names
    only its rod end's y, whose equations hold its x too)."""
    unknowns = set(compiled.system.unknowns) - set(spec.unknowns)
    earlier = {str(v) for v in condition.free_symbols} & unknowns
    if not earlier:
        return condition
    defaults = _defaults(compiled)
    names = lambda e: {str(v) for v in e.free_symbols}  # noqa: E731
    system = [e for e in compiled.system.equations if not names(e) & set(spec.unknowns)]
    while True:
        equations = [e for e in system if names(e) & earlier]
        grown = earlier.union(*(names(e) & unknowns for e in equations))
        if grown == earlier:
            break
        earlier = grown
    (variables,) = compiled.system.inputs.values()
    equations = [sympy.expand(e.xreplace(defaults)) for e in equations]
    return eliminate([condition] + equations, sorted(earlier), list(variables), method="resultant",
                     budget=deadline).polynomial


def single_input(compiled: Compiled, what: str = "toggles") -> tuple[str, Parametrisation]:
    """``(name, parametrisation)`` of the scene's one input (``system.angles.Parametrisation``,
    in ``t_<name>`` for an angle); a usage error naming ``what`` if it has more."""
    if len(compiled.system.inputs) != 1:
        raise UsageError("scene", compiled.scene.name, f"{what} are computed for one-input scenes")
    (name, variables), = compiled.system.inputs.items()
    t = symbol(f"t_{name}") if len(variables) == 2 else symbol(name)
    return name, Parametrisation(tuple(symbol(v) for v in variables), t)


@one_at_a_time
def toggles(scene: SceneLike, artefacts: bool = True,
            set: Values | None = None, *,  # noqa: A002 - the public name (the command line's --set)
            budget: Budget | Deadline | None = None) -> Toggles:
    """Every toggle of every dyad and slider of ``scene`` over its input range, certified.

    With ``artefacts`` the eliminants are also derived, to report which factors of their
    discriminants are not toggles. ``set`` gives dimensions exact values in place of their defaults.
    ``scene`` may be a ``Prepared`` one (``prepare``) with every dyad and slider among its outputs.
    A ``Budget`` (or the ``Deadline`` of one running) bounds the time and the eliminants' terms.
    """
    deadline = started(budget)
    prepared = given(scene, set=set)
    scene = prepared.scene if prepared else with_values(as_scene(scene), set)  # a name, a path (str or pathlib) or a Scene
    refuse_solved_together(scene)
    implicit = [n for n, p in scene.points.items() if p.labels]  # the points with assembly modes
    if not implicit:
        raise UsageError("scene", scene.name, "has no dyad or slider, so no assembly modes to meet")
    if prepared and {d.point for d in prepared.compiled.implicit} != frozenset(implicit):
        raise UsageError("scene", scene.name, f"prepared for {', '.join(prepared.compiled.outputs)}: toggles need "
                         f"every dyad and slider (prepare it with outputs={implicit})")
    compiled = prepared.compiled if prepared else compile_scene(scene, implicit)
    name, line = single_input(compiled)
    lo, hi = scene.inputs[name].span
    found: list[Toggle] = []
    moded = [spec.point for spec in compiled.implicit if spec.labels]
    if len(moded) > 1 or artefacts:  # the branches, to see earlier points assemble (and for the artefacts)
        prepared = prepared or prepared_from(compiled)
    with flint.ctx.workprec(ROOT_BITS):
        for spec in compiled.implicit:
            earlier = moded[:moded.index(spec.point)] if spec.point in moded else moded
            for kind, condition in toggle_conditions(compiled, spec, deadline=deadline).items():
                for ball in line.roots(condition):
                    if earlier and prepared and not _earlier_may_assemble(compiled, prepared.branches, earlier,
                                                                          line, ball):
                        continue
                    found += [Toggle(float(ball.mid()) + turn, ball + turn, spec.point, kind, line.is_angle)
                              for turn in line.turns if lo <= float(ball.mid()) + turn <= hi]
        # the eliminants' branches and witnesses: the scene's own, prepared once
        dropped = _artefacts(prepared, line, deadline) if artefacts and prepared else []
    found.sort(key=lambda g: g.input_deg)
    unit = "deg" if line.is_angle else "length"
    return Toggles(scene.name, name, (lo, hi), found, grashof(compiled), dropped, unit)


def _artefacts(prepared: Prepared, line: Parametrisation, deadline: Deadline) -> list[Artefact]:
    """Factors of the eliminants' discriminants that are not toggles, with the certificate."""
    from ..derivation.pipeline import derive

    compiled, branches = prepared.compiled, list(prepared.branches)
    derived = derive(prepared, samples=0, certify=False, budget=deadline)  # its eliminants alone
    geometric = [line.numerator(cond) for d in compiled.implicit
                 for cond in toggle_conditions(compiled, d, deadline=deadline).values()]
    t = line.t
    dropped: list[Artefact] = []
    for unknown, elimination in derived.eliminations.items():
        u = symbol(unknown)
        if sympy.degree(elimination.polynomial, u) < 2:
            continue
        for factor in discriminant_factors(elimination.polynomial, u, _defaults(compiled)):
            numerator = line.numerator(factor)
            if not numerator.has(t) or any(sympy.rem(g, numerator, t) == 0 for g in geometric if g.has(t)):
                continue
            dropped.append({"eliminant": unknown, "factor": str(factor),
                            "why": _why_not_a_toggle(compiled, branches, factor, line)})
    return dropped


def discriminant_factors(polynomial: sympy.Expr, unknown: sympy.Symbol,
                         values: Mapping[sympy.Symbol, sympy.Expr]) -> list[sympy.Expr]:
    """The irreducible factors of ``polynomial``'s discriminant in ``unknown`` with ``values`` put in:
    those of ``sympy.factor_list``, in its order, computed in python-flint (sympy's discriminant and
    factoring took over a minute on a six-bar's eliminants).

    sympy's ``factor_list`` takes the terms' common monomial out first (``together``), so each of its
    variables is a factor of its own, then factors the rest over the variables it has; each factor is
    primitive with a positive leading coefficient in the lex order of sympy's generators, as python-flint's.

    >>> u, c, a = sympy.symbols("u c a")
    >>> discriminant_factors((c - 2) * u**2 + a * u + c**2 - 4, u, {a: sympy.Integer(0)})  # -4 (c + 2) (c - 2)**2
    [c + 2, c - 2]
    """
    gens = _sort_gens(polynomial.free_symbols)
    given = {k: v for k, v in values.items() if k in polynomial.free_symbols}
    if not all(v.is_Rational for v in given.values()):  # a dimension python-flint cannot take: sympy's way
        discriminant = sympy.expand(sympy.discriminant(polynomial, unknown).xreplace(values))
        return [factor for factor, _ in sympy.factor_list(discriminant)[1]]
    ctx = flint_context([g.name for g in gens])
    discriminant = to_flint(polynomial, ctx).discriminant(unknown.name)
    if given:
        discriminant = discriminant.subs({k.name: flint.fmpq(int(v.p), int(v.q)) for k, v in given.items()})
    if discriminant.is_zero():
        return []
    common = [min(m[k] for m in discriminant.monoms()) for k in range(len(gens))]
    factors = [(sympy.Poly(gens[k], gens[k], domain=sympy.ZZ), e) for k, e in enumerate(common) if e]
    rest = discriminant / ctx.from_dict({tuple(common): 1})
    if not rest.is_constant():
        kept = [k for k, d in enumerate(rest.degrees()) if d]  # the variables sympy factors the rest over
        factors += [(_sympy_poly(f, [gens[k] for k in kept], kept), e) for f, e in rest.factor()[1]]
    return [poly.as_expr() for poly, _ in _sorted_factors(factors, "factor")]


def _sympy_poly(poly: flint.fmpq_mpoly, gens: Sequence[sympy.Symbol], kept: Sequence[int]) -> sympy.Poly:
    """A primitive integer ``poly`` as a sympy ``Poly`` over ``gens``, the variables at ``kept``."""
    terms = {tuple(m[k] for k in kept): int(flint.fmpq(c).p) for m, c in poly.to_dict().items()}
    return sympy.Poly.from_dict(terms, *gens, domain=sympy.ZZ)


def _earlier_may_assemble(compiled: Compiled, branches: Sequence[Branch], earlier: Sequence[str],
                          line: Parametrisation, ball: flint.arb) -> bool:
    """Whether the points ``earlier`` (those a toggling point comes after) may all be real at the input
    ``ball``: False where on every branch one of them is certified not to assemble (its discriminant < 0).
    A toggle's condition holds the earlier points eliminated, their complex configurations too: Hart's
    C "folds" at 120 degrees, where D, on which it is built, cannot close."""
    values = _ball_values(compiled, line, ball)
    return any(all(not evaluate(b.discriminants[p], values, ARB) < 0 for p in earlier if p in b.discriminants)
               for b in branches)


def _ball_values(compiled: Compiled, line: Parametrisation, ball: flint.arb) -> dict[str, flint.arb]:
    """The dimensions' defaults and the input's variables at ``ball`` (degrees, or a length) as balls."""
    defaults = {k.name: ARB.number(int(sympy.Rational(v).p), int(sympy.Rational(v).q))
                for k, v in _defaults(compiled).items()}
    names = tuple(v.name for v in line.variables)
    return dict(defaults, **input_values(names, ball * flint.arb.pi() / 180 if line.is_angle else ball))


def _why_not_a_toggle(compiled: Compiled, branches: Sequence[Branch], factor: sympy.Expr, line: Parametrisation) -> str:
    """At every real root of ``factor``, ball arithmetic shows the modes apart or not assembled."""
    reasons: set[str] = set()
    for ball in line.roots(factor):
        values = _ball_values(compiled, line, ball)
        reason = _separated(compiled, branches, values)
        if reason is None:
            return "undecided: the balls could not separate the modes"
        reasons.add(reason)
    return " / ".join(sorted(reasons)) + " (certified)" if reasons else "no real root (certified)"


def _separated(compiled: Compiled, branches: Sequence[Branch], values: Mapping[str, Any]) -> str | None:
    signs = [[evaluate(d, values, ARB) for d in b.discriminants.values()] for b in branches]
    if any(not (all(d > 0 for d in ds) or any(d < 0 for d in ds)) for ds in signs):
        return None  # a branch at its own dead centre, or undecided
    # the branches that assemble there (on another mode of an earlier point, a later one may not)
    branches = [b for b, ds in zip(branches, signs) if all(d > 0 for d in ds)]
    if not branches:
        return "a dyad or slider cannot assemble there"
    points = [{u: evaluate(v, values, ARB) for u, v in b.values.items()} for b in branches]
    for spec in compiled.implicit:
        x, y = spec.unknowns
        # its two modes on the same modes of every other point (the branches that differ in its label
        # alone): on the same earlier points, where it toggles they meet
        pairs = [(p, q) for p, a in zip(points, branches) for q, b in zip(points, branches)
                 if {n for n in a.labels if a.labels[n] != b.labels[n]} == {spec.point}]
        # d * d, not d ** 2: python-flint's arb power is nan on a ball around zero.
        gaps = [_square(p[x] - q[x]) + _square(p[y] - q[y]) for p, q in pairs]
        if not all(g > 0 for g in gaps):
            return None
    return "the modes share this coordinate but are apart"


def _square(ball: flint.arb) -> flint.arb:
    return ball * ball


def grashof(compiled: Compiled) -> Grashof | None:
    """The Grashof class of a four-bar (crank about a ground pivot, dyad on crank tip and ground)."""
    scene = compiled.scene
    for dyad in (spec for spec in compiled.implicit if isinstance(spec, DyadSpec)):
        construction = scene.points[dyad.point]
        assert isinstance(construction, Dyad), "a dyad spec's point is a dyad"
        first, second = (scene.points[p] for p in construction.bases)
        lengths = construction.lengths
        if isinstance(first, Fixed) and isinstance(second, Crank):
            first, second, lengths = second, first, lengths[::-1]
        if isinstance(first, Crank) and isinstance(second, Fixed) and isinstance(scene.points[first.center], Fixed):
            return _classify(compiled, lengths, first, second)
    return None


def _classify(compiled: Compiled, lengths: Sequence[sympy.Expr], crank: Crank, ground_pivot: Fixed) -> Grashof:
    values = {symbol(n): v for n, v in compiled.parameter_values.items()}
    pivot = compiled.scene.points[crank.center]
    assert isinstance(pivot, Fixed), "grashof checked the crank's centre is fixed"
    # Defaults are exact already; nsimplify would trade a large rational for a "simpler" radical.
    exact = lambda e: sympy.sympify(e).xreplace(values)  # noqa: E731
    ground = sympy.sqrt((exact(ground_pivot.x) - exact(pivot.x)) ** 2 + (exact(ground_pivot.y) - exact(pivot.y)) ** 2)
    bars = {"crank": exact(crank.length), "ground": ground,
            "coupler": exact(lengths[0]), "rocker": exact(lengths[1])}
    ordered = sorted(bars.values(), key=lambda v: float(v))
    shortest, longest = ordered[0], ordered[-1]
    margin = ordered[1] + ordered[2] - shortest - longest
    if not margin.is_Rational:  # a ground of sqrt(...): simplified (a rational is already its simplest)
        margin = sympy.simplify(margin)
    if margin < 0:
        kind = "non-grashof (triple rocker)"
    elif margin == 0:
        kind = "change point"
    else:
        role = min(bars, key=lambda k: float(bars[k]))
        kind = {"crank": "crank-rocker", "ground": "double crank", "coupler": "double rocker",
                "rocker": "rocker-crank"}[role]
    return {"class": kind, "bars": {k: str(v) for k, v in bars.items()}, "margin": str(margin),
            "rule": "shortest + longest vs the other two"}
