"""Numeric solutions of a polynomial system, found without any closed form, for many inputs at once.

The system is split into blocks solved in turn (a square subsystem in the unknowns not
solved yet). Every block is solved for all samples (and every partial solution) in one
vectorised pass over float64: a block in one unknown by the eigenvalues of its companion
matrices, a larger one by Newton's method from many random starts per sample. What comes
out are candidates: ``balls.Certifier`` proves each one (or not) on the original equations.

>>> import numpy as np, sympy
>>> from algkin.system import System, symbol
>>> x, y, c = symbol("x"), symbol("y"), symbol("c")
>>> system = System(("x", "y"), (), {"t": ("c", "s")}, (x**2 + y**2 - 4, x - y - c))
>>> found = solve_floats(blocks_of(system), {"c": np.array([0.0]), "s": np.array([1.0])},
...                      np.random.default_rng(0))
>>> sorted(np.round(found.values["x"], 12).tolist())
[-1.414213562373, 1.414213562373]
"""

from __future__ import annotations

import functools
import itertools
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from fractions import Fraction
from typing import TypeAlias

import flint
import numpy as np
import sympy
from numpy.typing import NDArray

from ..evaluate import NUMPY
from ..evaluate.program import ArrayProgram, Floats, columns, compile_program
from ..runtime.cache import BoundedCache
from ..system import System, symbol
from ..system.convert import coefficients
from .pencil import Pencil

__all__ = ["Blocks", "Candidates", "blocks_of", "solve_floats", "STARTS"]

Rows: TypeAlias = NDArray[np.intp]  # row numbers: of samples, or of partial solutions

STARTS = 8  # random Newton starts per sample and block; a sample that lacks a root retries with more
STEPS = 60
ABANDON_AFTER = 8  # Newton steps after which a start still far from vanishing is given up
ABANDON_RESIDUAL = 1e-4  # relative to the squared scale: the equations are quadratic in lengths
CONVERGED = 1e-13  # a Newton step this small (relative to the block's scale) ends the iteration
NOISE = 1e-14  # a coefficient this small beside the sum of its terms' sizes is taken as 0
SAME_ROOT = 1e-7  # end points closer than this (relative) are one root


class Blocks:
    """The block-triangular structure of a system, each block compiled once for numpy arrays."""

    def __init__(self, system: System) -> None:
        self.system = system
        self.names = list(system.variables)
        unknown = {symbol(u) for u in system.unknowns}
        moving = [k for k, eq in enumerate(system.equations) if eq.free_symbols & unknown]
        pending = [system.equations[k] for k in moving]
        # Coordinates are about as large as the lengths, whose squares are coefficients: Newton's
        # starts must spread over that size too, not only over the known values (cos, sin). The
        # coefficients are the system's python-flint polynomials' (converted once, for the elimination)
        self.size = max((abs(_float(c)) ** 0.5 for k in moving for c in system.polynomials[k].coeffs()), default=0.0)
        solved: set[str] = set()
        self.blocks: list[_Block] = []
        self.equations: list[sympy.Expr] = []
        while len(solved) < len(system.unknowns):
            names, equations = self._next_block(pending, solved)
            for eq in equations:
                pending.remove(eq)
            solved |= set(names)
            self.equations += equations
            self.blocks.append(_Block(names, equations, self.names))

    def _next_block(self, pending: list[sympy.Expr], solved: set[str]) -> tuple[list[str], list[sympy.Expr]]:
        unknown = {symbol(u) for u in self.system.unknowns} - {symbol(u) for u in solved}
        for size in range(1, 5):
            candidates = [eq for eq in pending if 0 < len(eq.free_symbols & unknown) <= size]
            for group in itertools.combinations(candidates, size):
                block_vars = set().union(*(eq.free_symbols & unknown for eq in group))
                if len(block_vars) == size:
                    return sorted(str(v) for v in block_vars), list(group)
        raise ValueError("the system has no square block left to solve numerically")


class _Block:
    def __init__(self, names: list[str], equations: list[sympy.Expr], variables: list[str]) -> None:
        self.names = names
        self.equations = equations
        used = {str(v) for eq in equations for v in eq.free_symbols}
        # only the variables the block uses are passed in: fewer arrays to gather per Newton step
        arguments = self.arguments = [v for v in variables if v in used or v in names]
        unknowns = [symbol(n) for n in names]
        # Newton solves a linear block in one step from anywhere: one start is enough
        terms = [coefficients(eq, unknowns) for eq in equations]
        self.linear = all(sum(m) <= 1 for t in terms for m in t)
        self.unknowns = unknowns
        self.pencil: Pencil | None = None  # two circles (or a circle and a line): the certifier's too
        if len(names) == 1:
            degree = max(m[0] for m in terms[0])
            highest_first = [terms[0].get((d,), sympy.Integer(0)) for d in range(degree, -1, -1)]
            self.coefficients: ArrayProgram | None = compile_program(highest_first, arguments, NUMPY)
            self.magnitudes: ArrayProgram = compile_program([_magnitude(c) for c in highest_first], arguments, NUMPY)
        else:
            self.coefficients = None
            self.residual: ArrayProgram = compile_program(equations, arguments, NUMPY)
            self.pencil = Pencil.of(equations, unknowns, [a for a in arguments if a not in names])

    @functools.cached_property
    def jacobian(self) -> ArrayProgram:
        """The Jacobian as a program, differentiated when first needed: a block its pencil solves
        and proves never needs it."""
        return compile_program(jacobian(self.equations, self.unknowns), self.arguments, NUMPY)


def _float(value: flint.fmpq) -> float:
    """``float(sympy.Rational(value))``: the nearest float (``Fraction``'s division rounds correctly too)."""
    return float(Fraction(int(value.p), int(value.q)))


def _magnitude(coefficient: sympy.Expr) -> sympy.Expr:
    """The sum of the absolute values of ``coefficient``'s terms (a polynomial in the known values):
    the size its float value is rounded against.

    >>> c, s = symbol("c"), symbol("s")
    >>> _magnitude(3 - 2*c*s)
    2*Abs(c*s) + 3
    """
    return sympy.Add(*[sympy.Abs(term) for term in sympy.Add.make_args(coefficient)])


def jacobian(equations: list[sympy.Expr], unknowns: list[sympy.Symbol]) -> list[sympy.Expr]:
    """The Jacobian of ``equations`` in ``unknowns``, row by row: the expressions of
    ``list(sympy.Matrix(equations).jacobian(unknowns))``, each ``derivative``'s.

    >>> from algkin.system import symbol
    >>> x, y = symbol("x"), symbol("y")
    >>> jacobian([x**2 + y**2 - 4, x - 3*y], [x, y])
    [2*x, 2*y, 1, -3]
    """
    return [derivative(eq, u) for eq in equations for u in unknowns]


def derivative(expr: sympy.Expr, u: sympy.Symbol) -> sympy.Expr:
    """``expr.diff(u)``, the same expression, built by the rules sympy's ``diff`` applies to sums,
    products and integer powers, without its ``Derivative`` at every node (most of a cold
    process's Jacobians: its assumptions are asked of every subexpression).

    >>> from algkin.system import symbol
    >>> x, c = symbol("x"), symbol("c")
    >>> derivative((x - c)**2 + 3*c*x**3 - 1, x)
    9*c*x**2 - 2*c + 2*x
    """
    if u not in expr.free_symbols:
        return sympy.S.Zero
    if expr == u:
        return sympy.S.One
    if expr.is_Add:
        return sympy.Add(*[derivative(a, u) for a in expr.args])
    if expr.is_Mul:  # sympy's Leibniz rule: one factor differentiated in each term
        factors = expr.args
        return sympy.Add(*[sympy.Mul(*factors[:k], derivative(f, u), *factors[k + 1:]) for k, f in enumerate(factors)])
    if expr.is_Pow and expr.exp.is_Integer:  # sympy's b**e * (b' * e / b): its log(b) term is zero
        return expr * (derivative(expr.base, u) * expr.exp / expr.base)
    return expr.diff(u)


def blocks_of(system: System) -> Blocks:
    """The system's ``Blocks``, compiled once per system (a hashable value: its own key) and
    reused by later calls (``BLOCKS``)."""
    return BLOCKS.get(system, lambda: Blocks(system))


BLOCKS: BoundedCache[Blocks] = BoundedCache(64, name="systems' numeric blocks")


@dataclass
class Candidates:
    """Newton's end points for every sample; nothing here is proved.

    ``owner[k]`` is the sample candidate ``k`` solves, ``values`` maps every variable to an
    array over the candidates, ``lineage[b][k]`` is the partial solution candidate ``k``
    extends after block ``b`` (candidates share their first blocks' roots), and
    ``inverses[b][r]`` is the float inverse of block ``b``'s Jacobian at partial solution
    ``r`` (nan for a univariate block), for the proof in balls to start from.
    """

    owner: Rows
    values: dict[str, Floats]
    lineage: list[Rows]
    inverses: Inverses


class Inverses:
    """Per block ``b``, ``inverses[b]``: its Jacobian's float inverse at each of its partial solutions
    (``_inverses``), computed when first asked: a block its pencil or its formula proves needs none.
    ``at(b, r)`` is ``inverses[b][r]``."""

    def __init__(self) -> None:
        self._blocks: list[tuple[_Block, Mapping[str, Floats], int]] = []
        self._made: dict[int, Floats] = {}

    def add(self, block: _Block, values: Mapping[str, Floats], count: int) -> None:
        """The next block, solved: ``values`` over its ``count`` partial solutions (never changed after)."""
        self._blocks.append((block, values, count))

    def __getitem__(self, b: int) -> Floats:
        if b not in self._made:
            self._made[b] = _inverses(*self._blocks[b])
        return self._made[b]

    def __len__(self) -> int:
        return len(self._blocks)

    def at(self, b: int, r: int) -> Floats:
        inverse: Floats = self[b][r]
        return inverse


def solve_floats(blocks: Blocks, known: Mapping[str, Floats], rng: np.random.Generator,
                 starts: int = STARTS) -> Candidates:
    """``Candidates`` for every sample; ``known`` maps each input and parameter variable to a
    float array over the samples."""
    count = len(next(iter(known.values()))) if known else 1
    owner = np.arange(count)
    values = {n: np.broadcast_to(np.asarray(v, dtype=float), (count,)) for n, v in known.items()}
    parents, inverses = [], Inverses()
    for block in blocks.blocks:
        if block.coefficients is not None:
            parent, found = _univariate(block, values, len(owner))
        elif block.pencil is not None and starts <= STARTS:  # a retry searches by Newton, more widely
            parent, first, second = block.pencil.solve(values, len(owner))
            found = dict(zip(block.names, (first, second)))
        else:
            parent, found = _newton(block, values, scale=_scale(values, blocks.size, len(owner)), rng=rng,
                                    starts=starts)
        parents.append(parent)
        owner = owner[parent]
        values = {n: v[parent] for n, v in values.items()}
        values.update(found)
        inverses.add(block, values, len(owner))
    lineage = [np.arange(len(owner))]
    for parent in reversed(parents[1:]):
        lineage.insert(0, parent[lineage[0]])
    return Candidates(owner, values, lineage, inverses)


def _inverses(block: _Block, values: Mapping[str, Floats], count: int) -> Floats:
    """The block's Jacobian inverted at every row, in floats (nan where singular or univariate)."""
    size = len(block.names)
    if block.coefficients is not None or not count:
        return np.full((count, size, size), np.nan)
    j = columns(block.jacobian(*_arguments(block.arguments, values, count)), count).reshape(count, size, size)
    inverse = np.full_like(j, np.nan)
    with np.errstate(all="ignore"):
        regular = np.isfinite(j).all(axis=(1, 2)) & (np.abs(np.linalg.det(j)) > 0)
        inverse[regular] = np.linalg.inv(j[regular])
    return inverse


def _scale(values: Mapping[str, Floats], size: float, count: int) -> Floats:
    """Per row: how far from the origin the roots may be (the known values and the lengths)."""
    known = [np.abs(v) for v in values.values()]
    largest = np.max(np.stack(known), axis=0) if known else np.zeros(count)
    return 2 * (np.maximum(largest, size) + 1)


def _arguments(names: Iterable[str], values: Mapping[str, Floats], count: int) -> list[Floats]:
    """The arrays of ``names`` in ``values``, zeros for a variable with none."""
    return [values[n] if n in values else np.zeros(count) for n in names]


def _univariate(block: _Block, values: Mapping[str, Floats], count: int) -> tuple[Rows, dict[str, Floats]]:
    """Real eigenvalues of each of the ``count`` rows' companion matrices (rows grouped by their actual
    degree); ``values`` holds no array where nothing is known (a point fixed in a scene with no input)."""
    assert block.coefficients is not None  # only a block in one unknown is solved here
    arguments = _arguments(block.arguments, values, count)
    coeffs = columns(block.coefficients(*arguments), count)
    # a coefficient is zero where it is within its own rounding, not where it is small beside the
    # others: roots far from the origin (a mechanism of lengths 1e15) have a leading coefficient
    # 1e-15 of the constant's
    nonzero = np.abs(coeffs) > NOISE * columns(block.magnitudes(*arguments), count)
    lead = np.where(nonzero.any(axis=1), nonzero.argmax(axis=1), coeffs.shape[1])
    parents, roots = [], []
    for first in sorted(set(lead.tolist())):  # np.unique's: it would load numpy.ma, 10 ms of a cold command
        rows = np.flatnonzero(lead == first)
        degree = coeffs.shape[1] - 1 - first
        if degree < 1:
            continue
        monic = coeffs[rows, first + 1:] / coeffs[rows, first][:, None]
        if degree == 1 and _plain(monic):  # the 1 x 1 companion's eigenvalue, as LAPACK gives it
            parents.append(rows)
            roots.append(-monic[:, 0])
            continue
        companion = np.zeros((len(rows), degree, degree))
        companion[:, 0, :] = -monic
        companion[:, np.arange(1, degree), np.arange(degree - 1)] = 1
        eig = np.linalg.eigvals(companion)
        real = np.abs(eig.imag) <= 1e-7 * (1 + np.abs(eig.real))
        parents.append(np.repeat(rows, real.sum(axis=1)))
        roots.append(eig.real[real])
    parent = np.concatenate(parents) if parents else np.zeros(0, dtype=int)
    return parent, {block.names[0]: np.concatenate(roots) if roots else np.zeros(0)}


def _plain(values: Floats) -> bool:
    """Whether every value is 0 or within 1e-130 and 1e130 in size: where LAPACK's eigenvalue of a
    1 x 1 matrix is its entry, exactly (it rescales a matrix near the floats' ends, and refuses nan).

    >>> _plain(np.array([[0.0], [-2.5e100]])), _plain(np.array([[1e200]])), _plain(np.array([[np.nan]]))
    (True, False, False)
    """
    size = np.abs(values)
    return bool(np.all((size == 0) | ((size > 1e-130) & (size < 1e130))))


def _newton(block: _Block, values: Mapping[str, Floats], *, scale: Floats, rng: np.random.Generator,
            starts: int) -> tuple[Rows, dict[str, Floats]]:
    """Newton from ``starts`` random points per row, all rows at once; distinct end points per row."""
    rows, size = len(scale), len(block.names)
    starts = 1 if block.linear else starts
    points = rng.uniform(-1, 1, size=(rows * starts, size)) * np.repeat(scale, starts)[:, None]
    base = {n: np.repeat(np.broadcast_to(v, (rows,)), starts) for n, v in values.items()}
    points = _iterate(block, base, points, np.repeat(scale, starts))
    points = points.reshape(rows, starts, size)
    keep = _distinct(points, scale)
    parent = np.repeat(np.arange(rows), keep.sum(axis=1))
    return parent, {n: points[..., i][keep] for i, n in enumerate(block.names)}


def _iterate(block: _Block, base: Mapping[str, Floats], points: Floats, scale: Floats) -> Floats:
    """Newton steps on the rows still moving; rows that diverge or stall end as nan."""
    done = np.full(len(points), np.nan)[:, None] * points
    active = np.arange(len(points))
    base = {n: v for n, v in base.items() if n in block.arguments}
    with np.errstate(all="ignore"):
        for count in range(STEPS):
            x = points[active]
            values = {n: v[active] for n, v in base.items()}
            values.update({n: x[:, i] for i, n in enumerate(block.names)})
            residual, step = _step(block, values, len(active))
            x = x - step
            moved = np.max(np.abs(step), axis=1)
            finished = moved <= CONVERGED * scale[active]
            lost = ~np.isfinite(moved) | (np.max(np.abs(x), axis=1) > 1e6 * scale[active])
            if count >= ABANDON_AFTER:  # far from any root by now: no real root there (the circles miss)
                lost |= residual > ABANDON_RESIDUAL * scale[active] ** 2
            points[active] = x
            done[active[finished]] = x[finished]
            active = active[~(finished | lost)]
            if not active.size:
                break
    return done


def _step(block: _Block, values: Mapping[str, Floats], count: int) -> tuple[Floats, Floats]:
    """``(|F|, J^-1 F)`` per row."""
    args = _arguments(block.arguments, values, count)
    size = len(block.names)
    f = columns(block.residual(*args), count)
    j = columns(block.jacobian(*args), count).reshape(count, size, size)
    if size == 2:  # Cramer's rule: several times faster than a batched LU on 2 x 2 matrices
        det = j[:, 0, 0] * j[:, 1, 1] - j[:, 0, 1] * j[:, 1, 0]
        step = np.stack([j[:, 1, 1] * f[:, 0] - j[:, 0, 1] * f[:, 1],
                         j[:, 0, 0] * f[:, 1] - j[:, 1, 0] * f[:, 0]], axis=1) / det[:, None]
    else:
        step = np.full((count, size), np.nan)
        regular = np.abs(np.linalg.det(j)) > 0
        step[regular] = np.linalg.solve(j[regular], f[regular][..., None])[..., 0]
    return np.max(np.abs(f), axis=1), step


def _distinct(points: Floats, scale: Floats) -> NDArray[np.bool_]:
    """``rows x starts`` mask: the finite end points not within ``SAME_ROOT`` of an earlier one."""
    finite = np.all(np.isfinite(points), axis=2)
    gap = np.max(np.abs(points[:, :, None, :] - points[:, None, :, :]), axis=3)
    close = (gap <= SAME_ROOT * scale[:, None, None]) & finite[:, None, :] & finite[:, :, None]
    earlier = np.tril(np.ones(points.shape[1], dtype=bool), -1)
    return np.asarray(finite & ~np.any(close & earlier, axis=2), dtype=np.bool_)
