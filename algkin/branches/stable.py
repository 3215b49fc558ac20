"""A branch evaluated fast and without cancellation, from the input angles.

Each implicit point is evaluated by its own stable evaluator (``algkin.branches.constructions``:
a dyad's midpoint form with its span factored through its toggles, a slider's root that
cannot cancel), from exact expressions with the dimensions at their defaults.

Every input enters through one transcendental, ``t = tan(theta/2)`` (numpy's is
vectorised and correctly rounded to within an ulp), with ``c = (1 - t**2) w``,
``s = 2 t w``, ``w = 1 / (1 + t**2)``; an evaluator may use ``t`` and ``w`` themselves.
The base coordinates are compiled once (``numpy_function``, with common subexpressions
shared) and the samples are run in cache-sized chunks. A length input enters as it is.

>>> import numpy as np
>>> from algkin.scene import load_scene, compile_scene
>>> from algkin.branches import closed_forms
>>> compiled = compile_scene(load_scene("chebyshev-lambda"), ["B"])
>>> stable = StableBranch(compiled, closed_forms(compiled)[0])
>>> point = stable(np.array([0.0]))   # crank at 0 deg: A = (1, 0), D = (2, 0)
>>> round(float(point["B_x"][0]), 12), round(float(point["B_y"][0]), 12)
(1.5, 2.449489742783)
"""

from collections.abc import Callable, Mapping, Sequence

import numpy as np
import numpy.typing as npt
import sympy

from ..evaluate.fused import Kernel
from ..evaluate.program import numpy_function
from ..evaluate.trace import trace
from ..scene import Compiled
from ..scene.compile import resolve_outputs
from ..scene.implicit.algebra import reduce_on_circles
from ..scene.implicit.base import FloatArray
from ..system import symbol
from .closed_form import Branch
from .constructions import HalfAngle, StableEvaluator, algebra_of

__all__ = ["StableBranch", "chunked", "output_forms", "Outputs"]

Outputs = Callable[[Mapping[str, FloatArray]], Sequence[FloatArray]]  # variables -> the outputs wanted
CHUNK = 4096  # samples per pass: temporaries stay in cache and below malloc's mmap threshold


class StableBranch:
    """Vectorised float64 evaluation of every dyad and slider point of ``branch`` (dimensions at defaults)."""

    def __init__(self, compiled: Compiled, branch: Branch) -> None:
        self.defaults = {symbol(n): sympy.Rational(str(v)) for n, v in compiled.parameter_values.items()}
        self.compiled, self.branch = compiled, branch
        self.half_angles = compiled.circles
        self.inputs = [tuple(variables) for variables in compiled.system.inputs.values()]  # (c, s), or a length's
        self.arguments = [symbol(v) for variables in self.inputs for v in variables]
        arguments = list(self.arguments)
        self.evaluators: list[StableEvaluator] = []  # every implicit point's, in construction order
        for spec in compiled.implicit:
            sigma = float(spec.sign(branch.labels[spec.point])) if spec.labels else 1.0
            self.evaluators.append(algebra_of(spec).stable_evaluator(
                fix=self.fix, arguments=list(arguments), half_angles=self.half_angles, sigma=sigma))
            arguments += [symbol(u) for u in spec.unknowns]

    def fix(self, expr: sympy.Expr) -> sympy.Expr:
        """``expr`` with every dimension at its default, reduced on the inputs' circles."""
        return reduce_on_circles(sympy.sympify(expr).xreplace(self.defaults), self.half_angles)

    def __call__(self, *angles: npt.ArrayLike) -> dict[str, FloatArray]:
        """Each implicit point's coordinates (unknown -> array) from each input's angles in radians
        (a length as it is)."""
        unknowns = [u for e in self.evaluators for u in e.unknowns]
        values = chunked(lambda *part: self._unknowns(part, unknowns), angles)
        return dict(zip(unknowns, values))

    def _unknowns(self, angles: Sequence[FloatArray], unknowns: Sequence[str]) -> list[FloatArray]:
        variables = self.variables(angles)
        return [variables[u] for u in unknowns]

    def variables(self, angles: Sequence[FloatArray], tangents: bool = False) -> dict[str, FloatArray]:
        """Every variable (each input's cos and sin, then each point's unknowns) on one chunk of
        inputs (angles in radians, or with ``tangents`` their half-angle tangents ``tan(theta/2)``);
        numpy's operations only, in an order ``algkin.evaluate.trace`` records."""
        result: dict[str, FloatArray] = {}
        values: list[FloatArray] = []
        half: list[HalfAngle] = []
        for variables, theta in zip(self.inputs, angles):
            if len(variables) == 1:  # a length input enters as it is
                values.append(theta)
                result[variables[0]] = theta
                continue
            t = theta if tangents else np.tan(0.5 * theta)
            w = 1 / (1 + t * t)
            values += [(1 - t) * (1 + t) * w, 2 * t * w]
            result.update(zip(variables, values[-2:]))
            half.append((t, w))
        for evaluator in self.evaluators:
            x, y = evaluator(values, half)
            values += [x, y]
            result.update(zip(evaluator.unknowns, (x, y)))
        return result

    def kernel(self, outputs: Outputs | None = None, tangents: bool = False) -> Kernel:
        """The fused evaluator of ``outputs`` (a function of ``variables``' dictionary returning a
        list of arrays; default: every unknown), numba's loop where it pays, this numpy form elsewhere;
        from the input angles, or with ``tangents`` from their half-angle tangents (no transcendental
        left: the whole evaluation in the compiled loop).

        >>> from algkin.scene import load_scene, compile_scene
        >>> from algkin.branches import closed_forms
        >>> compiled = compile_scene(load_scene("chebyshev-lambda"), ["B"])
        >>> stable = StableBranch(compiled, closed_forms(compiled)[0])
        >>> [round(float(v[0]), 12) for v in stable.kernel()(np.array([0.0]), engine="numpy")]
        [1.5, 2.449489742783]
        """
        if outputs is None:
            unknowns = [u for e in self.evaluators for u in e.unknowns]
            outputs = lambda variables: [variables[u] for u in unknowns]  # noqa: E731
        step = lambda *angles: list(outputs(self.variables(angles, tangents)))  # noqa: E731
        names = [f"{'t' if tangents else 'theta'}{k}" for k in range(len(self.inputs))]
        return Kernel(trace(step, names), lambda *angles: chunked(step, angles))


def output_forms(stable: StableBranch, requested: Sequence[str] | None = None) -> tuple[list[str], Outputs]:
    """``(unknowns, outputs)``: the unknowns of the ``requested`` outputs (default: the compiled
    scene's) in order, and their stabilised forms from ``variables``: a dyad or slider point's
    own, an explicit one from its definition with its offsets cancelled exactly (a distance is
    the ``hypot`` of exact coordinate differences, no square root of expanded squares).

    >>> from algkin.scene import load_scene, compile_scene
    >>> from algkin.branches import closed_forms
    >>> compiled = compile_scene(load_scene("chebyshev-lambda"), ["P", "dist(O, P)"])
    >>> stable = StableBranch(compiled, closed_forms(compiled)[0])
    >>> names, forms = output_forms(stable, ["P", "dist(O, P)"])
    >>> names, [round(float(v), 12) for v in forms(stable.variables([np.array(0.0)]))]
    (['P_x', 'P_y', 'dist_O_P'], [2.0, 4.898979485566, 5.291502622129])
    """
    compiled, fix = stable.compiled, stable.fix
    arguments = stable.arguments + [symbol(u) for e in stable.evaluators for u in e.unknowns]
    names: list[str] = []
    parts: list[Callable[..., Sequence[FloatArray]]] = []
    for output in resolve_outputs(compiled.scene, requested or list(compiled.scene.outputs)):
        unknowns = list(compiled.outputs[output.name])
        if output.kind == "dist":  # offsets cancel symbolically before any rounding
            (px, py), (qx, qy) = (compiled.coordinates[p] for p in output.points)
            parts.append(_distance(numpy_function(arguments, [fix(px - qx), fix(py - qy)])))
        else:
            formulas = [fix(compiled.definitions.get(u, symbol(u))) for u in unknowns]
            parts.append(numpy_function(arguments, formulas))
        names += unknowns

    def forms(variables: Mapping[str, FloatArray]) -> list[FloatArray]:
        values = [variables[str(a)] for a in arguments]
        return [v for part in parts for v in part(*values)]
    return names, forms


def _distance(span: Callable[..., Sequence[FloatArray]]) -> Callable[..., list[FloatArray]]:
    """``values -> [hypot(dx, dy)]`` from the exact differences ``(dx, dy)`` that ``span`` computes."""
    def distance(*values: FloatArray) -> list[FloatArray]:
        return [np.hypot(*span(*values))]
    return distance


def chunked(step: Callable[..., Sequence[FloatArray]], angles: Sequence[npt.ArrayLike]) -> list[FloatArray]:
    """``step``'s outputs over ``angles`` (broadcast), run on ``CHUNK`` samples at a time."""
    arrays = np.broadcast_arrays(*(np.asarray(a, dtype=float) for a in angles))
    flat = [a.ravel() for a in arrays]
    out: list[FloatArray] = []
    for start in range(0, flat[0].size, CHUNK):
        part = slice(start, start + CHUNK)
        values = step(*(a[part] for a in flat))
        if not out:
            out = [np.empty(flat[0].size) for _ in values]
        for k, value in enumerate(values):
            out[k][part] = value
    if not out:  # no samples: one empty array per output
        out = [np.empty(0) for _ in step(*flat)]
    return [v.reshape(arrays[0].shape) for v in out]
