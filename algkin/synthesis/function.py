"""Function generation (Freudenstein): the four-bars whose rocker follows the crank at given pairs of angles.

The four-bar: the crank ``a`` turns about the origin at angle ``phi``, the rocker ``c`` about
``(d, 0)`` at angle ``psi`` (the ground ``d`` along the x axis from the crank's pivot to the
rocker's; both angles counterclockwise from it) and the coupler ``b`` joins their ends. The
loop ``a (cos phi, sin phi) + b (cos theta, sin theta) = (d, 0) + c (cos psi, sin psi)`` gives,
``theta`` eliminated by squaring ``b (cos theta, sin theta) = (d + c cos psi - a cos phi,
c sin psi - a sin phi)``::

    b**2 = a**2 + c**2 + d**2 + 2 c d cos psi - 2 a d cos phi - 2 a c cos(phi - psi)

and, divided by ``2 a c``, Freudenstein's equation in the sign convention used here::

    R1 cos psi - R2 cos phi + R3 = cos(phi - psi),
    R1 = d/a,  R2 = d/c,  R3 = (a**2 - b**2 + c**2 + d**2) / (2 a c).

- **Three pairs** (absolute angles): three equations linear in ``R1, R2, R3``, solved exactly.
- **Unknown starts**: the pairs are offsets from the starting angles; pair ``i`` is at the start
  plus (its offset minus the first pair's), so a start is the angle at the first pair. Four
  pairs: the inputs absolute, the output's start unknown; five pairs: both starts unknown.
  The equations are linear in ``R``: a solution exists where the matrix of rows
  ``[cos psi_i, -cos phi_i, 1, cos(phi_i - psi_i)]`` has rank 3 (its 4-by-4 minors vanish,
  the first three columns of rank 3). Each minor is of degree 2 in the cos and sin of each
  start, so a function of twice the start: turning a link by 180 degrees (``a`` to ``-a`` with
  ``phi`` to ``phi + 180``, or ``c`` and ``psi``) is the same four-bar, and the unknowns are
  ``Ci, Si`` (cos and sin of twice the input's start) and ``Co, So`` (the output's), on the
  unit circle: one unknown per four-bar, none counted twice. Four pairs: the one minor and the
  circle (2 complex solutions); five pairs: the minors of pairs 1, 2, 3, 4 and 1, 2, 3, 5 and
  the circles, solved by ``algkin.eliminate.group.solve_group`` (every complex solution; the
  real ones in certified balls by ``modes``). Those two minors also vanish where pairs 1, 2, 3
  alone are of rank 2 (Cramer's rule on them fails): such factors of the eliminant are decided
  exactly (the other minors are not zero on them) and left out as extraneous (generic data: 3
  of 6), leaving 3 complex solutions for five pairs. Where that system is not zero-dimensional
  (special data: pairs sharing a crank angle), the minors holding the next three pairs.
  Data with a minor a nonzero number have no solution; data with every minor zero, a family
  (a UsageError: they determine no four-bar).

A length found negative is the link pointing the other way: the length is made positive and
its start turned by 180 degrees (the ratios then those of the turned starts). Every real
solution with finite lengths (R1, R2 not zero) assembles: at each pair, ``b**2`` as given by R3
is ``|A - B|**2`` for the crank's end ``A`` and the rocker's ``B`` (the first display), so not
negative; and zero only where every pair puts ``A`` and ``B`` at one of the two points the
crank's and the rocker's circles share, which three distinct pairs cannot. So ``b**2 > 0``
always; the solutions left out are those with R1 or R2 zero (a link infinitely long) and the
extraneous and degenerate factors of the eliminant.

>>> from algkin.synthesis.data import Angle, AnglePair
>>> half = Angle.of_tan_half
>>> pairs = [AnglePair(half(flint.fmpq(-5, 2)), half(flint.fmpq(-3, 2))),
...          AnglePair(half(flint.fmpq(-7, 4)), half(flint.fmpq(-4, 3))),
...          AnglePair(half(flint.fmpq(-5, 6)), half(flint.fmpq(-1)))]
>>> found = freudenstein(pairs, ground=flint.fmpq(6))
>>> linkage, = found.solutions
>>> [str(x) for x in (linkage.crank, linkage.rocker, linkage.ground, linkage.coupler_squared)]
['2', '5', '6', '41']
>>> found.complex_count, found.real_count
(1, 1)
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable, Sequence
from typing import Union

import attrs
import flint

from ..eliminate.group import GroupSolution, Mode, Polynomial, modes, solve_group
from ..eliminate.group.algebra import univariate
from ..eliminate.group.samples import ball_value
from ..errors import ComputationError, UsageError
from ..system.roots import RealRoot, real_roots
from .data import Angle, AnglePair

__all__ = ["freudenstein", "system", "FunctionSynthesis", "FreudensteinSolution", "Exclusion", "Number"]

Number = Union[flint.fmpq, flint.arb]
"""A value known exactly (``fmpq``) or in a certified ball (``arb``)."""
CosSin = tuple[Number, Number]

HALF = ("ci", "si", "co", "so")
"""The cos and sin of the input's and the output's start (the rows' ring)."""
DOUBLE = ("Ci", "Si", "Co", "So")
"""The cos and sin of twice each start: the unknowns solved for."""
MAX_DOUBLINGS = 4
"""How many times the precision is doubled to decide a sign in balls (of a value known nonzero)."""


@attrs.frozen
class FreudensteinSolution:
    """One four-bar: ``ratios`` (R1, R2, R3) of Freudenstein's equation in its start angles;
    positive ``crank``, ``coupler``, ``rocker``, ``ground`` lengths (``coupler_squared`` too:
    exact where the others are); ``start_input`` and ``start_output``: the crank's and the
    rocker's angle at the first pair, as (cos, sin). Values exact (``fmpq``) where the data
    allow, else certified balls, which are not compared: ``identity`` is the solution exactly,
    the ratios (three pairs) or the root of the eliminant it comes from (unknown starts)."""

    identity: tuple[flint.fmpq, flint.fmpq, flint.fmpq] | RealRoot
    ratios: tuple[Number, Number, Number] = attrs.field(eq=False)
    crank: Number = attrs.field(eq=False)
    coupler: Number = attrs.field(eq=False)
    rocker: Number = attrs.field(eq=False)
    ground: Number = attrs.field(eq=False)
    coupler_squared: Number = attrs.field(eq=False)
    start_input: CosSin = attrs.field(eq=False)
    start_output: CosSin = attrs.field(eq=False)

    def start_degrees(self) -> tuple[float, float]:
        """The start angles in degrees, in (-180, 180].

        >>> solution = FreudensteinSolution((flint.fmpq(1),) * 3, (flint.fmpq(1),) * 3, *[flint.fmpq(1)] * 5,
        ...                                 (flint.fmpq(0), flint.fmpq(1)), (flint.fmpq(-1), flint.fmpq(0)))
        >>> solution.start_degrees()
        (90.0, 180.0)
        """
        return _degrees(self.start_input), _degrees(self.start_output)


@attrs.frozen
class Exclusion:
    """Solutions left out, and why: ``complex_count`` of them, ``real_count`` of those real;
    ``solutions``: whether they solve the system (and are counted in the synthesis's counts),
    False for an extraneous factor of the eliminant or where R1, R2, R3 are undetermined."""

    reason: str
    complex_count: int
    real_count: int
    solutions: bool = True


@attrs.frozen
class FunctionSynthesis:
    """Every four-bar through the ``pairs``: ``solutions``, the real ones that assemble (``b**2 > 0``);
    ``complex_count`` and ``real_count``: the solutions of the system (over C, and the real
    ones, whether they assemble or not); ``excluded``: what was left out and why (an extraneous
    factor's solutions are no solutions of the system, and in neither count); ``group``: the
    group solved (unknown starts)."""

    pairs: tuple[AnglePair, ...]
    unknown_start: bool
    ground: flint.fmpq
    solutions: tuple[FreudensteinSolution, ...]
    complex_count: int
    real_count: int
    excluded: tuple[Exclusion, ...]
    group: GroupSolution | None = None


def freudenstein(pairs: Sequence[AnglePair], *, unknown_start: bool = False, ground: flint.fmpq | int = 1,
                 bits: int = 128) -> FunctionSynthesis:
    """The four-bars whose (crank, rocker) angles pass through ``pairs``: three absolute pairs,
    or four or five offsets from unknown starts (``unknown_start``); the ground of length
    ``ground``; balls at ``bits`` of precision. A UsageError on a wrong number of pairs, two
    equal pairs, a singular linear system or a ground not positive.

    >>> from algkin.synthesis.data import Angle, AnglePair
    >>> pairs = [AnglePair(Angle.of_tan_half(flint.fmpq(p)), Angle.of_tan_half(flint.fmpq(q)))
    ...          for p, q in [(0, 0), ("1/3", "1/5"), ("2/3", "1/2"), (1, "3/4"), ("4/3", 1)]]
    >>> found = freudenstein(pairs, unknown_start=True)
    >>> found.complex_count, found.real_count, len(found.solutions)
    (3, 1, 1)
    >>> [e.reason.split(":")[0] for e in found.excluded]
    ['extraneous', 'extraneous', 'extraneous']
    """
    pairs, ground = _checked(pairs, unknown_start=unknown_start, ground=ground)
    if not unknown_start:
        return _absolute(pairs, ground=ground, bits=bits)
    return _unknown_start(pairs, ground=ground, bits=bits)


def system(pairs: Sequence[AnglePair], *, unknown_start: bool = False) -> tuple[list[flint.fmpq_mpoly], list[str]]:
    """The polynomial system of the synthesis and its unknowns, for another solver: three
    pairs, the linear equations in ``R1, R2, R3``; four pairs, the minor and the circle in
    ``Co, So``; five pairs, the two minors and the circles in ``Ci, Si, Co, So`` with
    ``w * D**2 - 1`` (``D``: Cramer's determinant of pairs 1, 2, 3), which removes the
    extraneous solutions: its solutions are ``freudenstein``'s ``complex_count``.

    >>> from algkin.synthesis.data import Angle, AnglePair
    >>> right = AnglePair(Angle.of_degrees(90), Angle.of_degrees(90))
    >>> pairs = [AnglePair(Angle.of_degrees(0), Angle.of_degrees(90)), right, AnglePair(Angle.of_degrees(180), Angle.of_degrees(0))]
    >>> equations, unknowns = system(pairs)
    >>> unknowns, [str(e) for e in equations]
    (['R1', 'R2', 'R3'], ['-R2 + R3', 'R3 - 1', 'R1 + R2 + R3 + 1'])
    """
    pairs, _ = _checked(pairs, unknown_start=unknown_start, ground=1)
    if not unknown_start:
        ctx = flint.fmpq_mpoly_ctx.get(("R1", "R2", "R3"), "lex")
        r1, r2, r3 = ctx.gens()
        return [r1 * row[0] + r2 * row[1] + r3 * row[2] - row[3] for row in _exact_rows(pairs)], ["R1", "R2", "R3"]
    problem = _Problem.of(pairs)
    if len(pairs) == 4:
        return list(problem.equations()), list(problem.unknowns)
    ctx = flint.fmpq_mpoly_ctx.get(DOUBLE + ("w",), "lex")
    w = ctx.gens()[-1]
    saturation = w * problem.invariants[(0, 1, 2)].determinant.project_to_context(ctx) - 1
    return [e.project_to_context(ctx) for e in problem.equations()] + [saturation], list(problem.unknowns) + ["w"]


def _checked(pairs: Sequence[AnglePair], *, unknown_start: bool,
             ground: flint.fmpq | int) -> tuple[tuple[AnglePair, ...], flint.fmpq]:
    pairs = tuple(pairs)
    wanted = (4, 5) if unknown_start else (3,)
    if len(pairs) not in wanted:
        kind = "offsets from unknown starts" if unknown_start else "absolute pairs"
        raise UsageError("pairs", len(pairs), f"function generation takes {' or '.join(map(str, wanted))} pairs "
                         f"({kind}), not {len(pairs)}")
    for (i, first), (j, second) in itertools.combinations(enumerate(pairs, 1), 2):
        if (first.input.cos, first.input.sin, first.output.cos, first.output.sin) == \
                (second.input.cos, second.input.sin, second.output.cos, second.output.sin):
            raise UsageError("pairs", f"{i} and {j}", f"pairs {i} and {j} are equal: they give one equation, not two")
    ground = flint.fmpq(ground)
    if ground <= 0:
        raise UsageError("ground", str(ground), "the ground's length must be positive")
    return pairs, ground


# --- three pairs: exact -------------------------------------------------------------------------


def _exact_rows(pairs: Sequence[AnglePair]) -> list[tuple[flint.fmpq, flint.fmpq, flint.fmpq, flint.fmpq]]:
    """Freudenstein's equation of each pair: the coefficients of R1, R2, R3 and the right side."""
    return [(p.output.cos, -p.input.cos, flint.fmpq(1), p.input.cos * p.output.cos + p.input.sin * p.output.sin)
            for p in pairs]


def _absolute(pairs: tuple[AnglePair, ...], *, ground: flint.fmpq, bits: int) -> FunctionSynthesis:
    rows = _exact_rows(pairs)
    matrix = flint.fmpq_mat([list(r[:3]) for r in rows])
    if matrix.det() == 0:
        raise UsageError("pairs", "three pairs", "the linear system for R1, R2, R3 is singular: the points "
                         "(cos output, cos input) of the three pairs are on one line")
    ratios = matrix.solve(flint.fmpq_mat([[r[3]] for r in rows]))
    r1, r2, r3 = (ratios[k, 0] for k in range(3))
    infinite = _infinite(r1 == 0, r2 == 0, 1, 1)
    if infinite is not None:
        return FunctionSynthesis(pairs, False, ground, (), 1, 1, (infinite,))
    first = pairs[0]
    crank, rocker, r3 = ground / abs(r1), ground / abs(r2), r3 * _sign(r1) * _sign(r2)
    squared = crank**2 + rocker**2 + ground**2 - 2 * crank * rocker * r3   # positive: see the module's docstring
    start_input = _turned((first.input.cos, first.input.sin), r1 < 0)
    start_output = _turned((first.output.cos, first.output.sin), r2 < 0)
    ratios_ = (abs(r1), abs(r2), r3)
    solution = FreudensteinSolution(ratios_, ratios_, crank, _root(squared, bits), rocker, ground, squared,
                                    start_input, start_output)
    return FunctionSynthesis(pairs, False, ground, (solution,), 1, 1, ())


def _root(square: flint.fmpq, bits: int) -> Number:
    """The positive square root: exact where ``square`` is a rational square."""
    if square.p.is_square() and square.q.is_square():
        return square.sqrt()
    with flint.ctx.workprec(bits):
        return flint.arb(square).sqrt()


def _infinite(crank: bool, rocker: bool, count: int, real: int) -> Exclusion | None:
    """The exclusion of ``count`` solutions (``real`` of them real) with an infinitely long
    crank (R1 zero) or rocker (R2 zero); None where neither is."""
    if crank:
        return Exclusion("R1 = 0: the crank would be infinitely long", count, real)
    return Exclusion("R2 = 0: the rocker would be infinitely long", count, real) if rocker else None


def _sign(value: flint.fmpq) -> int:
    return 1 if value > 0 else -1


def _turned(angle: tuple[flint.fmpq, flint.fmpq], turn: bool) -> tuple[flint.fmpq, flint.fmpq]:
    return (-angle[0], -angle[1]) if turn else angle


# --- unknown starts: the minors, on the circles of twice the starts ------------------------------


@attrs.frozen
class _Cramer:
    """Cramer's rule on three pairs, as invariants (polynomials in ``DOUBLE``): ``determinant``
    the square of Cramer's determinant ``D``; ``crank`` and ``rocker`` the squares of R1's and
    R2's numerators; ``half``: the four determinants over ``HALF`` for the values (R_k = D_k / D)."""

    rows: tuple[int, int, int]
    determinant: flint.fmpq_mpoly
    crank: flint.fmpq_mpoly
    rocker: flint.fmpq_mpoly
    half: tuple[flint.fmpq_mpoly, flint.fmpq_mpoly, flint.fmpq_mpoly, flint.fmpq_mpoly]


@attrs.frozen
class _Problem:
    """The pairs' rows over ``HALF``; over ``DOUBLE``, every 4-by-4 minor (``minors``, by the
    pairs they hold) and Cramer's rule on every three pairs (``invariants``)."""

    pairs: tuple[AnglePair, ...]
    minors: dict[tuple[int, int, int, int], flint.fmpq_mpoly]
    invariants: dict[tuple[int, int, int], _Cramer]

    @classmethod
    def of(cls, pairs: tuple[AnglePair, ...]) -> _Problem:
        rows = _rows(pairs)
        minors = {chosen: _on_double(_det([rows[i] for i in chosen]))
                  for chosen in itertools.combinations(range(len(rows)), 4)}
        invariants = {chosen: _cramer([rows[i] for i in chosen], chosen)
                      for chosen in itertools.combinations(range(len(rows)), 3)}
        return cls(pairs, minors, invariants)

    @property
    def unknowns(self) -> tuple[str, ...]:
        return ("Co", "So") if len(self.pairs) == 4 else DOUBLE

    def equations(self, rows: tuple[int, int, int] = (0, 1, 2)) -> tuple[flint.fmpq_mpoly, ...]:
        """The minors holding the three pairs ``rows`` (where they are of rank 3, Cramer's rule
        on them and the other pairs' equations), and the circles."""
        ctx = flint.fmpq_mpoly_ctx.get(DOUBLE, "lex")
        ci, si, co, so = ctx.gens()
        minors = tuple(m for chosen, m in self.minors.items() if set(rows) <= set(chosen))
        return minors + ((co**2 + so**2 - 1,) if len(self.pairs) == 4 else (ci**2 + si**2 - 1, co**2 + so**2 - 1))


def _rows(pairs: tuple[AnglePair, ...]) -> list[tuple[flint.fmpq_mpoly, ...]]:
    """Each pair's row ``[cos psi, -cos phi, 1, cos(phi - psi)]`` over ``HALF``: the angles the
    starts plus the offsets from the first pair; four pairs: the input's start the first input."""
    ctx = flint.fmpq_mpoly_ctx.get(HALF, "lex")
    ci, si, co, so = ctx.gens()
    first = pairs[0]
    if len(pairs) == 4:
        ci, si = ctx.constant(first.input.cos), ctx.constant(first.input.sin)
    rows: list[tuple[flint.fmpq_mpoly, ...]] = []
    for pair in pairs:
        cos_in, sin_in = _difference(pair.input, first.input).rotate(ci, si)
        cos_out, sin_out = _difference(pair.output, first.output).rotate(co, so)
        rows.append((cos_out, -cos_in, ctx.constant(1), cos_in * cos_out + sin_in * sin_out))
    return rows


def _difference(angle: Angle, start: Angle) -> Angle:
    """``angle - start``, exactly."""
    return Angle(angle.cos * start.cos + angle.sin * start.sin, angle.sin * start.cos - angle.cos * start.sin)


def _det(matrix: Sequence[Sequence[flint.fmpq_mpoly]]) -> flint.fmpq_mpoly:
    """The determinant, by cofactors along the first row (matrices of 3 and 4 rows)."""
    if len(matrix) == 1:
        return matrix[0][0]
    total = matrix[0][0] * 0
    for j, entry in enumerate(matrix[0]):
        minor = _det([list(row[:j]) + list(row[j + 1:]) for row in matrix[1:]])
        total += entry * minor if j % 2 == 0 else -entry * minor
    return total


def _cramer(rows: Sequence[tuple[flint.fmpq_mpoly, ...]], chosen: tuple[int, int, int]) -> _Cramer:
    """Cramer's rule for ``A R = z`` on three rows ``[A | z]``."""
    columns = [[row[k] for row in rows] for k in range(4)]

    def det(*picked: int) -> flint.fmpq_mpoly:
        return _det([list(r) for r in zip(*(columns[k] for k in picked))])

    d, d1, d2, d3 = det(0, 1, 2), det(3, 1, 2), det(0, 3, 2), det(0, 1, 3)
    square, crank, rocker = _on_double(d**2), _on_double(d1**2), _on_double(d2**2)
    return _Cramer(chosen, square, crank, rocker, (d, d1, d2, d3))


def _on_double(poly: flint.fmpq_mpoly) -> flint.fmpq_mpoly:
    """``poly`` over ``HALF``, of even degree in each start's (cos, sin), as a polynomial in the
    cos and sin of twice the starts, equal on the unit circles: ``c**2 = (1 + C)/2``,
    ``s**2 = (1 - C)/2``, ``c s = S/2``."""
    ctx = flint.fmpq_mpoly_ctx.get(DOUBLE, "lex")
    big_ci, big_si, big_co, big_so = ctx.gens()
    one = ctx.constant(1)
    total = ctx.constant(0)
    for (i, j, k, m), coefficient in zip(poly.monoms(), poly.coeffs()):
        total += coefficient * _even(i, j, one + big_ci, one - big_ci, big_si) * _even(k, m, one + big_co,
                                                                                     one - big_co, big_so)
    return total


def _even(cos: int, sin: int, twice_cos_squared: flint.fmpq_mpoly, twice_sin_squared: flint.fmpq_mpoly,
          twice_product: flint.fmpq_mpoly) -> flint.fmpq_mpoly:
    """``c**cos * s**sin`` (an even total degree) in the double angle."""
    if (cos + sin) % 2:
        raise ValueError(f"c**{cos} s**{sin}: odd degree, no function of the double angle")
    odd = cos % 2
    return ((twice_product / 2) ** odd * (twice_cos_squared / 2) ** ((cos - odd) // 2)
            * (twice_sin_squared / 2) ** ((sin - odd) // 2))


# --- unknown starts: solved, the factors decided exactly, the real solutions in balls -----------


@attrs.frozen
class _Factor:
    """An irreducible factor of the eliminant: ``residue`` reduces a polynomial in ``DOUBLE``
    modulo it (its value at the factor's solutions); ``real``: how many real roots it has."""

    polynomial: flint.fmpq_poly
    residue: Callable[[flint.fmpq_mpoly], flint.fmpq_poly]
    real: int

    @property
    def degree(self) -> int:
        return int(self.polynomial.degree())


def _unknown_start(pairs: tuple[AnglePair, ...], *, ground: flint.fmpq, bits: int) -> FunctionSynthesis:
    problem = _Problem.of(pairs)
    if all(m.is_zero() for m in problem.minors.values()):
        raise UsageError("pairs", f"{len(pairs)} pairs", "every start satisfies these pairs: they do not "
                         "determine a four-bar")
    if any(m.is_constant() and not m.is_zero() for m in problem.minors.values()):  # no start makes it vanish
        return FunctionSynthesis(pairs, True, ground, (), 0, 0, ())
    group, rows = _solved(problem)
    eliminant = univariate(group.eliminant.to_flint(), group.variable)
    excluded: list[Exclusion] = []
    kept: list[tuple[_Factor, _Cramer]] = []
    complex_count = real_count = 0
    for polynomial, _ in eliminant.factor()[1]:
        factor = _Factor(polynomial, _reducer(group, polynomial), len(real_roots(polynomial)))
        verdict = _decided(problem, factor, rows)
        if not isinstance(verdict, Exclusion) or verdict.solutions:
            complex_count, real_count = complex_count + factor.degree, real_count + factor.real
        if isinstance(verdict, Exclusion):
            excluded.append(verdict)
        else:
            kept.append((factor, verdict))
    solutions: list[FreudensteinSolution] = []
    if kept:
        product = flint.fmpq_poly([1])
        for factor, _ in kept:
            product *= factor.polynomial
        restricted = attrs.evolve(group, eliminant=Polynomial.of(_in_variable(product, group)))
        for mode in modes(restricted, {}, bits=bits):
            root = mode.root
            assert root is not None  # solved over QQ: every mode is an exact root
            cramer = next(c for f, c in kept if root.sign(f.polynomial) == 0)
            solutions.append(_four_bar(problem, restricted, mode, cramer, ground=ground, bits=bits))
    return FunctionSynthesis(pairs, True, ground, tuple(solutions), complex_count, real_count, tuple(excluded), group)


def _solved(problem: _Problem) -> tuple[GroupSolution, tuple[int, int, int]]:
    """The group of the minors holding pairs 1, 2, 3; where that system is not zero-dimensional
    or has repeated solutions (special data), those holding the next three pairs, in order."""
    failures = []
    for rows in itertools.combinations(range(len(problem.pairs)), 3) if len(problem.pairs) == 5 else [(0, 1, 2)]:
        try:
            return solve_group(list(problem.equations(rows)), list(problem.unknowns)), rows
        except ComputationError as error:
            failures.append(f"pairs {', '.join(str(r + 1) for r in rows)}: {error}")
    raise ComputationError("the pairs are special: no system of minors could be solved (" + "; ".join(failures[:2])
                           + (f"; and {len(failures) - 2} more" if len(failures) > 2 else "") + ")")


def _decided(problem: _Problem, factor: _Factor, rows: tuple[int, int, int]) -> _Cramer | Exclusion:
    """The factor's solutions decided exactly: extraneous (a minor not zero on them), degenerate
    (R undetermined, or a length infinite), or solutions, with the Cramer's rule that holds there."""
    if any(not factor.residue(minor).is_zero() for minor in problem.minors.values()):
        named = ", ".join(str(r + 1) for r in rows)
        return Exclusion(f"extraneous: pairs {named} leave R1, R2, R3 undetermined there, and the other pairs' "
                         "equations fail", factor.degree, factor.real, solutions=False)
    cramer = next((c for c in problem.invariants.values() if not factor.residue(c.determinant).is_zero()), None)
    if cramer is None:
        return Exclusion("degenerate: no three pairs determine R1, R2, R3 there", factor.degree, factor.real,
                         solutions=False)
    infinite = _infinite(factor.residue(cramer.crank).is_zero(), factor.residue(cramer.rocker).is_zero(),
                         factor.degree, factor.real)
    return cramer if infinite is None else infinite


def _reducer(group: GroupSolution, factor: flint.fmpq_poly) -> Callable[[flint.fmpq_mpoly], flint.fmpq_poly]:
    """A polynomial in ``DOUBLE`` at the solutions on ``factor``: reduced modulo it, the unknowns their lifts."""
    x = flint.fmpq_poly([0, 1])
    values = {group.variable: x % factor}
    for lift in group.lifts:
        numerator = univariate(lift.numerator.to_flint(), group.variable)
        denominator = univariate(lift.denominator.to_flint(), group.variable)
        common, inverse, _ = denominator.xgcd(factor)
        if common.degree() != 0:
            raise ComputationError(f"the lift of {lift.unknown} is undefined on a factor of its eliminant")
        values[lift.unknown] = numerator * inverse / common[0] % factor

    def residue(poly: flint.fmpq_mpoly) -> flint.fmpq_poly:
        names = [str(n) for n in poly.context().names()]
        total = flint.fmpq_poly([0])
        for monomial, coefficient in zip(poly.monoms(), poly.coeffs()):
            term = flint.fmpq_poly([coefficient])
            for name, exponent in zip(names, monomial):
                if exponent:
                    term = term * _power(values[name], int(exponent), factor) % factor
            total += term
        return total % factor

    return residue


def _power(base: flint.fmpq_poly, exponent: int, modulus: flint.fmpq_poly) -> flint.fmpq_poly:
    result = flint.fmpq_poly([1])
    for _ in range(exponent):
        result = result * base % modulus
    return result


def _in_variable(poly: flint.fmpq_poly, group: GroupSolution) -> flint.fmpq_mpoly:
    ctx = flint.fmpq_mpoly_ctx.get((group.variable,), "lex")
    return ctx.from_dict({(k,): c for k, c in enumerate(poly.coeffs()) if c != 0})


def _four_bar(problem: _Problem, group: GroupSolution, mode: Mode, cramer: _Cramer, *, ground: flint.fmpq,
              bits: int) -> FreudensteinSolution:
    """The four-bar of a real solution, in balls: the precision doubled until every sign is decided."""
    root = mode.root
    assert root is not None
    for doubling in range(MAX_DOUBLINGS + 1):
        precision = bits << doubling
        if doubling:
            mode = next(m for m in modes(group, {}, bits=precision) if m.root == root)
        found = _in_balls(problem, mode, cramer, root, ground=ground, bits=precision)
        if found is not None:
            return found
    raise ComputationError(f"the signs of R1 and R2 stayed undecided at {bits << MAX_DOUBLINGS} bits")


def _in_balls(problem: _Problem, mode: Mode, cramer: _Cramer, root: RealRoot, *, ground: flint.fmpq,
              bits: int) -> FreudensteinSolution | None:
    """The four-bar at the mode's balls; None where a sign is undecided at this precision."""
    with flint.ctx.workprec(bits):
        first = problem.pairs[0]
        start_input: CosSin = (first.input.cos, first.input.sin) if len(problem.pairs) == 4 else \
            _half(mode.values["Ci"], mode.values["Si"])
        start_output = _half(mode.values["Co"], mode.values["So"])
        values = dict(zip(HALF, map(flint.arb, start_input + start_output)))
        d, d1, d2, d3 = (ball_value(p, values) for p in cramer.half)
        r1, r2, r3 = d1 / d, d2 / d, d3 / d
        if any(r.contains(0) for r in (r1, r2)):
            return None
        turn_input, turn_output = r1 < 0, r2 < 0
        r1, r2 = abs(r1), abs(r2)
        r3 = -r3 if turn_input != turn_output else r3
        crank, rocker = ground / r1, ground / r2
        squared = crank**2 + rocker**2 + ground**2 - 2 * crank * rocker * r3
        if not squared > 0:  # positive (the module's docstring): undecided at this precision
            return None
        return FreudensteinSolution(root, (r1, r2, r3), crank, squared.sqrt(), rocker, ground, squared,
                                    _turned_ball(start_input, turn_input), _turned_ball(start_output, turn_output))


def _half(cos_twice: flint.arb, sin_twice: flint.arb) -> tuple[flint.arb, flint.arb]:
    """An angle (cos, sin) of which ``(cos_twice, sin_twice)`` is twice (the other is it turned by
    180 degrees): the larger of cos and sin from its square, the other from their product."""
    if cos_twice.mid() >= 0:
        cos = ((1 + cos_twice) / 2).sqrt()
        return cos, sin_twice / (2 * cos)
    sin = ((1 - cos_twice) / 2).sqrt()
    return sin_twice / (2 * sin), sin


def _turned_ball(angle: CosSin, turn: bool) -> CosSin:
    return (-angle[0], -angle[1]) if turn else angle


def _degrees(angle: CosSin) -> float:
    return math.degrees(math.atan2(float(angle[1]), float(angle[0])))
