"""A group of unknowns solved together: one eliminant, every other unknown rational in its root.

The unknowns of a group (a triad's joints, a parallel manipulator's platform) are held by as
many polynomial equations, in which every other variable (an input's cos and sin, a symbolic
dimension) is a parameter. ``solve_group`` answers a rational univariate representation:

- the **eliminant**: the equations' eliminant in one unknown ``u`` (the ``linear`` method), its
  factors free of ``u`` (conditions on the parameters) and its extraneous factors dropped;
- a **lift** of every other unknown ``x``: the unknowns but ``u`` and ``x`` eliminated leave
  equations in ``x`` and ``u`` whose pseudo-remainder sequence in ``x`` ends at ``a*x + b``,
  so ``x = -b/a`` at every root of the eliminant where ``a`` does not vanish (the shape lemma);
- which factors are **genuine** is decided exactly at a random rational point of the
  parameters: there each factor is a polynomial over QQ, and a factor is kept when the lifts,
  reduced modulo it, satisfy every original equation modulo it (its roots are solutions),
  dropped when they do not;
- ``u`` **separates** the solutions when the kept factors are squarefree in the eliminant and
  every lift's denominator is prime to them: two solutions with the same ``u`` and different
  ``x`` would be two common roots of the equations the lift of ``x`` came from, and make its
  ``a`` vanish there. Where no unknown separates (a symmetric design: mirror solutions share
  ``x``), a random linear form of the unknowns, a new variable, takes ``u``'s place.

>>> import flint
>>> ctx = flint.fmpq_mpoly_ctx.get(("x", "y", "r"), "lex")
>>> x, y, r = ctx.gens()
>>> solution = solve_group([x**2 + y**2 - r, x - y], ["x", "y"])      # a circle and a line
>>> solution.variable, str(solution.eliminant), solution.complex_count
('x', '2*x**2 - r', 2)
>>> lift, = solution.lifts
>>> lift.unknown, str(lift.numerator), str(lift.denominator)
('y', 'x', '1')
>>> solve_group([x**2 + y**2 - r, x + y], ["x", "y"], prefer=["y"]).variable
'y'
"""

from __future__ import annotations

import itertools
import random
from collections.abc import Callable, Iterable, Sequence
from typing import Any

import attrs
import flint

from ...errors import ComputationError, UsageError
from ..backends import FlintBackend
from ..linear import linear_elimination
from ..methods import prepare
from ..request import EliminationRequest
from .algebra import coefficients, linear_relation, primitive, primitive_scale, pseudo_remainder, univariate
from .records import GroupSolution, Lift, Polynomial, Values

__all__ = ["solve_group", "FORMS", "POINTS"]

FORMS = 3
"""Random linear forms tried when no unknown separates the solutions."""
POINTS = 4
"""Random rational points of the parameters tried for one where every factor keeps its degree."""


class _NotSeparating(Exception):
    """The variable tried does not separate the group's solutions (the message says why)."""


@attrs.frozen
class _Group:
    """The equations over one ring, the unknowns solved for, and the parameters (the ring's other names)."""

    equations: tuple[flint.fmpq_mpoly, ...]
    unknowns: tuple[str, ...]
    parameters: tuple[str, ...]

    def with_form(self, name: str, form: dict[str, int]) -> _Group:
        """The group with one more unknown, ``name``, equal to the linear form ``form``."""
        names = self.unknowns + (name,) + self.parameters
        ctx = flint.fmpq_mpoly_ctx.get(names, "lex")
        gens = dict(zip(names, ctx.gens()))
        equation = gens[name] - sum((c * gens[u] for u, c in form.items()), ctx.from_dict({}))
        moved = tuple(p.project_to_context(ctx) for p in self.equations)
        return _Group(moved + (equation,), self.unknowns + (name,), self.parameters)


def solve_group(equations: Sequence[flint.fmpq_mpoly], unknowns: Sequence[str], *,
                prefer: Sequence[str] | None = None, seed: int = 0) -> GroupSolution:
    """The rational univariate representation of the group of ``unknowns`` held by
    ``equations`` (python-flint ``fmpq_mpoly``, over any names: the other names are the
    parameters). The unknowns are tried as the separating variable in the order of ``prefer``
    (by default, as given), then random linear forms drawn from ``seed``.

    A UsageError if the equations are not as many as the unknowns; a ComputationError if the
    equations have no solution, or no variable tried separates their solutions.
    """
    group = _group(equations, unknowns)
    strays = [v for v in prefer or () if v not in group.unknowns]
    if strays:
        raise UsageError("prefer", list(prefer or ()), f"{', '.join(strays)}: not among the unknowns "
                         f"({', '.join(group.unknowns)})")
    rng = random.Random(seed)
    rejected: list[tuple[str, str]] = []
    for variable in prefer or group.unknowns:
        try:
            return attrs.evolve(_solve_by(group, variable, rng), rejected=tuple(rejected))
        except _NotSeparating as why:
            rejected.append((variable, str(why)))
    for _ in range(FORMS):
        form = {u: rng.choice((-1, 1)) * rng.randint(1, 9) for u in group.unknowns}
        name = _fresh("w", group.unknowns + group.parameters)
        try:
            solution = _solve_by(group.with_form(name, form), name, rng)
        except _NotSeparating as why:
            rejected.append((_written(form), str(why)))
            continue
        return attrs.evolve(solution, unknowns=group.unknowns, form=form, rejected=tuple(rejected))
    raise ComputationError(f"no variable separates the solutions of {', '.join(group.unknowns)}: "
                           + "; ".join(f"{v}: {why}" for v, why in rejected))


def _group(equations: Sequence[flint.fmpq_mpoly], unknowns: Sequence[str]) -> _Group:
    """The equations moved to one ring: the unknowns, then the other names they hold, in order of appearance."""
    if len(set(unknowns)) != len(unknowns):
        raise UsageError("unknowns", list(unknowns), "an unknown is named twice")
    if len(equations) != len(unknowns):
        raise UsageError("equations", len(equations), f"a group of {len(unknowns)} unknowns "
                         f"({', '.join(unknowns)}) needs as many equations")
    held = [str(n) for p in equations for n, d in zip(p.context().names(), p.degrees()) if d > 0]
    parameters = tuple(dict.fromkeys(n for n in held if n not in unknowns))
    ctx = flint.fmpq_mpoly_ctx.get(tuple(unknowns) + parameters, "lex")
    return _Group(tuple(p.project_to_context(ctx) for p in equations), tuple(unknowns), parameters)


def _fresh(stem: str, taken: Sequence[str]) -> str:
    name = stem
    while name in taken:
        name += "_"
    return name


def _written(form: dict[str, int]) -> str:
    return " + ".join(f"{c}*{u}" for u, c in form.items()).replace("+ -", "- ")


def _solve_by(group: _Group, variable: str, rng: random.Random) -> GroupSolution:
    """The representation with ``variable`` separating, or _NotSeparating."""
    home = flint.fmpq_mpoly_ctx.get((variable,) + group.parameters, "lex")
    eliminant = _eliminant(group, variable).project_to_context(home)
    others = [u for u in group.unknowns if u != variable]
    lifted = _relations(group, others, variable=variable, home=home, eliminant=eliminant)
    factored = _factored(eliminant, _hint(lifted.values(), home=home, bound=len(eliminant)))
    factors = [(f, m) for f, m in factored if f.degrees()[0] > 0]
    conditions = [f for f, _ in factored if f.degrees()[0] == 0]
    relations = {x: (r.a, r.b) for x, r in lifted.items()}
    try:
        genuine = _genuine(group, variable, factors=factors, relations=relations, rng=rng)
    except _NotSeparating:
        if all(r.holder is not None for r in lifted.values()):
            raise
        # a relation found through another unknown may fail where a direct one holds: decided on those
        relations = {x: (r.a, r.b) for x, r in ((x, _lift(group, x, variable=variable, home=home)) for x in others)}
        genuine = _genuine(group, variable, factors=factors, relations=relations, rng=rng)
    kept = [f for f, _ in factors if any(f is g for g in genuine)]
    product = home.from_dict({(0,) * len(home.names()): 1})
    for factor in kept:
        product *= factor
    lifts = tuple(_reduced(x, relations[x], eliminant=product, variable=variable) for x in others)
    dropped = [f for f, _ in factors if not any(f is g for g in genuine)] + conditions
    return GroupSolution(group.unknowns, group.parameters, variable, Polynomial.of(primitive(product)), lifts,
                         dropped=tuple(Polynomial.of(primitive(f)) for f in dropped))


def _eliminated(group: _Group, keep: tuple[str, ...]) -> list[flint.fmpq_mpoly]:
    """The equations left once every unknown but ``keep`` is eliminated (the ``linear`` method):
    the unknowns sharing the fewest equations with ``keep`` first (on the 3-RPR, the far
    platform joint before the kept joint's other coordinate: 7 ms, where the reverse takes 13 s)."""
    eliminate = tuple(sorted((u for u in group.unknowns if u not in keep), key=lambda u: _shared(group, u, keep)))
    backend = FlintBackend(eliminate + keep + group.parameters)
    request = EliminationRequest(eliminate, (), group.parameters)
    prepared = prepare(backend, [backend.from_flint(p) for p in group.equations], eliminate)
    outcome = linear_elimination(backend, prepared.left, request)
    return [p for p in outcome.left if not p.is_zero()]


def _shared(group: _Group, unknown: str, keep: tuple[str, ...]) -> int:
    """How many equations hold ``unknown`` and one of ``keep``."""
    names = group.equations[0].context().names()
    indices = [names.index(k) for k in keep]
    index = names.index(unknown)
    return sum(1 for p in group.equations if p.degrees()[index] and any(p.degrees()[k] for k in indices))


def _eliminant(group: _Group, variable: str) -> flint.fmpq_mpoly:
    """The eliminant in ``variable``: the gcd of what elimination leaves, or the least of them if coprime."""
    try:
        left = _eliminated(group, (variable,))
    except ComputationError as error:  # a resultant vanished or is a number: said of this group
        raise ComputationError(f"the equations of {', '.join(group.unknowns)}: {error}") from None
    if not left or any(p.is_constant() for p in left):
        raise ComputationError(f"the equations of {', '.join(group.unknowns)} have no solution")
    eliminant = left[0]
    for poly in left[1:]:
        eliminant = eliminant.gcd(poly)
    if eliminant.is_constant():
        eliminant = min(left, key=lambda p: (p.total_degree(), len(p)))
    return eliminant


@attrs.frozen
class _Relation:
    """``a*unknown + b`` in the ideal (``a``, ``b`` in the variable and the parameters, over
    ``home``), and ``holder``, the member of least degree in ``unknown`` of the ideal's
    elimination to ``unknown`` and the variable (in its own ring); None for a relation found
    through another unknown's."""

    unknown: str
    a: flint.fmpq_mpoly
    b: flint.fmpq_mpoly
    holder: flint.fmpq_mpoly | None


def _relations(group: _Group, others: Sequence[str], *, variable: str, home: flint.fmpq_mpoly_ctx,
               eliminant: flint.fmpq_mpoly) -> dict[str, _Relation]:
    """A relation linear in each of ``others``: the one sharing most equations with the
    variable (the base) directly, every other through the base where it can (the base kept
    in the elimination, then replaced by its lift): on the 3-RPR, P2's coordinates from the
    radical axes given P1, linear already, where eliminating P1's other coordinate too leaves
    relations twice the size that take three times as long. Where the base's lift is of high
    degree (a triad's, with its crank symbolic), the direct relations (``_through``)."""
    base = max(others, key=lambda x: _shared(group, x, (variable,)))
    direct = _lift(group, base, variable=variable, home=home)
    found = {x: _through(group, x, base=direct, variable=variable, home=home, eliminant=eliminant)
             for x in others if x != base}
    return {x: direct if x == base else found[x] or _lift(group, x, variable=variable, home=home) for x in others}


def _lift(group: _Group, unknown: str, *, variable: str, home: flint.fmpq_mpoly_ctx) -> _Relation:
    """The relation linear in ``unknown`` over ``variable`` and the parameters."""
    left = _eliminated(group, (unknown, variable))
    index = list(left[0].context().names()).index(unknown) if left else 0
    holders = sorted((p for p in left if p.degrees()[index] > 0), key=lambda p: (p.degrees()[index], len(p)))
    if holders and holders[0].degrees()[index] == 1:
        b, a = coefficients(holders[0], unknown)
        return _Relation(unknown, a.project_to_context(home), b.project_to_context(home), holders[-1])
    for first, second in itertools.combinations(holders, 2):  # the lowest degrees first
        first, second = _apart(first, second, index)
        relation = linear_relation(first, second, unknown)
        if relation is not None:
            return _Relation(unknown, relation[0].project_to_context(home), relation[1].project_to_context(home),
                             holders[0])
    raise _NotSeparating(f"no relation linear in {unknown} over {variable}")


def _apart(first: flint.fmpq_mpoly, second: flint.fmpq_mpoly, index: int) -> tuple[flint.fmpq_mpoly, flint.fmpq_mpoly]:
    """``first`` and ``second`` without their common factor in the unknown at ``index``: a
    multiplier elimination left in both (a Cramer step's), whose zeros are a curve, not the
    group's finitely many solutions; their remainder sequence would end at it, a relation
    false at every solution (five poses' Burmester equations: the centre on a line)."""
    common = first.gcd(second)
    if common.degrees()[index] == 0:
        return first, second
    return first / common, second / common


def _through(group: _Group, unknown: str, *, base: _Relation, variable: str, home: flint.fmpq_mpoly_ctx,
             eliminant: flint.fmpq_mpoly) -> _Relation | None:
    """The relation linear in ``unknown`` over the variable and ``base``'s unknown, with
    ``base = -b/a`` put in (both sides times ``a**d``, ``d`` their degree in it); None where
    elimination finds none, or where a content divided out on the way shares a factor in the
    variable with the ``eliminant`` (the relation might fail at a solution)."""
    try:
        left = _eliminated(group, (unknown, variable, base.unknown))
    except ComputationError:
        return None
    index = list(left[0].context().names()).index(unknown) if left else 0
    holders = sorted((p for p in left if p.degrees()[index] > 0), key=lambda p: (p.degrees()[index], len(p)))
    pairs = [(h, None) for h in holders[:1] if h.degrees()[index] == 1] + list(itertools.combinations(holders, 2))
    for first, second in pairs:
        contents: list[flint.fmpq_mpoly] = []
        relation = linear_relation(first, second, unknown, contents=contents) if second is not None else \
            tuple(reversed(coefficients(first, unknown)))
        if relation is None:
            continue
        if _degree_through(tuple(relation), base, variable) >= eliminant.degrees()[0]:
            return None  # longer to reduce modulo the eliminant than a direct relation (a triad's: 20 s)
        a, b = _substituted(tuple(relation), base)
        removed = [_substituted((c,), base)[0].project_to_context(home) for c in contents]
        if a.is_zero() or any(_meets(c, eliminant) for c in removed):
            return None
        return _Relation(unknown, a.project_to_context(home), b.project_to_context(home), None)
    return None


def _meets(content: flint.fmpq_mpoly, eliminant: flint.fmpq_mpoly) -> bool:
    """Whether ``content`` and ``eliminant`` (over one ring, the variable first) share a factor in the variable."""
    return content.is_zero() or content.gcd(eliminant).degrees()[0] > 0


def _degree_through(relation: tuple[flint.fmpq_mpoly, ...], base: _Relation, variable: str) -> int:
    """A bound on the degree in ``variable`` of ``relation`` with ``base`` put in (``_substituted``)."""
    names = list(relation[0].context().names())
    power = max(int(p.degrees()[names.index(base.unknown)]) for p in relation)
    own = max(int(p.degrees()[names.index(variable)]) for p in relation)
    return own + power * max(int(base.a.degrees()[0]), int(base.b.degrees()[0]))


def _substituted(relation: tuple[flint.fmpq_mpoly, ...], base: _Relation) -> tuple[flint.fmpq_mpoly, ...]:
    """The polynomials of ``relation`` with ``base``'s unknown ``-b/a`` put in, times the same power of ``a``."""
    ctx = relation[0].context()
    a, minus_b = base.a.project_to_context(ctx), -base.b.project_to_context(ctx)
    index = list(ctx.names()).index(base.unknown)
    power = max(int(p.degrees()[index]) for p in relation)
    done = []
    for poly in relation:
        parts = coefficients(poly, base.unknown)
        done.append(sum((part * minus_b**k * a**(power - k) for k, part in enumerate(parts)), ctx.from_dict({})))
    return tuple(done)


def _hint(relations: Iterable[_Relation], *, home: flint.fmpq_mpoly_ctx, bound: int) -> flint.fmpq_mpoly | None:
    """A polynomial in the variable and the parameters that the genuine part of the eliminant
    likely divides and its extraneous factors likely do not: the resultant in ``x`` of the
    smallest relation ``a*x + b`` with its holder of degree at most 2 (the holder at
    ``x = -b/a``; on the 3-RPR, the platform joint's circle at its lift: the sextic itself);
    None where there is none, or it is zero or larger than ``bound`` terms. Only a hint: it
    splits the eliminant before factoring (``_factored``), never decides a factor."""
    small = [r for r in relations
             if r.holder is not None and r.holder.degrees()[list(r.holder.context().names()).index(r.unknown)] <= 2]
    if not small:
        return None
    relation = min(small, key=lambda r: len(r.a) + len(r.b))
    assert relation.holder is not None
    ctx = relation.holder.context()
    x = ctx.gens()[list(ctx.names()).index(relation.unknown)]
    linear = relation.a.project_to_context(ctx) * x + relation.b.project_to_context(ctx)
    hint = relation.holder.resultant(linear, relation.unknown)
    return None if hint.is_zero() or len(hint) > bound else hint.project_to_context(home)


def _factored(eliminant: flint.fmpq_mpoly, hint: flint.fmpq_mpoly | None) -> list[tuple[flint.fmpq_mpoly, int]]:
    """The eliminant's irreducible factors with their multiplicities, as ``factor`` gives them;
    where ``hint`` splits it (their gcd a proper factor ``g``), the factors of ``g`` and of
    the cofactor merged: factoring two small polynomials costs a fifth of factoring their
    product (the 3-RPR's eliminant: its sextic and an extraneous octic)."""
    common = eliminant.gcd(hint) if hint is not None else None
    if common is None or common.is_constant() or common.degrees() == eliminant.degrees():
        return list(eliminant.factor()[1])
    merged: dict[str, tuple[flint.fmpq_mpoly, int]] = {}
    for part in (common, eliminant / common):
        for factor, multiplicity in part.factor()[1]:
            key = str(_monic(factor))
            merged[key] = (merged[key][0], merged[key][1] + multiplicity) if key in merged else (factor, multiplicity)
    return list(merged.values())


def _monic(poly: flint.fmpq_mpoly) -> flint.fmpq_mpoly:
    return poly / poly.leading_coefficient()


def _genuine(group: _Group, variable: str, *, factors: list[tuple[flint.fmpq_mpoly, int]],
             relations: dict[str, tuple[flint.fmpq_mpoly, flint.fmpq_mpoly]],
             rng: random.Random) -> list[flint.fmpq_mpoly]:
    """The factors whose roots are solutions, decided at a random rational point of the
    parameters where every factor keeps its degree; _NotSeparating if a lift is undefined on a
    factor or a genuine factor is repeated."""
    for _ in range(POINTS):
        point: Values = {p: rng.choice((-1, 1)) * rng.randint(2, 999) for p in group.parameters}
        special = [univariate(f.subs(point), variable) for f, _ in factors]
        if all(s.degree() == f.degrees()[0] for s, (f, _) in zip(special, factors)):
            break
    else:
        raise ComputationError(f"no point of {', '.join(group.parameters)} keeps the eliminant's degree")
    lifted = {x: (univariate(a.subs(point), variable), univariate(b.subs(point), variable))
              for x, (a, b) in relations.items()}
    equations = [e.subs(point) for e in group.equations]
    genuine = []
    for (factor, multiplicity), modulus in zip(factors, special):
        if _solves(equations, variable, lifted=lifted, modulus=modulus):
            if multiplicity > 1:
                raise _NotSeparating(f"a factor of degree {modulus.degree()} of its eliminant is repeated")
            genuine.append(factor)
    if not genuine:
        raise ComputationError(f"the equations of {', '.join(group.unknowns)} have no solution")
    return genuine


def _solves(equations: Sequence[flint.fmpq_mpoly], variable: str, *,
            lifted: dict[str, tuple[flint.fmpq_poly, flint.fmpq_poly]], modulus: flint.fmpq_poly) -> bool:
    """Whether the lifts satisfy every equation modulo ``modulus`` (over QQ, at the point);
    a factor that a prime shows they do not is answered there (``_fails_modulo``)."""
    if _fails_modulo(equations, variable, lifted=lifted, modulus=modulus):
        return False
    values = {variable: flint.fmpq_poly([0, 1]) % modulus}
    for x, (a, b) in lifted.items():
        common, inverse, _ = a.xgcd(modulus)
        if common.degree() > 0 or common.is_zero():
            raise _NotSeparating(f"{x} is not a function of {variable} on a factor of degree {modulus.degree()}")
        values[x] = -b * inverse % modulus
    return all(_residue(e, values, modulus).is_zero() for e in equations)


def _fails_modulo(equations: Sequence[flint.fmpq_mpoly], variable: str, *,
                  lifted: dict[str, tuple[flint.fmpq_poly, flint.fmpq_poly]], modulus: flint.fmpq_poly) -> bool:
    """Whether, modulo the prime ``PRIME``, every lift's denominator is invertible modulo
    ``modulus`` and some equation's residue is not zero: then so over QQ (a common factor over
    QQ stays one modulo a prime that keeps the degrees; a residue zero over QQ is zero modulo
    any), and the factor is no solution, decided without the exact inverses (an extraneous
    factor's: five milliseconds on the 3-RPR). False at a prime that divides a denominator or a
    leading coefficient, or shows nothing: the exact check decides."""
    image = _image(modulus)
    if image is None or image.degree() != modulus.degree():
        return False
    values = {variable: flint.nmod_poly([0, 1], PRIME) % image}
    for x, (a, b) in lifted.items():
        a_image, b_image = _image(a), _image(b)
        if a_image is None or b_image is None:
            return False
        common, inverse, _ = a_image.xgcd(image)
        if common.degree() != 0:
            return False
        values[x] = -b_image * inverse % image
    residues = [_residue(e, values, image, constant=_constant) for e in equations]
    return None not in residues and any(not r.is_zero() for r in residues if r is not None)


PRIME = 2**61 - 1
"""The prime of ``_fails_modulo`` (a Mersenne prime, the largest below a machine word)."""


def _image(poly: flint.fmpq_poly) -> flint.nmod_poly | None:
    """``poly`` modulo ``PRIME``; None where the prime divides a denominator."""
    coefficients_ = []
    for c in poly.coeffs():
        denominator = int(c.q) % PRIME
        if denominator == 0:
            return None
        coefficients_.append(int(c.p) * pow(denominator, -1, PRIME) % PRIME)
    return flint.nmod_poly(coefficients_, PRIME)


def _constant(value: flint.fmpq) -> flint.nmod_poly | None:
    return _image(flint.fmpq_poly([value]))


def _residue(poly: flint.fmpq_mpoly, values: dict[str, Any], modulus: Any, *,
             constant: Callable[[flint.fmpq], Any] = lambda c: flint.fmpq_poly([c])) -> Any:
    """``poly`` (in the unknowns alone) at ``values``, modulo ``modulus`` (``fmpq_poly``, or
    ``nmod_poly`` with ``constant`` the image of a coefficient; None if one has none)."""
    names = [str(n) for n in poly.context().names()]
    total = None
    for monomial, coefficient in zip(poly.monoms(), poly.coeffs()):
        term = constant(coefficient)
        if term is None:
            return None
        for name, exponent in zip(names, monomial):
            for _ in range(exponent):
                term = term * values[name] % modulus
        total = term if total is None else total + term
    return (constant(flint.fmpq(0)) if total is None else total) % modulus


def _reduced(unknown: str, relation: tuple[flint.fmpq_mpoly, flint.fmpq_mpoly], *, eliminant: flint.fmpq_mpoly,
             variable: str) -> Lift:
    """The lift ``-b/a`` with both reduced modulo the eliminant (pseudo-remainders under a
    common power of its leading coefficient, so the ratio holds at its roots), and cancelled."""
    a, b = relation
    numerator, denominator = -b, a
    degree = eliminant.degrees()[0]
    if max(numerator.degrees()[0], denominator.degrees()[0]) >= degree:
        power = max(numerator.degrees()[0], denominator.degrees()[0]) - degree + 1
        numerator = pseudo_remainder(numerator, eliminant, variable, power=power)
        denominator = pseudo_remainder(denominator, eliminant, variable, power=power)
    common = numerator.gcd(denominator)
    if not common.is_constant():
        numerator, denominator = numerator / common, denominator / common
    scale = primitive_scale(denominator)
    return Lift(unknown, Polynomial.of(numerator * scale), Polynomial.of(denominator * scale))
