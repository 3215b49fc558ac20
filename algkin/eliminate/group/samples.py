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

from collections.abc import Mapping

import flint
import sympy

from ...errors import ComputationError, UsageError
from ...system.roots import RealRoot, real_roots
from .algebra import univariate
from .records import GroupSolution, Mode, Values

__all__ = ["modes"]


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

