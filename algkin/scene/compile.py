"""Compile a scene into an exact polynomial system holding only what the outputs need.

Explicit points (fixed, crank, frame) are substituted as polynomials; only implicit
points (dyads, sliders) and the asked-for outputs become unknowns.

>>> from algkin.scene import load_scene
>>> compiled = compile_scene(load_scene("arm-string"), ["AB"])
>>> compiled.system.unknowns
('AB',)
>>> compiled.system.equations[0]
AB**2 - 122500*c_theta**2 + 56000*c_theta - 122500*s_theta**2 + 280000*s_theta - 166400
"""

import dataclasses
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass

import sympy

from ..errors import SceneError, UsageError
from ..system import System, symbol
from .constructions import Builder, Construction, Indicator, Unbuildable
from .expr import MAX_VALUE_BITS, bits_bound
from .implicit import DyadSpec, ImplicitSpec, SliderSpec
from .implicit.algebra import Circles
from .implicit.base import Point
from .load import parse_output
from .model import Output, Scene
from .names import check_names, check_symbol_name

__all__ = ["Compiled", "DyadSpec", "SliderSpec", "compile_scene"]

Substitution = Mapping[sympy.Symbol, sympy.Expr]


@dataclass(frozen=True)
class Compiled:
    """A scene compiled for some outputs: the system plus what branches need to know."""

    scene: Scene
    system: System
    coordinates: dict[str, Point]  # needed point -> (x, y) in system variables
    dyads: tuple[DyadSpec, ...]  # in construction order
    indicators: tuple[Indicator, ...]  # one per dyad or slider
    definitions: dict[str, sympy.Expr]  # output unknown -> its value in other variables (sqrt for distances)
    outputs: dict[str, tuple[str, ...]]  # output name -> unknown names standing for it
    parameter_values: dict[str, sympy.Expr]  # every scene parameter -> exact default
    symbolic: tuple[str, ...]  # parameters kept symbolic
    implicit: tuple[ImplicitSpec, ...] = ()  # dyads and sliders, in construction order

    @property
    def circles(self) -> Circles:
        """Each input's (cos, sin) symbols, on whose unit circles closed forms are reduced."""
        return [(symbol(c), symbol(s)) for c, s in self.system.inputs.values()]


def _resolve_outputs(scene: Scene, requested: Sequence[str] | None) -> list[Output]:
    generated = check_names(scene)  # a scene built in Python has not been through the loader
    outputs: list[Output] = []
    for text in requested or list(scene.outputs):
        if text in scene.outputs:
            outputs.append(scene.outputs[text])
            continue
        output = parse_output(text, text, scene.points, scene.source, "--outputs")
        if output.kind == "dist":
            output = dataclasses.replace(output, name=f"dist_{output.points[0]}_{output.points[1]}")
            if output.name in scene.parameters:
                raise UsageError("--outputs", text, f"its unknown {output.name!r} is the name of a parameter")
            check_symbol_name(scene.source, "--outputs", output.name, generated)
        outputs.append(output)
    if not outputs:
        raise SceneError(scene.source, "outputs", "the scene has no outputs; name some with --outputs")
    return outputs


def _needed_points(scene: Scene, outputs: Sequence[Output]) -> list[str]:
    needed: set[str] = set()
    stack = [p for o in outputs for p in o.points]
    while stack:
        name = stack.pop()
        if name not in needed:
            needed.add(name)
            stack.extend(scene.points[name].references)
    return [name for name in _construction_order(scene) if name in needed]


def _construction_order(scene: Scene) -> list[str]:
    order: list[str] = []
    seen: set[str] = set()

    def visit(name: str) -> None:
        if name not in seen:
            seen.add(name)
            for ref in scene.points[name].references:
                visit(ref)
            order.append(name)

    for name in scene.points:
        visit(name)
    return order


def _parameter_values(scene: Scene, symbolic: Sequence[str]) \
        -> tuple[dict[str, sympy.Expr], dict[sympy.Symbol, sympy.Expr], dict[str, int]]:
    for name in symbolic:
        if name not in scene.parameters:
            known = ", ".join(scene.parameters) or "none"
            raise UsageError("--param", name, f"not a parameter of {scene.name} (parameters: {known})")
    symbols = scene.parameter_symbols()
    defaults: dict[str, sympy.Expr] = {}
    substitution: dict[sympy.Symbol, sympy.Expr] = {}
    bits: dict[str, int] = {}
    for name, default in scene.parameters.items():
        bits[name] = bits_bound(sympy.sympify(default), bits)
        if bits[name] > MAX_VALUE_BITS:
            raise SceneError(scene.source, f"parameters.{name}", f"its value with the defaults above it could "
                             f"reach {bits[name]} bits (at most {MAX_VALUE_BITS})")
        defaults[name] = default.xreplace(defaults_subs(defaults, symbols))
        _check_finite(scene, f"parameters.{name}", defaults[name])
        if name not in symbolic:
            substitution[symbols[name]] = defaults[name]
    return defaults, substitution, bits


def defaults_subs(defaults: Mapping[str, sympy.Expr],
                  symbols: Mapping[str, sympy.Symbol]) -> dict[sympy.Symbol, sympy.Expr]:
    """Substitution of every already-resolved parameter by its default."""
    return {symbols[n]: v for n, v in defaults.items()}


def compile_scene(scene: Scene, outputs: Sequence[str] | None = None, params: Iterable[str] = ()) -> Compiled:
    """Compile ``scene`` for ``outputs`` (names, point names, ``dist(P, Q)``, ``P.x``).

    Parameters named in ``params`` stay symbolic; the others take their exact defaults.
    """
    symbolic = tuple(params)
    defaults, substitution, bits = _parameter_values(scene, symbolic)
    resolved = _resolve_outputs(scene, outputs)
    points = _needed_points(scene, resolved)
    used_inputs = {getattr(scene.points[p], "input", None) for p in points}  # the cranks' inputs
    inputs = {n: i.symbols for n, i in scene.inputs.items() if n in used_inputs}
    builder = Builder(inputs)
    coords: dict[str, Point] = {}
    for name in points:
        _check_bits(scene, name, scene.points[name], bits)
        construction = _substituted(scene.points[name], substitution)
        for value in vars(construction).values():
            for item in value if isinstance(value, tuple) else (value,):
                _check_finite(scene, f"points.{name}", item)
        _check_lengths(scene, name, construction)
        _check_direction(scene, name, construction)
        try:
            x, y = construction.build(name, coords, builder)
        except Unbuildable as err:
            raise SceneError(scene.source, f"points.{name}", str(err)) from None
        coords[name] = (sympy.expand(x), sympy.expand(y))
    definitions, output_unknowns, nonnegative = _output_equations(resolved, coords, builder)
    equations = [sympy.expand(eq) for eq in builder.equations]
    equations += [c**2 + s**2 - 1 for c, s in inputs.values()]
    _check_polynomial(scene, equations, symbolic)
    used = set().union(*(eq.free_symbols for eq in equations)) if equations else set()
    system = System(
        unknowns=tuple(str(u) for u in builder.unknowns),
        parameters=tuple(p for p in symbolic if symbol(p) in used),
        inputs={n: (str(c), str(s)) for n, (c, s) in inputs.items()},
        equations=tuple(equations),
        nonnegative=tuple(nonnegative),
    )
    return Compiled(scene, system, coords, tuple(builder.dyads.values()), tuple(builder.indicators), definitions,
                    output_unknowns, defaults, symbolic, tuple(builder.implicit.values()))


def _substituted(construction: Construction, substitution: Substitution) -> Construction:
    fields = {k: _subs(v, substitution) for k, v in vars(construction).items()}
    return type(construction)(**fields)


def _subs(value: object, substitution: Substitution) -> object:
    if isinstance(value, sympy.Basic):
        return value.xreplace(substitution)
    if isinstance(value, tuple):
        return tuple(_subs(v, substitution) for v in value)
    return value


_NOT_FINITE = (sympy.zoo, sympy.nan, sympy.oo, -sympy.oo)


# Floats (sampling, drawing, the stabilised forms) square lengths: their magnitudes must stay
# far inside float range, 1e-308 to 1e308, squared.
MAGNITUDES = (sympy.Rational(1, 10**100), sympy.Integer(10**100))


def _check_finite(scene: Scene, element: str, value: object) -> None:
    """A value that the parameters' defaults turn into 1/0 or sqrt(-1), or beyond what floats
    can square, is a scene error."""
    if not isinstance(value, sympy.Basic):
        return
    if value.has(*_NOT_FINITE) or (value.is_number and value.is_real is False):
        raise SceneError(scene.source, element,
                         f"not a finite real number with the parameters' default values: {value}")
    if value.is_number and value != 0 and not MAGNITUDES[0] <= abs(value) <= MAGNITUDES[1]:
        raise SceneError(scene.source, element, f"{sympy.Float(value, 3)} is outside the magnitudes "
                         "1e-100 to 1e100 that floating-point checks can square")


def _check_bits(scene: Scene, name: str, construction: Construction, bits: Mapping[str, int]) -> None:
    """Refuse, before substituting, a coordinate or length whose value would be huge."""
    for value in vars(construction).values():
        for item in value if isinstance(value, tuple) else (value,):
            reach = bits_bound(item, bits) if isinstance(item, sympy.Basic) else 0
            if reach > MAX_VALUE_BITS:
                raise SceneError(scene.source, f"points.{name}", f"{item} could reach {reach} "
                                 f"bits with the parameters' defaults (at most {MAX_VALUE_BITS})")


def _check_polynomial(scene: Scene, equations: Sequence[sympy.Expr], symbolic: Sequence[str]) -> None:
    """A symbolic parameter under a division or sqrt cannot go into a polynomial system."""
    for eq in equations:
        if not eq.is_polynomial(*eq.free_symbols):
            culprits = [p for p in symbolic if not eq.is_polynomial(symbol(p))] or [""]
            raise UsageError("--param", culprits[0],
                             f"{scene.source} is not polynomial in it (keep it exact): {eq} = 0")


def _check_lengths(scene: Scene, name: str, construction: Construction) -> None:
    lengths = getattr(construction, "lengths", None) or (getattr(construction, "length", None),)
    for length in lengths:
        if length is not None and length.is_number and not length > 0:
            raise SceneError(scene.source, f"points.{name}", f"length must be positive, got {length}")


def _check_direction(scene: Scene, name: str, construction: Construction) -> None:
    direction = getattr(construction, "direction", None)
    if direction is not None and all(d.is_number and d == 0 for d in direction):
        raise SceneError(scene.source, f"points.{name}.slider.direction",
                         "direction must not be zero, got [0, 0] with the parameters' default values")


def _output_equations(outputs: Sequence[Output], coords: Mapping[str, Point], builder: Builder) \
        -> tuple[dict[str, sympy.Expr], dict[str, tuple[str, ...]], list[str]]:
    definitions: dict[str, sympy.Expr] = {}
    output_unknowns: dict[str, tuple[str, ...]] = {}
    nonnegative: list[str] = []
    implicit = {str(u) for u in builder.unknowns}
    for output in outputs:
        if output.kind == "dist":
            (px, py), (qx, qy) = coords[output.points[0]], coords[output.points[1]]
            square = sympy.expand((px - qx) ** 2 + (py - qy) ** 2)
            unknown = builder.unknown(output.name)
            builder.equations.append(unknown**2 - square)
            definitions[output.name] = sympy.sqrt(square)
            nonnegative.append(output.name)
            output_unknowns[output.name] = (output.name,)
            continue
        axes = {"point": "xy", "x": "x", "y": "y"}[output.kind]
        point = output.points[0]
        names = []
        for axis in axes:
            name = f"{point}_{axis}"
            value = coords[point]["xy".index(axis)]
            if name not in implicit:
                builder.equations.append(builder.unknown(name) - value)
                implicit.add(name)
                definitions[name] = value
            names.append(name)
        output_unknowns[output.name] = tuple(names)
    return definitions, output_unknowns, nonnegative
