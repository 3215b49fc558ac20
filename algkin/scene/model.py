"""Scene data: parameters, inputs, points built by constructions, named outputs."""

from dataclasses import dataclass, field

import sympy

__all__ = ["Scene", "Input", "Output", "range_problem"]

# The motion repeats after a turn; a range past two turns or far from zero only multiplies
# the work (certificates and samples are spread over it).
MAX_SPAN_DEGREES = 720
MAX_ABS_DEGREES = 36000


def range_problem(lo_deg, hi_deg):
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


@dataclass(frozen=True)
class Input:
    """A driving angle; ``lo``/``hi`` in ``unit`` ('deg' or 'rad')."""

    name: str
    lo: sympy.Rational
    hi: sympy.Rational
    unit: str = "deg"

    @property
    def symbols(self):
        return (sympy.Symbol(f"c_{self.name}", real=True), sympy.Symbol(f"s_{self.name}", real=True))

    def to_radians(self, value):
        return value * sympy.pi / 180 if self.unit == "deg" else value

    @property
    def range_degrees(self):
        """(lo, hi) in degrees, as floats."""
        return tuple(float(sympy.deg(self.to_radians(v))) for v in (self.lo, self.hi))


@dataclass(frozen=True)
class Output:
    """A named output: ``kind`` is 'point', 'dist', 'x' or 'y' of ``points``."""

    name: str
    kind: str
    points: tuple
    text: str


@dataclass(frozen=True)
class Scene:
    """A declarative mechanism, as loaded from a scene file (see ``algkin.scene.load``)."""

    name: str
    description: str
    parameters: dict  # name -> default value (sympy expr, may use earlier parameters)
    inputs: dict  # name -> Input
    points: dict  # name -> construction, in file order
    outputs: dict  # name -> Output
    source: str = field(default="<scene>", compare=False)
    parameter_ranges: dict = field(default_factory=dict)  # name -> (lo, hi) rationals, for sliders and sweeps

    def parameter_symbols(self):
        return {name: sympy.Symbol(name, real=True) for name in self.parameters}
