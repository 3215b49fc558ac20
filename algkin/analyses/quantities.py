"""The seed documents' way of working, done by elimination: load, ask for a quantity, get sympy.

>>> arm = load_quantities("arm-string", params=["b"])
>>> AB = arm.dist("A", "B")
>>> AB.expr
sqrt(b**2 - 700*b*cos(theta) - 280000*sin(theta) + 282500)
>>> AB.expr_cs  # the same in the polynomial system's symbols, as derive and --json give it
sqrt(b**2 - 700*b*c_theta - 280000*s_theta + 282500)
>>> round(AB.at(theta=90, b=80), 9)
94.339811321
>>> found = AB.extremum(range=(0, 180))
>>> round(found.minimum.value, 9), round(found.minimum.input_deg, 6)
(57.921561087, 78.690068)
>>> found.closed_form.value
sqrt(b**2 + 160000) - 350
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from functools import cached_property
from typing import TYPE_CHECKING, Any

import attrs
import mpmath
import numpy as np
import sympy

from ..errors import UsageError
from ..evaluate import MPMATH, evaluate
from ..runtime import suggest, validation
from ..runtime.budget import Budget, Deadline, started
from ..runtime.exclusive import one_at_a_time
from ..scene import Scene
from ..scene.implicit.base import FloatArray
from ..scene.load import SceneLike, Values, as_scene
from ..scene.settings import with_values
from ..system import symbol

if TYPE_CHECKING:
    from ..branches.certify import Interval
    from ..derivation.pipeline import Derivation
    from ..derivation.prepared import Prepared
    from .extremum import Extremum
    from .extremum.critical import Problem

__all__ = ["load_quantities", "Mechanism", "Quantity"]


def load_quantities(scene: SceneLike, params: Sequence[str] = (),
                    set: Values | None = None,  # noqa: A002 - ``set=`` is the public name (the command line's --set)
                    *, budget: Budget | Deadline | None = None) -> Mechanism:
    """A mechanism from a catalog name, a path or a ``Scene``; ``params`` stay symbolic, and
    ``set`` gives others exact values in place of their defaults (``set={"b": "3/2"}``).
    A ``Budget`` (started now) or the ``Deadline`` of one running bounds the eliminations of
    its quantities' derivations and extrema: their time and their eliminants' terms."""
    names = validation.names("params", params) or ()
    return Mechanism(with_values(as_scene(scene), set, names), names, deadline=started(validation.budget(budget)))


class Mechanism:
    """A scene with some dimensions symbolic: the place to ask for quantities."""

    def __init__(self, scene: SceneLike, params: Sequence[str] = (), *, deadline: Deadline | None = None) -> None:
        self.scene = scene if isinstance(scene, Scene) else as_scene(scene)  # a name or a path too; None refused
        self.params = validation.names("params", params) or ()
        validation.budget(deadline, "deadline")
        self.deadline = deadline  # what its quantities' eliminations keep to (None: no bound)

    @property
    def parameters(self) -> dict[str, sympy.Expr]:
        """Every dimension with its default (symbolic ones too)."""
        return dict(self.scene.parameters)

    # Each quantity is on the scene's chosen assembly mode, or on ``mode``: a label as ``derive``,
    # ``solve`` and ``follow --mode`` give it (``left``/``right`` of a dyad's directed base line,
    # ``ahead``/``behind`` along a slider's line; ``B:left F:right`` where several points have
    # modes), among the quantity's ``modes``.

    def dist(self, p: str, q: str, *, mode: str | None = None) -> Quantity:
        """The distance from ``p`` to ``q`` as a ``Quantity`` (on ``mode``, by default the scene's)."""
        return Quantity(self, f"dist({p}, {q})", mode=mode)

    def x(self, point: str, *, mode: str | None = None) -> Quantity:
        """The x coordinate of ``point`` as a ``Quantity``, on the assembly mode ``mode`` (a label
        among the quantity's ``modes``), by default the scene's chosen one.

        >>> lam = load_quantities("chebyshev-lambda")
        >>> round(lam.x("B").at(angle=0), 12)   # the crank along the ground: B above (2 - 1/2, 0)
        1.5
        >>> lam.x("B").modes
        ['left', 'right']
        """
        return Quantity(self, f"{point}.x", mode=mode)

    def y(self, point: str, *, mode: str | None = None) -> Quantity:
        """The y coordinate of ``point`` as a ``Quantity``, on the assembly mode ``mode`` (a label
        among the quantity's ``modes``), by default the scene's chosen one.

        With the crank along the ground, B is on the perpendicular bisector of AD, ``sqrt(5/2**2 -
        (1/2)**2) = sqrt(6)`` above it on the left of A -> D, below it on the right:

        >>> lam = load_quantities("chebyshev-lambda")
        >>> round(lam.y("B").at(angle=0), 12), round(lam.y("B", mode="right").at(angle=0), 12)
        (2.449489742783, -2.449489742783)
        >>> lam.y("B", mode="rigth").expr
        Traceback (most recent call last):
        ...
        algkin.errors.UsageError: mode='rigth': not a mode of B.y in chebyshev-lambda (modes: left, right); did you mean 'right'?
        """
        return Quantity(self, f"{point}.y", mode=mode)

    def angle(self, p: str, q: str, r: str | None = None, *, mode: str | None = None) -> Quantity:
        """The direction of ``p`` -> ``q``, or with ``r`` the angle at ``q`` between ``qp`` and ``qr``
        (in [0, 180]), as a ``Quantity`` in degrees (on ``mode``, by default the scene's)."""
        return Quantity(self, f"angle({p}, {q})" if r is None else f"angle({p}, {q}, {r})", mode=mode)

    def output(self, name: str, *, mode: str | None = None) -> Quantity:
        """A named output of the scene file (or any output text, e.g. ``"dist(A, B)"``), on ``mode``."""
        return Quantity(self, name, mode=mode)

    def __repr__(self) -> str:
        return f"Mechanism({self.scene.name!r}, params={list(self.params)})"


class Quantity:
    """A scalar on the motion: closed form in the input angle, its relation, its extremum."""

    def __init__(self, mechanism: Mechanism, text: str, *, mode: str | None = None) -> None:
        if not isinstance(mechanism, Mechanism):  # else an AttributeError at its first use
            raise UsageError("mechanism", mechanism, "expected an algkin.Mechanism, e.g. load_quantities('arm-string')")
        if not isinstance(text, str):
            raise UsageError("text", text, "expected an output's text, such as 'dist(A, B)'")
        self.mechanism = mechanism
        self.text = text
        self.mode = mode  # the assembly mode's label; None: the scene's chosen one

    @cached_property
    def prepared(self) -> Prepared:
        """The mechanism's scene prepared for this quantity (``algkin.prepare``): its derivation's and extremum's."""
        from ..derivation.prepared import prepare

        return prepare(self.mechanism.scene, outputs=[self.text], params=self.mechanism.params,
                       deadline=self.mechanism.deadline)

    @cached_property
    def derivation(self) -> Derivation:
        """The quantity's derivation, its ``mode`` the branch it calls selected."""
        from ..derivation.pipeline import derive

        derived = derive(self.prepared, samples=0, budget=self.mechanism.deadline)
        if self.mode is None:
            return derived
        labels = [b.label for b in derived.branches]
        if self.mode not in labels:
            raise UsageError("mode", self.mode, f"not a mode of {self.text} in {self.mechanism.scene.name}"
                             + suggest.known(self.mode, labels, plural="modes"))
        # what reads the derivation (the closed form, the extremum) takes the selected branch
        return attrs.evolve(derived, branches=[attrs.evolve(b, selected=b.label == self.mode)
                                               for b in derived.branches])

    @property
    def modes(self) -> list[str]:
        """The labels of the quantity's assembly modes, as ``mode=`` takes them."""
        return [b.label for b in self.derivation.branches]

    @cached_property
    def _problem(self) -> Problem:
        from .extremum import problem_for

        return problem_for(self.derivation, self.text, witnesses=self.prepared.witnesses,
                           deadline=self.mechanism.deadline)

    @property
    def input(self) -> sympy.Symbol:
        """The input angle as a sympy symbol (radians, as in the seed)."""
        (name,) = self.derivation.compiled.system.inputs
        return symbol(name)

    def _in_angle(self, expr: sympy.Expr) -> sympy.Expr:
        line = self._problem.line
        if not line.is_angle:  # a length input is its own variable already
            return expr
        c, s = line.variables
        return expr.xreplace({c: sympy.cos(self.input), s: sympy.sin(self.input)})

    # Two spellings of the same forms: ``expr``/``relation`` in the input angle itself
    # (``cos(theta)``, as the seed documents write them, to differentiate or plot), and
    # ``expr_cs``/``relation_cs`` in the polynomial system's symbols ``c_theta, s_theta``
    # (what ``derive`` and every JSON document use, with ``c**2 + s**2 = 1`` implied: docs/scene-format.md).

    @property
    def expr(self) -> sympy.Expr:
        """The closed form on the quantity's ``mode`` (by default the scene's chosen one), in the
        input angle (``cos(theta)``, ``sin(theta)``) and symbolic dimensions; an angle in degrees
        (``acos``/``atan`` of the closed form of the scalar standing for it, see
        ``algkin.analyses.extremum.angles``).

        The input angle here is in **radians**, as sympy's ``cos`` takes it, while ``at`` takes
        degrees, as the scene's range and every command do:

        >>> AB = load_quantities("arm-string", params=["b"]).dist("A", "B")
        >>> theta, (b,) = AB.input, AB.symbolic_dimensions
        >>> round(float(AB.expr.subs({theta: sympy.pi / 2, b: 80})), 9), round(AB.at(theta=90, b=80), 9)
        (94.339811321, 94.339811321)
        """
        return self._in_angle(self.expr_cs)

    @property
    def expr_cs(self) -> sympy.Expr:
        """``expr`` in the system's symbols ``c_theta``, ``s_theta`` (as in ``derive``'s results)."""
        problem = self._problem
        return problem.closed if problem.scale is None else problem.scale.expr(problem.closed)

    @property
    def degrees(self) -> bool:
        """Whether the quantity is an angle, its values in degrees."""
        return self._problem.scale is not None

    @property
    def relation(self) -> sympy.Expr:
        """The polynomial the quantity satisfies (= 0), in ``cos`` and ``sin`` of the input angle
        (an angle's: the polynomial of the scalar standing for it, ``symbol``)."""
        return self._in_angle(self._problem.eliminant)

    @property
    def relation_cs(self) -> sympy.Expr:
        """``relation`` in the system's symbols ``c_theta``, ``s_theta`` (as in ``derive``'s eliminants)."""
        return self._problem.eliminant

    @property
    def symbol(self) -> sympy.Symbol:
        return self._problem.u

    @property
    def symbolic_dimensions(self) -> tuple[sympy.Symbol, ...]:
        """The symbolic dimensions (sympy symbols) the closed form is in, as the system orders them."""
        return self._problem.parameters

    @property
    def derivative(self) -> sympy.Expr:
        """d(quantity)/d(input) in radians, from the closed form (for plots, not for extrema)."""
        return sympy.diff(self.expr, self.input)

    @one_at_a_time  # mpmath's precision and python-flint's are the process's: see algkin.runtime.exclusive
    def at(self, **values: Any) -> float | FloatArray:
        """The quantity at an input in degrees (and dimensions), e.g. ``at(theta=90, b=80)``.

        One input: the closed form in mpmath at 30 digits. An array of inputs (not of an angle
        quantity): an array, the stabilised form in floats on the scene's branch, numba's fused
        loop where it is installed and pays (``algkin.evaluate.fused``), numpy's otherwise; nan
        where the branch's label is not certified (by a toggle: ``undecided``) or it does not assemble.

        >>> AB = load_quantities("arm-string", params=["b"]).dist("A", "B")
        >>> [round(float(v), 9) for v in AB.at(theta=np.array([90.0, 0.0]), b=80)]   # at 0: sqrt(232900)
        [94.339811321, 482.597140481]
        """
        (name,) = self.derivation.compiled.system.inputs
        if name not in values:
            raise UsageError(name, None, f"give the input {name} in degrees (a length input as it is)")
        if np.ndim(values[name]) > 0 and not self.degrees:
            return self._sweep(name, values)
        problem = self._problem
        with mpmath.workdps(30):
            numbers = problem.line.numbers_at(mpmath.mpf(values[name]))
            for p in problem.parameters:
                default = self.derivation.compiled.parameter_values[p.name]
                numbers[p.name] = mpmath.mpf(str(values.get(p.name, default)))
            value = evaluate(problem.closed, numbers, MPMATH)
            return float(value if problem.scale is None else problem.scale.degrees(value))

    def _sweep(self, name: str, values: dict[str, Any]) -> FloatArray:
        """``at`` over an array of inputs: the stabilised kernel at these dimensions (made once per set)."""
        settings = {p.name: str(values[p.name]) for p in self._problem.parameters if p.name in values}
        key = tuple(sorted(settings.items()))
        kernels: dict[tuple[tuple[str, str], ...], tuple[Callable[..., Sequence[FloatArray]], list[Interval] | None]] = \
            self.__dict__.setdefault("_kernels", {})
        if key not in kernels:
            from ..branches import closed_forms
            from ..branches.stable import StableBranch, output_forms
            from ..derivation.assembles import certify_labels
            from ..scene import compile_scene

            compiled = compile_scene(with_values(self.mechanism.scene, settings or None), [self.text])
            chosen = next(b for b in closed_forms(compiled) if b.label == self.mode or self.mode is None and b.selected)
            stable = StableBranch(compiled, chosen)
            # floats say nothing where the branch's label is not certified (a toggle's neighbourhood)
            kernels[key] = (stable.kernel(output_forms(stable, [self.text])[1]), certify_labels(compiled, [chosen])[0])
        kernel, intervals = kernels[key]
        given = np.asarray(values[name], dtype=float)
        turning = self._problem.line.is_angle
        found = kernel(np.radians(given) if turning else given)[0]
        if intervals:
            from ..branches.certify import uncertified

            found = np.where(uncertified(intervals, given, turning), np.nan, found)
        return found

    @one_at_a_time
    def extremum(self, range: tuple[float | str, float | str] | None = None,  # noqa: A002 (the seed's word)
                 largest: bool = False) -> Extremum:
        """Critical points, minimum and maximum; closed forms in the symbolic dimensions."""
        from .extremum import extremum_of

        return extremum_of(self.derivation, self.text, range, largest, witnesses=self.prepared.witnesses,
                           deadline=self.mechanism.deadline)

    def __repr__(self) -> str:
        mode = "" if self.mode is None else f", mode={self.mode!r}"
        return f"Quantity({self.text!r} of {self.mechanism.scene.name}{mode})"
