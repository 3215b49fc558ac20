"""Speed against error of each way to evaluate a branch, on ordinary and hard samples.

What is measured is one output (``of``: a point, a distance, a coordinate; by default the
scene's first dyad point, else its first output). Strategies, all vectorised over float64
samples of the input:

- ``closed-form``: the eliminants solved the seeds' way (``sympy.solve``, then
  ``lambdify``); the root nearest the truth is credited, since solving does not pair roots;
- ``stabilised``: ``branches.stable.StableBranch`` (local frame, sorted Heron) for dyad and
  slider points; an explicit output from those with its offsets cancelled exactly (a distance
  is the ``hypot`` of exact coordinate differences);
- ``compiled``: the same stabilised operations, traced once and compiled by numba into one
  fused loop per sample (``evaluate.fused``; numpy's vectorised ``tan`` for the half-angle
  tangents), the same values as ``stabilised`` bit for bit where both round alike; without
  numba (the ``fast`` extra), the numpy form again, with a note;
- ``numeric``: float Newton on the original equations, what a user's solver would do:
  continuation (started from the construction at the previous sample), iterated while the
  step shrinks (at most ``NEWTON_STEPS``), then checked: converged (last step within
  ``SOLVED`` of the root's size) and on the labelled branch (each indicator's sign, in float,
  the label's). A sample that fails either is ``unsolved``: counted in the row (its
  ``unsolved`` field and a note) and left out of its errors, since an unconverged answer, or
  the other branch's, compared against the truth says nothing of the strategy's accuracy.
  Far from the origin the expanded equations' terms (1e14 at 1e7) cancel in its residual:
  converged, it is still some 1e7 kappa eps off there;
- ``reference``: ``reference.Reference``, the root of the original equations certified by a
  Krawczyk step in arb at 200 bits and labelled by side: nothing of the closed form enters.
  Every sample of a case is certified at once (numpy arrays of balls); its time is per
  certified sample, the ones it cannot certify included in it.

Errors are against the reference. ``condition`` is the relative condition number of the
output in the input angle from the system's Jacobian, ``|theta| * |X'(theta)| / |X|`` (plus
one for the rounding of the result), so ``error_over_kappa_eps`` near 1 means as accurate as
the problem allows. Cases: ``uniform`` over the certified intervals, within 1e-6, 1e-10 and
1e-14 (relative) of each toggle on its assembling side, ``near-fold`` around the input where a
dyad that never toggles comes within 1% of it (a near-change-point four-bar: its closest
approach to a dead centre), and the mechanism translated 1e7 away. A sample the reference
cannot certify (on the side of a toggle where the branch does not assemble) is left out.
"""

import functools
import time
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, TypedDict, TypeVar

import numpy as np
import sympy
from numpy.typing import NDArray

from ..branches import Branch, closed_forms
from ..branches.stable import StableBranch, output_forms
from ..derivation.assembles import certify_labels
from ..derivation.pipeline import derive
from ..errors import UsageError, renamed
from ..evaluate.fused import numba_available
from ..runtime import progress, validation
from ..runtime.budget import Budget, Deadline, started
from ..scene import Scene, compile_scene
from ..scene.compile import Compiled
from ..scene.groups import compile_groups
from ..scene.constructions import Dyad
from ..scene.implicit.base import ImplicitSpec
from ..scene.load import SceneLike, Values, as_scene
from ..scene.settings import with_values
from ..system import symbol
from .groupaccuracy import GroupAccuracy, group_accuracy
from .reference import BITS, Floats, Reference

_T = TypeVar("_T")

__all__ = ["accuracy", "Accuracy", "Subject", "sample_cases", "STRATEGIES", "EPS", "REFERENCE"]

EPS = 2.0**-53
REFERENCE = f"certified root of the original equations (Krawczyk in arb at {BITS} bits), labelled by side"
TOGGLE_OFFSETS = (1e-6, 1e-10, 1e-14)
NEAR_FOLD = 1e-2  # a discriminant factor's smallest value, relative to its largest
FAR = 10**7
ROUNDING_FLOOR = 4  # err/(kappa eps) that a handful of correctly rounded operations reach
NEWTON_STEPS = 40  # the numeric strategy's most steps: continuation starts are near, a few suffice
SOLVED = 2.0**-26  # its last step, relative to the root's size, when it counts as converged


class _Figures(TypedDict):
    strategy: str
    case: str
    samples: int
    ns_per_sample: float
    max_abs_error: float
    max_rel_error: float
    condition: float
    error_over_kappa_eps: float


class AccuracyRow(_Figures, total=False):
    """One strategy on one case: its speed and errors; why, where it needs saying; the
    numeric strategy's samples it did not solve."""

    note: str
    unsolved: int


@dataclass
class Accuracy:
    scene: str
    point: str  # the output measured
    rows: list[AccuracyRow]

    def to_json(self) -> dict[str, object]:
        return {"scene": self.scene, "point": self.point, "rows": self.rows, "reference": REFERENCE, "eps": EPS}


class Subject:
    """What an accuracy run measures: ``scene`` compiled for the output ``of``, the scene's branch,
    the construction whose toggles matter (``dyad``) and each strategy's evaluator (``stable``,
    ``reference``, ``newton``, ``solved``); its derivation keeps to ``deadline``, if any."""

    def __init__(self, scene: Scene, of: str, *, deadline: Deadline | None = None) -> None:
        self.compiled = compile_scene(scene, [of])
        self.branch = next(b for b in closed_forms(self.compiled) if b.selected)
        (self.unknowns,) = self.compiled.outputs.values()
        self.c, self.s = _one_input(self.compiled, self.branch, self.unknowns, of)
        # the construction whose toggles matter: the output's own, else the last one it rests on
        self.dyad = next((d for d in self.compiled.implicit if d.point == of), None) or \
            (self.compiled.implicit[-1] if self.compiled.implicit else None)
        self.stable = _StableOutput(self.compiled, self.branch, of)
        self.reference = Reference(self.compiled, self.branch, self.unknowns)
        self.newton = _Newton(self.reference)
        derived = derive(scene, [of], samples=0, budget=deadline)
        cs = (symbol(self.c), symbol(self.s))
        self.solved = {u: [sympy.lambdify(cs, r, "numpy")
                           for r in sympy.solve(derived.eliminations[u].polynomial, symbol(u))]
                       for u in self.unknowns}


def _one_input(compiled: Compiled, branch: Branch, unknowns: tuple[str, ...], of: str) -> tuple[str, ...]:
    """The one input angle's (cos, sin) names that ``of`` moves with; a UsageError if it moves with
    none (a fixed point, a bar's length: no error to measure) or with more than one."""
    inputs = compiled.system.inputs
    if len(inputs) > 1:
        raise UsageError("of", of, f"moves with {len(inputs)} inputs ({', '.join(inputs)}); accuracy is measured "
                                   "over one input angle")
    angles = {symbol(n) for pair in inputs.values() for n in pair}
    if not any(sympy.sympify(branch.values[u]).free_symbols & angles for u in unknowns):
        raise UsageError("of", of, "does not move with the input: no error to measure")
    (pair,) = inputs.values()
    return pair


class _StableOutput:
    """The stabilised form of the output: StableBranch's implicit points, explicit ones on top."""

    def __init__(self, compiled: Compiled, branch: Branch, of: str) -> None:
        self.branch = StableBranch(compiled, branch)
        self.unknowns, forms = output_forms(self.branch, [of])
        self.kernel = self.branch.kernel(forms)

    def __call__(self, theta: Floats, engine: str = "numpy") -> Floats:
        """The output's coordinates (rows) per sample: numpy's form, or with ``engine="compiled"``
        the same operations fused by numba (numpy's again where numba is not installed)."""
        return np.array(self.kernel(theta, engine=engine))


class _Newton:
    """Float Newton on the original equations, vectorised: the ``numeric`` strategy.

    Each sample starts from the construction at the previous sample's input (continuation; the
    first sample from the last's) and iterates while its step shrinks (at most ``NEWTON_STEPS``).
    It is solved when its last step is within ``SOLVED`` of its size and every indicator has
    the label's sign (in float) there; otherwise it is NaN: unconverged or on the other branch.
    """

    def __init__(self, reference: Reference) -> None:
        arguments = reference.unknowns + list(reference.cs)
        self.f = sympy.lambdify(arguments, reference.equations, "numpy")
        self.j = sympy.lambdify(arguments, sympy.Matrix(reference.equations).jacobian(reference.unknowns).tolist(),
                                "numpy")
        self.signs = sympy.lambdify(arguments, reference.indicators, "numpy")
        self.expected = reference.expected[:, None]
        self.start, self.outputs = reference.start, reference.outputs

    def __call__(self, theta: Floats) -> Floats:
        """The outputs (rows) per sample (columns); NaN where the sample is not solved."""
        x = self.start(np.roll(theta, 1))
        c, s = np.cos(theta), np.sin(theta)
        last = np.full(theta.shape, np.inf)  # each sample's last step, relative to the root's size
        going = np.ones(theta.shape, dtype=bool)
        with np.errstate(invalid="ignore"):
            for _ in range(NEWTON_STEPS):
                step = _solve(_matrix(self.j(*x[:, going], c[going], s[going]), going.sum()),
                              _matrix(self.f(*x[:, going], c[going], s[going]), going.sum()))
                x[:, going] -= step
                size = np.maximum(np.abs(x[:, going]).max(axis=0), np.finfo(float).tiny)
                relative = np.abs(step).max(axis=0) / size
                shrinking = relative < last[going]
                last[going] = relative
                going[going] = shrinking & (relative > 0)
                if not going.any():
                    break
            signs = _matrix(self.signs(*x, c, s), theta.size)
            labelled = np.where(self.expected, signs > 0, signs < 0).all(axis=0)
        x[:, ~(labelled & (last <= SOLVED))] = np.nan
        return x[self.outputs]


def _matrix(values: list[Any], count: int) -> Floats:
    """lambdify's nested lists (a constant entry is a number) as floats, the ``count`` samples last."""
    if not values:  # no indicator: nothing to check
        return np.zeros((0, count))
    return np.array([_matrix(v, count) if isinstance(v, list) else np.broadcast_to(v, (count,)) for v in values],
                    dtype=float)


def _solve(j: Floats, f: Floats) -> Floats:
    """``j^-1 f`` per sample (``j``: n x n x samples); a singular sample (a start on a toggle) gives nan."""
    stacked = j.transpose(2, 0, 1)
    try:
        return np.linalg.solve(stacked, f.T[:, :, None])[:, :, 0].T
    except np.linalg.LinAlgError:
        singular = np.linalg.matrix_rank(stacked) < f.shape[0]
        return (np.linalg.pinv(stacked) @ f.T[:, :, None])[:, :, 0].T * np.where(singular, np.nan, 1.0)


def _closed_form(subject: Subject, theta: Floats, truth: Floats) -> Floats:
    c, s = np.cos(theta), np.sin(theta)
    out = []
    for k, unknown in enumerate(subject.unknowns):
        with np.errstate(invalid="ignore", divide="ignore"):
            roots = np.array([np.broadcast_to(f(c, s), theta.shape) for f in subject.solved[unknown]])
        pick = np.argmin(np.abs(roots - truth[k]), axis=0)
        out.append(roots[pick, np.arange(theta.size)])
    return np.array(out)


def _timed(run: Callable[[], _T], repeats: int = 3) -> tuple[_T, float]:
    best = float("inf")
    for _ in range(repeats):
        start = time.perf_counter()
        result = run()
        elapsed = time.perf_counter() - start
        best = min(best, elapsed)
    return result, best


def _row(strategy: str, case: str, theta: Floats, estimate: Floats, seconds: float, truth: Floats, kappa: Floats,
         note: str = "", solved: NDArray[np.bool_] | None = None) -> AccuracyRow:
    """One strategy's row; its errors over the ``solved`` samples (default: all)."""
    solved = np.ones(theta.size, dtype=bool) if solved is None else solved
    error = np.sqrt(((estimate - truth)[:, solved] ** 2).sum(axis=0))
    relative = error / np.sqrt((truth[:, solved] ** 2).sum(axis=0))
    row: AccuracyRow = {"strategy": strategy, "case": case, "samples": int(theta.size),
           "ns_per_sample": seconds / theta.size * 1e9,
           "max_abs_error": _worst(error), "max_rel_error": _worst(relative),
           "condition": float(np.max(kappa)),
           "error_over_kappa_eps": _worst(relative / (kappa[solved] * EPS))}
    if note:
        row["note"] = note
    return row


def _worst(errors: Floats) -> float:
    """The largest error; infinite if one is not finite, or if nothing was compared."""
    return float(np.max(errors)) if errors.size and np.isfinite(errors).all() else float("inf")


def _numeric_row(case: str, theta: Floats, estimate: Floats, seconds: float, truth: Floats,
                 kappa: Floats) -> AccuracyRow:
    """The numeric strategy's row: errors over the samples it solved, the others counted as
    ``unsolved`` (an unconverged or wrong-branch answer compared would flatter the others)."""
    solved = np.all(np.isfinite(estimate), axis=0)
    unsolved = int(theta.size - solved.sum())
    note = (f"{unsolved} of {theta.size} samples unsolved (not converged, or on the other branch); "
            "the errors are over the others") if unsolved else ""
    row = _row("numeric", case, theta, estimate, seconds, truth, kappa, note, solved)
    row["unsolved"] = unsolved
    return row


STRATEGIES = ("closed-form", "stabilised", "compiled", "numeric")


def _certified(subject: Subject, theta: Floats) -> tuple[Floats, Floats, Floats]:
    """``(theta, truth, kappa)`` on the samples the reference certifies (the others do not assemble)."""
    certified = subject.reference.certify(theta)
    return theta[certified.ok], certified.points[:, certified.ok], certified.kappas[certified.ok]


def _rows(subject: Subject, case: str, theta: Floats) -> list[AccuracyRow]:
    (theta, truth, kappa), reference_seconds = _timed(lambda: _certified(subject, theta), 1)
    if not theta.size:
        return []
    runs: dict[str, Callable[[], Floats]] = {"closed-form": lambda: _closed_form(subject, theta, truth),
            "stabilised": lambda: subject.stable(theta),
            "compiled": lambda: subject.stable(theta, engine="compiled"),
            "numeric": lambda: subject.newton(theta)}
    rows: list[AccuracyRow] = []
    for name in STRATEGIES:
        estimate, seconds = _timed(runs[name])
        row = _numeric_row if name == "numeric" else functools.partial(_row, name)
        rows.append(row(case, theta, estimate, seconds, truth, kappa))
    _explain(*rows[:2])
    if not numba_available():
        rows[2]["note"] = "numba is not installed (the fast extra): numpy's stabilised form, the fallback"
    rows.append(_row("reference", case, theta, truth, reference_seconds, truth, kappa))
    return rows


def _explain(raw: AccuracyRow, stabilised: AccuracyRow) -> None:
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


def sample_cases(subject: Subject, samples: int, rng: np.random.Generator) -> dict[str, Floats]:
    """The cases an accuracy run measures ``subject`` on (see the module's text), drawn with the
    numpy generator ``rng``: name (``uniform``, ``toggle-1e-06``..., ``near-fold``) -> sorted float64
    input angles (radians), about ``samples`` of them per case."""
    intervals = [i for i in certify_labels(subject.compiled, [subject.branch])[0] or [] if i["status"] == "certified"]
    if not intervals:
        raise UsageError("scene", subject.compiled.scene.name, "no input interval where the branch is certified")
    widths = np.array([i["to_deg"] - i["from_deg"] for i in intervals])
    pick = rng.choice(len(intervals), size=samples, p=widths / widths.sum())
    lows = np.array([intervals[k]["from_deg"] for k in pick])
    cases = {"uniform": np.sort(np.radians(lows + rng.random(samples) * widths[pick]))}
    if subject.dyad is None:
        return cases
    from ..analyses.toggles import toggles

    edges = [np.radians(t.input_deg) for t in toggles(subject.compiled.scene, artefacts=False).toggles
             if t.point == subject.dyad.point]
    for offset in TOGGLE_OFFSETS:
        # Both sides: the reference certifies only the assembling one. A toggle at 0 gets absolute offsets.
        near = [edge + side * offset * max(abs(edge), 1.0) * (0.5 + 0.5 * rng.random(samples // (2 * len(edges)) + 1))
                for edge in edges for side in (-1, 1)]
        if near:
            cases[f"toggle-{offset:.0e}"] = np.sort(np.concatenate(near))
    folds = _near_folds(subject, subject.dyad)
    if folds:
        spread = 1e-6 * (2 * rng.random((len(folds), samples // len(folds) + 1)) - 1)
        cases["near-fold"] = np.sort((np.array(folds)[:, None] * (1 + spread)).ravel())
    return cases


def _near_folds(subject: Subject, dyad: ImplicitSpec) -> list[float]:
    """Inputs (radians) where a factor ``k + beta c + gamma s`` of the discriminant, never zero,
    comes closest to zero: ``k - R`` or ``k + R`` with ``R = hypot(beta, gamma)``, at the angle
    of ``-(beta, gamma)`` or ``(beta, gamma)``."""
    defaults = {symbol(n): sympy.Rational(str(v)) for n, v in subject.compiled.parameter_values.items()}
    c, s = symbol(subject.c), symbol(subject.s)
    discriminant = subject.branch.discriminants.get(dyad.point)
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


def accuracy(scene: SceneLike, samples: int = 2000, seed: int = 0, set: Values | None = None,  # noqa: A002 - the public name (--set)
             of: str | None = None, *, budget: Budget | Deadline | None = None) -> Accuracy | GroupAccuracy:
    """Rows of speed and error per strategy and case for the output ``of`` (a point, ``dist(A, B)``,
    ``B.x`` or an output's name; default: the first dyad point, else the first output);
    ``set`` gives dimensions exact values in place of their defaults. A ``Budget`` (or the
    ``Deadline`` of one running) bounds the derivation's eliminants and says what is measured.
    A scene with points solved together is measured by ``groupaccuracy.group_accuracy`` (every
    moving point; ``of`` not taken)."""
    deadline = started(budget)
    validation.count("samples", samples, validation.MAX_ACCURACY_SAMPLES, minimum=10)
    validation.seed(seed)
    scene = with_values(as_scene(scene), set)
    if scene.unknown_points:
        if of is not None:
            raise UsageError("of", of, "points solved together are measured all at once: leave out the output")
        compile_groups(scene)  # bad groups are bad input: a SceneError first
        return group_accuracy(scene, samples, seed)
    if of is None:
        of = next((n for n, p in scene.points.items() if isinstance(p, Dyad)), None) or next(iter(scene.outputs), None)
    if of is None:
        raise UsageError("scene", scene.name, "has no dyad and no output to evaluate; name one (of)")
    lengths = [n for n, i in scene.inputs.items() if not i.is_angle]
    if lengths:  # the stabilised forms and the hard cases near toggles are laid out on a turning input
        raise UsageError("scene", scene.name, f"accuracy is measured over an input angle; {lengths[0]} is a length")
    rng = np.random.default_rng(seed)
    with renamed("outputs", to="of"):
        subject = Subject(scene, of, deadline=deadline)
    rows: list[AccuracyRow] = []
    deadline.note(f"measuring each strategy on {scene.name}")
    for case, theta in progress.counted(sample_cases(subject, samples, rng).items(), "cases"):
        rows += _rows(subject, case, theta)
    far = Subject(scene.translated(FAR), of, deadline=deadline)
    rows += _rows(far, "far-1e7", sample_cases(far, samples, rng)["uniform"])
    return Accuracy(scene.name, of, rows)
