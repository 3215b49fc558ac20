"""Path generation: a four-bar whose coupler point passes through five given points, both
ground pivots given (Morgan and Wampler 1990: 36 solutions in general), solved completely by
elimination and every real solution certified.

The coupler point P is at ``P_j`` (j = 0..4) with the coupler turned by ``theta_j`` from its
place at ``P_0`` (``theta_0 = 0``). A dyad with ground pivot ``A`` has its moving pivot at
``P_j + R(theta_j) z``, ``z`` fixed in the coupler; it keeps its length when
``|P_j + R(theta_j) z - A|**2 = |P_0 + z - A|**2``, an equation LINEAR in ``z`` once
``cos**2 + sin**2 = 1`` (``|z|**2`` cancels): with ``d_j = P_j - A``,

    ``(d_j^T R_j - d_0^T) z + (|d_j|**2 - |d_0|**2) / 2 = 0``,   j = 1..4,

four rows ``[row_j | constant]`` of a 4x3 matrix that has rank 2 at a solution; the same for
the rocker's dyad, with pivot ``B`` and its own ``z``. The twelve equations in
``c_j, s_j`` (cos and sin of ``theta_j``) and both ``z`` (``system``) have 36 solutions for
general data.

Elimination (``five_point_path``): with half-angle tangents ``t_j`` (about an ``offset``
rotation) each row is quadratic in its ``t_j``, and rank 2 is ``det(rows 1, 2, 3) = 0`` and
``det(rows 1, 2, 4) = 0`` for each dyad, four equations in ``t_1..t_4``. Their resultants in
``t_3`` and in ``t_4`` are of degree (8, 8) in ``(t_1, t_2)``, each ``(1 + t_1**2)(1 + t_2**2)``
(the circle points) times a part of degree (6, 6); the resultant of those two parts in ``t_2``
is the eliminant, of degree 72 in ``t_1``. For general data its factors are one of degree 36,
the solutions, and spurious ones, each excluded with its reason (``Excluded``): the circle
points ``1 + t_1**2`` (to the 9th power), the two points where a dyad's rows 1 and 2 are
dependent (to the 4th: its joint is undetermined there, and every ``t_3, t_4`` satisfy its two
equations), and a quadratic where ``t_3`` is at a circle point. On special data more (five
points on a line: ``t_1 = 0``, where the crank's joint is undetermined).

Each factor is decided by lifting its roots: ``t_2`` from a relation linear in it (the
resultants' pseudo-remainder sequence), ``t_3`` and ``t_4`` each the common root of two
quadratics, each ``z`` the kernel of its dyad's rows 1 and 2. Where none of the divisors on the
way vanishes at the factor's roots, they are solutions (``_values`` says why); that is decided
modulo a prime where it shows every divisor invertible (a proof), exactly over QQ otherwise,
and the lifts are checked in the twelve equations of ``system``. The real roots of the
solution factors, isolated in certified balls (``algkin.system.roots``), give every real
four-bar, each value a certified ball computed by the same lift.

Beyond five points (``path_synthesis``): with both pivots given the problem is overdetermined,
and its solutions are those of the first five points' that reach every further point. Each
solution factor is decided whole, exactly: at a further point ``P_j`` both dyads' rows are linear
in ``cos, sin`` of ``theta_j``, so they give ``theta_j`` in the factor's number field ``Q[t1]/(f)``,
and the factor's roots reach ``P_j`` exactly when ``cos**2 + sin**2 - 1`` is zero there (a
field: for all its roots or for none). General data then have no solution, which is an answer.

>>> from flint import fmpq
>>> points = [(fmpq(x), fmpq(y)) for x, y in [(3, -2), (7, 5), (-4, 9), (11, -6), (2, 13)]]
>>> result = five_point_path(points, crank_pivot=(fmpq(-5), fmpq(1)), rocker_pivot=(fmpq(8), fmpq(-3)))
>>> result.complex_count, result.real_count, result.size.resultant_degree
(36, 22, 72)
>>> [(e.degree, e.multiplicity) for e in result.excluded]
[(2, 1), (2, 4), (2, 4), (2, 9)]
"""

from __future__ import annotations

import itertools
from collections.abc import Callable, Sequence
from typing import Generic, TypeVar

import attrs
import flint

from ..eliminate.group.algebra import coefficients, linear_relation
from ..errors import ComputationError, UsageError
from ..system.roots import RealRoot, real_roots, refined_together
from .data import Angle, Point

__all__ = ["five_point_path", "path_synthesis", "system", "PathSynthesis", "PathSolution", "Excluded", "Size", "UNKNOWNS",
           "GENERIC_COUNT", "OFFSETS"]

GENERIC_COUNT = 36
"""Complex solutions of the five-point problem for general data (Morgan and Wampler 1990)."""

UNKNOWNS = ("c1", "s1", "c2", "s2", "c3", "s3", "c4", "s4", "xa", "ya", "xb", "yb")
"""The unknowns of ``system``: cos and sin of each turn, then the crank's and the rocker's ``z``."""

OFFSETS = (Angle(flint.fmpq(1), flint.fmpq(0)), Angle.of_tan_half(flint.fmpq(3, 7)),
           Angle.of_tan_half(flint.fmpq(-5, 11)))
"""The rotations the half-angle tangents are taken about, tried in turn: a turn of exactly the
offset plus 180 degrees has no finite tangent, and is found about the next one."""

_TANGENTS = ("t1", "t2", "t3", "t4")
_CTX = flint.fmpq_mpoly_ctx.get(_TANGENTS, "lex")

Row = tuple[flint.fmpq_mpoly, flint.fmpq_mpoly, flint.fmpq_mpoly]
Ball2 = tuple[flint.arb, flint.arb]


@attrs.frozen
class Excluded:
    """A factor of the eliminant left out: its ``degree`` in ``t1``, its ``multiplicity`` in the
    eliminant, the ``factor`` itself (sympy syntax) and the ``reason`` its roots are no solutions."""

    degree: int
    multiplicity: int
    factor: str
    reason: str


@attrs.frozen
class Size:
    """The elimination's sizes: the ``intermediate`` resultants' degrees in ``(t1, t2)``, once
    the circle points are divided out; the eliminant's degree in ``t1``, its terms and the bits of
    its largest integer coefficient (made primitive); the degree of its solution factors."""

    intermediate: tuple[int, int]
    resultant_degree: int
    resultant_terms: int
    resultant_bits: int
    solution_degree: int


@attrs.frozen
class PathSolution:
    """One real four-bar. ``root``: its identity, exactly: ``t1``, the half-angle tangent of
    ``theta_1`` about the synthesis' ``offset`` (its irreducible factor and rank among its real
    roots). In certified balls: ``rotations``, ``(cos, sin)`` of ``theta_1`` to the last point's; the moving
    pivots when the coupler point is at ``P_0`` (fixed frame); the link lengths."""

    root: RealRoot
    rotations: tuple[Ball2, ...] = attrs.field(eq=False)
    crank_joint: Ball2 = attrs.field(eq=False)
    rocker_joint: Ball2 = attrs.field(eq=False)
    crank: flint.arb = attrs.field(eq=False)
    coupler: flint.arb = attrs.field(eq=False)
    rocker: flint.arb = attrs.field(eq=False)


@attrs.frozen
class PathSynthesis:
    """Every four-bar through the ``points`` (five or more) with the given pivots: the real ones
    (``solutions``, ascending in ``t1``; ``real_count`` of them), the number of complex ones
    (``complex_count``, each once), the factors of the eliminant left out and why (``excluded``), the sizes (``size``)
    and the rotation the half-angle tangents are taken about (``offset``)."""

    points: tuple[Point, ...]
    crank_pivot: Point
    rocker_pivot: Point
    solutions: tuple[PathSolution, ...]
    complex_count: int
    real_count: int
    excluded: tuple[Excluded, ...]
    size: Size
    offset: Angle


def system(points: Sequence[Point], *, crank_pivot: Point, rocker_pivot: Point
           ) -> tuple[list[flint.fmpq_mpoly], list[str]]:
    """The twelve equations over QQ in ``UNKNOWNS`` (the circles ``c_j**2 + s_j**2 = 1``, then
    the crank's rows, then the rocker's), with their unknowns' names: 36 solutions in general.

    >>> from flint import fmpq
    >>> points = [(fmpq(k), fmpq(k * k)) for k in range(5)]
    >>> equations, names = system(points, crank_pivot=(fmpq(0), fmpq(-1)), rocker_pivot=(fmpq(3), fmpq(0)))
    >>> len(equations), names[:2], str(equations[4])  # d_1 = (1, 2), d_0 = (0, 1): (c + 2s) xa + (2c - s - 1) ya + 2
    (12, ['c1', 's1'], 'c1*xa + 2*c1*ya + 2*s1*xa - s1*ya - ya + 2')
    """
    _validate(points, crank_pivot, rocker_pivot)
    ctx = flint.fmpq_mpoly_ctx.get(UNKNOWNS, "lex")
    gens = dict(zip(UNKNOWNS, ctx.gens()))
    circles = [gens[f"c{j}"] ** 2 + gens[f"s{j}"] ** 2 - 1 for j in range(1, 5)]
    rows = [_row(points, j, pivot, (gens[f"c{j}"], gens[f"s{j}"]), gens[f"x{name}"], gens[f"y{name}"])
            for pivot, name in ((crank_pivot, "a"), (rocker_pivot, "b")) for j in range(1, 5)]
    return circles + rows, list(UNKNOWNS)


def _row(points: Sequence[Point], j: int, pivot: Point, turn: tuple[flint.fmpq_mpoly, flint.fmpq_mpoly],
         x: flint.fmpq_mpoly, y: flint.fmpq_mpoly) -> flint.fmpq_mpoly:
    """``(d_j^T R_j - d_0^T) z + (|d_j|**2 - |d_0|**2) / 2`` with ``d = P - pivot``, ``z = (x, y)``."""
    (dx, dy), (ex, ey) = _minus(points[j], pivot), _minus(points[0], pivot)
    c, s = turn
    return (dx * c + dy * s - ex) * x + (dy * c - dx * s - ey) * y + (dx * dx + dy * dy - ex * ex - ey * ey) / 2


def _minus(p: Point, q: Point) -> Point:
    return p[0] - q[0], p[1] - q[1]


def _validate(points: Sequence[Point], crank_pivot: Point, rocker_pivot: Point, *, more: bool = False) -> None:
    """A UsageError unless there are five distinct points (five or more with ``more``) and two distinct pivots."""
    if len(points) < 5 or (len(points) > 5 and not more):
        raise UsageError("points", len(points), "path synthesis with both pivots given needs at least five points"
                         if more else "the five-point problem needs exactly five points")
    for (i, p), (k, q) in itertools.combinations(enumerate(points), 2):
        if p == q:
            raise UsageError("points", _text(p), f"points {i} and {k} are equal")
    if crank_pivot == rocker_pivot:
        raise UsageError("rocker_pivot", _text(rocker_pivot), "equal to the crank's pivot")


def _text(p: Point) -> str:
    return f"({p[0]}, {p[1]})"


def five_point_path(points: Sequence[Point], *, crank_pivot: Point, rocker_pivot: Point,
                    bits: int = 128) -> PathSynthesis:
    """Every four-bar with ground pivots ``crank_pivot`` and ``rocker_pivot`` whose coupler
    point passes through the five ``points`` (exact), its real ones in balls computed at
    ``bits``. The tangents are taken about each of ``OFFSETS`` in turn until one gives
    ``GENERIC_COUNT`` solutions (then all: special data have at most as many isolated solutions
    as general data); otherwise (special data) the first offset that gives the most."""
    points, crank_pivot, rocker_pivot = _exact(points, crank_pivot, rocker_pivot)
    _validate(points, crank_pivot, rocker_pivot)
    best = _best(points, crank_pivot, rocker_pivot)
    return _synthesis(points, crank_pivot, rocker_pivot, best, best.factors, best.excluded, bits=bits)


def path_synthesis(points: Sequence[Point], *, crank_pivot: Point, rocker_pivot: Point,
                   bits: int = 128) -> PathSynthesis:
    """Every four-bar with ground pivots ``crank_pivot`` and ``rocker_pivot`` whose coupler point
    passes through the ``points`` (five or more, exact): five as ``five_point_path``; more, those
    of the first five's solutions whose factors reach every further point (each factor left out
    says the first point it misses). General data past five points have none: an answer.

    >>> from flint import fmpq
    >>> points = [(fmpq(x), fmpq(y)) for x, y in [(3, -2), (7, 5), (-4, 9), (11, -6), (2, 13), (1, 1)]]
    >>> result = path_synthesis(points, crank_pivot=(fmpq(-5), fmpq(1)), rocker_pivot=(fmpq(8), fmpq(-3)))
    >>> result.complex_count, result.real_count, [e.reason for e in result.excluded][-1]
    (0, 0, 'the solutions through the first five points miss point 5')
    """
    points, crank_pivot, rocker_pivot = _exact(points, crank_pivot, rocker_pivot)
    _validate(points, crank_pivot, rocker_pivot, more=True)
    if len(points) == 5:
        return five_point_path(points, crank_pivot=crank_pivot, rocker_pivot=rocker_pivot, bits=bits)
    try:
        best = _best(points[:5], crank_pivot, rocker_pivot)
    except ComputationError as err:  # the first five alone are special: other five first may not be
        raise ComputationError(f"the first five points: {err}; give the points in another order "
                               "(the first five are solved, the others decided)") from None
    kept, excluded = [], list(best.excluded)
    for factor, multiplicity in zip(best.factors, best.multiplicities):
        missed = _first_missed(factor, best.chain, points, (crank_pivot, rocker_pivot))
        if missed is None:
            kept.append(factor)
        else:
            excluded.append(Excluded(factor.degree(), multiplicity, _written(factor),
                                     f"the solutions through the first five points miss point {missed}"))
    return _synthesis(points, crank_pivot, rocker_pivot, best, tuple(kept),
                      tuple(sorted(excluded, key=lambda e: (e.degree, e.multiplicity))), bits=bits)


def _exact(points: Sequence[Point], crank_pivot: Point, rocker_pivot: Point
           ) -> tuple[tuple[Point, ...], Point, Point]:
    return (tuple((flint.fmpq(x), flint.fmpq(y)) for x, y in points),
            (flint.fmpq(crank_pivot[0]), flint.fmpq(crank_pivot[1])),
            (flint.fmpq(rocker_pivot[0]), flint.fmpq(rocker_pivot[1])))


def _best(points: tuple[Point, ...], crank_pivot: Point, rocker_pivot: Point) -> _Solved:
    """The five points' elimination about each of ``OFFSETS`` in turn until one gives
    ``GENERIC_COUNT`` solutions; otherwise (special data) the first that gives the most."""
    best: _Solved | None = None
    for offset in OFFSETS:
        solved = _solve(points, crank_pivot, rocker_pivot, offset)
        if best is None or solved.count > best.count:
            best = solved
        if solved.count == GENERIC_COUNT:  # no data have more isolated solutions than general ones
            break
    assert best is not None
    return best


def _synthesis(points: tuple[Point, ...], crank_pivot: Point, rocker_pivot: Point, best: _Solved,
               factors: tuple[flint.fmpq_poly, ...], excluded: tuple[Excluded, ...], *, bits: int) -> PathSynthesis:
    """The result with the solutions of ``factors``, the real ones in balls."""
    solutions = [s for factor in factors
                 for s in _real_solutions(factor, best.chain, points, crank_pivot, rocker_pivot, bits=bits)]
    return PathSynthesis(points, crank_pivot, rocker_pivot, tuple(sorted(solutions, key=_order)),
                         sum(f.degree() for f in factors), len(solutions), excluded, best.size, best.chain.offset)


def _order(solution: PathSolution) -> flint.fmpq:
    return solution.root.interval()[0]


@attrs.frozen
class _Solved:
    """The elimination about one offset: the ``chain`` the lift works from, the solution ``factors``
    of the eliminant (irreducible in t1), the others ``excluded``."""

    chain: _Chain
    factors: tuple[flint.fmpq_poly, ...]
    multiplicities: tuple[int, ...]  # each factor's in the eliminant
    excluded: tuple[Excluded, ...]
    size: Size

    @property
    def count(self) -> int:
        return sum(f.degree() for f in self.factors)


class _NoLift(Exception):
    """The roots of a factor do not lift to a solution (the message says why)."""


def _solve(points: tuple[Point, ...], crank_pivot: Point, rocker_pivot: Point, offset: Angle) -> _Solved:
    """The eliminant in ``t1`` with the tangents about ``offset``, its factors lifted or excluded."""
    t = _CTX.gens()
    crank = [_tangent_row(points, j, crank_pivot, t[j - 1], offset) for j in range(1, 5)]
    rocker = [_tangent_row(points, j, rocker_pivot, t[j - 1], offset) for j in range(1, 5)]
    dets = {(name, k): _det(rows[0], rows[1], rows[k]) for name, rows in (("crank", crank), ("rocker", rocker))
            for k in (2, 3)}
    third = _without_circles(dets["crank", 2].resultant(dets["rocker", 2], "t3"))
    fourth = _without_circles(dets["crank", 3].resultant(dets["rocker", 3], "t4"))
    eliminant = third.resultant(fourth, "t2")
    if eliminant.is_zero():
        raise ComputationError("the path equations share a curve of solutions: the data are special")
    reasons = _spurious(crank, rocker)
    leads = (_univariate(coefficients(third, "t2")[-1]), _univariate(coefficients(fourth, "t2")[-1]))
    chain = _Chain(offset, {"crank": crank, "rocker": rocker}, dets, _relation(third, fourth), leads)
    equations, _ = system(points, crank_pivot=crank_pivot, rocker_pivot=rocker_pivot)
    lifted, multiplicities, excluded = [], [], []
    for factor, multiplicity in eliminant.factor()[1]:
        modulus = _univariate(factor)
        try:
            _lift(modulus, chain, equations)
            lifted.append(modulus)
            multiplicities.append(int(multiplicity))
        except _NoLift as why:
            known = [reason for test, reason in reasons if test(modulus)][:1]  # the first: the circle
            # points' factor divides the dependent rows' polynomials too
            excluded.append(Excluded(modulus.degree(), int(multiplicity), _written(modulus),
                                     "; ".join(known + [str(why)])))
    size = Size((int(third.degrees()[0]), int(third.degrees()[1])), int(eliminant.degrees()[0]), len(eliminant),
                _bits(_univariate(eliminant)), sum(f.degree() for f in lifted))
    return _Solved(chain, tuple(lifted), tuple(multiplicities),
                   tuple(sorted(excluded, key=lambda e: (e.degree, e.multiplicity))), size)


def _tangent_row(points: Sequence[Point], j: int, pivot: Point, t: flint.fmpq_mpoly, offset: Angle) -> Row:
    """The row of pose ``j`` with ``cos, sin`` of its turn the offset turned by the angle of
    half-angle tangent ``t``, times ``1 + t**2`` (a polynomial, quadratic in ``t``)."""
    (dx, dy), (ex, ey) = _minus(points[j], pivot), _minus(points[0], pivot)
    w = 1 + t * t
    c, s = offset.rotate(1 - t * t, 2 * t)
    return dx * c + dy * s - ex * w, dy * c - dx * s - ey * w, (dx * dx + dy * dy - ex * ex - ey * ey) / 2 * w


def _det(a: Row, b: Row, c: Row) -> flint.fmpq_mpoly:
    return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0])


def _without_circles(resultant: flint.fmpq_mpoly) -> flint.fmpq_mpoly:
    """The resultant with its factors ``1 + t1**2``, ``1 + t2**2`` divided out (a circle point:
    no angle there): a ComputationError if another factor holds one tangent alone (special data)."""
    if resultant.is_zero():
        raise ComputationError("a dyad's two conditions share a factor: the data are special")
    kept = _CTX.from_dict({(0, 0, 0, 0): 1})
    for factor, multiplicity in resultant.factor()[1]:
        degrees = factor.degrees()
        if degrees[0] and degrees[1]:
            kept *= factor ** int(multiplicity)
        elif not any(factor / factor.leading_coefficient() == 1 + g * g for g in _CTX.gens()[:2]) \
                and not factor.is_constant():
            raise ComputationError(f"a resultant has the factor {factor} in one angle alone: the data are special")
    return kept


def _spurious(crank: list[Row], rocker: list[Row]) -> list[tuple[Callable[[flint.fmpq_poly], bool], str]]:
    """Tests of a factor of the eliminant, each with the reason its roots are no solutions."""
    circle = flint.fmpq_poly([1, 0, 1])
    tests: list[tuple[Callable[[flint.fmpq_poly], bool], str]] = [
        (lambda q: (circle % q).is_zero(), "theta_1 at a circle point (1 + t1**2 = 0): no angle")]
    for name, rows in (("crank", crank), ("rocker", rocker)):
        tests.append((_divides(_dependent(rows[0], rows[1])),
                      f"the {name}'s rows at theta_1, theta_2 are dependent: its joint is undetermined"))
    return tests


def _divides(poly: flint.fmpq_poly) -> Callable[[flint.fmpq_poly], bool]:
    """Whether a factor divides ``poly``."""
    return lambda factor: (poly % factor).is_zero()


def _dependent(a: Row, b: Row) -> flint.fmpq_poly:
    """The polynomial in ``t1`` whose roots are the ``t1`` of the points where rows ``a`` and
    ``b`` are dependent (their 2x2 minors vanish together)."""
    minors = [a[i] * b[k] - a[k] * b[i] for i, k in ((0, 1), (0, 2), (1, 2))]
    common = minors[0].resultant(minors[1], "t2").gcd(minors[0].resultant(minors[2], "t2"))
    return _univariate(common) if not common.is_zero() else flint.fmpq_poly([0])


def _univariate(poly: flint.fmpq_mpoly) -> flint.fmpq_poly:
    """``poly``, in ``t1`` alone, as an ``fmpq_poly``."""
    parts = coefficients(poly, "t1")
    return flint.fmpq_poly([p.coeffs()[0] if not p.is_zero() else 0 for p in parts])


def _primitive(poly: flint.fmpq_poly) -> flint.fmpz_poly:
    integer = poly.numer()
    content = flint.fmpz(0)
    for c in integer.coeffs():
        content = content.gcd(c)
    integer = flint.fmpz_poly([c // content for c in integer.coeffs()])
    return -integer if integer.coeffs()[-1] < 0 else integer


def _written(poly: flint.fmpq_poly) -> str:
    """``poly``, primitive, in ``t1`` and sympy's syntax."""
    ctx = flint.fmpz_mpoly_ctx.get(("t1",), "lex")
    return str(ctx.from_dict({(k,): c for k, c in enumerate(_primitive(poly).coeffs()) if c})).replace("^", "**")


def _bits(poly: flint.fmpq_poly) -> int:
    return max(int(abs(c)).bit_length() for c in _primitive(poly).coeffs())


# The lift. The same formulas give every unknown from t1 in three kinds of numbers: residues
# modulo a factor of the eliminant over a prime field (fast: deciding the factor), the same over
# QQ (exact, where the prime decides nothing), and balls at a real root (the solutions' values).

P = TypeVar("P", flint.nmod_poly, flint.fmpq_poly)

PRIME = 2**61 - 1
"""The prime of the fast decision: a value invertible modulo the image of a factor there is
not zero modulo the factor over QQ (a factor dividing it would have its image divide the image)."""


@attrs.frozen(eq=False)
class _Residue(Generic[P]):
    """A polynomial in t1 modulo ``modulus`` (over the prime field or over QQ)."""

    value: P
    modulus: P

    def __add__(self, other: _Residue[P]) -> _Residue[P]:
        return _Residue((self.value + other.value) % self.modulus, self.modulus)

    def __sub__(self, other: _Residue[P]) -> _Residue[P]:
        return _Residue((self.value - other.value) % self.modulus, self.modulus)

    def __mul__(self, other: _Residue[P]) -> _Residue[P]:
        return _Residue(self.value * other.value % self.modulus, self.modulus)

    def __neg__(self) -> _Residue[P]:
        return _Residue(-self.value % self.modulus, self.modulus)

    def __truediv__(self, other: _Residue[P]) -> _Residue[P]:
        common, inverse, _ = other.value.xgcd(self.modulus)  # common: monic, 1 where invertible
        if common.degree() != 0:
            raise _NoLift("a division by a value that is not invertible")
        return _Residue(self.value * inverse % self.modulus, self.modulus)

    def invertible(self) -> bool:
        return self.value.gcd(self.modulus).degree() == 0


E = TypeVar("E", _Residue[flint.nmod_poly], _Residue[flint.fmpq_poly], flint.arb)


@attrs.frozen(eq=False)
class _Chain:
    """What the lift works from: the rows of each dyad in the tangents, the determinants that
    vanish at a solution (``(dyad, k)``: rows 1, 2 and k + 1), the linear relation in t2 and the
    leading coefficients in t2 of the two resultants it comes from (univariate in t1)."""

    offset: Angle
    rows: dict[str, list[Row]]
    dets: dict[tuple[str, int], flint.fmpq_mpoly]
    relation: _Relation | None
    leads: tuple[flint.fmpq_poly, flint.fmpq_poly]


@attrs.frozen
class _Relation:
    """``a*t2 + b``, free of t2, in the ideal of the two resultants in ``t1, t2``, where none of
    the ``contents`` divided out on the way vanishes."""

    a: flint.fmpq_poly
    b: flint.fmpq_poly
    contents: tuple[flint.fmpq_poly, ...]


def _relation(third: flint.fmpq_mpoly, fourth: flint.fmpq_mpoly) -> _Relation | None:
    contents: list[flint.fmpq_mpoly] = []
    found = linear_relation(third, fourth, "t2", contents=contents)
    if found is None:
        return None
    a, b = found
    return _Relation(_univariate(a), _univariate(b), tuple(_univariate(c) for c in contents))


def _values(chain: _Chain, t1: E, number: Callable[[flint.fmpq], E], nonzero: Callable[[E], bool]
            ) -> dict[str, E]:
    """Every unknown of ``system`` at ``t1`` (a root of a factor of the eliminant): ``t2`` from the
    linear relation, ``t3`` and ``t4`` each the common root of two determinants quadratic in it,
    ``cos, sin`` from the tangents, each ``z`` the kernel of its dyad's rows 1 and 2. A _NoLift
    where ``nonzero`` cannot tell a divisor from 0 (each ``_NoLift`` says which).

    Where every one is nonzero, the values solve ``system``: the relation's ``t2`` is the common
    root of the two resultants (one of their leading coefficients nonzero), so the two
    determinants in ``t3`` have a common root, ``t3`` (and so for ``t4``); rows 3 and 4 of each
    dyad are then in the span of rows 1 and 2, whose kernel has a last entry nonzero."""
    relation = chain.relation
    assert relation is not None
    if not (nonzero(_at(chain.leads[0], t1, number)) or nonzero(_at(chain.leads[1], t1, number))):
        raise _NoLift("t2 is infinite: both resultants drop their degree in it")
    a = _at(relation.a, t1, number)
    if not nonzero(a):
        raise _NoLift("t2 is undetermined or infinite: its coefficient in the linear relation vanishes")
    tangents = {"t1": t1, "t2": -_at(relation.b, t1, number) / a}
    for var, k in (("t3", 2), ("t4", 3)):
        f, g = (_padded([_evaluated(c, tangents, number) for c in coefficients(chain.dets[dyad, k], var)], number)
                for dyad in ("crank", "rocker"))
        coefficient = f[2] * g[1] - g[2] * f[1]
        if not nonzero(coefficient):
            raise _NoLift(f"{var} is undetermined or infinite (a turn of the offset plus 180 degrees)")
        tangents[var] = -(f[2] * g[0] - g[2] * f[0]) / coefficient
    one = number(flint.fmpq(1))
    values: dict[str, E] = {}
    for j in range(1, 5):
        t = tangents[f"t{j}"]
        norm = one + t * t
        if not nonzero(norm):
            raise _NoLift(f"theta_{j} at a circle point (1 + t{j}**2 = 0)")
        c, s = (one - t * t) / norm, (t + t) / norm
        values[f"c{j}"] = number(chain.offset.cos) * c - number(chain.offset.sin) * s
        values[f"s{j}"] = number(chain.offset.sin) * c + number(chain.offset.cos) * s
    for dyad, name in (("crank", "a"), ("rocker", "b")):
        first, second = ([_evaluated(entry, tangents, number) for entry in row] for row in chain.rows[dyad][:2])
        kernel = [first[i] * second[k] - first[k] * second[i] for i, k in ((1, 2), (2, 0), (0, 1))]
        if not nonzero(kernel[2]):
            raise _NoLift(f"the {dyad}'s joint is undetermined or at infinity (its rows at theta_1, theta_2 "
                          "are dependent)")
        values[f"x{name}"], values[f"y{name}"] = kernel[0] / kernel[2], kernel[1] / kernel[2]
    return values


def _padded(parts: list[E], number: Callable[[flint.fmpq], E]) -> list[E]:
    return parts + [number(flint.fmpq(0))] * (3 - len(parts))


def _at(poly: flint.fmpq_poly, t: E, number: Callable[[flint.fmpq], E]) -> E:
    """``poly`` at ``t`` (Horner)."""
    total = number(flint.fmpq(0))
    for c in reversed(poly.coeffs()):
        total = total * t + number(c)
    return total


def _evaluated(poly: flint.fmpq_mpoly, values: dict[str, E], number: Callable[[flint.fmpq], E]) -> E:
    """``poly`` at ``values`` (its variables' values by name)."""
    names = [str(n) for n in poly.context().names()]
    powers: dict[tuple[str, int], E] = {}
    total = number(flint.fmpq(0))
    for monomial, coefficient in zip(poly.monoms(), poly.coeffs()):
        term = number(coefficient)
        for name, exponent in zip(names, monomial):
            if exponent:
                if (name, exponent) not in powers:
                    power = values[name]
                    for _ in range(int(exponent) - 1):
                        power = power * values[name]
                    powers[name, exponent] = power
                term = term * powers[name, exponent]
        total = total + term
    return total


def _lift(modulus: flint.fmpq_poly, chain: _Chain, equations: list[flint.fmpq_mpoly]) -> None:
    """Whether the roots of the irreducible ``modulus`` are solutions: silent if they are,
    _NoLift (saying why) if not. Decided modulo ``PRIME`` where every divisor is invertible there
    (a proof: see ``PRIME``), exactly over QQ otherwise; the lifts then checked in ``equations``."""
    relation = chain.relation
    if relation is None or any((c % modulus).is_zero() for c in relation.contents):
        raise _NoLift("t2 has no relation linear in it there")
    image = _image(modulus)
    if image is not None:
        try:
            _check(chain, equations, _Residue(flint.nmod_poly([0, 1], PRIME) % image, image),
                   lambda c: _Residue(_constant(c), image))
            return
        except _NoLift:
            pass  # the prime may see a zero that QQ does not: decided exactly
    _check(chain, equations, _Residue(flint.fmpq_poly([0, 1]) % modulus, modulus),
           lambda c: _Residue(flint.fmpq_poly([c]), modulus))


R = TypeVar("R", _Residue[flint.nmod_poly], _Residue[flint.fmpq_poly])


def _meeting(values: dict[str, E], point: Point, first: Point, pivots: tuple[Point, Point],
             number: Callable[[flint.fmpq], E]) -> tuple[E, E, E]:
    """Where the coupler's turn must be for its point to be at ``point``: each dyad's row there
    (``_row``, its ``z`` known from the lift's ``values``) is a line ``alpha cos + beta sin + gamma = 0``
    in that turn's cos and sin, and the two lines meet at ``(x/w, y/w)``, ``(x, y, w)`` their cross
    product (``w`` zero where they are parallel)."""
    lines = []
    for pivot, name in zip(pivots, "ab"):
        (dx, dy), (ex, ey) = _minus(point, pivot), _minus(first, pivot)
        x, y = values[f"x{name}"], values[f"y{name}"]
        lines.append((number(dx) * x + number(dy) * y, number(dy) * x - number(dx) * y,
                      number((dx * dx + dy * dy - ex * ex - ey * ey) / 2) - number(ex) * x - number(ey) * y))
    (alpha, beta, gamma), (alpha2, beta2, gamma2) = lines
    return beta * gamma2 - gamma * beta2, gamma * alpha2 - alpha * gamma2, alpha * beta2 - beta * alpha2


def _further_turns(values: dict[str, E], points: Sequence[Point], pivots: tuple[Point, Point],
                   number: Callable[[flint.fmpq], E], invertible: Callable[[E], bool]) -> dict[str, E]:
    """``cos, sin`` of ``theta_j`` for each point past the fifth (``c5, s5``, ...), given the lift's
    ``values``: where the two dyads' lines meet (``_meeting``). A _NoLift where ``w`` is not shown
    invertible (the two lines parallel at that point)."""
    found: dict[str, E] = {}
    for j in range(5, len(points)):
        x, y, w = _meeting(values, points[j], points[0], pivots, number)
        if not invertible(w):
            raise _NoLift(f"the two dyads' conditions at point {j} are dependent")
        found[f"c{j}"], found[f"s{j}"] = x / w, y / w
    return found


def _first_missed(modulus: flint.fmpq_poly, chain: _Chain, points: Sequence[Point],
                  pivots: tuple[Point, Point]) -> int | None:
    """The first point past the fifth that the roots of the solution factor ``modulus`` miss, None
    where they reach every one (``_misses``), decided in the factor's field. A residue nonzero
    modulo ``PRIME`` is nonzero over QQ (a proof of a miss); a zero there proves nothing, and is
    decided exactly over QQ."""
    image = _image(modulus)
    if image is not None:
        try:
            missed = _misses(chain, points, pivots, _Residue(flint.nmod_poly([0, 1], PRIME) % image, image),
                             lambda c: _Residue(_constant(c), image))
            if missed:
                return missed[0]
        except _NoLift:
            pass  # the prime may see a zero that QQ does not: decided exactly
    try:
        missed = _misses(chain, points, pivots, _Residue(flint.fmpq_poly([0, 1]) % modulus, modulus),
                         lambda c: _Residue(flint.fmpq_poly([c]), modulus), exact=True)
    except _NoLift as why:  # a field: what is not invertible is zero
        raise ComputationError(f"{why} for a solution through the first five points: the data are special") from None
    return missed[0] if missed else None


def _misses(chain: _Chain, points: Sequence[Point], pivots: tuple[Point, Point], t1: R,
            number: Callable[[flint.fmpq], R], *, exact: bool = False) -> list[int]:
    """The points past the fifth not reached at ``t1`` (a residue), in order. The two dyads' lines in
    ``(cos, sin)`` meet at ``(x/w, y/w)`` (``_meeting``): the point is reached where that is on the circle,
    ``x**2 + y**2 - w**2 = 0``, a residue nonzero modulo a prime being nonzero over QQ. With ``w``
    zero (``exact``: in a field) it is missed where ``(x, y)`` is not zero (the lines apart: a pivot
    among such points), and a _NoLift where the lines are one (every turn on it reaches the point)."""
    values = _values(chain, t1, number, lambda r: r.invertible())
    missed = []
    for j in range(5, len(points)):
        x, y, w = _meeting(values, points[j], points[0], pivots, number)
        if not (x * x + y * y - w * w).value.is_zero():
            missed.append(j)
        elif exact and not w.invertible():
            if not (x.invertible() or y.invertible()):
                raise _NoLift(f"the two dyads' conditions at point {j} are one (the point is reached at two turns "
                              "or more: a double point of the coupler curve)")
            missed.append(j)
    return missed


def _check(chain: _Chain, equations: list[flint.fmpq_mpoly], t1: R, number: Callable[[flint.fmpq], R]) -> None:
    """The lift at ``t1`` (a residue modulo the factor), checked in ``equations``: a
    ComputationError if they fail (the lift's argument would be wrong)."""
    values = _values(chain, t1, number, lambda r: r.invertible())
    failed = [k for k, e in enumerate(equations) if not _evaluated(e, values, number).value.is_zero()]
    if failed:
        raise ComputationError(f"the lifts at a factor of degree {t1.modulus.degree()} fail equation {failed[0]} "
                               "of the path system: an error in the lift")


def _image(poly: flint.fmpq_poly) -> flint.nmod_poly | None:
    """``poly`` modulo ``PRIME``, None where that drops its degree (or a denominator)."""
    numerator = poly.numer()
    image = flint.nmod_poly([int(c) % PRIME for c in numerator.coeffs()], PRIME)
    return image if image.degree() == poly.degree() else None


def _constant(value: flint.fmpq) -> flint.nmod_poly:
    """``value`` modulo ``PRIME``; a _NoLift where the prime divides its denominator."""
    denominator = int(value.q) % PRIME
    if denominator == 0:
        raise _NoLift(f"{PRIME} divides a denominator")
    return flint.nmod_poly([int(value.p) * pow(denominator, -1, PRIME) % PRIME], PRIME)


# The real solutions, in balls.

def _real_solutions(modulus: flint.fmpq_poly, chain: _Chain, points: tuple[Point, ...], crank_pivot: Point,
                    rocker_pivot: Point, *, bits: int) -> list[PathSolution]:
    found = []
    for root, v in _balls(chain, real_roots(modulus, bits=bits), bits, lambda values: _further_turns(
            values, points, (crank_pivot, rocker_pivot), flint.arb, lambda b: not b.contains(0))):
        with flint.ctx.workprec(root.bits):
            x0, y0 = (flint.arb(c) for c in points[0])
            crank_joint = (x0 + v["xa"], y0 + v["ya"])
            rocker_joint = (x0 + v["xb"], y0 + v["yb"])
            found.append(PathSolution(
                root, tuple((v[f"c{j}"], v[f"s{j}"]) for j in range(1, len(points))), crank_joint, rocker_joint,
                _distance(crank_joint, crank_pivot), _distance(crank_joint, rocker_joint),
                _distance(rocker_joint, rocker_pivot)))
    return found


def _balls(chain: _Chain, roots: Sequence[RealRoot], bits: int,
           further: Callable[[dict[str, flint.arb]], dict[str, flint.arb]]
           ) -> list[tuple[RealRoot, dict[str, flint.arb]]]:
    """Every unknown at each of ``roots`` (of one factor) and the ``further`` values made from them
    (the turns past the fifth point), each ball's radius within ``2**-bits`` of its size: the roots
    refined as needed (the relation's coefficients are large), together, each with the root it
    was computed at."""
    done: dict[int, tuple[RealRoot, dict[str, flint.arb]]] = {}
    pending, precision = list(roots), bits
    while pending:
        waiting = []
        for root in refined_together(pending, precision):
            with flint.ctx.workprec(precision):
                try:
                    values = _values(chain, root.ball, flint.arb, lambda b: not b.contains(0))
                    values.update(further(values))
                except _NoLift:
                    values = {}
                if values and all(v.rad() <= flint.arb(2) ** (-bits) * max(abs(v.mid()), flint.arb(1))
                                  for v in values.values()):
                    done[root.index] = (root, values)
                else:
                    waiting.append(root)
        if waiting and precision >= 256 * bits:
            raise ComputationError(f"a solution's values stayed wider than 2**-{bits} at {precision} bits")
        pending, precision = waiting, 2 * precision
    return [done[root.index] for root in roots]


def _distance(p: Ball2, q: Ball2 | Point) -> flint.arb:
    dx, dy = p[0] - q[0], p[1] - q[1]
    return (dx * dx + dy * dy).sqrt()
