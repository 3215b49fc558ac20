"""Numeric solutions of a polynomial system, found without any closed form.

The system is split into blocks that can be solved in turn (a square subsystem in the
unknowns not solved yet); a block in one unknown is solved by ``mpmath.polyroots``, a
larger one by Newton's method from many starts (floats, vectorised), each root then
polished at high precision with mpmath.
"""

import itertools

import mpmath
import numpy as np
import sympy

from ..system import symbol

__all__ = ["Blocks", "solve_all"]

STARTS = 64
FLOAT_STEPS = 60
POLISH_STEPS = 12


class Blocks:
    """The block-triangular structure of a system, with compiled residuals and Jacobians."""

    def __init__(self, system):
        self.system = system
        names = list(system.variables)
        self.args = [symbol(n) for n in names]
        self.names = names
        pending = [eq for eq in system.equations if eq.free_symbols & {symbol(u) for u in system.unknowns}]
        # Coordinates are about as large as the lengths, whose squares are coefficients: Newton's
        # starts must spread over that size too, not only over the known values (cos, sin).
        self.size = max((abs(float(c)) ** 0.5 for eq in pending
                         for c in sympy.Poly(eq, *eq.free_symbols).coeffs()), default=0.0)
        solved, self.blocks = set(), []
        while len(solved) < len(system.unknowns):
            block = self._next_block(pending, solved)
            for eq in block[1]:
                pending.remove(eq)
            solved |= set(block[0])
            self.blocks.append(self._compile(*block))

    def _next_block(self, pending, solved):
        unknown = {symbol(u) for u in self.system.unknowns} - {symbol(u) for u in solved}
        for size in range(1, 5):
            candidates = [eq for eq in pending if 0 < len(eq.free_symbols & unknown) <= size]
            for group in itertools.combinations(candidates, size):
                block_vars = set().union(*(eq.free_symbols & unknown for eq in group))
                if len(block_vars) == size:
                    return sorted(str(v) for v in block_vars), list(group)
        raise ValueError("the system has no square block left to solve numerically")

    def _compile(self, names, equations):
        vars_ = [symbol(n) for n in names]
        if len(names) == 1:
            coeffs = sympy.Poly(equations[0], vars_[0]).all_coeffs()
            return ("univariate", names, sympy.lambdify(self.args, coeffs, "mpmath"))
        jac = sympy.Matrix(equations).jacobian(vars_)
        return (
            "newton",
            names,
            sympy.lambdify(self.args, equations, "numpy"),
            sympy.lambdify(self.args, jac.tolist(), "numpy"),
            sympy.lambdify(self.args, equations, "mpmath"),
            sympy.lambdify(self.args, jac.tolist(), "mpmath"),
        )


def _arguments(blocks, values):
    return [values.get(n, 0) for n in blocks.names]


def _solve_univariate(block, values, blocks):
    _, names, coeffs_fn = block
    coeffs = [mpmath.mpf(c) for c in coeffs_fn(*_arguments(blocks, values))]
    while coeffs and coeffs[0] == 0:
        coeffs.pop(0)
    if len(coeffs) < 2:
        return []
    if len(coeffs) == 2:
        return [{names[0]: -coeffs[1] / coeffs[0]}]
    roots = mpmath.polyroots(coeffs, maxsteps=200, extraprec=2 * mpmath.mp.prec)
    scale = max(abs(r) for r in roots) + 1
    return [{names[0]: mpmath.re(r)} for r in roots if abs(mpmath.im(r)) <= mpmath.mpf(10) ** (-20) * scale]


def _solve_newton(block, values, blocks, rng):
    _, names, f_np, j_np, f_mp, j_mp = block
    known = [abs(float(v)) for v in values.values()]
    scale = 2 * (max(known + [blocks.size]) + 1)
    starts = rng.uniform(-scale, scale, size=(STARTS, len(names)))
    base = {k: float(v) for k, v in values.items()}
    points = _float_newton(starts, names, base, blocks, f_np, j_np)
    roots = []
    for point in points:
        if not any(np.allclose(point, r, rtol=1e-7, atol=1e-7 * scale) for r in roots):
            roots.append(point)
    solutions = []
    for root in roots:
        polished = _polish(root, names, values, blocks, f_mp, j_mp)
        if polished is not None and not any(
            max(abs(polished[n] - s[n]) for n in names) <= mpmath.mpf(10) ** (-20) * scale for s in solutions
        ):
            solutions.append(polished)
    return solutions


def _float_newton(points, names, base, blocks, f_np, j_np):
    """Newton's method from every start at once; returns the finite end points."""
    count, size = points.shape
    with np.errstate(all="ignore"):
        for _ in range(FLOAT_STEPS):
            args = _arguments(blocks, {**base, **{n: points[:, i] for i, n in enumerate(names)}})
            f = np.stack([np.broadcast_to(v, (count,)) for v in f_np(*args)], axis=1)
            rows = j_np(*args)
            j = np.stack([np.stack([np.broadcast_to(v, (count,)) for v in row], axis=1) for row in rows], axis=1)
            ok = np.abs(np.linalg.det(j)) > 0
            step = np.zeros_like(points)
            step[ok] = np.linalg.solve(j[ok], f[ok][..., None])[..., 0]
            points = np.where(ok[:, None], points - step, np.nan)
    return points[np.all(np.isfinite(points), axis=1)]


def _polish(root, names, values, blocks, f_mp, j_mp):
    point = [mpmath.mpf(float(v)) for v in root]
    tiny = mpmath.mpf(2) ** (-mpmath.mp.prec) * (1 + max(abs(p) for p in point))
    for _ in range(POLISH_STEPS):
        args = _arguments(blocks, {**values, **dict(zip(names, point))})
        f = mpmath.matrix(f_mp(*args))
        j = mpmath.matrix(j_mp(*args))
        try:
            step = mpmath.lu_solve(j, f)
        except ZeroDivisionError:
            return None
        point = [p - step[i] for i, p in enumerate(point)]
        if max(abs(v) for v in step) <= tiny:  # converged quadratically: more steps change nothing
            break
    args = _arguments(blocks, {**values, **dict(zip(names, point))})
    residual = max(abs(v) for v in f_mp(*args))
    size = 1 + max(abs(v) for v in list(values.values()) + point)
    if residual > mpmath.mpf(2) ** (-mpmath.mp.prec // 2) * size**2:
        return None
    return dict(zip(names, point))


def solve_all(blocks, values, rng):
    """Every real solution of the unknowns, given ``values`` (name -> mpf) of the rest."""
    partial = [dict(values)]
    for block in blocks.blocks:
        extended = []
        for known in partial:
            if block[0] == "univariate":
                found = _solve_univariate(block, known, blocks)
            else:
                found = _solve_newton(block, known, blocks, rng)
            extended += [{**known, **sol} for sol in found]
        partial = extended
    nonneg = blocks.system.nonnegative
    return [sol for sol in partial if all(sol[n] >= 0 for n in nonneg)]
