"""Two quadrics whose quadratic parts are a fixed multiple of each other (two circles, a
circle and a line), solved through their linear combination, with no random start.

``q2 * first - q1 * second`` (``q1 != 0`` the first's leading quadratic coefficient) has no
quadratic term: the block is equivalent to ``first`` and that line. Solving the line for
one unknown leaves one quadratic in the other: every real root of the block comes from it,
in floats for all samples at once (``Pencil.solve``) and in balls for one sample
(``Pencil.enclose``). Both work from the block's own equations, never from a closed form.

>>> import flint
>>> from algkin.system import symbol
>>> x, y = symbol("x"), symbol("y")
>>> circles = Pencil.of([x**2 + y**2 - 4, (x - 2)**2 + y**2 - 4], [x, y], [])
>>> with flint.ctx.workprec(200):
...     root = circles.enclose([1.0, 1.7320508], [])
>>> root[0].overlaps(flint.arb(1)), root[1].overlaps(flint.arb(3).sqrt()), root[1].rad() < 1e-50
(True, True, True)
"""

from __future__ import annotations

import operator
from collections.abc import Mapping, Sequence
from typing import TypeAlias

import flint
import numpy as np
import sympy
from flint import arb
from numpy.typing import NDArray

from ..evaluate import ARB, NUMPY
from ..evaluate.program import ArrayProgram, BallProgram, Floats, columns, compile_program
from ..system.convert import flint_context, from_terms, to_flint
from ..system.roots import quadratic_roots

__all__ = ["Pencil"]

NEAR = 1e-6  # how far (relative) a float candidate may be from the root it stands for
Enclosure: TypeAlias = list[arb]  # one ball per unknown of the block

MONOMIALS = ((2, 0), (1, 1), (0, 2), (1, 0), (0, 1), (0, 0))


class Pencil:
    """The pencil of a 2 x 2 block: ``first``'s six coefficients (u^2, uv, v^2, u, v, 1) and the
    linear combination's three (u, v, 1), compiled as programs of the known values."""

    def __init__(self, first: list[sympy.Expr], line: list[sympy.Expr], known: list[str]) -> None:
        self.known = known
        self.first: ArrayProgram = compile_program(first, known, NUMPY)
        self.line: ArrayProgram = compile_program(line, known, NUMPY)
        # balls: one program for all nine coefficients; the two roots of the last sample remembered,
        # with their midpoints in floats (each of the sample's candidates is measured against them)
        self.coefficients: BallProgram = compile_program(list(first) + list(line), known, ARB)
        self._last: tuple[tuple[arb, ...] | None, list[Enclosure] | None, list[list[float]] | None] = \
            (None, None, None)

    @classmethod
    def of(cls, equations: Sequence[sympy.Expr], unknowns: Sequence[sympy.Symbol], known: list[str]) -> Pencil | None:
        """The pencil of a block of ``equations`` in ``unknowns``, or ``None`` where it is not one.

        Its combination is taken in python-flint: sympy's product of a number and an equation
        asked the assumptions of every term, most of a cold verification's setup."""
        if len(equations) != 2:
            return None
        others = sorted(set().union(*(eq.free_symbols for eq in equations)) - set(unknowns), key=lambda v: v.name)
        names = [v.name for v in [*unknowns, *others]]
        if len(set(names)) != len(names):
            return None
        ring = flint_context(names)
        try:
            polys = [to_flint(eq, ring) for eq in equations]
        except TypeError:  # not polynomials over the rationals
            return None
        if any(sum(m[:2]) > 2 for p in polys for m in p.monoms()):
            return None
        found = [[_number(p, m) for m in MONOMIALS[:3]] for p in polys]
        quadratic = [[q for q in row if q is not None] for row in found]
        # the combination q2 * first - q1 * second must cancel every quadratic term, with numbers
        pivot = next((k for k in range(3) if found[0][k] != 0), None)
        if pivot is None or any(len(row) < 3 for row in quadratic):
            return None
        q1, q2 = quadratic[0][pivot], quadratic[1][pivot]
        if any(q2 * a - q1 * b != 0 for a, b in zip(*quadratic)):
            return None
        first, line = _split(polys[0], others), _split(q2 * polys[0] - q1 * polys[1], others)
        zero = sympy.Integer(0)
        return cls([first.get(m, zero) for m in MONOMIALS], [line.get(m, zero) for m in MONOMIALS[3:]], known)

    def solve(self, values: Mapping[str, Floats], count: int) -> tuple[NDArray[np.intp], Floats, Floats]:
        """``(parent rows, u, v)`` in floats: the real solutions of every row (a double root counts twice)."""
        arguments = [values[n] if n in values else np.zeros(count) for n in self.known]
        first = columns(self.first(*arguments), count).T
        a, b, c = columns(self.line(*arguments), count).T
        # solve the line for the unknown with the larger coefficient: u = p v + r (or v = p u + r)
        swap = np.abs(b) > np.abs(a)
        lead, other = np.where(swap, b, a), np.where(swap, a, b)
        with np.errstate(all="ignore"):
            p, r = -other / lead, -c / lead
            # the first equation in the free unknown t (v, or u where swapped)
            uu, uv, vv, u, v, one = first
            uu, vv, u, v = np.where(swap, vv, uu), np.where(swap, uu, vv), np.where(swap, v, u), np.where(swap, u, v)
            quad = uu * p * p + uv * p + vv
            lin = 2 * uu * p * r + uv * r + u * p + v
            const = uu * r * r + u * r + one
            disc = lin * lin - 4 * quad * const
            root = np.sqrt(np.maximum(disc, 0))
            # the two roots without cancellation: q = -(lin + sign(lin) root) / 2
            q = -0.5 * (lin + np.copysign(root, lin))
            t = np.stack([q / quad, const / q], axis=1)
        keep = np.isfinite(t) & (disc >= -1e-12 * (lin * lin + np.abs(4 * quad * const)))[:, None]
        rows = np.repeat(np.arange(count)[:, None], 2, axis=1)[keep]
        t = t[keep]
        dependent = p[rows] * t + r[rows]
        return rows, np.where(swap[rows], t, dependent), np.where(swap[rows], dependent, t)

    def enclose(self, candidate: Sequence[float], known: Sequence[arb]) -> Enclosure | None:
        """Balls ``[u, v]`` holding the root next to the float ``candidate``, for every value of the
        ``known`` balls, or ``None`` where the two roots are not proved distinct (near a double
        root) or the candidate is near neither.

        Both roots are enclosed at once (a sample's candidates share their ``known`` balls)."""
        last_known, roots, middles = self._last
        if last_known is None or len(last_known) != len(known) or not all(map(operator.is_, last_known, known)):
            roots = self._roots([c if type(c) is arb else arb(c) for c in self.coefficients(*known)])
            middles = None if roots is None else [[float(b) for b in root] for root in roots]
            self._last = (tuple(known), roots, middles)
        if roots is None or middles is None:
            return None
        u, v = candidate
        (u0, v0), (u1, v1) = middles
        near, far = max(abs(u0 - u), abs(v0 - v)), max(abs(u1 - u), abs(v1 - v))
        gap, root = (far, roots[1]) if far < near else (near, roots[0])  # the nearer root, the first if both are
        # a candidate far from both roots is no float solution: nothing is proved next to it
        return root if gap <= NEAR * max(1.0, abs(u), abs(v)) else None

    @staticmethod
    def _roots(coefficients: list[arb]) -> list[Enclosure] | None:
        """Both roots in balls, each unknown's, or ``None`` unless they are proved real and distinct."""
        uu, uv, vv, u, v, one, a, b, c = coefficients
        swap = abs(float(b.mid())) > abs(float(a.mid()))
        lead, other = (b, a) if swap else (a, b)
        if not (lead > 0 or lead < 0):
            return None
        p, r = -other / lead, -c / lead
        if swap:
            uu, vv, u, v = vv, uu, v, u
        quad = uu * p * p + uv * p + vv
        lin = 2 * uu * p * r + uv * r + u * p + v
        const = uu * r * r + u * r + one
        both = quadratic_roots(quad, lin, const)
        if both is None:
            return None
        roots = []
        for t in both:
            dependent = p * t + r
            if not (t.is_finite() and dependent.is_finite()):
                return None
            roots.append([t, dependent] if swap else [dependent, t])
        return roots


def _number(poly: flint.fmpq_mpoly, monomial: tuple[int, int]) -> flint.fmpq | None:
    """The coefficient of ``monomial`` of the two unknowns (the ring's first two variables) in
    ``poly``, where it is a number (0 where there is no such term); None where it holds other variables."""
    terms = [(m, c) for m, c in zip(poly.monoms(), poly.coeffs()) if tuple(m[:2]) == monomial]
    if any(any(m[2:]) for m, _ in terms):
        return None
    return terms[0][1] if terms else flint.fmpq(0)


def _split(poly: flint.fmpq_mpoly, others: Sequence[sympy.Symbol]) -> dict[tuple[int, ...], sympy.Expr]:
    """``poly``'s coefficients in the two unknowns (the ring's first two variables), each a sympy
    expression in ``others``: ``convert.coefficients`` of the same polynomial, the same expressions."""
    split: dict[tuple[int, ...], dict[tuple[int, ...], flint.fmpq]] = {}
    for exponents, coefficient in zip(poly.monoms(), poly.coeffs()):
        split.setdefault(tuple(exponents[:2]), {})[tuple(exponents[2:])] = coefficient
    return {exponents: from_terms(terms, others) for exponents, terms in split.items()}
