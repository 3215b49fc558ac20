"""Velocity and acceleration of a group's unknowns by the implicit function theorem on its own equations.

Along the motion the group's equations ``F(X, t) = 0`` hold, so ``J X' = -F_t`` (``J`` the
Jacobian in the unknowns ``X``, ``F_t`` the derivative in the input). By Cramer's rule each
velocity is ``N_k / D`` with ``D = det J`` and ``N_k`` the determinant of ``J`` with its
``k``-th column replaced by ``-F_t``: polynomials in the unknowns and the input's variables,
rational at every mode where ``D`` does not vanish (where it does, two modes meet: a toggle).
The acceleration is the total derivative ``d/dt = d/dt|_X + sum_j X'_j d/dX_j`` of the velocity:
``(D (D N_k,t + sum_j N_j N_k,j) - N_k (D D_t + sum_j N_j D_j)) / D**3``. An angle's variables are
its ``c``, ``s``, and ``d/dt = -s d/dc + c d/ds`` (per radian); a length's is itself.

A point on the circle of radius 2 about the origin whose ``x`` is the input ``r``: ``x' = 1`` and
``y' = -x/y`` (``D = 2y``, ``N_y = -2x``); at ``(0, 2)``, ``y'' = -(y**2 + x**2)/y**3 = -1/2``:

>>> import flint
>>> ctx = flint.fmpq_mpoly_ctx.get(("x", "y", "r"), "lex")
>>> x, y, r = ctx.gens()
>>> forms = implicit_rates([x - r, x**2 + y**2 - 4], ("x", "y"), ("r",))
>>> str(forms.denominator), str(forms.velocity["y"]), str(forms.acceleration["y"])
('2*y', '-2*x', '-8*x^2 - 8*y^2')
>>> balls = {"x": flint.arb(0), "y": flint.arb(2), "r": flint.arb(0)}
>>> [str(v) for v in forms.at(balls)["y"]]
['0', '-0.500000000000000']
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import attrs
import flint

from ...runtime.frozen import FrozenDict, frozen

__all__ = ["ImplicitRates", "implicit_rates", "evaluate", "total_input_derivative"]


@attrs.frozen(eq=False)
class ImplicitRates:
    """A group's rates: ``denominator`` ``D = det J``, and per unknown the ``velocity`` numerator
    (over ``D``) and the ``acceleration`` numerator (over ``D**3``), python-flint polynomials in
    the unknowns and the input's variables (and any other parameter of the equations)."""

    unknowns: tuple[str, ...]
    variables: tuple[str, ...]
    denominator: flint.fmpq_mpoly
    velocity: FrozenDict[str, flint.fmpq_mpoly] = attrs.field(converter=frozen)
    acceleration: FrozenDict[str, flint.fmpq_mpoly] = attrs.field(converter=frozen)

    def at(self, values: Mapping[str, flint.arb], exact: Mapping[str, flint.fmpq] | None = None,
           ) -> dict[str, tuple[flint.arb, flint.arb]]:
        """Each unknown's velocity and acceleration in balls at ``values`` (a ball for every variable
        not in ``exact``); the ``exact`` ones (the input's, rational) put in first, exactly: fewer terms."""
        def at(poly: flint.fmpq_mpoly) -> flint.arb:
            names = {str(n) for n in poly.context().names()}
            point: dict[str | int, int | flint.fmpz | flint.fmpq] = \
                {n: v for n, v in (exact or {}).items() if n in names}
            return evaluate(poly.subs(point) if point else poly, values)

        d = at(self.denominator)
        cube = d * d * d
        return {u: (at(self.velocity[u]) / d, at(self.acceleration[u]) / cube) for u in self.unknowns}


def implicit_rates(equations: Sequence[flint.fmpq_mpoly], unknowns: Sequence[str],
                   variables: Sequence[str]) -> ImplicitRates:
    """The rates of ``unknowns`` held by ``equations`` (as many, one context) as the input moves
    (``variables``: an angle's ``(c, s)`` or a length's one name)."""
    (first,) = {e.context() for e in equations}
    names = [str(n) for n in first.names()]
    zero = first.from_dict({})
    jacobian = [[e.derivative(u) for u in unknowns] for e in equations]
    moving = [-total_input_derivative(e, variables, names) for e in equations]
    d = determinant(jacobian, zero)
    velocity = {u: determinant([row[:k] + [moving[i]] + row[k + 1:] for i, row in enumerate(jacobian)], zero)
                for k, u in enumerate(unknowns)}

    def along(p: flint.fmpq_mpoly) -> flint.fmpq_mpoly:  # D times p's total derivative
        return d * total_input_derivative(p, variables, names) + sum((velocity[u] * p.derivative(u) for u in unknowns),
                                                                     zero)

    moving_d = along(d)
    acceleration = {u: d * along(velocity[u]) - velocity[u] * moving_d for u in unknowns}
    return ImplicitRates(tuple(unknowns), tuple(variables), d, velocity, acceleration)


def total_input_derivative(poly: flint.fmpq_mpoly, variables: Sequence[str], names: Sequence[str]) -> flint.fmpq_mpoly:
    """``poly``'s derivative in the input with the unknowns held (per radian of an angle whose
    ``variables`` are ``(c, s)``; per unit of a length); zero where the input is not in ``names``.

    >>> ctx = flint.fmpq_mpoly_ctx.get(("x", "c", "s"), "lex")
    >>> x, c, s = ctx.gens()
    >>> total_input_derivative(x * c + s, ("c", "s"), ("x", "c", "s"))
    -x*s + c
    """
    zero = poly.context().from_dict({})
    if len(variables) == 2:
        c, s = variables
        gens = dict(zip(names, poly.context().gens()))
        cosine = poly.derivative(c) if c in names else zero
        sine = poly.derivative(s) if s in names else zero
        return (gens[c] * sine if s in names else zero) - (gens[s] * cosine if c in names else zero)
    (length,) = variables
    return poly.derivative(length) if length in names else zero


def determinant(rows: Sequence[Sequence[flint.fmpq_mpoly]], zero: flint.fmpq_mpoly) -> flint.fmpq_mpoly:
    """The determinant by Bareiss's fraction-free elimination (every division exact).

    >>> ctx = flint.fmpq_mpoly_ctx.get(("a", "b"), "lex")
    >>> a, b = ctx.gens()
    >>> str(determinant([[a, b], [b, a]], ctx.from_dict({}))), str(determinant([[0 * a, a], [b, 0 * a]], 0 * a))
    ('a^2 - b^2', '-a*b')
    """
    m = [list(r) for r in rows]
    n, sign, previous = len(m), 1, zero + 1
    for k in range(n - 1):
        pivot = next((i for i in range(k, n) if not m[i][k].is_zero()), None)
        if pivot is None:
            return zero
        if pivot != k:
            m[k], m[pivot], sign = m[pivot], m[k], -sign
        for i in range(k + 1, n):
            for j in range(k + 1, n):
                m[i][j] = (m[i][j] * m[k][k] - m[i][k] * m[k][j]) / previous
        previous = m[k][k]
    return m[n - 1][n - 1] * sign


def evaluate(poly: flint.fmpq_mpoly, values: Mapping[str, flint.arb]) -> flint.arb:
    """``poly`` in balls at ``values`` (a ball for every variable it holds), term by term."""
    names = [str(n) for n in poly.context().names()]
    powers: dict[tuple[int, int], flint.arb] = {}  # each variable's powers once, not once per term
    total = flint.arb(0)
    for exponents, coefficient in zip(poly.monoms(), poly.coeffs()):
        term = flint.arb(coefficient)
        for k, e in enumerate(exponents):
            if e:
                power = powers.get((k, e))
                if power is None:
                    power = powers[(k, e)] = values[names[k]] ** int(e)
                term *= power
        total += term
    return total
