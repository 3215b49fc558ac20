"""``toggles`` on a scene with points solved together: where its modes meet.

Per group, the eliminant's discriminant in the separating variable, a polynomial in the input
(an angle through ``t = tan(angle/2)``: ``c = (1 - t**2)/(1 + t**2)``, ``s = 2t/(1 + t**2)``;
a length as itself), factored; each real root in the input's range is isolated in a ball. It
is certified exactly, in the number field ``K = QQ[t]/(f)`` of its irreducible factor ``f``:
there the eliminant and its derivative have a gcd of degree 1, so the two modes meet at a real
configuration (``u = -g0/g1`` in ``K``, every other unknown its lift), and the Jacobian
determinant of the group's own equations is exactly 0 there. A root where that fails (two
complex modes meeting, or more than two roots at once) is listed as not certified.

>>> found = toggles_groups("3rpr")
>>> [(round(t.value, 6), t.certified) for t in found.toggles]
[(7.92278, True), (11.206442, True)]
"""

from __future__ import annotations

import math
import time
from collections.abc import Mapping, Sequence
from typing import Any

import attrs
import flint
import sympy

from ...eliminate import eliminate
from ...eliminate.group import GroupSolution, modes_in_balls
from ...eliminate.group.samples import ball_value
from ...eliminate.group.algebra import coefficients, linear_relation
from ...errors import ComputationError, UsageError
from ...runtime.frozen import FrozenDict, frozen
from ...scene import Scene
from ...system import symbol
from ...system.convert import flint_context, to_flint
from ...system.roots import RealRoot, real_roots
from .scene import GroupScene, prepare_groups

__all__ = ["toggles_groups", "GroupToggles", "GroupToggle"]

Field = flint.fmpq_poly
"""An element of ``QQ[t]/(f)``: a polynomial in ``t`` of degree below ``f``'s."""


@attrs.frozen
class GroupToggle:
    """Where two modes of a group meet: the input's ``value`` (degrees for an angle, the length),
    its ``enclosure`` (a ball, as text), the group's ``points``, the discriminant's irreducible
    ``factor`` (in ``t`` or the length) and the root's rank among its real roots, and whether it
    is ``certified`` (with ``why`` not)."""

    value: float
    enclosure: str
    points: tuple[str, ...]
    factor: str
    index: int
    certified: bool
    why: str = ""

    def to_json(self, unit: str) -> dict[str, Any]:
        document: dict[str, Any] = {"point": ", ".join(self.points), "kind": "modes meet",
                                    "certified": self.certified, "factor": self.factor, "root": self.index + 1}
        if unit == "deg":
            document.update(input_deg=self.value, enclosure_deg=self.enclosure)
        else:
            document.update(input_length=self.value, enclosure_length=self.enclosure)
        if self.why:
            document["why"] = self.why
        return document


@attrs.frozen
class GroupToggles:
    """Every toggle of a group scene's input in its range, ascending."""

    scene: Scene
    input: str
    unit: str
    range: tuple[float, float]
    toggles: tuple[GroupToggle, ...]
    timings: FrozenDict[str, float] = attrs.field(converter=frozen)

    def to_json(self) -> dict[str, Any]:
        return {"scene": self.scene.name, "input": self.input, "unit": self.unit, "range": list(self.range),
                "toggles": [t.to_json(self.unit) for t in self.toggles], "grashof": None, "artefacts": [],
                "timings": dict(self.timings)}


def toggles_groups(scene: Scene | str | GroupScene) -> GroupToggles:
    """Where the modes of each group of ``scene`` (or of its groups solved) meet as its one input
    moves over its range, certified."""
    start = time.perf_counter()
    prepared = scene if isinstance(scene, GroupScene) else prepare_groups(scene, command="toggles")
    if prepared.input is None:
        raise UsageError("scene", prepared.scene.name, "moves with no input: its groups have no toggles to find")
    found: list[GroupToggle] = []
    later = prepared.later()
    for index, solution in enumerate(prepared.solutions):
        found += _later_toggles(prepared, index) if index in later else _group_toggles(prepared, index, solution)
    found.sort(key=lambda t: t.value)
    unit = "deg" if prepared.input.is_angle else "length"
    return GroupToggles(prepared.scene, prepared.input.name, unit, prepared.input.span, tuple(found),
                        {"total": time.perf_counter() - start})


def _group_toggles(prepared: GroupScene, index: int, solution: GroupSolution) -> list[GroupToggle]:
    """The group's toggles: the real roots in range of its discriminant's factors, each certified."""
    assert prepared.input is not None
    angle = prepared.input.is_angle
    param = "t" if angle else prepared.variables[0]  # t = tan(theta/2), as the docs name it
    names = (solution.variable, param)
    eliminant = _in_input(solution.eliminant.to_flint(), prepared.variables, names)
    discriminant = eliminant.discriminant(solution.variable)
    relation = linear_relation(eliminant, eliminant.derivative(solution.variable), solution.variable)
    ring = flint.fmpq_mpoly_ctx.get((param,), "lex")
    found = []
    lo, hi = prepared.input.span
    for factor, _ in discriminant.project_to_context(ring).factor()[1]:
        if factor.is_constant():
            continue
        poly = flint.fmpq_poly([c.coeffs()[0] if not c.is_zero() else 0 for c in coefficients(factor, param)])
        roots = [(root, _shown(root.ball, angle)) for root in real_roots(poly, bits=128)]
        roots = [(root, value) for root, value in roots if _inside(value, lo, hi, angle)]
        for root, value in roots:
            why = _certify(prepared, index, solution, relation=relation, root=root, param=param)
            found.append(GroupToggle(float(value.mid()), value.str(12), prepared.compiled.groups[index].points,
                                     str(factor).replace("^", "**"), root.index, not why, why))
    if angle:
        found += _half_turn(prepared, index, solution)
    return found


LATER = ("a group solved after another: its discriminant holds 0 in balls at a real configuration of the "
         "earlier groups there (not certified)")


def _later_toggles(prepared: GroupScene, index: int) -> list[GroupToggle]:
    """Toggles of a group solved after others (a dyad on a triad's joint): the real roots in range
    of the eliminant, in the input alone, of the equations of the group and those it is solved
    after with its Jacobian's determinant; kept where, at a real configuration of the earlier
    groups there (their modes in balls), the group's discriminant holds 0; dropped where it is
    certified nonzero at every one (a meeting of complex modes, or no meeting)."""
    assert prepared.input is not None
    angle = prepared.input.is_angle
    groups = prepared.compiled.groups
    chain = prepared.chain(index)
    group = groups[index]
    jacobian = sympy.Matrix([[sympy.diff(e, symbol(u)) for u in group.unknowns] for e in group.equations]).det()
    equations = [e for k in chain for e in groups[k].equations] + [sympy.expand(jacobian)]
    param = "t" if angle else prepared.variables[0]  # t = tan(theta/2), as the docs name it
    if angle:
        c, s, t = (symbol(v) for v in (*prepared.variables, param))
        half = {c: (1 - t**2) / (1 + t**2), s: 2 * t / (1 + t**2)}
        equations = [sympy.numer(sympy.together(e.xreplace(half))) for e in equations]
    result = eliminate(equations, [u for k in chain for u in groups[k].unknowns], [param])
    eliminant, _ = result.exact
    solution = prepared.solutions[index]
    discriminant = solution.eliminant.to_flint().discriminant(solution.variable)
    lo, hi = prepared.input.span
    found = []
    for factor, _ in eliminant.factor()[1]:
        if factor.is_constant():
            continue
        poly = flint.fmpq_poly([c.coeffs()[0] if not c.is_zero() else 0 for c in coefficients(factor, param)])
        for root in real_roots(poly, bits=BITS):
            value = _shown(root.ball, angle)
            if _inside(value, lo, hi, angle) and _meets(prepared, chain[:-1], discriminant, root.ball):
                found.append(GroupToggle(float(value.mid()), value.str(12), group.points,
                                         str(factor).replace("^", "**"), root.index, False, LATER))
    return found


def _meets(prepared: GroupScene, chain: Sequence[int], discriminant: flint.fmpq_mpoly, t: flint.arb) -> bool:
    """Whether, at the input ``t`` (a ball), the discriminant may vanish at some real configuration
    of the groups in ``chain`` (True too where those cannot be told apart there)."""
    with flint.ctx.workprec(BITS):
        inputs = _input_balls(prepared.variables, t)
        combinations: list[dict[str, flint.arb]] = [dict(inputs)]
        try:
            for k in chain:
                solution = prepared.solutions[k]
                combinations = [dict(c, **m.values) for c in combinations
                                for m in modes_in_balls(solution, {}, {p: c[p] for p in solution.parameters},
                                                        bits=BITS)]
        except ComputationError:
            return True
        return any(ball_value(discriminant, c).contains(0) for c in combinations)


def _in_input(poly: flint.fmpq_mpoly, variables: Sequence[str], names: tuple[str, str]) -> flint.fmpq_mpoly:
    """``poly`` in the separating variable and the input: an angle's ``c``, ``s`` replaced by
    their rational forms in ``t`` (denominators cleared), a length as it is.

    >>> ctx = flint.fmpq_mpoly_ctx.get(("u", "c", "s"), "lex")
    >>> u, c, s = ctx.gens()
    >>> _in_input(u * s - c**3 * s**2, ("c", "s"), ("u", "t"))   # times (1+t^2)^5, its factor t dropped
    2*u*t^8 + 8*u*t^6 + 12*u*t^4 + 8*u*t^2 + 2*u + 4*t^7 - 12*t^5 + 12*t^3 - 4*t
    """
    ctx = flint.fmpq_mpoly_ctx.get(names, "lex")
    u, t = ctx.gens()
    if len(variables) == 1:
        return _primitive_in(poly.project_to_context(ctx), names[0])
    indices = [list(poly.context().names()).index(v) for v in variables]
    degree = max(sum(int(m[k]) for k in indices) for m in poly.monoms())  # the highest in c and s together
    lookup = {names[0]: u, variables[0]: (1 - t * t), variables[1]: 2 * t}
    # each term c**i s**j times (1 + t**2)**(degree - i - j): the form divided by (1 + t**2)**degree
    total = ctx.from_dict({})
    for monomial, coefficient in zip(poly.monoms(), poly.coeffs()):
        term = ctx.from_dict({(0, 0): coefficient})
        powers = dict(zip([str(n) for n in poly.context().names()], monomial))
        for name, exponent in powers.items():
            if exponent:
                term *= lookup[name] ** int(exponent)
        spent = sum(int(powers.get(v, 0)) for v in variables)
        total += term * (1 + t * t) ** (degree - spent)
    return _primitive_in(total, names[0])


def _primitive_in(poly: flint.fmpq_mpoly, variable: str) -> flint.fmpq_mpoly:
    """``poly`` without its factors free of ``variable`` (their zeros are no meeting of modes)."""
    content = poly.context().from_dict({})
    for part in coefficients(poly, variable):
        content = content.gcd(part)
    return poly if content.is_constant() else poly / content


def _shown(ball: flint.arb, angle: bool) -> flint.arb:
    """A root's ball as the input's value: for an angle, ``2*atan(t)`` in degrees in [0, 360)."""
    if not angle:
        return ball
    degrees = 2 * ball.atan() * 180 / flint.arb.pi()
    return degrees + 360 if degrees < 0 else degrees


def _inside(value: flint.arb, lo: float, hi: float, angle: bool) -> bool:
    mid = float(value.mid())
    if angle and not lo <= mid <= hi:
        mid += 360 * math.floor((lo - mid) / 360 + 1) if mid < lo else 0
    return lo <= mid <= hi


def _half_turn(prepared: GroupScene, index: int, solution: GroupSolution) -> list[GroupToggle]:
    """The half turn, ``t`` at infinity: a toggle where the eliminant has a repeated root at ``c = -1``, ``s = 0``."""
    assert prepared.input is not None
    lo, hi = prepared.input.span
    if not _inside(flint.arb(180), lo, hi, True):
        return []
    try:
        prepared.modes(prepared.sample(180))
    except ComputationError as error:
        if "repeated root" in str(error):
            return [GroupToggle(180.0, "180", prepared.compiled.groups[index].points, "t = infinity", 0, False,
                                "the half turn: not certified")]
    return []


def _certify(prepared: GroupScene, index: int, solution: GroupSolution, *,
             relation: tuple[flint.fmpq_mpoly, flint.fmpq_mpoly] | None, root: RealRoot, param: str) -> str:
    """'' when, at the discriminant's root ``root`` (exact: its factor and rank), the modes meet
    at one real configuration and the Jacobian of the group's equations is singular there, in
    balls; else why not. ``relation``: ``(a, b)`` in the input alone with ``a*u + b`` in the ideal
    of the eliminant and its derivative in ``u``: where ``a`` is nonzero their common root is
    ``u = -b/a``, real (the root is)."""
    if solution.form:
        return "a linear form separates this group (not certified)"
    if relation is None:
        return "the modes meet more than two at a time there (not certified)"
    with flint.ctx.workprec(BITS):
        t = root.refined(BITS).ball
        slope, offset = (_ball(p, {param: t}) for p in relation)
        if slope.contains(0):
            return "the modes meet more than two at a time there (not certified)"
        values = dict(_input_balls(prepared.variables, t))
        values[solution.variable] = -offset / slope
        for lift in solution.lifts:
            bottom = _ball(lift.denominator.to_flint(), values)
            if bottom.contains(0):
                return f"the lift of {lift.unknown} is not proved defined there (not certified)"
            values[lift.unknown] = _ball(lift.numerator.to_flint(), values) / bottom
        group = prepared.compiled.groups[index]
        ctx = flint_context(group.unknowns + tuple(prepared.variables))
        equations = [to_flint(e, ctx) for e in group.equations]
        if not all(_ball(e, values).contains(0) for e in equations):
            return "the meeting point does not solve the equations"
        jacobian = flint.arb_mat([[_ball(e.derivative(u), values) for u in group.unknowns] for e in equations])
        if not jacobian.det().contains(0):
            return "the Jacobian is regular there"
    return ""


BITS = 512
"""Working precision of a toggle's certificate."""


def _input_balls(variables: Sequence[str], t: flint.arb) -> dict[str, flint.arb]:
    """The input's variables at ``t``: itself for a length, ``c`` and ``s`` of ``t`` for an angle."""
    if len(variables) == 1:
        return {variables[0]: t}
    return {variables[0]: (1 - t * t) / (1 + t * t), variables[1]: 2 * t / (1 + t * t)}


def _ball(poly: flint.fmpq_mpoly, values: Mapping[str, flint.arb]) -> flint.arb:
    """``poly`` at ``values`` (a ball for every name it holds), by Horner's rule in its first held name."""
    names = [str(n) for n in poly.context().names()]
    held = [n for n, d in zip(names, poly.degrees()) if d > 0]
    if not held:
        return flint.arb(poly.coeffs()[0]) if not poly.is_zero() else flint.arb(0)
    parts = coefficients(poly, held[0])
    total = flint.arb(0)
    for part in reversed(parts):
        total = total * values[held[0]] + _ball(part, values)
    return total
