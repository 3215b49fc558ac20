"""Scene data: parameters, inputs, points built by constructions, named outputs."""

from dataclasses import dataclass, field

import sympy

from .constructions import Construction

__all__ = ["Scene", "Input", "Output", "range_problem"]

# The motion repeats after a turn; a range past two turns or far from zero only multiplies
# the work (certificates and samples are spread over it).
MAX_SPAN_DEGREES = 720
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


@dataclass(frozen=True)
class Input:
    """A driving angle; ``lo``/``hi`` in ``unit`` ('deg' or 'rad')."""

    name: str
    lo: sympy.Rational
    hi: sympy.Rational
    unit: str = "deg"

    @property
    def symbols(self) -> tuple[sympy.Symbol, sympy.Symbol]:
        return (sympy.Symbol(f"c_{self.name}", real=True), sympy.Symbol(f"s_{self.name}", real=True))

    def to_radians(self, value: sympy.Expr) -> sympy.Expr:
        return value * sympy.pi / 180 if self.unit == "deg" else value

    @property
    def range_degrees(self) -> tuple[float, float]:
        """(lo, hi) in degrees, as floats."""
        lo, hi = (float(sympy.deg(self.to_radians(v))) for v in (self.lo, self.hi))
        return lo, hi


@dataclass(frozen=True)
class Output:
    """A named output: ``kind`` is 'point', 'dist', 'x' or 'y' of ``points``."""

    name: str
    kind: str
    points: tuple[str, ...]
    text: str


@dataclass(frozen=True)
class Scene:
    """A declarative mechanism, as loaded from a scene file (see ``algkin.scene.load``)."""

    name: str
    description: str
    parameters: dict[str, sympy.Expr]  # name -> default value (may use earlier parameters)
    inputs: dict[str, Input]
    points: dict[str, Construction]  # in file order
    outputs: dict[str, Output]
    source: str = field(default="<scene>", compare=False)
    # name -> (lo, hi), for sliders and sweeps
    parameter_ranges: dict[str, tuple[sympy.Rational, sympy.Rational]] = field(default_factory=dict)

    def parameter_symbols(self) -> dict[str, sympy.Symbol]:
        return {name: sympy.Symbol(name, real=True) for name in self.parameters}
