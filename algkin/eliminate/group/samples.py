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

At parameters known only as balls (an angle's irrational cosine; here r = 5 pi, so y = -+sqrt(pi)),
``ball_modes``:

>>> with flint.ctx.workprec(128):
...     found = ball_modes(solution, {"r": flint.arb.pi() * 5})
>>> [round(float(m.values["y"]), 6) for m in found], ball_modes(solution, {"r": flint.arb(0, 1)})
([-1.772454, 1.772454], None)
"""

from __future__ import annotations

from collections.abc import Mapping

import flint
import sympy

from ...errors import ComputationError, UsageError
from ...system.roots import RealRoot, real_roots
from .algebra import univariate
from .records import GroupSolution, Mode, Polynomial, Values

__all__ = ["modes", "ball_modes"]


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


def ball_modes(solution: GroupSolution, at: Mapping[str, flint.arb], *, bits: int = 128
               ) -> tuple[Mode, ...] | None:
    """Every real solution of ``solution``'s group with its parameters in the balls ``at`` (an
    angle's irrational cos and sin), at ``bits`` of precision, in increasing order of the
    variable (a mode's ``root`` is None: no exact root); None where the balls are too wide to
    tell: the leading coefficient's ball holds 0, the roots are not isolated (two meet, or
    nearly), a root is not told real or not, a lift's denominator holds 0. The caller raises
    the precision of ``at`` and ``bits``.

    A root is isolated in a box holding exactly one root of every polynomial in the balls (Arb's
    certified isolation); the eliminant is real, so a box meeting no other box's mirror image
    holds its own root's conjugate: that root is real. A box off the real axis holds none."""
    missing = [p for p in solution.parameters if p not in at]
    if missing:
        raise UsageError("at", dict(at), f"needs a value for every parameter; missing {', '.join(missing)}")
    with flint.ctx.workprec(bits):
        roots = _isolated(_ball_coefficients(solution.eliminant, solution.variable, at))
        if roots is None:
            return None
        found = []
        for index, root in enumerate(roots):
            values = {solution.variable: root}
            point = dict(at) | {solution.variable: root}
            for lift in solution.lifts:
                below = _ball_value(lift.denominator, point)
                if below.contains(0):
                    return None
                values[lift.unknown] = _ball_value(lift.numerator, point) / below
            found.append(Mode(index, None, values))
        return tuple(found)


def _ball_coefficients(poly: Polynomial, variable: str, at: Mapping[str, flint.arb]) -> list[flint.arb]:
    """``poly``'s coefficients in ``variable``, low to high, the other names in the balls ``at``."""
    coefficients = [flint.arb(0)] * (poly.degree(variable) + 1)
    place = poly.names.index(variable)
    for exponents, p, q in poly.terms:
        coefficients[exponents[place]] += _term(exponents, p, q, names=poly.names, at=at, skip=variable)
    return coefficients


def _ball_value(poly: Polynomial, at: Mapping[str, flint.arb]) -> flint.arb:
    return sum((_term(e, p, q, names=poly.names, at=at) for e, p, q in poly.terms), flint.arb(0))


def _term(exponents: tuple[int, ...], p: int, q: int, *, names: tuple[str, ...], at: Mapping[str, flint.arb],
          skip: str | None = None) -> flint.arb:
    value = flint.arb(flint.fmpq(p, q))
    for name, power in zip(names, exponents):
        if power and name != skip:
            value *= at[name] ** power
    return value


def _isolated(coefficients: list[flint.arb]) -> list[flint.arb] | None:
    """The real roots of the polynomial with these ball ``coefficients``, ascending, each
    certified real and alone in its ball; None where the balls cannot tell."""
    if coefficients[-1].contains(0):
        return None
    try:
        boxes = flint.acb_poly([flint.acb(c) for c in coefficients]).roots(tol=flint.arb(2) ** (32 - flint.ctx.prec))
    except ValueError:  # not isolated at this precision: roots meet or nearly
        return None
    real = []
    for k, box in enumerate(boxes):
        if not box.imag.contains(0):
            continue
        if any(box.overlaps(other.conjugate()) for j, other in enumerate(boxes) if j != k):
            return None
        real.append(box.real)
    return sorted(real, key=lambda ball: ball.mid())


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

