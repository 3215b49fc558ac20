"""Speed against error of each way to evaluate a branch, on ordinary and hard samples.

Strategies, all vectorised over float64 samples of the input:

- ``closed-form``: the eliminants solved the seeds' way (``sympy.solve``, then
  ``lambdify``); the root nearest the truth is credited, since solving does not pair roots;
- ``stabilised``: ``branches.stable.StableBranch`` (local frame, sorted Heron);
- ``numeric``: Newton on the two circle equations, started from the previous sample's
  answer (six steps);
- ``reference``: the closed form in mpmath at 200 bits, on the same float inputs.

Errors are against the reference. ``condition`` is the relative condition number of the
point in the input angle, ``|theta| * |X'(theta)| / |X|`` (plus one for the rounding of
the result), so ``error_over_kappa_eps`` near 1 means as accurate as the problem allows.
Cases: ``uniform`` over the certified intervals, within 1e-6, 1e-10 and 1e-14 (relative)
of each toggle on its assembling side, ``near-fold`` around the input where a dyad that
never toggles comes within 1% of it (a near-change-point four-bar: its closest approach
to a dead centre), and the mechanism translated 1e7 away.
"""

import dataclasses
import time
from dataclasses import dataclass

import mpmath
import numpy as np
import sympy

from .branches import closed_forms
from .branches.stable import StableBranch
from . import validation
from .errors import UsageError
from .evaluate import MPMATH, NUMPY, evaluate
from .pipeline import certify_labels, derive
from .scene import compile_scene
from .scene.load import as_scene
from .scene.settings import with_values
from .scene.constructions import Dyad, Fixed
from .system import symbol

__all__ = ["accuracy", "Accuracy", "STRATEGIES", "EPS"]

EPS = 2.0**-53
REFERENCE_DPS = 61  # 200 bits
TOGGLE_OFFSETS = (1e-6, 1e-10, 1e-14)
NEAR_FOLD = 1e-2  # a discriminant factor's smallest value, relative to its largest
FAR = 10**7


@dataclass
class Accuracy:
    scene: str
    point: str
    rows: list

    def to_json(self):
        return {"scene": self.scene, "point": self.point, "rows": self.rows,
                "reference": f"the closed form in mpmath at {REFERENCE_DPS} digits (200 bits) "
                             "on the same float64 inputs", "eps": EPS}


class _Subject:
    """One compiled variant of the scene: its branch, point and the strategies' evaluators."""

    def __init__(self, scene, point):
        self.compiled = compile_scene(scene, [point])
        self.branch = next(b for b in closed_forms(self.compiled) if b.selected)
        (self.c, self.s), = self.compiled.system.inputs.values()
        dyad = next(d for d in self.compiled.dyads if d.point == point)
        self.unknowns = dyad.unknowns
        self.dyad = dyad
        self.stable = StableBranch(self.compiled, self.branch)
        derived = derive(scene, [point], samples=0)
        cs = (symbol(self.c), symbol(self.s))
        self.solved = {u: [sympy.lambdify(cs, r, "numpy")
                           for r in sympy.solve(derived.eliminations[u].polynomial, symbol(u))]
                       for u in self.unknowns}


def _reference(subject, theta):
    """Point and condition number per sample, at 200 bits from the exact float inputs."""
    points, kappas = [], []
    with mpmath.workdps(REFERENCE_DPS):
        step = mpmath.mpf(10) ** -25
        for angle in theta:
            at = lambda a: [evaluate(subject.branch.values[u], {subject.c: mpmath.cos(a), subject.s: mpmath.sin(a)},  # noqa: E731
                                     MPMATH) for u in subject.unknowns]
            a = mpmath.mpf(float(angle))
            x = at(a)
            dx = [(p - q) / (2 * step) for p, q in zip(at(a + step), at(a - step))]
            size = mpmath.sqrt(sum(v * v for v in x))
            kappas.append(float(abs(a) * mpmath.sqrt(sum(v * v for v in dx)) / size) + 1)
            points.append([float(v) for v in x])
    return np.array(points).T, np.array(kappas)


def _closed_form(subject, theta, truth):
    c, s = np.cos(theta), np.sin(theta)
    out = []
    for k, unknown in enumerate(subject.unknowns):
        with np.errstate(invalid="ignore", divide="ignore"):
            roots = np.array([np.broadcast_to(f(c, s), theta.shape) for f in subject.solved[unknown]])
        pick = np.argmin(np.abs(roots - truth[k]), axis=0)
        out.append(roots[pick, np.arange(theta.size)])
    return np.array(out)


def _stabilised(subject, theta):
    point = subject.stable(theta)
    return np.array([point[u] for u in subject.unknowns])


def _numeric(subject, theta, truth):
    """Newton from the previous sample's answer (the first starts from the truth's neighbour)."""
    c, s = np.cos(theta), np.sin(theta)
    values = {subject.c: c, subject.s: s}
    (px, py), (qx, qy) = subject.dyad.base_p, subject.dyad.base_q
    defaults = {symbol(n): v for n, v in subject.compiled.parameter_values.items()}
    bases = [np.broadcast_to(evaluate(sympy.sympify(e).xreplace(defaults), values, NUMPY), theta.shape)
             for e in (px, py, qx, qy)]
    l1, l2 = (float(sympy.sympify(v).xreplace(defaults)) for v in subject.dyad.lengths)
    x, y = np.roll(truth[0], 1), np.roll(truth[1], 1)
    for _ in range(6):
        f1 = (x - bases[0]) ** 2 + (y - bases[1]) ** 2 - l1 * l1
        f2 = (x - bases[2]) ** 2 + (y - bases[3]) ** 2 - l2 * l2
        j11, j12 = 2 * (x - bases[0]), 2 * (y - bases[1])
        j21, j22 = 2 * (x - bases[2]), 2 * (y - bases[3])
        det = j11 * j22 - j12 * j21
        x, y = x - (j22 * f1 - j12 * f2) / det, y - (-j21 * f1 + j11 * f2) / det
    return np.array([x, y])


def _timed(run, repeats=3):
    best = None
    for _ in range(repeats):
        start = time.perf_counter()
        result = run()
        elapsed = time.perf_counter() - start
        best = elapsed if best is None else min(best, elapsed)
    return result, best


def _row(strategy, case, theta, estimate, seconds, truth, kappa):
    error = np.sqrt(((estimate - truth) ** 2).sum(axis=0))
    size = np.sqrt((truth**2).sum(axis=0))
    relative = error / size
    finite = np.isfinite(relative)
    return {"strategy": strategy, "case": case, "samples": int(theta.size),
            "ns_per_sample": seconds / theta.size * 1e9,
            "max_abs_error": float(np.max(error)) if finite.all() else float("inf"),
            "max_rel_error": float(np.max(relative)) if finite.all() else float("inf"),
            "condition": float(np.max(kappa)),
            "error_over_kappa_eps": float(np.max(relative / (kappa * EPS))) if finite.all() else float("inf")}


STRATEGIES = ("closed-form", "stabilised", "numeric")


def _rows(subject, case, theta):
    truth, kappa = _reference(subject, theta)
    _, reference_seconds = _timed(lambda: _reference(subject, theta[: max(1, theta.size // 10)]), 1)
    runs = {"closed-form": lambda: _closed_form(subject, theta, truth),
            "stabilised": lambda: _stabilised(subject, theta),
            "numeric": lambda: _numeric(subject, theta, truth)}
    rows = []
    for name in STRATEGIES:
        estimate, seconds = _timed(runs[name])
        rows.append(_row(name, case, theta, estimate, seconds, truth, kappa))
    rows.append(_row("reference", case, theta, truth, reference_seconds * theta.size / max(1, theta.size // 10),
                     truth, kappa))
    return rows


def _cases(subject, samples, rng):
    """name -> sorted float64 input angles (radians)."""
    intervals = [i for i in certify_labels(subject.compiled, [subject.branch])[0] if i["status"] == "certified"]
    if not intervals:
        raise UsageError("scene", subject.compiled.scene.name, "no input interval where the branch is certified")
    widths = np.array([i["to_deg"] - i["from_deg"] for i in intervals])
    pick = rng.choice(len(intervals), size=samples, p=widths / widths.sum())
    lows = np.array([intervals[k]["from_deg"] for k in pick])
    cases = {"uniform": np.sort(np.radians(lows + rng.random(samples) * widths[pick]))}
    from .toggles import toggles

    edges = [np.radians(t.input_deg) for t in toggles(subject.compiled.scene, artefacts=False).toggles if t.point == subject.dyad.point]
    for offset in TOGGLE_OFFSETS:
        near = []
        for edge in edges:
            for side in (-1, 1):
                trial = edge * (1 + side * offset * (0.5 + 0.5 * rng.random(samples // (2 * len(edges)) + 1)))
                near += [a for a in trial if _assembles(subject, a)]
        if near:
            cases[f"toggle-{offset:.0e}"] = np.sort(np.array(near))
    folds = _near_folds(subject)
    if folds:
        spread = 1e-6 * (2 * rng.random((len(folds), samples // len(folds) + 1)) - 1)
        cases["near-fold"] = np.sort((np.array(folds)[:, None] * (1 + spread)).ravel())
    return cases


def _near_folds(subject):
    """Inputs (radians) where a factor ``k + beta c + gamma s`` of the discriminant, never zero,
    comes closest to zero: ``k - R`` or ``k + R`` with ``R = hypot(beta, gamma)``, at the angle
    of ``-(beta, gamma)`` or ``(beta, gamma)``."""
    defaults = {symbol(n): sympy.Rational(str(v)) for n, v in subject.compiled.parameter_values.items()}
    c, s = symbol(subject.c), symbol(subject.s)
    folds = []
    for factor, _ in sympy.factor_list(subject.branch.discriminants[subject.dyad.point].xreplace(defaults))[1]:
        if not factor.free_symbols <= {c, s} or sympy.Poly(factor, c, s).total_degree() != 1:
            continue
        poly = sympy.Poly(factor, c, s)
        k, beta, gamma = (float(poly.coeff_monomial(m)) for m in (1, c, s))
        reach = np.hypot(beta, gamma)
        if abs(k) - reach > 0 and (abs(k) - reach) < NEAR_FOLD * (abs(k) + reach):
            toward = -np.sign(k)  # the side where k + beta c + gamma s is smallest in size
            folds.append(float(np.arctan2(toward * gamma, toward * beta)) % (2 * np.pi))
    return folds


def _assembles(subject, angle):
    with mpmath.workdps(REFERENCE_DPS):
        a = mpmath.mpf(float(angle))
        values = {subject.c: mpmath.cos(a), subject.s: mpmath.sin(a)}
        return all(evaluate(d, values, MPMATH) > 0 for d in subject.branch.discriminants.values())


def _translated(scene, offset):
    """The scene moved by (offset, offset): every ground point shifted."""
    points = {n: (Fixed(p.x + offset, p.y + offset) if isinstance(p, Fixed) else p) for n, p in scene.points.items()}
    return dataclasses.replace(scene, points=points)


def accuracy(scene, samples=2000, seed=0, set=None):  # noqa: A002 - the public name, SPEC §3's --set
    """Rows of speed and error per strategy and case for the scene's first dyad point;
    ``set`` gives dimensions exact values in place of their defaults."""
    validation.count("samples", samples, validation.MAX_ACCURACY_SAMPLES, minimum=10)
    validation.seed(seed)
    scene = with_values(as_scene(scene), set)
    point = next((n for n, p in scene.points.items() if isinstance(p, Dyad)), None)
    if point is None:
        raise UsageError("scene", scene.name, "has no dyad to evaluate")
    rng = np.random.default_rng(seed)
    subject = _Subject(scene, point)
    rows = []
    for case, theta in _cases(subject, samples, rng).items():
        rows += _rows(subject, case, theta)
    far = _Subject(_translated(scene, FAR), point)
    rows += _rows(far, "far-1e7", _cases(far, samples, rng)["uniform"])
    return Accuracy(scene.name, point, rows)
