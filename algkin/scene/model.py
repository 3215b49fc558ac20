"""Scene data: parameters, inputs, points built by constructions, named outputs."""

from dataclasses import dataclass, field

import sympy

__all__ = ["Scene", "Input", "Output"]


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

    def parameter_symbols(self):
        return {name: sympy.Symbol(name, real=True) for name in self.parameters}
