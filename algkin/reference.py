"""A certified reference for accuracy runs, from the original equations, never from a closed form.

The compiled system ``F(X; c, s) = 0`` (the construction's circle and line equations plus the
outputs' defining equations) is solved in python-flint balls, every sample at once: each
quantity is a numpy array of ``arb`` (one per sample), so the Python overhead of an operation
is paid once per batch, not per sample.

1. a float starting point straight from the construction (each dyad's two circles met in
   the textbook way, on the side its label names; each slider's line and circle likewise;
   explicit outputs from their formulas);
2. Newton steps in ``arb`` at the working precision: ``x <- mid(x - Y F(x))`` with ``Y`` the
   inverse of ``J(x)`` (Gauss-Jordan, the pivot chosen per sample); from a float start two
   steps reach 2**-200 (53 -> 106 -> 212 bits), near a toggle more;
3. once a step is below 2**-90 of the root's size, one Krawczyk step on a small box ``X``
   around the iterate ``x``, with the last ``Y``:
   ``K = x - Y F(x) + (I - Y J(X)) (X - x)``; ``K`` inside the interior of ``X`` *proves* that
   ``X`` holds exactly one root, and that root lies in ``K``. (Any ``Y`` makes the test sound;
   a good one makes it pass.) A sample whose box does not contract takes another Newton step;
4. each branch indicator (``cross(Q - P, X - P)`` for a dyad) is evaluated on ``K``: its sign
   must be decided and must be the label's, so the root is the labelled one. Near a double
   root Newton may cross to the other branch: such a sample starts again from the start's
   mirror image away from the root it found. A sample still not certified (past a toggle,
   where the branch does not assemble) is reported as such.

An explicit output (a distance, a frame point) enters through its defining equation
(``u - value = 0``, ``u**2 - |PQ|**2 = 0``): its enclosure is the formula's value, evaluated in
balls. The condition number comes from the same system by the implicit function theorem:
``dX/dtheta = -J_X^-1 (-s dF/dc + c dF/ds)``.
"""

from dataclasses import dataclass

import numpy as np
import sympy
from flint import arb, ctx

from .scene.compile import SliderSpec
from .system import symbol

__all__ = ["Reference", "Certified", "BITS", "NotCertified"]

BITS = 200
CLOSE = 2.0**-40  # a Newton step this small (relative to the root's size): try Krawczyk
MARGIN = 2.0**20  # the box's half-width over the step's square: Newton's next error is C step**2
BOX = 2.0**-140  # the box's least half-width (relative), well above the rounding at BITS
NEWTON_STEPS = 80  # at most: 1 or 2 away from toggles, ~60 onto a change point's near-double root
STALL = 5  # steps without a new smallest one: not converging (past a toggle, no real root)

_balls = np.frompyfunc(arb, 1, 1)  # float -> exact ball, per element
_box = np.frompyfunc(lambda radius: arb(0, radius), 1, 1)
_sin_cos = np.frompyfunc(arb.sin_cos, 1, 2)
_mid = np.frompyfunc(arb.mid, 1, 1)


class NotCertified(ArithmeticError):
    """The balls could not prove a unique labelled root near the sample (a double root, say)."""


@dataclass
class Certified:
    """Per sample: whether it is certified, and where it is, its enclosure, outputs and condition."""

    ok: np.ndarray  # bool
    roots: np.ndarray  # samples x unknowns, arb (the Krawczyk enclosures; None where not ok)
    points: np.ndarray  # outputs x samples, float (nan where not ok)
    kappas: np.ndarray  # float (nan where not ok)


class _Balls:
    """``exprs`` as a function of arrays of ``arb`` (one per sample): a samples x exprs array.

    lambdify would print ``1/1000`` as a float; each non-integer rational becomes an extra
    argument holding its ``arb`` quotient, made at call time (so at the caller's precision).
    """

    def __init__(self, exprs, arguments):
        exprs = [sympy.sympify(e) for e in exprs]
        self.rationals = sorted({r for e in exprs for r in e.atoms(sympy.Rational) if not r.is_Integer}, key=str)
        swap = dict(zip(self.rationals, (sympy.Dummy() for _ in self.rationals)))
        self.body = sympy.lambdify(list(arguments) + list(swap.values()), [e.xreplace(swap) for e in exprs],
                                   "numpy", cse=True)
        self.count = len(exprs)

    def __call__(self, *values):
        out = np.empty((len(values[0]), self.count), dtype=object)
        # a constant entry comes back as a number: a ball, so no int / int division follows
        for k, value in enumerate(self.body(*values, *(arb(int(r.p)) / int(r.q) for r in self.rationals))):
            out[:, k] = value if isinstance(value, np.ndarray) else arb(value)
        return out


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
        self.n = len(self.unknowns)
        arguments = self.unknowns + list(self.cs)
        self.equations = [fix(e) for e in system.equations if not e.free_symbols <= set(self.cs)]
        self.f = _Balls(self.equations, arguments)
        self.j = _Balls(sympy.Matrix(self.equations).jacobian(self.unknowns), arguments)
        moved = sympy.Matrix(self.equations).jacobian(self.cs) * sympy.Matrix([-self.cs[1], self.cs[0]])
        self.moved = _Balls(moved, arguments)  # dF/dtheta = -s dF/dc + c dF/ds
        labels = [i for i in compiled.indicators if i.point in branch.labels]
        self.indicators = [fix(i.expr) for i in labels]
        self.expected = np.array([i.chosen == i.positive for i in labels], dtype=bool)  # positive?
        self.signs = _Balls(self.indicators, arguments)
        self.start = _Start(compiled, fix, self.cs)

    def __call__(self, theta):
        """``(points, kappas)``: the outputs (rows) per sample (columns) and each condition number."""
        certified = self.certify(theta)
        if not certified.ok.all():
            angle = float(np.asarray(theta)[~certified.ok][0])
            raise NotCertified(f"at {angle!r} rad no root on the label's side was certified")
        return certified.points, certified.kappas

    def certify(self, theta):
        """Every sample's certified labelled root (see the module), or ``ok`` false."""
        theta = np.asarray(theta, dtype=float)
        start = self.start(theta).T
        ok = np.zeros(theta.size, dtype=bool)
        roots, y = np.full((theta.size, self.n), None), np.full((theta.size, self.n, self.n), None)
        with ctx.workprec(BITS):
            cs = _sin_cos(_balls(theta))[::-1]
            found, enclosures, inverses = self._roots(start, cs)
            roots[found], y[found] = enclosures, inverses
            labelled = self._labelled(enclosures, cs, found)
            ok[found[labelled]] = True
            wrong = found[~labelled]
            if wrong.size:
                # Near a double root Newton may cross to the other branch: start again from the
                # start's mirror image away from the root it found.
                mirror = 2 * start[wrong] - roots[wrong].astype(float)
                again, enclosures, inverses = self._roots(mirror, tuple(v[wrong] for v in cs))
                roots[wrong[again]], y[wrong[again]] = enclosures, inverses
                ok[wrong[again[self._labelled(enclosures, cs, wrong[again])]]] = True
            roots[~ok] = None
            kappas = self._kappas(theta, roots, y, cs, np.flatnonzero(ok))
        points = np.full((len(self.outputs), theta.size), np.nan)
        points[:, ok] = roots[ok][:, self.outputs].astype(float).T
        return Certified(ok, roots, points, kappas)

    def _roots(self, start, cs):
        """Newton then Krawczyk from ``start`` (samples x unknowns): the positions certified, their
        enclosures and the inverse Jacobians (points) their proofs used."""
        size = np.abs(start).max(axis=1)
        size = np.where(size > 0, size, 1.0)
        active = np.flatnonzero(np.isfinite(start).all(axis=1))
        x = np.full(start.shape, None)
        x[active] = _balls(start[active])
        step = np.full(len(start), np.inf)  # each sample's last Newton step, relative to its size
        least, stalled = step.copy(), np.zeros(len(start), dtype=int)
        inverse = np.full((len(start), self.n, self.n), None)
        done = [(np.zeros(0, dtype=int), x[:0], inverse[:0])]
        for _ in range(NEWTON_STEPS):
            if not active.size:
                break
            at = (*x[active].T, *(v[active] for v in cs))
            fx = self.f(*at)
            trying = step[active] < CLOSE
            if trying.any():
                tried = active[trying]
                radius = size[tried] * np.maximum(MARGIN * step[tried] ** 2, BOX)
                k, inside = self._krawczyk(x[tried], fx[trying], inverse[tried], radius,
                                           tuple(v[tried] for v in cs))
                done.append((tried[inside], k[inside], inverse[tried[inside]]))
                going = ~trying
                going[trying] = ~inside  # a box that did not contract: one more Newton step
                active, fx, at = active[going], fx[going], tuple(v[going] for v in at)
                if not active.size:
                    break
            inverse[active] = _mid(_inverse(self.j(*at).reshape(-1, self.n, self.n)))
            delta = (inverse[active] @ fx[:, :, None])[:, :, 0]
            x[active] = _mid(x[active] - delta)
            step[active] = np.abs(delta.astype(float)).max(axis=1) / size[active]
            # Converging, even linearly onto a double root, each step is the smallest yet.
            stalled[active] = np.where(step[active] < least[active], 0, stalled[active] + 1)
            least[active] = np.fmin(least[active], step[active])
            active = active[stalled[active] < STALL]
        return tuple(np.concatenate(part) for part in zip(*done))

    def _krawczyk(self, x, fx, y, radius, cs):
        """``(K, inside)``: the Krawczyk image of the box ``x +- radius`` and whether it lies inside."""
        box = x + _box(radius)[:, None]
        over = self.j(*box.T, *cs).reshape(-1, self.n, self.n)
        contract = np.eye(self.n, dtype=int) - y @ over
        k = x - (y @ fx[:, :, None])[:, :, 0] + (contract @ (box - x)[:, :, None])[:, :, 0]
        # |K - x| < radius (decided) puts K inside the open box, whose ball X holds at least that
        return k, np.asarray(np.abs(k - x) < radius[:, None], dtype=bool).all(axis=1)

    def _labelled(self, roots, cs, where):
        """Per enclosure (``roots``, of the samples ``where``): every indicator's sign decided, and the label's."""
        if not where.size:
            return np.zeros(0, dtype=bool)
        values = self.signs(*roots.T, *(v[where] for v in cs))
        positive, negative = np.asarray(values > 0, dtype=bool), np.asarray(values < 0, dtype=bool)
        return np.where(self.expected, positive, negative).all(axis=1)

    def _kappas(self, theta, roots, y, cs, where):
        """``|dX/dtheta| |theta| / |X|`` over the outputs, plus one for the rounding of the result
        (``y``, the inverse of ``J_X`` at the last Newton iterate, is within ``C |step|`` of the
        root's: ample for a float)."""
        kappas = np.full(theta.size, np.nan)
        if not where.size:
            return kappas
        x = roots[where]
        moved = self.moved(*x.T, *(v[where] for v in cs))
        slope = (y[where] @ moved[:, :, None])[:, self.outputs, 0].astype(float)
        size = np.sqrt((x[:, self.outputs].astype(float) ** 2).sum(axis=1))
        kappas[where] = np.abs(theta[where]) * np.sqrt((slope**2).sum(axis=1)) / size + 1
        return kappas


def _inverse(matrix):
    """Per sample (``matrix``: samples x n x n of balls), Gauss-Jordan on ``[A | I]``, each
    column's pivot the row whose midpoint is largest in size."""
    count, n, _ = matrix.shape
    work = np.concatenate([matrix, np.broadcast_to(np.eye(n, dtype=int), (count, n, n))], axis=2)
    samples = np.arange(count)
    for k in range(n):
        pivot = k + np.nan_to_num(np.abs(work[:, k:, k].astype(float)), nan=-1).argmax(axis=1)
        work[samples, k], work[samples, pivot] = work[samples, pivot], work[samples, k]
        # columns before k + 1 are read no more: only the right-hand side is kept up to date
        work[:, k, k + 1:] = work[:, k, k + 1:] / work[:, k, k, None]
        others = np.arange(n) != k
        work[:, others, k + 1:] = work[:, others, k + 1:] - work[:, others, k, None] * work[:, None, k, k + 1:]
    return work[:, :, n:]


def _float_function(exprs, arguments):
    return sympy.lambdify(list(arguments), list(exprs), "numpy")


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
    """Two circles meet: the foot on PQ, then the half-chord to the labelled side. Where they
    miss, the half-chord of the discriminant's size: a start off the fold, whose J is singular
    (Newton's first step from there would fly off, and take ~50 steps to come back)."""
    dx, dy = qx - px, qy - py
    d2 = dx * dx + dy * dy
    along = (d2 + l1 * l1 - l2 * l2) / (2 * d2)
    across = sigma * np.sqrt(np.abs(l1 * l1 / d2 - along * along))
    return px + along * dx - across * dy, py + along * dy + across * dx


def _slider(px, py, dx, dy, qx, qy, length, sigma):
    """The line through P along d meets the circle about Q: ``X = P + a d``, ahead or behind Q's
    foot (where they miss, by the discriminant's size, as for a dyad)."""
    wx, wy = qx - px, qy - py
    d2 = dx * dx + dy * dy
    foot = (dx * wx + dy * wy) / d2
    half = np.sqrt(np.abs(length * length / d2 - (dx * wy - dy * wx) ** 2 / d2**2))
    along = foot + sigma * half
    return px + along * dx, py + along * dy
