"""What every design of a sweep shares, worked out once: the scene with the swept dimensions symbolic.

A sweep's designs differ in a few dimensions only. A ``Family`` compiles the scene once with
those dimensions symbolic, finds its branches and, when an analysis first asks, the generic
coupler curve (the eliminant with the dimensions symbolic). A design then takes its values:

- it assembles where the float grid of its discriminants, evaluated with the dimensions as
  numbers, is clear of zero (the test ``check_assembly`` and ``where_assembled`` make, with
  the same grid), and its scene loads with the values (a value that breaks it, as a file would);
- the values its own compilation checks (lengths positive...) are checked without compiling;
- its curve is the generic eliminant specialised, taken only when it keeps the generic degree,
  is irreducible and passes the design's own verification (sampled on its motion, the
  dimensions as numbers in the same compiled checks every design shares);
- its transmission angle's extremes come from the extremum derived once for the family
  (``algkin.analyses.extremum.family``).

Anything else, a discriminant near zero somewhere on the grid (a design at a change point, or
one that may not assemble), a point placed by side or a mode named by a configuration, values
its scene's checks refuse (a length not positive), a curve that drops degree or splits, is
left to the design's own path (``None``): the answer is then the one each design computed
alone gives, by construction, and where the family answers it gives that answer too.

>>> from fractions import Fraction
>>> from algkin.scene import load_scene
>>> family = Family.of(load_scene("fourbar"), ("a",), "P", analyses=("curve",))
>>> design = family.design({"a": Fraction(1, 2)})
>>> curve = family.curve(design)
>>> curve.degree, curve.circularity, curve.verification
(6, 3, 'passed')
>>> family.design({"a": Fraction(5, 6), "d": Fraction(22, 3)}) is None   # assembles at theta = 0 only
True
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from fractions import Fraction
from typing import TYPE_CHECKING, Any

import attrs
import flint
import numpy as np
import sympy

from ..errors import AlgkinError
from ..runtime.budget import Budget

if TYPE_CHECKING:
    from ..analyses.extremum.family import ExtremumFamily
    from ..derivation.prepared import Prepared
    from ..scene import Compiled, Scene

__all__ = ["Family", "SharedDesign", "SharedCurve", "CLEARANCE"]

# a discriminant within this part of its largest magnitude on the grid is "near zero": the float
# arithmetic of the design's own path (its numbers folded in) may then see another sign
CLEARANCE = 1e-9
MAX_EXPONENT = 300  # a dimension whose float is past 2**±this is decided by the design's own path
MARGIN = 1e-9  # a value the design's compilation checks, in floats: within this of zero, its own path decides
# the generic curve's intermediate eliminants at most this many terms: a family that would swell
# past it (many dimensions symbolic in a big scene) is left to each design's own elimination
GENERIC_TERMS = 20_000
# ... nor longer than this many seconds (in a child process, stopped there): a family whose generic
# curve costs more than many designs' own would is not worth it for a sweep of a few
GENERIC_SECONDS = 10.0


@dataclass
class SharedDesign:
    """One design of a family: its values, its scene (loaded with them) and the family's compiled
    scene and branches with the values as the dimensions'."""

    values: Mapping[str, Fraction]
    scene: Scene
    compiled: Compiled  # assembling on the whole range (where_assembled's None): its checks sample all of it


@dataclass(frozen=True)
class SharedCurve:
    """A design's coupler curve from the generic one: what the sweep's ``curve`` columns hold."""

    exact: flint.fmpq_mpoly  # irreducible: a curve that splits is the design's own
    variables: tuple[str, str]  # the point's coordinates
    degree: int
    circularity: int
    verification: str

    @property
    def text(self) -> str:
        """The polynomial as sympy writes it (what the design's own path gives)."""
        from ..system.convert import sympy_text

        return sympy_text(self.exact, self.exact.context())

    @property
    def polynomial(self) -> sympy.Expr:
        from ..system.convert import to_sympy

        return to_sympy(self.exact, self.exact.context())


@dataclass
class Family:
    """The scene compiled once with the dimensions ``names`` symbolic, for the point ``point``."""

    scene: Scene
    names: tuple[str, ...]
    point: str
    _prepared: Prepared | None = field(default=None, repr=False)
    _generic: Any = field(default=None, repr=False)  # the generic curve (eliminant, variables), once asked for
    _grid: Any = field(default=None, repr=False)
    # output -> its extremum for the family (``algkin.analyses.extremum.family``), or None where there is none
    _extrema: dict[str, Any] = field(default_factory=dict, repr=False)
    _checks: _Checks | None = field(default=None, repr=False)

    @classmethod
    def of(cls, scene: Scene, names: tuple[str, ...], point: str, *, analyses: tuple[str, ...]) -> Family | None:
        """The family of ``scene`` in the dimensions ``names``, its shared work done now for ``analyses``
        (in this process: a design run in a child under its budget inherits it); None where there is
        none to share (points solved together, more than one input). Its generic curve is given
        ``GENERIC_SECONDS`` and ``GENERIC_TERMS``: past them each design eliminates its own."""
        from ..derivation.modes import moded_points
        from ..derivation.prepared import prepare

        # a mode named by a configuration is named with each design's values (its own path)
        if scene.unknown_points or not names or moded_points(scene) or _follows(scene, names):
            return None
        try:
            prepared = prepare(scene, outputs=[point], params=list(names))
            if len(prepared.compiled.system.inputs) != 1:
                return None
            # a design assembles when every dyad and slider of the scene does, not only the point's
            if not set(_implicit(scene)) <= set(prepared.compiled.coordinates):
                return None
            if any(spec.side() is not None for spec in prepared.compiled.implicit):
                return None  # a point placed by side: its own path checks the side on each design's motion
            checks = _Checks.of(scene, names, _implicit(scene) or [point])
            if checks is None:
                return None
            family = cls(scene, names, point, prepared, _checks=checks)
            if {"curve", "singular"} & set(analyses):
                family._generic_curve()
            family._grid_programs()
            if "transmission" in analyses:
                family._transmission()
        except Exception:  # noqa: BLE001 - a shortcut: whatever stops it, each design takes its own path
            return None  # (and its row says what is wrong with it, as without the family)
        return family

    @property
    def prepared(self) -> Prepared:
        """The scene compiled for ``point`` with ``names`` symbolic, its branches found."""
        assert self._prepared is not None, "made by Family.of"
        return self._prepared

    def design(self, values: Mapping[str, Fraction]) -> SharedDesign | None:
        """The design with ``values`` when the family can answer for it, else None (its own path decides).

        An error of the values is raised as the design's own path raises it (``valued``: its scene is the one
        ``with_values`` loads, without the loading); one of compiling them (a length that is not
        positive...) leaves the design to its own path, which says it."""
        from ..scene.settings import valued

        scene = valued(self.scene, dict(values))
        if set(values) != set(self.names) or not all(_float_safe(v) for v in values.values()):
            return None
        if self._checks is None or not self._checks.clear(values):
            return None  # its own compilation may refuse it (a length that is not positive...): it says how
        if not self._clearly_assembles(values):
            return None
        defaults = dict(self.prepared.compiled.parameter_values)
        defaults.update({n: sympy.Rational(v.numerator, v.denominator) for n, v in values.items()})
        return SharedDesign(values, scene, attrs.evolve(self.prepared.compiled, parameter_values=defaults))

    def _clearly_assembles(self, values: Mapping[str, Fraction]) -> bool:
        """Whether the design's own path decides that it assembles on the whole range, whatever the
        rounding of the grid values near zero (within ``CLEARANCE``): every discriminant of the chosen
        branch clearly positive somewhere (``check_assembly``), and the chosen branch and the branches
        together real on at least ``NARROW`` of the grid counting only clearly positive values
        (``where_assembled``: no narrowing, no structure). A dead centre at a grid input (a change
        point) is decided so; a design whose decision rests on values near zero is not."""
        from ..derivation.assembles import NARROW

        grid = self._grid_programs()
        numbers = [float(values[n]) for n in self.names]
        surely_real, chosen = [], next(k for k, b in enumerate(self.prepared.branches) if b.selected)
        for k, program in enumerate(grid.programs):
            with np.errstate(all="ignore"):
                values_on_grid = [np.broadcast_to(np.asarray(v, dtype=np.float64), grid.size)
                                  for v in program(*grid.inputs, *numbers)]
            rows = np.array(values_on_grid) if values_on_grid else np.ones((1, grid.size))
            if not np.all(np.isfinite(rows)):
                return False
            positive = rows > CLEARANCE * np.max(np.abs(rows), axis=1, keepdims=True)
            if k == chosen and not np.all(np.any(positive, axis=1)):
                return False
            surely_real.append(np.all(positive, axis=0))
        return bool(surely_real[chosen].mean() >= NARROW and np.any(surely_real, axis=0).mean() >= NARROW)

    def _grid_programs(self) -> _Grid:
        if self._grid is None:
            self._grid = _Grid.of(self.prepared, self.names)
        grid: _Grid = self._grid
        return grid

    def curve(self, design: SharedDesign, *, samples: int = 40, seed: int = 0) -> SharedCurve | None:
        """The design's curve: the generic eliminant specialised, when it keeps the generic degree, is
        irreducible and passes the design's verification; None otherwise (the design's own path)."""
        from ..derivation.checking import check_setup
        from ..derivation.curves import curve_figures
        from ..eliminate.backends import FlintBackend
        from ..verify import verify_branches

        generic = self._generic_curve()
        if generic is None:
            return None
        exact, names = generic
        variables = (names[0], names[1])
        present = {str(n) for n in exact.context().names()}  # a dimension the point's curve is free of is not in it
        special = exact.subs({n: flint.fmpq(v.numerator, v.denominator) for n, v in design.values.items()
                              if n in present})
        if special.is_zero() or _degree(special, variables) != _degree(exact, variables):
            return None
        _, factors = special.factor()
        if len(factors) != 1 or factors[0][1] != 1:
            return None
        special = FlintBackend(sorted(present)).primitive(special)  # the normal form the design's own eliminant has
        # the dimensions kept symbolic, valued by the design: the check's programs are every design's
        setup = check_setup(design.compiled, self.prepared.branches, keep_dimensions=True)
        checked = verify_branches(setup, samples=samples, seed=seed,
                                  polynomials={"curve": special}, factors={"curve": [special]})
        if not checked.passed:
            return None
        degree, circularity = curve_figures(special, variables)
        return SharedCurve(special, variables, degree, circularity, checked.status.value)

    def extremum(self, output: str) -> ExtremumFamily | None:
        """The extremum of ``output`` for the family (derived once with the dimensions symbolic), or
        None where it cannot be (each design then computes its own)."""
        if output not in self._extrema:
            from ..analyses.extremum.family import extremum_family

            try:
                self._extrema[output] = extremum_family(self.scene, output, list(self.names),
                                                        budget=Budget(terms=GENERIC_TERMS))
            except AlgkinError:
                self._extrema[output] = None
        found: ExtremumFamily | None = self._extrema[output]
        return found

    def _transmission(self) -> None:
        """The transmission angle's extremum for the family, if the scene has one (``extremum``)."""
        from .analyses import transmission_of

        try:
            output = transmission_of(self.scene)
        except AlgkinError:
            return  # each design says it has none
        self.extremum(output)

    def _generic_curve(self) -> tuple[flint.fmpq_mpoly, tuple[str, ...]] | None:
        """The curve's eliminant with the dimensions symbolic and its variables, the point's x and y
        first (None where it could not be had in budget). It comes back from its child process as
        sympy: made flint again over all its variables, those it is free of too (a ram's curve y = 6)."""
        if self._generic is None:
            from ..derivation.pipeline import curve
            from ..system.convert import flint_context, to_flint

            try:
                elimination = curve(self.prepared, self.point, samples=0,
                                    budget=Budget(seconds=GENERIC_SECONDS, terms=GENERIC_TERMS)).elimination
                names = tuple(elimination.variables)
                self._generic = to_flint(elimination.polynomial, flint_context(names)), names
            except AlgkinError:
                self._generic = False
        found: tuple[flint.fmpq_mpoly, tuple[str, ...]] | None = self._generic or None
        return found


@dataclass(frozen=True)
class _Grid:
    """Every branch's discriminants compiled once with the dimensions as arguments, and the grid of
    inputs ``check_assembly`` and ``where_assembled`` use (its values in the input's variables)."""

    programs: tuple[Any, ...]
    inputs: tuple[np.ndarray, ...]
    size: int

    @classmethod
    def of(cls, prepared: Prepared, names: tuple[str, ...]) -> _Grid:
        from ..derivation.assembles import GRID
        from ..evaluate import NUMPY
        from ..evaluate.program import compile_program
        from ..system import input_values

        compiled = prepared.compiled
        (name, variables), = compiled.system.inputs.items()
        spec = compiled.scene.inputs[name]
        lo, hi = spec.span
        grid = np.linspace(float(lo), float(hi), GRID)
        floats = input_values(variables, np.radians(grid) if spec.is_angle else grid)
        programs = tuple(compile_program(list(b.discriminants.values()), [*variables, *names], NUMPY)
                         for b in prepared.branches)
        return cls(programs, tuple(floats[v] for v in variables), GRID)


@dataclass(frozen=True)
class _Checks:
    """What the design's own compilation checks of its values (``dimension_checks``), made without
    compiling: a value that is a swept dimension itself exactly, any other in floats with a margin
    (clear of zero, of the magnitudes' bounds); a design not clear of them takes its own path."""

    names: tuple[str, ...]
    lengths: tuple[sympy.Expr, ...]
    numbers: tuple[sympy.Expr, ...]
    directions: tuple[tuple[sympy.Expr, sympy.Expr], ...]
    floats: Any  # every one of them as a float program of the swept dimensions

    @classmethod
    def of(cls, scene: Scene, names: tuple[str, ...], outputs: list[str]) -> _Checks | None:
        """The checks of the design's own compilation for ``outputs``; None where they cannot be made
        without compiling (a crank's phase given by a swept dimension, values that could reach too many bits,
        a value that moves with a length input)."""
        from ..evaluate import FLOAT
        from ..evaluate.program import compile_program
        from ..scene.compile import dimension_checks
        from ..scene.expr import MAX_VALUE_BITS

        checks = dimension_checks(scene, outputs, names)
        if checks.phases or checks.reach(dict.fromkeys(names, MAX_EXPONENT + 1)) > MAX_VALUE_BITS:
            return None
        every = [*checks.lengths, *checks.numbers, *(v for pair in checks.directions for v in pair)]
        if any(not {str(v) for v in e.free_symbols} <= set(names) for e in every):
            return None  # a check that moves with an input (a frame at a length input's value): compiled alone
        return cls(names, checks.lengths, checks.numbers, checks.directions, compile_program(every, names, FLOAT))

    def clear(self, values: Mapping[str, Fraction]) -> bool:
        with np.errstate(all="ignore"):
            try:
                numbers = iter(self.floats(*(float(values[n]) for n in self.names)))
            except (ArithmeticError, ValueError):
                return False
        lengths = [(e, next(numbers)) for e in self.lengths]
        others = [(e, next(numbers)) for e in self.numbers]
        directions = [((x, next(numbers)), (y, next(numbers))) for x, y in self.directions]
        return all(_positive(e, v, values) for e, v in lengths) and all(_in_range(e, v, values) for e, v in others) \
            and all(not (_near_zero(*x, values) and _near_zero(*y, values)) for x, y in directions)


def _exact(expr: sympy.Expr, values: Mapping[str, Fraction]) -> Fraction | None:
    """``expr``'s exact value where it is a number or a dimension itself, else None."""
    if expr.is_Rational:
        return Fraction(int(expr.p), int(expr.q))
    return values.get(expr.name) if expr.is_Symbol else None


def _positive(expr: sympy.Expr, value: float, values: Mapping[str, Fraction]) -> bool:
    exact = _exact(expr, values)
    return exact > 0 if exact is not None else bool(math.isfinite(value) and value > MARGIN * (1 + abs(value)))


def _in_range(expr: sympy.Expr, value: float, values: Mapping[str, Fraction]) -> bool:
    """Zero or within ``MAGNITUDES`` (exactly for a dimension, with a margin in floats otherwise)."""
    from ..scene.compile import MAGNITUDES

    exact = _exact(expr, values)
    if exact is not None:
        return exact == 0 or Fraction(str(MAGNITUDES[0])) <= abs(exact) <= Fraction(str(MAGNITUDES[1]))
    return bool(math.isfinite(value) and 10.0 ** -90 <= abs(value) <= 10.0 ** 90)


def _near_zero(expr: sympy.Expr, value: float, values: Mapping[str, Fraction]) -> bool:
    exact = _exact(expr, values)
    return exact == 0 if exact is not None else not (math.isfinite(value) and abs(value) > MARGIN)


def _follows(scene: Scene, names: tuple[str, ...]) -> bool:
    """Whether a dimension not swept is given by one that is (``m = "a + 5/2"``): compiled with the
    swept ones symbolic it would keep its default's value, where each design's own scene moves it."""
    swept, moved = set(names), True
    while moved:  # a dimension given by one given by a swept one follows too
        moved = False
        for name, value in scene.parameters.items():
            if name not in swept and {str(s) for s in getattr(value, "free_symbols", ())} & swept:
                swept.add(name)
                moved = True
    return swept != set(names)


def _implicit(scene: Scene) -> list[str]:
    """The scene's dyads and sliders: the points the design's own path checks the assembly of."""
    return [n for n, p in scene.points.items() if p.labels]


def _degree(poly: flint.fmpq_mpoly, variables: tuple[str, ...]) -> int:
    names = [str(n) for n in poly.context().names()]
    index = [names.index(v) for v in variables]
    return max((sum(int(m[i]) for i in index) for m in poly.monoms()), default=-1)


def _float_safe(value: Fraction) -> bool:
    """Whether ``value`` is a float without overflow or underflow (its numerator and denominator too)."""
    if value == 0:
        return True
    return all(abs(math.log2(abs(x))) < MAX_EXPONENT for x in (value.numerator, value.denominator) if x != 1) \
        and abs(math.log2(abs(value))) < MAX_EXPONENT

