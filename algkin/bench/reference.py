"""A certified reference for accuracy runs, from the original equations, never from a closed form.

The compiled system ``F(X; c, s) = 0`` (the construction's circle and line equations plus the
outputs' defining equations) is solved in python-flint balls, every sample at once: each
quantity is a numpy array of ``arb`` (one per sample), so the Python overhead of an operation
is paid once per batch, not per sample. The system is triangular by construction: each dyad
or slider's two equations involve only its own point and earlier ones. So it is certified
one construction at a time (a 2 x 2 system, its equations as the construction writes them,
unexpanded (its spec's ``written``), checked equal to the system's), the earlier points entering as their enclosures:

1. a float starting point straight from the construction (its spec's ``start``: each dyad's
   two circles met in the textbook way, on the side its label names; each slider's line and
   circle likewise; an inversor's second point as the mirror image of the first);
2. Newton steps in ``arb`` at the working precision: ``x <- mid(x - Y F(x))`` with ``Y`` the
   inverse of ``J(x)`` (by its adjugate); from a float start one step reaches about 2**-106,
   near a toggle it takes more, and a sample whose steps stop shrinking is given up;
3. once a step ``d`` is below 2**-40 of the root's size, one Krawczyk step on the box ``X`` of
   half-width ``2**20 d**2`` (Newton's next error is ``C d**2``; at least 2**-140) around the
   iterate ``x``, with the last ``Y``: ``K = x - Y F(x) + (I - Y J(X)) (X - x)``, the earlier
   points' enclosures in ``F`` and ``J``. ``K`` inside the interior of ``X`` *proves* that, for
   every earlier point in its enclosure, ``X`` holds exactly one root, and that it lies in
   ``K``. (Any ``Y`` makes the test sound; a good one makes it pass.) A sample whose box does
   not contract takes another Newton step;
4. each branch indicator (``cross(Q - P, X - P)`` for a dyad) is evaluated on ``K``: its sign
   must be decided and must be the label's, so the root is the labelled one. Near a double
   root Newton may cross to the other branch: such a sample starts again from the start's
   mirror image away from the root it found. A sample still not certified (past a toggle,
   where the branch does not assemble) is reported as such.

An explicit output (a distance, a frame point) is defined by a formula in the constructed
points (its equation ``u - value = 0`` or ``u**2 - |PQ|**2 = 0``): its enclosure is that
formula evaluated in balls on theirs. The condition number comes from the same system by the
implicit function theorem, construction by construction:
``dX/dtheta = -J_X^-1 (dF/dtheta + dF/dE dE/dtheta)`` with ``E`` the earlier points.
"""

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
import sympy
from flint import arb, ctx
from numpy.typing import ArrayLike, NDArray

from ..branches.closed_form import Branch
from ..scene.compile import Compiled
from ..branches.constructions.base import Fix
from ..scene.implicit.base import ImplicitSpec
from ..system import symbol

__all__ = ["Reference", "Certified", "BITS", "NotCertified"]

BITS = 200
CLOSE = 2.0**-40  # a Newton step this small (relative to the root's size): try Krawczyk
MARGIN = 2.0**20  # the box's half-width over the step's square: Newton's next error is C step**2
BOX = 2.0**-140  # the box's least half-width (relative), well above the rounding at BITS
NEWTON_STEPS = 80  # at most: 1 or 2 away from toggles, ~60 onto a change point's near-double root
STALL = 5  # steps without a new smallest one: not converging (past a toggle, no real root)

Balls = NDArray[np.object_]  # of flint.arb, None where nothing is known
Mask = NDArray[np.bool_]
Indices = NDArray[np.intp]
Floats = NDArray[np.float64]

_balls = np.frompyfunc(arb, 1, 1)  # float -> exact ball, per element
_box = np.frompyfunc(lambda radius: arb(0, radius), 1, 1)
_sin_cos = np.frompyfunc(arb.sin_cos, 1, 2)
_mid = np.frompyfunc(arb.mid, 1, 1)


class NotCertified(ArithmeticError):
    """The balls could not prove a unique labelled root near the sample (a double root, say)."""


@dataclass
class Certified:
    """Per sample: whether it is certified, and where it is, its enclosure, outputs and condition."""

    ok: Mask
    roots: Balls  # samples x unknowns (Krawczyk's enclosures, explicit ones by formula; None if not ok)
    points: Floats  # outputs x samples (nan where not ok)
    kappas: Floats  # nan where not ok


class _Balls:
    """``exprs`` as a function of arrays of ``arb`` (one per sample): a samples x exprs array.

    lambdify would print ``1/1000`` as a float; each non-integer rational becomes an extra
    argument holding its ``arb`` quotient, made at call time (so at the caller's precision).
    """

    def __init__(self, exprs: Sequence[sympy.Expr], arguments: Sequence[sympy.Symbol]) -> None:
        exprs = [sympy.sympify(e) for e in exprs]
        self.rationals = sorted({r for e in exprs for r in e.atoms(sympy.Rational) if not r.is_Integer}, key=str)
        swap = dict(zip(self.rationals, (sympy.Dummy() for _ in self.rationals)))
        self.body = sympy.lambdify(list(arguments) + list(swap.values()), [e.xreplace(swap) for e in exprs],
                                   "numpy", cse=True)
        self.count = len(exprs)

    def __call__(self, *values: Balls) -> Balls:
        out = np.empty((len(values[0]), self.count), dtype=object)
        # a constant entry comes back as a number: a ball, so no int / int division follows
        for k, value in enumerate(self.body(*values, *(arb(int(r.p)) / int(r.q) for r in self.rationals))):
            out[:, k] = value if isinstance(value, np.ndarray) else arb(value)
        return out


class Reference:
    """Certified configurations of one compiled scene, labelled by its branch (see the module).

    ``unknowns``, ``equations``, ``indicators`` and ``expected`` are the whole system's, for
    a solver that takes it at once (accuracy's ``numeric`` strategy).
    """

    def __init__(self, compiled: Compiled, branch: Branch, outputs: Sequence[str]) -> None:
        defaults = {symbol(n): sympy.Rational(str(v)) for n, v in compiled.parameter_values.items()}
        fix = lambda e: sympy.sympify(e).xreplace(defaults)  # noqa: E731
        system = compiled.system
        (c, s), = system.inputs.values()
        self.cs = (symbol(c), symbol(s))
        self.unknowns = [symbol(u) for u in system.unknowns]
        self.outputs = [system.unknowns.index(u) for u in outputs]
        self.equations = [fix(e) for e in system.equations if not e.free_symbols <= set(self.cs)]
        labels = [i for i in compiled.indicators if i.point in branch.labels]
        self.indicators = [fix(i.expr) for i in labels]
        self.expected = np.array([i.chosen == i.positive for i in labels], dtype=bool)  # positive?
        self.start = _Start(compiled, fix, self.cs)
        self.stages: list[_Stage] = []
        earlier: list[sympy.Symbol] = []
        for spec in compiled.implicit:
            mine = [symbol(u) for u in spec.unknowns]
            equations = _written(spec, fix)
            # the system's own equations of this construction, expanded: the same polynomials
            assert [sympy.expand(e) for e in equations] == \
                [e for e in self.equations if e.free_symbols & set(mine)
                 and e.free_symbols <= set(mine + earlier + list(self.cs))], spec.point
            signs = [(e, x) for e, x, i in zip(self.indicators, self.expected, labels) if i.point == spec.point]
            self.stages.append(_Stage(equations, mine, earlier, self.cs, signs, self._at(mine), self._at(earlier)))
            earlier = earlier + mine
        explicit = [symbol(u) for u in system.unknowns if symbol(u) not in earlier]
        self.explicit = _Explicit([fix(compiled.definitions[str(u)]) for u in explicit], earlier, self.cs,
                                  self._at(explicit), self._at(earlier))

    def _at(self, unknowns: Sequence[sympy.Symbol]) -> Indices:
        return np.array([self.unknowns.index(u) for u in unknowns], dtype=int)

    def __call__(self, theta: ArrayLike) -> tuple[Floats, Floats]:
        """``(points, kappas)``: the outputs (rows) per sample (columns) and each condition number."""
        certified = self.certify(theta)
        if not certified.ok.all():
            angle = float(np.asarray(theta)[~certified.ok][0])
            raise NotCertified(f"at {angle!r} rad no root on the label's side was certified")
        return certified.points, certified.kappas

    def certify(self, theta: ArrayLike) -> Certified:
        """Every sample's certified labelled root (see the module), or ``ok`` false."""
        theta = np.asarray(theta, dtype=float)
        ok = np.ones(theta.size, dtype=bool)
        roots, slopes = (np.full((theta.size, len(self.unknowns)), None) for _ in range(2))
        with ctx.workprec(BITS):
            cs = _sin_cos(_balls(theta))[::-1]
            self._construct(self.start(theta).T, cs, ok, roots, slopes)
            live = np.flatnonzero(ok)
            self.explicit(roots, slopes, live, tuple(v[live] for v in cs))
            # an explicit output's formula may fail on the enclosures (a square root reaching below 0)
            ok[live] = np.isfinite(roots[live][:, self.outputs].astype(float)).all(axis=1)
            roots[~ok] = None
            points = np.full((len(self.outputs), theta.size), np.nan)
            points[:, ok] = roots[ok][:, self.outputs].astype(float).T
            kappas = np.full(theta.size, np.nan)
            kappas[ok] = _kappas(theta[ok], points[:, ok], slopes[ok][:, self.outputs].astype(float).T)
        return Certified(ok, roots, points, kappas)

    def _construct(self, start: Floats, cs: tuple[Balls, Balls], ok: Mask, roots: Balls, slopes: Balls) -> None:
        """Certifies each construction in turn on the samples ``ok`` so far (see the module),
        filling in ``roots`` and ``slopes``; a sample that fails one is ``ok`` no more."""
        for stage in self.stages:
            live = np.flatnonzero(ok)
            given = (*roots[live][:, stage.earlier].T, *(v[live] for v in cs))
            done, enclosures, inverses = stage.certify(start[live][:, stage.at], given)
            ok[live] = False
            ok[live[done]] = True
            roots[np.ix_(live[done], stage.at)] = enclosures
            slopes[np.ix_(live[done], stage.at)] = stage.slopes(
                enclosures, tuple(v[done] for v in given), inverses, slopes[live[done]][:, stage.earlier])


def _written(spec: ImplicitSpec, fix: Fix) -> list[sympy.Expr]:
    """A construction's two equations as it writes them (unexpanded: the circles about P and Q,
    or the slider's line and circle), which take fewer operations in balls than expanded."""
    return [fix(e) for e in spec.written()]


def _kappas(theta: Floats, points: Floats, slopes: Floats) -> Floats:
    """``|dX/dtheta| |theta| / |X|`` (outputs x samples), plus one for the rounding of the result."""
    return np.abs(theta) * np.sqrt((slopes**2).sum(axis=0)) / np.sqrt((points**2).sum(axis=0)) + 1


class _Explicit:
    """Explicit unknowns: their formulas in the constructed points, evaluated on the enclosures."""

    def __init__(self, definitions: list[sympy.Expr], earlier: list[sympy.Symbol], cs: tuple[sympy.Symbol, sympy.Symbol],
                 at: Indices, given_at: Indices) -> None:
        arguments = earlier + list(cs)
        c, s = cs
        self.at, self.given_at = at, given_at
        self.values = _Balls(definitions, arguments)
        matrix = sympy.Matrix(definitions)
        self.moved = _Balls(matrix.jacobian(cs) * sympy.Matrix([-s, c]), arguments) if definitions else None
        self.pushed = _Balls(matrix.jacobian(earlier), arguments) if definitions and earlier else None

    def __call__(self, roots: Balls, slopes: Balls, live: Indices, cs: tuple[Balls, ...]) -> None:
        """Fills ``roots`` and ``slopes`` of the samples ``live`` (rows) at the explicit unknowns."""
        if self.moved is None or not live.size:  # no explicit unknown, or no sample
            return
        given = (*roots[live][:, self.given_at].T, *cs)
        roots[np.ix_(live, self.at)] = self.values(*given)
        slope = self.moved(*given)
        if self.pushed is not None:
            pushed = self.pushed(*given).reshape(live.size, self.at.size, self.given_at.size)
            slope = slope + (pushed @ slopes[live][:, self.given_at, None])[:, :, 0]
        slopes[np.ix_(live, self.at)] = slope


class _Stage:
    """One dyad or slider's unknowns, certified with the earlier points' enclosures (see the module)."""

    def __init__(self, equations: list[sympy.Expr], mine: list[sympy.Symbol], earlier: list[sympy.Symbol],
                 cs: tuple[sympy.Symbol, sympy.Symbol], signs: list[tuple[sympy.Expr, bool]], at: Indices,
                 earlier_at: Indices) -> None:
        arguments = mine + earlier + list(cs)
        c, s = cs
        self.n, self.at, self.earlier = len(mine), at, earlier_at  # positions in the system's unknowns
        matrix = sympy.Matrix(equations)
        self.f = _Balls(equations, arguments)
        self.j = _Balls(matrix.jacobian(mine), arguments)
        self.moved = _Balls(matrix.jacobian(cs) * sympy.Matrix([-s, c]), arguments)  # dF/dtheta, points held
        self.pushed = _Balls(matrix.jacobian(earlier), arguments) if earlier else None
        self.signs = _Balls([e for e, _ in signs], arguments)
        self.expected = np.array([x for _, x in signs], dtype=bool)

    def certify(self, start: Floats, given: tuple[Balls, ...]) -> tuple[Indices, Balls, Balls]:
        """The positions (in ``start``: samples x my unknowns) certified on the label's side,
        their enclosures and the inverse Jacobians (points) their proofs used."""
        found, enclosures, inverses = self._roots(start, given)
        labelled = self._labelled(enclosures, given, found)
        wrong = found[~labelled]
        done = [(found[labelled], enclosures[labelled], inverses[labelled])]
        if wrong.size:
            # Near a double root Newton may cross to the other branch: start again from the
            # start's mirror image away from the root it found.
            mirror = 2 * start[wrong] - enclosures[~labelled].astype(float)
            again, enclosures, inverses = self._roots(mirror, tuple(v[wrong] for v in given))
            labelled = self._labelled(enclosures, given, wrong[again])
            done.append((wrong[again[labelled]], enclosures[labelled], inverses[labelled]))
        return _joined(done)

    def slopes(self, roots: Balls, given: tuple[Balls, ...], inverses: Balls, earlier: Balls) -> Balls:
        """``dX/dtheta`` at the enclosures ``roots``, given the earlier points' slopes ``earlier``
        (``inverses``, of ``J`` at the last Newton iterate, are within ``C |step|`` of the
        root's: ample for a float condition number)."""
        moved = self.moved(*roots.T, *given)
        if self.pushed is not None:
            pushed = self.pushed(*roots.T, *given).reshape(len(roots), self.n, -1)
            moved = moved + (pushed @ earlier[:, :, None])[:, :, 0]
        return -(inverses @ moved[:, :, None])[:, :, 0]

    def _roots(self, start: Floats, given: tuple[Balls, ...]) -> tuple[Indices, Balls, Balls]:
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
            at = (*x[active].T, *(v[active] for v in given))
            fx = self.f(*at)
            trying = step[active] < CLOSE
            if trying.any():
                tried = active[trying]
                radius = size[tried] * np.maximum(MARGIN * step[tried] ** 2, BOX)
                k, inside = self._krawczyk(x[tried], fx[trying], inverse[tried], radius,
                                           tuple(v[tried] for v in given))
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
        return _joined(done)

    def _krawczyk(self, x: Balls, fx: Balls, y: Balls, radius: Floats, given: tuple[Balls, ...]) -> tuple[Balls, Mask]:
        """``(K, inside)``: the Krawczyk image of the box ``x +- radius`` and whether it lies inside."""
        box = x + _box(radius)[:, None]
        over = self.j(*box.T, *given).reshape(-1, self.n, self.n)
        contract = np.eye(self.n, dtype=int) - y @ over
        k = x - (y @ fx[:, :, None])[:, :, 0] + (contract @ (box - x)[:, :, None])[:, :, 0]
        # |K - x| < radius (decided) puts K inside the open box, whose ball X holds at least that
        return k, _every(np.abs(k - x) < radius[:, None])

    def _labelled(self, roots: Balls, given: tuple[Balls, ...], where: Indices) -> Mask:
        """Per enclosure (``roots``, of the samples ``where``): every indicator's sign decided, and the label's."""
        if not where.size:
            return np.zeros(0, dtype=bool)
        values = self.signs(*roots.T, *(v[where] for v in given))
        positive, negative = np.asarray(values > 0, dtype=bool), np.asarray(values < 0, dtype=bool)
        return _every(np.where(self.expected, positive, negative))
def _joined(parts: Sequence[tuple[Indices, Balls, Balls]]) -> tuple[Indices, Balls, Balls]:
    """Certified positions, enclosures and inverses found in parts, each joined in order."""
    found, enclosures, inverses = zip(*parts)
    return np.concatenate(found), np.concatenate(enclosures), np.concatenate(inverses)


def _every(decided: NDArray[np.bool_]) -> Mask:
    """Per row (sample), whether all of it holds: a ball comparison reads True only where decided."""
    return np.all(np.asarray(decided, dtype=bool), axis=1)


def _inverse(matrix: Balls) -> Balls:
    """Per sample (``matrix``: samples x 2 x 2 of balls), the inverse by its adjugate: every
    construction has two unknowns. A determinant ball holding 0 gives NaN, which certifies nothing."""
    (a, b), (c, d) = matrix[:, 0].T, matrix[:, 1].T
    det = a * d - b * c
    return np.stack([np.stack([d, -b], axis=1), np.stack([-c, a], axis=1)], axis=1) / det[:, None, None]


def _float_function(exprs: Sequence[sympy.Expr], arguments: Sequence[sympy.Symbol]) -> Callable[..., Any]:
    return sympy.lambdify(list(arguments), list(exprs), "numpy")


class _Start:
    """Float starting points from the construction itself (textbook formulas, no elimination)."""

    def __init__(self, compiled: Compiled, fix: Fix, cs: tuple[sympy.Symbol, sympy.Symbol]) -> None:
        self.steps: list[tuple[tuple[str, str], Callable[..., Any], float, Callable[..., Any]]] = []
        known = list(cs)
        for spec in compiled.implicit:
            sigma = float(spec.sign(spec.branch)) if spec.labels else 1.0
            parts = _float_function([fix(p) for p in spec.start_parts()], known)
            self.steps.append((spec.unknowns, parts, sigma, spec.start))
            known = known + [symbol(u) for u in spec.unknowns]
        self.known = [str(v) for v in known]
        rest = [u for u in compiled.system.unknowns if u not in self.known]
        self.rest = rest, _float_function([fix(compiled.definitions[u]) for u in rest], known)
        self.order = compiled.system.unknowns

    def __call__(self, theta: Floats) -> Floats:
        values = {str(v): a for v, a in zip(self.known[:2], (np.cos(theta), np.sin(theta)))}
        for unknowns, parts, sigma, start in self.steps:
            point = start(np.broadcast_arrays(*parts(*values.values()), theta)[:-1], sigma)
            values.update(zip(unknowns, point))
        names, formulas = self.rest
        values.update(zip(names, formulas(*values.values())))
        return np.array([np.broadcast_to(values[u], theta.shape) for u in self.order], dtype=float)
