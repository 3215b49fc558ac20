"""A certified reference for accuracy runs, from the original equations, never from a closed form.

Per sample, the compiled system ``F(X; c, s) = 0`` (the construction's circle and line
equations plus the outputs' defining equations) is solved in python-flint balls:

1. a float starting point straight from the construction (each dyad's two circles met in
   the textbook way, on the side its label names; each slider's line and circle likewise;
   explicit outputs from their formulas);
2. Newton steps in ``arb`` up to the working precision;
3. one Krawczyk step on a small box ``X`` around the result ``x``:
   ``K = x - Y F(x) + (I - Y J(X)) (X - x)``; ``K`` inside the interior of ``X`` *proves* that
   ``X`` holds exactly one root, and that root lies in ``K``;
4. each branch indicator (``cross(Q - P, X - P)`` for a dyad) is evaluated on ``K``: its sign
   must be decided and must be the label's, so the root is the labelled one.

An explicit output (a distance, a frame point) enters through its defining equation
(``u - value = 0``, ``u**2 - |PQ|**2 = 0``): its enclosure is the formula's value, evaluated in
balls. The condition number comes from the same system by the implicit function theorem:
``dX/dtheta = -J_X^-1 (-s dF/dc + c dF/ds)``.
"""

import numpy as np
import sympy
from flint import arb, arb_mat, ctx

from .scene.compile import SliderSpec
from .system import symbol

__all__ = ["Reference", "BITS", "NotCertified"]

BITS = 200
BOX = 2.0**-140  # the Krawczyk box's half-width, relative to the root's size
NEWTON_STEPS = 80  # at most: 53 -> 106 -> 212 bits takes 3 away from toggles, ~60 on one


class NotCertified(ArithmeticError):
    """The balls could not prove a unique labelled root near the sample (a double root, say)."""


def _arb_function(exprs, arguments):
    """``exprs`` as a Python function of ``arguments`` over ``arb``, with rationals kept exact.

    lambdify would print ``1/1000`` as a float; each non-integer rational becomes an extra
    argument holding its ``arb`` quotient, made at call time (so at the caller's precision).
    """
    rationals = sorted({r for e in exprs for r in sympy.sympify(e).atoms(sympy.Rational)
                        if not r.is_Integer}, key=str)
    names = [sympy.Dummy() for _ in rationals]
    swap = dict(zip(rationals, names))
    body = sympy.lambdify(list(arguments) + names, [sympy.sympify(e).xreplace(swap) for e in exprs],
                          modules=[{"sqrt": lambda v: v.sqrt()}])
    return lambda *values: body(*values, *(arb(int(r.p)) / int(r.q) for r in rationals))


def _float_function(exprs, arguments):
    return sympy.lambdify(list(arguments), list(exprs), "numpy")


class Reference:
    """Certified configurations of one compiled scene, labelled by its branch (see the module)."""

    def __init__(self, compiled, branch, outputs):
        defaults = {symbol(n): sympy.Rational(str(v)) for n, v in compiled.parameter_values.items()}
        fix = lambda e: sympy.sympify(e).xreplace(defaults)  # noqa: E731
        system = compiled.system
        (c, s), = system.inputs.values()
        self.cs = (symbol(c), symbol(s))
        self.unknowns = [symbol(u) for u in system.unknowns]
        self.outputs = [system.unknowns.index(u) for u in outputs]
        arguments = self.unknowns + list(self.cs)
        equations = [fix(e) for e in system.equations if not e.free_symbols <= set(self.cs)]
        jacobian = sympy.Matrix(equations).jacobian(arguments)
        self.f = _arb_function(equations, arguments)
        self.j = _arb_function(list(jacobian), arguments)
        self.n = len(self.unknowns)
        self.signs = [(_arb_function([fix(i.expr)], arguments), 1 if i.chosen == i.positive else -1)
                      for i in compiled.indicators if i.point in branch.labels]
        self.start = _Start(compiled, fix, self.cs)

    def __call__(self, theta):
        """``(points, kappas)``: the outputs (rows) per sample (columns) and each condition number."""
        starts = self.start(theta)
        points, kappas = [], []
        with ctx.workprec(BITS):
            for k, angle in enumerate(theta):
                x, kappa = self.one(float(angle), starts[:, k])
                points.append([float(x[i].mid()) for i in self.outputs])
                kappas.append(kappa)
        return np.array(points).T, np.array(kappas)

    def one(self, angle, start):
        """The certified root (balls) at one angle and its condition number (float)."""
        a = arb(angle)
        cs = (a.cos(), a.sin())
        root = self._krawczyk(self._newton([arb(v) for v in start], cs), cs)
        if not self._labelled(root, cs):
            # Near a double root Newton may cross to the other branch: start again from the
            # start's mirror image away from the root it found.
            mirror = [arb(2 * float(v) - float(r.mid())) for v, r in zip(start, root)]
            root = self._krawczyk(self._newton(mirror, cs), cs)
            if not self._labelled(root, cs):
                raise NotCertified(f"at {angle!r} rad no root on the label's side was found")
        return root, self._kappa(root, a, cs)

    def _labelled(self, root, cs):
        """Every indicator's sign is decided on the enclosure, and is the label's."""
        values = [(sign(*root, *cs)[0], expected) for sign, expected in self.signs]
        return all(v > 0 if expected > 0 else v < 0 for v, expected in values)

    def _jacobian(self, x, cs):
        """``J`` in the unknowns, then in c and s: ``n x (n + 2)``."""
        return arb_mat(self.n, self.n + 2, self.j(*x, *cs))

    def _newton(self, x, cs):
        """Newton in balls (midpoints kept) until the step is below the box; near a double root
        (a toggle) it only halves the distance per step until the two roots part."""
        size = max(abs(float(v)) for v in x) or 1.0
        for _ in range(NEWTON_STEPS):
            jac = self._jacobian(x, cs)
            step = _columns(jac, self.n).solve(arb_mat(self.n, 1, self.f(*x, *cs)))
            x = [arb((x[i] - step[i, 0]).mid()) for i in range(self.n)]
            if max(abs(float(step[i, 0].mid())) for i in range(self.n)) < BOX * 2.0**-20 * size:
                break
        return x

    def _krawczyk(self, x, cs):
        size = max(abs(float(v.mid())) for v in x) or 1.0
        radius = arb(0, BOX * size)
        box = [v + radius for v in x]
        y = _columns(self._jacobian(x, cs), self.n).mid().inv().mid()
        over_box = _columns(self._jacobian(box, cs), self.n)
        fx = arb_mat(self.n, 1, self.f(*x, *cs))
        spread = arb_mat(self.n, 1, [b - v for b, v in zip(box, x)])
        k = arb_mat(self.n, 1, x) - y * fx + (arb_mat(_identity(self.n)) - y * over_box) * spread
        root = [k[i, 0] for i in range(self.n)]
        if not all(b.contains_interior(r) for b, r in zip(box, root)):
            raise NotCertified("the Krawczyk step does not map the box into itself")
        return root

    def _kappa(self, root, angle, cs):
        """``|dX/dtheta| |theta| / |X|`` over the outputs, plus one for the rounding of the result."""
        jac = self._jacobian(root, cs)
        c, s = cs
        moved = arb_mat(self.n, 1, [-s * jac[i, self.n] + c * jac[i, self.n + 1] for i in range(self.n)])
        slope = _columns(jac, self.n).solve(-moved)
        rate = sum(slope[i, 0] ** 2 for i in self.outputs).sqrt()
        size = sum(root[i] ** 2 for i in self.outputs).sqrt()
        return float((abs(angle) * rate / size).mid()) + 1


def _columns(matrix, n):
    """The first ``n`` columns: the Jacobian in the unknowns (the last two are in c and s)."""
    return arb_mat([[matrix[i, j] for j in range(n)] for i in range(matrix.nrows())])


def _identity(n):
    return [[1 if i == j else 0 for j in range(n)] for i in range(n)]


class _Start:
    """Float starting points from the construction itself (textbook formulas, no elimination)."""

    def __init__(self, compiled, fix, cs):
        self.steps = []
        known = list(cs)
        for spec in compiled.implicit:
            sigma = 1.0 if spec.branch == spec.labels[0] else -1.0
            if isinstance(spec, SliderSpec):
                parts = [*spec.through, *spec.direction, *spec.center, spec.length]
            else:
                parts = [*spec.base_p, *spec.base_q, *spec.lengths]
            self.steps.append((spec.unknowns, _float_function([fix(p) for p in parts], known), sigma,
                               _slider if isinstance(spec, SliderSpec) else _dyad))
            known = known + [symbol(u) for u in spec.unknowns]
        self.known = [str(v) for v in known]
        rest = [u for u in compiled.system.unknowns if u not in self.known]
        self.rest = rest, _float_function([fix(compiled.definitions[u]) for u in rest], known)
        self.order = compiled.system.unknowns

    def __call__(self, theta):
        values = {str(v): a for v, a in zip(self.known[:2], (np.cos(theta), np.sin(theta)))}
        for unknowns, parts, sigma, meet in self.steps:
            point = meet(*np.broadcast_arrays(*parts(*values.values()), theta)[:-1], sigma)
            values.update(zip(unknowns, point))
        names, formulas = self.rest
        values.update(zip(names, formulas(*values.values())))
        return np.array([np.broadcast_to(values[u], theta.shape) for u in self.order], dtype=float)


def _dyad(px, py, qx, qy, l1, l2, sigma):
    """Two circles meet: the foot on PQ, then the half-chord to the labelled side (clamped at 0)."""
    dx, dy = qx - px, qy - py
    d2 = dx * dx + dy * dy
    along = (d2 + l1 * l1 - l2 * l2) / (2 * d2)
    across = sigma * np.sqrt(np.maximum(l1 * l1 / d2 - along * along, 0))
    return px + along * dx - across * dy, py + along * dy + across * dx


def _slider(px, py, dx, dy, qx, qy, length, sigma):
    """The line through P along d meets the circle about Q: ``X = P + a d``, ahead or behind Q's foot."""
    wx, wy = qx - px, qy - py
    d2 = dx * dx + dy * dy
    foot = (dx * wx + dy * wy) / d2
    half = np.sqrt(np.maximum(length * length / d2 - (dx * wy - dy * wx) ** 2 / d2**2, 0))
    along = foot + sigma * half
    return px + along * dx, py + along * dy
