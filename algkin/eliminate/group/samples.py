"""A group's modes at a sample: its real solutions at rational parameter values, in balls.

At the sample, the eliminant is a polynomial over QQ in the group's variable: its real roots
are isolated and certified (``algkin.system.roots``: each ball holds exactly one root); every other unknown is its
lift there, reduced to a polynomial modulo the eliminant (the shape lemma), evaluated on the
root's ball.

>>> import flint
>>> from .solve import solve_group
>>> ctx = flint.fmpq_mpoly_ctx.get(("x", "y", "r"), "lex")
>>> x, y, r = ctx.gens()
>>> solution = solve_group([x**2 + y**2 - r, x - 2*y], ["x", "y"])
>>> [(str(m.values["x"].mid())[:6], str(m.values["y"].mid())[:6]) for m in modes(solution, {"r": 5})]
[('-2.000', '-1.000'), ('2.0000', '1.0000')]
>>> modes(solution, {"r": -5})
()
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import flint
import sympy

from ...errors import ComputationError, UsageError
from ...system.roots import RealRoot, real_roots
from .algebra import coefficients, univariate
from .records import GroupSolution, Mode, Values

__all__ = ["modes", "modes_in_balls", "modes_in_sequence", "ball_value"]


def modes(solution: GroupSolution, at: Mapping[str, int | str | flint.fmpq], *, bits: int = 128) -> tuple[Mode, ...]:
    """Every real solution of ``solution``'s group with its parameters ``at`` those exact
    values (integers, fractions as text, or ``fmpq``), in balls computed at ``bits`` of
    precision, in increasing order of the variable. A ComputationError where the sample is
    not generic: the eliminant drops its degree or has a repeated root there (modes meet),
    or a lift's denominator vanishes at a root."""
    point = _point(solution, at)
    eliminant = univariate(solution.eliminant.to_flint().subs(point), solution.variable)
    _check_generic(solution, eliminant)
    shapes = {lift.unknown: _shape(lift.numerator.to_flint().subs(point), lift.denominator.to_flint().subs(point),
                                   eliminant=eliminant, variable=solution.variable) for lift in solution.lifts}
    found = []
    for index, root in enumerate(real_roots(eliminant, bits=bits)):
        values = {solution.variable: root.ball} | {x: _ratio(root, *shape) for x, shape in shapes.items()}
        found.append(Mode(index, root, values))
    return tuple(found)


def _ratio(root: RealRoot, numerator: flint.fmpq_poly, denominator: flint.fmpq_poly) -> flint.arb:
    """``numerator / denominator`` at ``root``, in balls: the root refined while the
    denominator's ball holds 0 (it has no zero at a root: ``_shape``) or the ratio is wider
    than the root's precision allows (up to four times its bits)."""
    bits = root.bits
    while True:
        below = root.value(denominator)
        if not below.contains(0):
            with flint.ctx.workprec(root.bits):  # the division at the root's precision, not the default 53 bits
                value = root.value(numerator) / below
                scale = abs(value.mid()) if abs(value.mid()) > 1 else flint.arb(1)
                if value.rad() <= flint.arb(2) ** (16 - bits) * scale or root.bits >= 4 * bits:
                    return value
        root = root.refined(root.bits * 2)


def _point(solution: GroupSolution, at: Mapping[str, int | str | flint.fmpq]) -> Values:
    missing = [p for p in solution.parameters if p not in at]
    if missing:
        raise UsageError("at", dict(at), f"needs a value for every parameter; missing {', '.join(missing)}")
    point: Values = {}
    for name in solution.parameters:
        try:
            point[name] = flint.fmpq(sympy.Rational(str(at[name])).p, sympy.Rational(str(at[name])).q)
        except (TypeError, ValueError, sympy.SympifyError):
            raise UsageError("at", dict(at), f"{name}: not an exact rational value") from None
    return point


def _check_generic(solution: GroupSolution, eliminant: flint.fmpq_poly) -> None:
    if eliminant.degree() != solution.complex_count:
        raise ComputationError(f"at this sample the eliminant in {solution.variable} drops its degree "
                               f"({solution.complex_count} to {eliminant.degree()})")
    if eliminant.gcd(eliminant.derivative()).degree() > 0:
        raise ComputationError(f"at this sample the eliminant in {solution.variable} has a repeated root: "
                               "two modes meet")


def _shape(numerator: flint.fmpq_mpoly, denominator: flint.fmpq_mpoly, *, eliminant: flint.fmpq_poly,
           variable: str) -> tuple[flint.fmpq_poly, flint.fmpq_poly]:
    """``numerator`` and ``denominator`` in ``variable`` alone, the denominator prime to the
    eliminant (no zero at a root). Evaluated as a ratio in balls: the inverse modulo the
    eliminant (``xgcd`` over QQ) costs a thousand times the gcd, for the same values."""
    below = univariate(denominator, variable)
    if below.gcd(eliminant).degree() != 0:
        raise ComputationError(f"at this sample a lift's denominator vanishes at a root in {variable}")
    return univariate(numerator, variable) % eliminant, below % eliminant


def modes_in_balls(solution: GroupSolution, at: Mapping[str, flint.fmpq], balls: Mapping[str, flint.arb], *,
                   bits: int = 128) -> tuple[Mode, ...]:
    """Every real solution of ``solution``'s group with some parameters at exact values (``at``)
    and the others in balls (``balls``: an earlier group's unknowns at one of its modes), in
    increasing order of the variable, each ``root`` None. Certified for every value in the balls:
    the eliminant's complex roots are isolated in disjoint discs (Arb), and a disc that meets the
    real axis and whose mirror image meets no other disc holds a real root (the mirror image of a
    root of a real polynomial is a root). A ComputationError where that cannot be told: the
    leading coefficient's ball holds 0, two roots are too close (modes meet), a disc is undecided,
    or a lift's denominator's ball holds 0.

    >>> import flint
    >>> from .solve import solve_group
    >>> ctx = flint.fmpq_mpoly_ctx.get(("x", "y", "r"), "lex")
    >>> x, y, r = ctx.gens()
    >>> solution = solve_group([x**2 + y**2 - r, x - 2*y], ["x", "y"])
    >>> [m.values["x"].str(6, radius=False) for m in modes_in_balls(solution, {}, {"r": flint.arb(5)})]
    ['-2.00000', '2.00000']
    """
    with flint.ctx.workprec(bits):
        exact = {n: v for n, v in at.items() if n in solution.parameters}
        given = {n: flint.arb(v) for n, v in exact.items()} | dict(balls)
        missing = [p for p in solution.parameters if p not in given]
        if missing:
            raise UsageError("at", sorted(given), f"needs a value for every parameter; missing {', '.join(missing)}")
        eliminant = solution.eliminant.to_flint()
        with flint.ctx.workprec(2 * bits):  # rounded far below the roots' tolerance: near a toggle (a small
            # derivative) a root moves by a coefficient's error over the derivative there
            parts = [ball_value(c, given) for c in coefficients(eliminant, solution.variable)]
        while len(parts) > 1 and parts[-1].is_zero():
            parts.pop()
        if len(parts) - 1 != solution.complex_count or parts[-1].contains(0):
            raise ComputationError(f"at this sample the eliminant in {solution.variable} may drop its degree")
        try:
            roots = flint.acb_poly([flint.acb(c) for c in parts]).roots(tol=flint.arb(2) ** (16 - bits), maxprec=4 * bits)
        except ValueError:
            raise ComputationError(f"at this sample the roots of the eliminant in {solution.variable} could not be "
                                   "isolated: two modes meet, or nearly") from None
        real = [r.real for r in roots if _real(r, roots)]
        found = []
        for index, root in enumerate(sorted(real, key=lambda b: float(b.mid()))):
            values = {**given, solution.variable: root}
            for lift in solution.lifts:
                bottom = ball_value(lift.denominator.to_flint(), values)
                if bottom.contains(0):
                    raise ComputationError(f"at this sample a lift's denominator may vanish at a root in "
                                           f"{solution.variable}")
                values[lift.unknown] = ball_value(lift.numerator.to_flint(), values) / bottom
            found.append(Mode(index, None, {u: values[u] for u in (solution.variable, *solution.unknowns)
                                            if u in values}))
    return tuple(found)


def _real(root: flint.acb, roots: Sequence[flint.acb]) -> bool:
    """Whether the isolated ``root`` is real (its disc meets the real axis and its mirror image
    meets no other disc), False where it is certified not real."""
    if not root.imag.contains(0):
        return False
    mirror = root.conjugate()
    if any(other is not root and mirror.overlaps(other) for other in roots):
        raise ComputationError("at this sample a root of the eliminant is too close to another to tell whether "
                               "it is real")
    return True


def modes_in_sequence(solutions: Sequence[GroupSolution], at: Mapping[str, flint.fmpq], *,
                      balls: Mapping[str, flint.arb] | None = None, bits: int = 128) -> list[tuple[Mode, ...]]:
    """Every real configuration of groups solved in turn (``solutions`` in dependency order, a
    later group's parameters the inputs ``at`` and earlier groups' unknowns): one mode per group,
    a later group's modes found at each earlier combination's balls (``modes_in_balls``), the
    first groups' over QQ (``modes``). Combinations in order: the first group's modes outermost.
    ``balls``: inputs known only as balls (an angle's irrational cos and sin): a group holding one
    is solved in balls too (``modes_in_balls``'s ComputationError where they are too wide to tell).

    >>> import flint
    >>> from .solve import solve_group
    >>> ctx = flint.fmpq_mpoly_ctx.get(("x", "y", "r"), "lex")
    >>> x, y, r = ctx.gens()
    >>> solution = solve_group([x**2 + y**2 - r, x - 2*y], ["x", "y"])
    >>> with flint.ctx.workprec(256):   # the balls narrower than the 128 bits the roots are refined to
    ...     r_ball = flint.arb.pi() * 5    # so y = -+sqrt(pi)
    >>> found = modes_in_sequence([solution], {}, balls={"r": r_ball})
    >>> [round(float(m.values["y"]), 6) for m, in found]
    [-1.772454, 1.772454]
    """
    known = {u for s in solutions for u in s.unknowns}
    inexact = dict(balls or {})
    combinations: list[tuple[Mode, ...]] = [()]
    for solution in solutions:
        held = [p for p in solution.parameters if p in known]
        given = {p: inexact[p] for p in solution.parameters if p in inexact}
        if not held and not given:
            own = modes(solution, {p: at[p] for p in solution.parameters}, bits=bits)
            combinations = [c + (m,) for c in combinations for m in own]
            continue
        combinations = [c + (m,) for c in combinations
                        for m in modes_in_balls(solution, at, _values(c, held) | given, bits=bits)]
    return combinations


def _values(combination: Sequence[Mode], names: Sequence[str]) -> dict[str, flint.arb]:
    values = {u: v for mode in combination for u, v in mode.values.items()}
    return {n: values[n] for n in names}


def ball_value(poly: flint.fmpq_mpoly, values: Mapping[str, flint.arb]) -> flint.arb:
    """``poly`` at ``values`` (a ball for every name it holds), by Horner's rule in its first held name."""
    names = [str(n) for n in poly.context().names()]
    held = [n for n, d in zip(names, poly.degrees()) if d > 0]
    if not held:
        return flint.arb(poly.coeffs()[0]) if not poly.is_zero() else flint.arb(0)
    total = flint.arb(0)
    for part in reversed(coefficients(poly, held[0])):
        total = total * values[held[0]] + ball_value(part, values)
    return total
