"""Points solved together: a scene's ``unknown = true`` points cut into groups, each with its equations.

Every constraint is one polynomial equation; every unknown point brings two unknowns (``P_x``,
``P_y``). Points built by constructions (a frame on the platform's side) are polynomials in the
points they are built on, so a constraint on one holds those. The groups are the strongly
connected parts of the constraint graph: each equation matched to an unknown it holds (a maximum
matching), an equation depends on the groups of the other unknowns it holds, and the parts where
equations depend on each other in a cycle (with a point's two coordinates kept together) are
solved together, in dependency order. Equations and unknowns that no matching pairs off make
the scene bad: a SceneError naming the points and the counts.

>>> from algkin.scene import load_scene_text
>>> scene = load_scene_text('''
... [points]
... A = { fixed = [0, 0] }
... B = { fixed = [4, 0] }
... P = { unknown = true }
... Q = { unknown = true }
... [constraints]
... a = "dist(A, P) = 3"
... b = "dist(B, P) = 3"
... c = "dist(P, Q) = 1"
... d = "on(Q, line(A, B))"
... ''', "two.toml")
>>> [(g.points, g.constraints) for g in compile_groups(scene).groups]
[(('P',), ('a', 'b')), (('Q',), ('c', 'd'))]
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence

import dataclasses

import attrs
import sympy

from ..errors import SceneError
from ..runtime.frozen import FrozenDict, frozen
from ..system import symbol
from .compile import checked_construction, checked_length, parameter_defaults
from .constraints import Constraint
from .constructions import Builder, Indicator, Unbuildable, Unknown
from .driven import driven_angles
from .implicit.base import Point
from .model import Scene

__all__ = ["Group", "Groups", "compile_groups"]


@attrs.frozen
class Group:
    """Points solved together: their unknowns (``P_x``, ``P_y`` of each point), and as many
    equations (one per constraint, every parameter at its exact default)."""

    points: tuple[str, ...]
    constraints: tuple[str, ...]
    unknowns: tuple[str, ...]
    equations: tuple[sympy.Expr, ...]


@attrs.frozen
class Groups:
    """A scene with points solved together, compiled: ``groups`` in dependency order,
    ``coordinates`` of every point (in the groups' unknowns, the inputs' variables), and
    ``inputs``: each input's variables (an angle's cos and sin, a length itself); ``sides``:
    each point built by a dyad or slider (a group of its own, its two equations named
    ``D.1``, ``D.2``) -> its branch indicator, whose sign is the side label of its mode."""

    scene: Scene
    groups: tuple[Group, ...]
    coordinates: FrozenDict[str, Point] = attrs.field(converter=frozen)
    inputs: FrozenDict[str, tuple[str, ...]] = attrs.field(converter=frozen)
    sides: FrozenDict[str, Indicator] = attrs.field(converter=frozen, factory=FrozenDict)


def compile_groups(scene: Scene) -> Groups:
    """The groups of ``scene``'s unknown points, their equations and every point's coordinates.

    A point built by a dyad, slider or meet is an unknown of its own with the construction's two
    equations (its two circles; its line and circle; its two lines): a group of its own, solved
    after the groups its base points belong to. SceneError for a group whose equations are not as
    many as its unknowns, or for a value that compiling a chain refuses (a length not positive, a
    number past what floats can square)."""
    values = _checked_values(scene)
    builder = _builder(scene)
    coordinates = _coordinates(scene, values, builder)
    equations = {name: sympy.expand(c.equation(coordinates).xreplace(values))
                 for name, c in scene.constraints.items()}
    _check_equations(scene, equations, coordinates)
    for indicator_point, pair in _built_equations(builder).items():
        equations.update({f"{indicator_point}.{k + 1}": sympy.expand(e.xreplace(values)) for k, e in enumerate(pair)})
    built = [p for p in scene.points if f"{p}.1" in equations]
    unknowns = {u: p for p in (*scene.unknown_points, *built) for u in (f"{p}_x", f"{p}_y")}
    holds = {name: [u for u in unknowns if symbol(u) in e.free_symbols] for name, e in equations.items()}
    matching = _matching(holds)
    _check_matched(scene, holds, matching, unknowns)
    parts = _parts(holds, matching, unknowns)
    groups = tuple(_group(part, equations, unknowns, matching) for part in parts)
    inputs = {n: tuple(str(s) for s in i.symbols) for n, i in scene.inputs.items()}
    sides = {i.point: dataclasses.replace(i, expr=sympy.expand(sympy.sympify(i.expr).xreplace(values)))
             for i in builder.indicators}
    return Groups(scene, groups, coordinates, inputs, sides)


def _checked_values(scene: Scene) -> dict[sympy.Symbol, sympy.Expr]:
    """Every parameter's symbol -> its exact default, after the checks a chain's compiling makes of
    the values of the parameters, of the constructions and of the constraints' lengths."""
    values, bits = parameter_defaults(scene)
    variables = {n: i.symbols for n, i in scene.inputs.items()}
    for name in scene.points:
        if not isinstance(scene.points[name], Unknown):
            checked_construction(scene, name, substitution=values, bits=bits, inputs=variables)
    for name, constraint in scene.constraints.items():
        if constraint.value is not None:
            checked_length(scene, f"constraints.{name}", constraint.value, substitution=values, inputs=variables)
    return values


def _check_equations(scene: Scene, equations: Mapping[str, sympy.Expr], coordinates: Mapping[str, Point]) -> None:
    """Each constraint's equation over the rationals and not 0 = 0 (a SceneError naming it)."""
    for name, equation in equations.items():
        _check_rational(scene, name, equation)
        if equation == 0:
            raise SceneError(scene.source, f"constraints.{name}", _why_always(scene.constraints[name], coordinates))


def _check_rational(scene: Scene, name: str, equation: sympy.Expr) -> None:
    """A constraint's equation is over the rationals, as a chain's are: ``dist(P, Q) = sqrt(2)``
    squares its root away, ``dist(P, Q)**2 = sqrt(2)`` cannot (a SceneError naming it)."""
    numbers = [p for p in equation.atoms(sympy.Pow) if p.is_number and not p.is_Rational]
    if numbers:
        raise SceneError(scene.source, f"constraints.{name}", f"{numbers[0]} makes its equation irrational: the "
                         "systems are over the rationals; give a length whose square is rational (dist(P, Q) = "
                         "sqrt(2)) or a rational squared length (dist(P, Q)**2 = 2)")


def _why_always(constraint: Constraint, coordinates: Mapping[str, Point]) -> str:
    """Why a constraint that is 0 = 0 with the parameters' defaults holds nothing."""
    if constraint.kind == "on":
        _, a, b = constraint.points
        if coordinates[a] == coordinates[b]:
            return f"line({a}, {b}) has no direction: {a} and {b} are at one place with the parameters' defaults"
    return f"{constraint.text} holds wherever its points are (0 = 0 with the parameters' defaults)"


def _builder(scene: Scene) -> Builder:
    angles = {n: i.symbols for n, i in scene.inputs.items() if i.is_angle}
    return Builder(angles, driven_angles(scene, angles))


def _built_equations(builder: Builder) -> dict[str, tuple[sympy.Expr, sympy.Expr]]:
    """Each point a construction built with two equations -> them (the builder adds them in pairs)."""
    points = [str(u)[:-2] for u in builder.unknowns[::2]]
    return {p: (builder.equations[2 * k], builder.equations[2 * k + 1]) for k, p in enumerate(points)}


def _coordinates(scene: Scene, values: Mapping[sympy.Symbol, sympy.Expr], builder: Builder) -> dict[str, Point]:
    """Every point's (x, y): an unknown point's own unknowns, a construction's in those of its
    references (a dyad's, slider's or meet's its own unknowns, its equations left in ``builder``)."""
    coordinates: dict[str, Point] = {}

    def build(name: str) -> Point:
        if name not in coordinates:
            construction = scene.points[name]
            for ref in construction.references:
                build(ref)
            if isinstance(construction, Unknown):
                point: Point = (symbol(f"{name}_x"), symbol(f"{name}_y"))
            else:
                try:
                    point = construction.build(name, coordinates, builder)
                except Unbuildable as err:
                    raise SceneError(scene.source, f"points.{name}", str(err)) from None
            coordinates[name] = tuple(sympy.expand(sympy.sympify(v).xreplace(values)) for v in point)
        return coordinates[name]

    for name in scene.points:
        build(name)
    return coordinates


def _matching(holds: Mapping[str, Sequence[str]]) -> dict[str, str]:
    """A maximum matching, equation -> an unknown it holds (augmenting paths: groups are small)."""
    owner: dict[str, str] = {}  # unknown -> its equation

    def augment(equation: str, seen: set[str]) -> bool:
        for unknown in holds[equation]:
            if unknown not in seen:
                seen.add(unknown)
                if unknown not in owner or augment(owner[unknown], seen):
                    owner[unknown] = equation
                    return True
        return False

    for equation in holds:
        augment(equation, set())
    return {e: u for u, e in owner.items()}


def _check_matched(scene: Scene, holds: Mapping[str, Sequence[str]], matching: Mapping[str, str],
                   unknowns: Mapping[str, str]) -> None:
    """SceneError naming the part where equations and unknowns do not pair off: what an unmatched
    equation (too many) or unknown (too few) reaches along alternating paths."""
    matched = set(matching.values())
    spare_equations = [e for e in holds if e not in matching]
    spare_unknowns = [u for u in unknowns if u not in matched]
    if not spare_equations and not spare_unknowns:
        return
    by_unknown = {u: e for e, u in matching.items()}
    equations: set[str] = set()
    reached: set[str] = set()
    if spare_equations:
        stack = [spare_equations[0]]
        while stack:
            equation = stack.pop()
            equations.add(equation)
            for u in holds[equation]:
                if u not in reached:
                    reached.add(u)
                    stack.append(by_unknown[u])
    else:
        stack = [spare_unknowns[0]]
        while stack:
            unknown = stack.pop()
            reached.add(unknown)
            for e in holds:
                if unknown in holds[e] and e not in equations:
                    equations.add(e)
                    if matching[e] not in reached:
                        stack.append(matching[e])
    points = list(dict.fromkeys(unknowns[u] for u in sorted(reached, key=list(unknowns).index)))
    said = [e for e in holds if e in equations]
    what = "more equations than unknowns" if spare_equations else "fewer equations than unknowns"
    raise SceneError(scene.source, "constraints", f"the group of {', '.join(points) or 'no point'} has {what}: "
                     f"{len(said)} ({', '.join(said) or 'none'}) for {len(reached)} ({', '.join(sorted(reached, key=list(unknowns).index))})")


def _parts(holds: Mapping[str, Sequence[str]], matching: Mapping[str, str],
           unknowns: Mapping[str, str]) -> list[list[str]]:
    """The equations cut into groups, in dependency order: strongly connected parts of "equation
    e holds the unknown matched to f", a point's two coordinates in one part."""
    point_of = {e: unknowns[u] for e, u in matching.items()}
    nodes = list(dict.fromkeys(point_of[e] for e in holds))  # points: their two equations together
    edges = {p: {unknowns[u] for e in holds if point_of[e] == p for u in holds[e]} - {p} for p in nodes}
    components = _strongly_connected(nodes, edges)
    return [[e for e in holds if point_of[e] in component] for component in components]


def _strongly_connected(nodes: Sequence[str], edges: Mapping[str, Iterable[str]]) -> list[set[str]]:
    """Tarjan's strongly connected components, each after every component it has an edge to."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    found: list[set[str]] = []

    def visit(node: str) -> None:
        index[node] = low[node] = len(index)
        stack.append(node)
        for other in edges[node]:
            if other not in index:
                visit(other)
                low[node] = min(low[node], low[other])
            elif other in stack:
                low[node] = min(low[node], index[other])
        if low[node] == index[node]:
            component = set()
            while True:
                member = stack.pop()
                component.add(member)
                if member == node:
                    break
            found.append(component)

    for node in nodes:
        if node not in index:
            visit(node)
    return found


def _group(part: Sequence[str], equations: Mapping[str, sympy.Expr], unknowns: Mapping[str, str],
           matching: Mapping[str, str]) -> Group:
    points = tuple(dict.fromkeys(unknowns[u] for u in unknowns if any(matching[e] == u for e in part)))
    names = tuple(u for u in unknowns if unknowns[u] in points)
    return Group(points, tuple(part), names, tuple(equations[e] for e in part))
