"""Speed against error of each way to evaluate a branch, on ordinary and hard samples.

What is measured is one output (``of``: a point, a distance, a coordinate; by default the
scene's first dyad point, else its first output). Strategies, all vectorised over float64
samples of the input:

- ``closed-form``: the eliminants solved the seeds' way (``sympy.solve``, then
  ``lambdify``); the root nearest the truth is credited, since solving does not pair roots;
- ``stabilised``: ``branches.stable.StableBranch`` (local frame, sorted Heron) for dyad and
  slider points; an explicit output from those with its offsets cancelled exactly (a distance
  is the ``hypot`` of exact coordinate differences);
- ``numeric``: Newton on the original equations, started from the construction at the previous
  sample (six steps);
- ``reference``: ``reference.Reference``, the root of the original equations certified by a
  Krawczyk step in arb at 200 bits and labelled by side: nothing of the closed form enters.

Errors are against the reference. ``condition`` is the relative condition number of the
output in the input angle from the system's Jacobian, ``|theta| * |X'(theta)| / |X|`` (plus
one for the rounding of the result), so ``error_over_kappa_eps`` near 1 means as accurate as
the problem allows. Cases: ``uniform`` over the certified intervals, within 1e-6, 1e-10 and
1e-14 (relative) of each toggle on its assembling side, ``near-fold`` around the input where a
dyad that never toggles comes within 1% of it (a near-change-point four-bar: its closest
approach to a dead centre), and the mechanism translated 1e7 away. A sample the reference
cannot certify (on the side of a toggle where the branch does not assemble) is left out.
"""

import dataclasses
import time
from dataclasses import dataclass

import numpy as np
import sympy
from flint import ctx

from .branches import closed_forms
from .branches.closed_form import reduce_on_circles
from .branches.stable import StableBranch
from . import validation
from .errors import UsageError
from .pipeline import certify_labels, derive
from .reference import BITS, NotCertified, Reference
from .scene import compile_scene
from .scene.compile import _resolve_outputs
from .scene.load import as_scene
from .scene.settings import with_values
from .scene.constructions import Dyad, Fixed
from .system import symbol

__all__ = ["accuracy", "Accuracy", "STRATEGIES", "EPS", "REFERENCE"]

EPS = 2.0**-53
REFERENCE = f"certified root of the original equations (Krawczyk in arb at {BITS} bits), labelled by side"
TOGGLE_OFFSETS = (1e-6, 1e-10, 1e-14)
NEAR_FOLD = 1e-2  # a discriminant factor's smallest value, relative to its largest
FAR = 10**7
ROUNDING_FLOOR = 4  # err/(kappa eps) that a handful of correctly rounded operations reach


@dataclass
class Accuracy:
    scene: str
    point: str  # the output measured
    rows: list

    def to_json(self):
        return {"scene": self.scene, "point": self.point, "rows": self.rows, "reference": REFERENCE, "eps": EPS}


class _Subject:
    """One compiled variant of the scene: its branch, output and the strategies' evaluators."""

    def __init__(self, scene, of):
        self.compiled = compile_scene(scene, [of])
        self.branch = next(b for b in closed_forms(self.compiled) if b.selected)
        (self.c, self.s), = self.compiled.system.inputs.values()
        (self.unknowns,) = self.compiled.outputs.values()
        # the construction whose toggles matter: the output's own, else the last one it rests on
        self.dyad = next((d for d in self.compiled.implicit if d.point == of), None) or \
            (self.compiled.implicit[-1] if self.compiled.implicit else None)
        self.stable = _StableOutput(self.compiled, self.branch, of)
        self.reference = Reference(self.compiled, self.branch, self.unknowns)
        self.newton = _Newton(self.compiled, self.reference)
        derived = derive(scene, [of], samples=0)
        cs = (symbol(self.c), symbol(self.s))
        self.solved = {u: [sympy.lambdify(cs, r, "numpy")
                           for r in sympy.solve(derived.eliminations[u].polynomial, symbol(u))]
                       for u in self.unknowns}


class _StableOutput:
    """The stabilised form of the output: StableBranch's implicit points, explicit ones on top."""

    def __init__(self, compiled, branch, of):
        self.branch = StableBranch(compiled, branch)
        defaults = {symbol(n): sympy.Rational(str(v)) for n, v in compiled.parameter_values.items()}
        circles = self.branch.half_angles
        fix = lambda e: reduce_on_circles(sympy.sympify(e).xreplace(defaults), circles)  # noqa: E731
        self.arguments = [v for pair in circles for v in pair] + \
            [symbol(u) for d in self.branch.dyads for u in d.unknowns]
        (self.unknowns,) = compiled.outputs.values()
        output = _resolve_outputs(compiled.scene, [of])[0]
        if output.kind == "dist":  # offsets cancel symbolically before any rounding
            (px, py), (qx, qy) = (compiled.coordinates[p] for p in output.points)
            span = sympy.lambdify(self.arguments, [fix(px - qx), fix(py - qy)], "numpy")
            self.explicit = lambda *values: [np.hypot(*span(*values))]
        else:
            formulas = [fix(compiled.definitions.get(u, symbol(u))) for u in self.unknowns]
            self.explicit = sympy.lambdify(self.arguments, formulas, "numpy")

    def __call__(self, theta):
        t = np.tan(0.5 * theta)
        w = 1 / (1 + t * t)
        implicit = self.branch(theta)
        values = [(1 - t) * (1 + t) * w, 2 * t * w] + [implicit[str(a)] for a in self.arguments[2:]]
        return np.array([np.broadcast_to(v, theta.shape) for v in self.explicit(*values)])


class _Newton:
    """Float Newton on the original equations, vectorised: the ``numeric`` strategy."""

    def __init__(self, compiled, reference):
        defaults = {symbol(n): sympy.Rational(str(v)) for n, v in compiled.parameter_values.items()}
        equations = [e.xreplace(defaults) for e in compiled.system.equations
                     if not e.free_symbols <= set(reference.cs)]
        arguments = reference.unknowns + list(reference.cs)
        self.f = sympy.lambdify(arguments, equations, "numpy")
        self.j = sympy.lambdify(arguments, sympy.Matrix(equations).jacobian(reference.unknowns), "numpy")
        self.start, self.outputs = reference.start, reference.outputs

    def __call__(self, theta):
        """Six steps from the construction at the previous sample's input (the first: the last's)."""
        x = self.start(np.roll(theta, 1))
        c, s = np.cos(theta), np.sin(theta)
        for _ in range(6):
            f = np.array([np.broadcast_to(v, theta.shape) for v in self.f(*x, c, s)])
            j = np.array([[np.broadcast_to(v, theta.shape) for v in row] for row in self.j(*x, c, s)])
            x = x - _solve(j, f)
        return x[self.outputs]


def _solve(j, f):
    """``j^-1 f`` per sample (``j``: n x n x samples); a singular sample (a start on a toggle) gives nan."""
    stacked = j.transpose(2, 0, 1)
    try:
        return np.linalg.solve(stacked, f.T[:, :, None])[:, :, 0].T
    except np.linalg.LinAlgError:
        singular = np.linalg.matrix_rank(stacked) < f.shape[0]
        return (np.linalg.pinv(stacked) @ f.T[:, :, None])[:, :, 0].T * np.where(singular, np.nan, 1.0)


def _closed_form(subject, theta, truth):
    c, s = np.cos(theta), np.sin(theta)
    out = []
    for k, unknown in enumerate(subject.unknowns):
        with np.errstate(invalid="ignore", divide="ignore"):
            roots = np.array([np.broadcast_to(f(c, s), theta.shape) for f in subject.solved[unknown]])
        pick = np.argmin(np.abs(roots - truth[k]), axis=0)
        out.append(roots[pick, np.arange(theta.size)])
    return np.array(out)


def _timed(run, repeats=3):
    best = None
    for _ in range(repeats):
        start = time.perf_counter()
        result = run()
        elapsed = time.perf_counter() - start
        best = elapsed if best is None else min(best, elapsed)
    return result, best


def _row(strategy, case, theta, estimate, seconds, truth, kappa, note=""):
    error = np.sqrt(((estimate - truth) ** 2).sum(axis=0))
    size = np.sqrt((truth**2).sum(axis=0))
    relative = error / size
    finite = np.isfinite(relative)
    row = {"strategy": strategy, "case": case, "samples": int(theta.size),
           "ns_per_sample": seconds / theta.size * 1e9,
           "max_abs_error": float(np.max(error)) if finite.all() else float("inf"),
           "max_rel_error": float(np.max(relative)) if finite.all() else float("inf"),
           "condition": float(np.max(kappa)),
           "error_over_kappa_eps": float(np.max(relative / (kappa * EPS))) if finite.all() else float("inf")}
    return dict(row, note=note) if note else row


STRATEGIES = ("closed-form", "stabilised", "numeric")


def _certified(subject, theta):
    """``(theta, truth, kappa)`` on the samples the reference certifies (the others do not assemble)."""
    keep, truth, kappas = [], [], []
    starts = subject.reference.start(theta)
    with ctx.workprec(BITS):
        for k, angle in enumerate(theta):
            try:
                root, kappa = subject.reference.one(float(angle), starts[:, k])
            except (NotCertified, ZeroDivisionError, ValueError):
                continue
            keep.append(k)
            truth.append([float(root[i].mid()) for i in subject.reference.outputs])
            kappas.append(kappa)
    return theta[keep], np.array(truth).reshape(-1, len(subject.unknowns)).T, np.array(kappas)


def _rows(subject, case, theta):
    (theta, truth, kappa), reference_seconds = _timed(lambda: _certified(subject, theta), 1)
    if not theta.size:
        return []
    runs = {"closed-form": lambda: _closed_form(subject, theta, truth),
            "stabilised": lambda: subject.stable(theta),
            "numeric": lambda: subject.newton(theta)}
    rows = []
    for name in STRATEGIES:
        estimate, seconds = _timed(runs[name])
        rows.append(_row(name, case, theta, estimate, seconds, truth, kappa))
    _explain(*rows[:2])
    rows.append(_row("reference", case, theta, truth, reference_seconds, truth, kappa))
    return rows


def _explain(raw, stabilised):
    """The stabilised row says why, where it is less accurate than the raw closed form."""
    if stabilised["max_rel_error"] <= raw["max_rel_error"]:
        return
    if stabilised["error_over_kappa_eps"] <= 1:
        stabilised["note"] = ("within kappa*eps, what the input's own rounding allows: it rounds "
                              "tan(theta/2), the raw form cos and sin, each of them an eps of theta")
    elif stabilised["error_over_kappa_eps"] <= ROUNDING_FLOOR:
        stabilised["note"] = (f"both at the rounding floor (within {ROUNDING_FLOOR} kappa*eps): the difference "
                              f"is the last bits of a few roundings ({stabilised['max_rel_error']:.1e} against "
                              f"{raw['max_rel_error']:.1e})")
    else:  # not explained: a finding the row must show
        stabilised["note"] = (f"less accurate than the raw closed form ({stabilised['max_rel_error']:.1e} "
                              f"against {raw['max_rel_error']:.1e}), beyond the rounding floor")


def _cases(subject, samples, rng):
    """name -> sorted float64 input angles (radians)."""
    intervals = [i for i in certify_labels(subject.compiled, [subject.branch])[0] if i["status"] == "certified"]
    if not intervals:
        raise UsageError("scene", subject.compiled.scene.name, "no input interval where the branch is certified")
    widths = np.array([i["to_deg"] - i["from_deg"] for i in intervals])
    pick = rng.choice(len(intervals), size=samples, p=widths / widths.sum())
    lows = np.array([intervals[k]["from_deg"] for k in pick])
    cases = {"uniform": np.sort(np.radians(lows + rng.random(samples) * widths[pick]))}
    if subject.dyad is None:
        return cases
    from .toggles import toggles

    edges = [np.radians(t.input_deg) for t in toggles(subject.compiled.scene, artefacts=False).toggles
             if t.point == subject.dyad.point]
    for offset in TOGGLE_OFFSETS:
        # Both sides: the reference certifies only the assembling one. A toggle at 0 gets absolute offsets.
        near = [edge + side * offset * max(abs(edge), 1.0) * (0.5 + 0.5 * rng.random(samples // (2 * len(edges)) + 1))
                for edge in edges for side in (-1, 1)]
        if near:
            cases[f"toggle-{offset:.0e}"] = np.sort(np.concatenate(near))
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
    discriminant = subject.branch.discriminants.get(subject.dyad.point)
    folds = []
    for factor, _ in sympy.factor_list(discriminant.xreplace(defaults))[1] if discriminant is not None else ():
        if not factor.free_symbols <= {c, s} or sympy.Poly(factor, c, s).total_degree() != 1:
            continue
        poly = sympy.Poly(factor, c, s)
        k, beta, gamma = (float(poly.coeff_monomial(m)) for m in (1, c, s))
        reach = np.hypot(beta, gamma)
        if abs(k) - reach > 0 and (abs(k) - reach) < NEAR_FOLD * (abs(k) + reach):
            toward = -np.sign(k)  # the side where k + beta c + gamma s is smallest in size
            folds.append(float(np.arctan2(toward * gamma, toward * beta)) % (2 * np.pi))
    return folds


def _translated(scene, offset):
    """The scene moved by (offset, offset): every ground point shifted."""
    points = {n: (Fixed(p.x + offset, p.y + offset) if isinstance(p, Fixed) else p) for n, p in scene.points.items()}
    return dataclasses.replace(scene, points=points)


def accuracy(scene, samples=2000, seed=0, set=None, of=None):  # noqa: A002 - the public name, SPEC §3's --set
    """Rows of speed and error per strategy and case for the output ``of`` (a point, ``dist(A, B)``,
    ``B.x`` or an output's name; default: the first dyad point, else the first output);
    ``set`` gives dimensions exact values in place of their defaults."""
    validation.count("samples", samples, validation.MAX_ACCURACY_SAMPLES, minimum=10)
    validation.seed(seed)
    scene = with_values(as_scene(scene), set)
    if of is None:
        of = next((n for n, p in scene.points.items() if isinstance(p, Dyad)), None) or next(iter(scene.outputs), None)
    if of is None:
        raise UsageError("scene", scene.name, "has no dyad and no output to evaluate; name one with --of")
    rng = np.random.default_rng(seed)
    subject = _Subject(scene, of)
    rows = []
    for case, theta in _cases(subject, samples, rng).items():
        rows += _rows(subject, case, theta)
    far = _Subject(_translated(scene, FAR), of)
    rows += _rows(far, "far-1e7", _cases(far, samples, rng)["uniform"])
    return Accuracy(scene.name, of, rows)
