"""Scene data: parameters, inputs, points built by constructions, named outputs."""

import dataclasses

import attrs
import sympy
from mpmath.libmp import from_rational, mpf_mul, mpf_pi, mpf_pos, mpf_pow_int, round_nearest, to_float

from ..runtime.frozen import FrozenDict, frozen
from .constraints import Constraint
from .constructions import Construction, Fixed, Mode, Unknown

__all__ = ["Scene", "Input", "DrivenInput", "Output", "range_problem", "length_range_problem"]

# The motion repeats after a turn; a range past two turns or far from zero only multiplies
# the work (certificates and samples are spread over it).
MAX_SPAN_DEGREES = 720
_EVALF_BITS = 53 + 4  # the precision sympy's float() evaluates at
MAX_ABS_DEGREES = 36000


def range_problem(lo_deg: float, hi_deg: float) -> str | None:
    """What is wrong with an input range in degrees, or None.

    >>> range_problem(0, 1e300)
    'spans more than 720 degrees (two turns)'
    """
    if not lo_deg < hi_deg:  # NaN too
        return "lo must be below hi"
    if hi_deg - lo_deg > MAX_SPAN_DEGREES:
        return f"spans more than {MAX_SPAN_DEGREES} degrees (two turns)"
    if max(abs(lo_deg), abs(hi_deg)) > MAX_ABS_DEGREES:
        return f"must lie within [-{MAX_ABS_DEGREES}, {MAX_ABS_DEGREES}] degrees"
    return None


def length_range_problem(lo: sympy.Rational, hi: sympy.Rational) -> str | None:
    """What is wrong with a length input's range, or None: floats square its values.

    >>> length_range_problem(sympy.Integer(0), sympy.Integer(10)**200)
    'must lie within the magnitudes 1e-100 to 1e100'
    """
    if not lo < hi:
        return "lo must be below hi"
    if max(abs(lo), abs(hi)) > sympy.Integer(10) ** 100 or 0 < hi - lo < sympy.Rational(1, 10**100):
        return "must lie within the magnitudes 1e-100 to 1e100"
    return None


def _sympys_float_of_pi_times(coefficient: sympy.Rational) -> float:
    """``float(coefficient * sympy.pi)``, the same float: sympy evaluates at 4 bits past a float's 53
    (``EvalfMixin.evalf``), a product's factors rounded down at 7 more (``evalf_mul``, ``evalf_rational``,
    ``mpf_pi``) and their product to the nearest, then rounds to 53 bits again (``Float._new``): not
    always the nearest float, so done the same way here."""
    if coefficient == 0:
        return 0.0
    if coefficient == 1:  # pi alone, not a product
        value = mpf_pi(_EVALF_BITS)
    else:
        factors = _EVALF_BITS + 2 + 5  # evalf_mul's working precision for two factors
        value = mpf_mul(from_rational(int(coefficient.p), int(coefficient.q), factors), mpf_pi(factors),
                        _EVALF_BITS, round_nearest)
    return float(to_float(mpf_pos(value, 53, round_nearest)))


def _sympys_float_of_over_pi(coefficient: sympy.Rational) -> float:
    """``float(coefficient / sympy.pi)``, the same float, as ``_sympys_float_of_pi_times`` makes its
    product: ``1/pi`` is ``evalf_pow``'s (pi at 5 bits more, inverted rounding down), the rest as there.
    Not the float of ``coefficient`` times that of ``1/pi`` (a third of them an ulp or two off sympy's).

    >>> _sympys_float_of_over_pi(sympy.Integer(18)), float(sympy.Integer(18) / sympy.pi)
    (5.729577951308232, 5.729577951308232)
    """
    if coefficient == 0:
        return 0.0
    if coefficient == 1:  # 1/pi alone, a power, not a product
        value = mpf_pow_int(mpf_pi(_EVALF_BITS + 5), -1, _EVALF_BITS)
    else:
        factors = _EVALF_BITS + 2 + 5  # evalf_mul's working precision for two factors
        inverse_pi = mpf_pow_int(mpf_pi(factors + 5), -1, factors)
        value = mpf_mul(from_rational(int(coefficient.p), int(coefficient.q), factors), inverse_pi,
                        _EVALF_BITS, round_nearest)
    return float(to_float(mpf_pos(value, 53, round_nearest)))


@attrs.frozen
class Input:
    """What drives the mechanism: an angle (``lo``/``hi`` in ``unit``, 'deg' or 'rad') or, with
    ``unit`` 'length', a length (a linear actuator, a string) taking the values ``lo``..``hi``.

    An angle enters the polynomial system as its (cos, sin) pair on the unit circle; a length
    as itself, a variable named like the input (a dimension that moves).

    >>> Input("s", sympy.Integer(1), sympy.Integer(3), "length").symbols
    (s,)
    >>> Input("s", sympy.Integer(1), sympy.Integer(3), "length").span
    (1.0, 3.0)
    """

    name: str
    lo: sympy.Rational
    hi: sympy.Rational
    unit: str = "deg"

    @property
    def is_angle(self) -> bool:
        return self.unit != "length"

    @property
    def symbols(self) -> tuple[sympy.Symbol, ...]:
        if not self.is_angle:
            return (sympy.Symbol(self.name, real=True),)
        return (sympy.Symbol(f"c_{self.name}", real=True), sympy.Symbol(f"s_{self.name}", real=True))

    def radians(self, value: sympy.Rational) -> float:
        """``value`` in the unit the system takes it in, as a float: radians for an angle, a length as it
        is. Degrees are turned as sympy's ``float(value * pi / 180)`` turns them, its rounding step
        for step (``_sympys_float_of_pi_times``), without its evalf (whose first call builds its
        tables: most of a millisecond of a cold command).

        >>> Input("t", sympy.Integer(0), sympy.Integer(360)).radians(sympy.Integer(360))
        6.283185307179586
        """
        if self.unit != "deg":
            return float(value)
        return _sympys_float_of_pi_times(sympy.Rational(value) / 180)

    @property
    def span(self) -> tuple[float, float]:
        """(lo, hi) as floats in the unit users read: degrees for an angle, the length itself."""
        if not self.is_angle:
            return float(self.lo), float(self.hi)
        if self.unit == "deg":
            return float(self.lo), float(self.hi)
        # sympy's float of deg (r/pi*180), without it (its pi would first import sympy's geometry)
        return _sympys_float_of_over_pi(sympy.Rational(self.lo) * 180), _sympys_float_of_over_pi(sympy.Rational(self.hi) * 180)

    def shown(self, value: float) -> str:
        """A value in users' units as text: ``30°`` for an angle, ``0.25`` for a length."""
        return f"{value:g}°" if self.is_angle else f"{value:g}"


@attrs.frozen
class DrivenInput:
    """An angle input turned by another through gears: ``t2 = { driven_by = "t1", ratio = "-2" }``
    is ``t2 = -2*t1`` (external gears mesh with a negative ratio). ``driver`` is an input or
    another driven input; ``ratio`` a nonzero integer, so that cos and sin of ``t2`` are
    polynomials in those of the input at the root of the chain (``algkin.scene.driven``).
    """

    name: str
    driver: str
    ratio: sympy.Integer


@attrs.frozen
class Output:
    """A named output: ``kind`` is 'point', 'dist', 'x' or 'y' of ``points``."""

    name: str
    kind: str
    points: tuple[str, ...]
    text: str


@attrs.frozen
class Scene:
    """A declarative mechanism, as loaded from a scene file (see ``algkin.scene.load``).

    An immutable value (its tables are ``FrozenDict``): ``attrs.evolve`` or
    ``algkin.scene.with_values`` make changed copies, and a scene is its own cache key.

    >>> from algkin.scene import load_scene
    >>> scene = load_scene("fourbar")
    >>> scene.parameters["a"] = 99
    Traceback (most recent call last):
    ...
    TypeError: 'FrozenDict' object does not support item assignment
    >>> hash(scene) == hash(load_scene("fourbar"))
    True
    """

    name: str
    description: str
    # name -> default value (may use earlier parameters)
    parameters: FrozenDict[str, sympy.Expr] = attrs.field(converter=frozen)
    inputs: FrozenDict[str, Input] = attrs.field(converter=frozen)
    points: FrozenDict[str, Construction] = attrs.field(converter=frozen)  # in file order
    outputs: FrozenDict[str, Output] = attrs.field(converter=frozen)
    source: str = attrs.field(default="<scene>", eq=False)
    # name -> (lo, hi), for sliders and sweeps
    parameter_ranges: FrozenDict[str, tuple[sympy.Rational, sympy.Rational]] = attrs.field(
        factory=FrozenDict, converter=frozen)
    # name -> a constraint on points solved together (``unknown = true``), in file order
    constraints: FrozenDict[str, Constraint] = attrs.field(factory=FrozenDict, converter=frozen)
    # name -> an angle input geared to another (no variables of its own), in file order
    driven: FrozenDict[str, DrivenInput] = attrs.field(factory=FrozenDict, converter=frozen)
    unit: str = ""  # the lengths' unit (``unit = "mm"``), written on axes; "" when not said

    @property
    def unknown_points(self) -> tuple[str, ...]:
        """The points solved together (``unknown = true``): a scene only ``algkin solve`` takes, for now."""
        return tuple(n for n, c in self.points.items() if isinstance(c, Unknown))

    def translated(self, offset: int) -> "Scene":
        """The scene moved by (offset, offset): every ground point, and every configuration that names
        a mode (``mode.near``), shifted; the same mechanism, its modes the same."""
        return attrs.evolve(self, points={n: _translated(c, offset) for n, c in self.points.items()})

    def parameter_symbols(self) -> dict[str, sympy.Symbol]:
        return {name: sympy.Symbol(name, real=True) for name in self.parameters}


def _translated(construction: Construction, offset: int) -> Construction:
    if isinstance(construction, Fixed):
        return Fixed(construction.x + offset, construction.y + offset)
    mode = getattr(construction, "mode", None)
    if mode is None:
        return construction
    near = (mode.near[0] + offset, mode.near[1] + offset)
    return dataclasses.replace(construction, mode=Mode(mode.at, near))  # type: ignore[type-var]
