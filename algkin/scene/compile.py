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

from collections.abc import Iterable, Mapping, Sequence
from typing import Optional

import attrs
import sympy

from ..runtime import suggest, validation
from ..errors import SceneError, UsageError
from ..runtime.frozen import FrozenDict, frozen
from ..system import System, symbol
from ..system.between import simplest_between
from ..system.convert import expanded, rational_polynomial, univariate
from ..system.roots import real_roots
from .constructions import Builder, Construction, Crank, Dyad, Indicator, Unbuildable
from .driven import driven_angles, root_of
from .expr import MAX_VALUE_BITS, bits_bound, irrational
from .implicit import DyadSpec, ImplicitSpec, SliderSpec
from .implicit.algebra import Circles, reduce_on_circles
from .implicit.base import Point
from .load import SceneLike, as_scene, parse_output
from .model import Output, Scene
from .names import angle_unknowns, check_names, check_output_unknowns, check_symbol_name

__all__ = ["Compiled", "DyadSpec", "SliderSpec", "AngleOutput", "compile_scene", "resolve_outputs", "refuse_solved_together",
           "refuse_lengths_not_positive", "length_not_positive", "Span", "lengths_in", "spans_lengths_positive",
           "DimensionChecks", "dimension_checks"]

Substitution = Mapping[sympy.Symbol, sympy.Expr]


@attrs.frozen
class AngleOutput:
    """An angle output compiled: the unknowns standing for it.

    ``points`` (P, Q) is the direction of PQ, with ``cos`` and ``sin`` its cosine and sine;
    (P, Q, R) the angle at Q between QP and QR, in [0, 180] degrees, with ``cos`` its
    cosine (``sin`` is None). ``length`` is the divisor, |PQ| (or |QP|*|QR|), when it is a
    constant of the mechanism; otherwise the helper unknown ``helper`` (>= 0) stands for it.
    """

    name: str
    points: tuple[str, ...]
    cos: str
    sin: str | None
    length: sympy.Expr | None
    helper: str | None = None

    @property
    def direction(self) -> bool:
        return len(self.points) == 2


@attrs.frozen
class Compiled:
    """A scene compiled for some outputs: the system plus what branches need to know (an
    immutable, hashable value)."""

    scene: Scene
    system: System
    # needed point -> (x, y) in system variables
    coordinates: FrozenDict[str, Point] = attrs.field(converter=frozen)
    # every implicit point's spec (dyads, sliders, second intersections), in construction order
    implicit: tuple[ImplicitSpec, ...]
    indicators: tuple[Indicator, ...]  # one per dyad or slider
    # output unknown -> its value in other variables (sqrt for distances)
    definitions: FrozenDict[str, sympy.Expr] = attrs.field(converter=frozen)
    # output name -> unknown names standing for it
    outputs: FrozenDict[str, tuple[str, ...]] = attrs.field(converter=frozen)
    # every scene parameter -> exact default
    parameter_values: FrozenDict[str, sympy.Expr] = attrs.field(converter=frozen)
    symbolic: tuple[str, ...]  # parameters kept symbolic
    # angle output name -> its unknowns
    angles: FrozenDict[str, AngleOutput] = attrs.field(factory=FrozenDict, converter=frozen)
    # dyad on two fixed bases -> why it never assembles (decided exactly; moving bases are not decided here)
    never_assembles: FrozenDict[str, str] = attrs.field(factory=FrozenDict, converter=frozen)

    @property
    def circles(self) -> Circles:
        """Each input angle's (cos, sin) symbols, on whose unit circles closed forms are reduced."""
        return [(symbol(pair[0]), symbol(pair[1])) for pair in self.system.inputs.values() if len(pair) == 2]


def resolve_outputs(scene: Scene, requested: Sequence[str] | None) -> list[Output]:
    """The outputs named in ``requested`` (the scene's own, or ``P``, ``dist(P, Q)``, ``angle(P, Q)``
    it does not declare), each once; all the scene's outputs when ``requested`` is empty.

    UsageError names a requested output that cannot be one; SceneError a scene with none.

    >>> from algkin.scene import load_scene
    >>> [(o.name, o.kind) for o in resolve_outputs(load_scene("fourbar"), ["dist(A, B)", "B"])]
    [('dist_A_B', 'dist'), ('B', 'point')]
    """
    generated = check_names(scene)  # a scene built in Python has not been through the loader
    outputs: list[Output] = []
    taken: dict[str, str] = {}  # unknowns of distance and angle outputs -> the output's name
    for text in [t.strip() if isinstance(t, str) else t for t in requested or ()] or list(scene.outputs):
        try:  # stripped: ' AB' (a quoted list, a pasted line) is the output AB, as ' B.x' is B.x
            output = scene.outputs[text] if text in scene.outputs else _requested_output(scene, text, generated)
            if any(o.name == output.name and (o.kind, o.points) == (output.kind, output.points) for o in outputs):
                continue  # asked for twice
            unknowns = {"dist": (output.name,), "angle": angle_unknowns(output.name, output)}.get(output.kind, ())
            check_output_unknowns(scene.source, "outputs", unknowns, generated=generated, parameters=scene.parameters,
                                  taken=taken, owner=output.name)
        except SceneError as err:
            if text in scene.outputs:  # the scene file's own output: the file is at fault
                raise
            raise UsageError("outputs", text, err.message + _output_names(scene, text, err.message)) from None
        outputs.append(output)
    if not outputs:
        raise SceneError(scene.source, "outputs", "the scene has no outputs; ask for some by name")
    return outputs


def _output_names(scene: Scene, text: str, said: str) -> str:
    """What an output may be, and the scene's output most like ``text`` unless ``said`` (the error
    so far) already suggests a point."""
    hint = "" if "did you mean" in said else suggest.did_you_mean(text, scene.outputs)
    return f" (outputs: {', '.join(scene.outputs) or 'none'}; or a point, P.x, P.y, dist(P, Q), angle(P, Q, R))" + hint


def _requested_output(scene: Scene, text: str, generated: Mapping[str, str]) -> Output:
    """An output the caller asked for that the scene does not declare (``dist(P, Q)``, ``P.x``,
    ``angle(P, Q)``...), named after its points; SceneError if it cannot be one."""
    output = parse_output(text, text, scene.points, source=scene.source, element="outputs")
    if output.kind == "dist":
        output = attrs.evolve(output, name=f"dist_{output.points[0]}_{output.points[1]}")
        if output.name in scene.parameters:
            raise UsageError("outputs", text, f"its unknown {output.name!r} is the name of a parameter")
        check_symbol_name(scene.source, "outputs", output.name, generated)
    elif output.kind == "angle":
        output = attrs.evolve(output, name="_".join(("angle",) + output.points))
    return output


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
            raise UsageError("params", name, f"not a parameter of {scene.name}"
                             + suggest.known(name, scene.parameters, plural="parameters"))
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
        problem = irrational(defaults[name])  # b = "sqrt(a)", a = 2
        if problem:
            raise SceneError(scene.source, f"parameters.{name}", f"with the defaults above it, {problem}")
        if name not in symbolic:
            substitution[symbols[name]] = defaults[name]
    return defaults, substitution, bits


def defaults_subs(defaults: Mapping[str, sympy.Expr],
                  symbols: Mapping[str, sympy.Symbol]) -> dict[sympy.Symbol, sympy.Expr]:
    """Substitution of every already-resolved parameter by its default."""
    return {symbols[n]: v for n, v in defaults.items()}


def parameter_defaults(scene: Scene) -> tuple[dict[sympy.Symbol, sympy.Expr], dict[str, int]]:
    """Every parameter's symbol -> its exact default, each checked as ``compile_scene`` checks it
    (finite, rational, within ``MAGNITUDES``, of a bounded size: a SceneError naming it); and the
    bound on each one's bits, for ``checked_construction``."""
    _, substitution, bits = _parameter_values(scene, ())
    return substitution, bits


def checked_construction(scene: Scene, name: str, *, substitution: Substitution, bits: Mapping[str, int],
                         inputs: Mapping[str, tuple[sympy.Symbol, ...]]) -> Construction:
    """Point ``name``'s construction with ``substitution`` (parameters -> values) made, its values
    checked: of a bounded size, finite and within ``MAGNITUDES``, lengths positive (at both ends of
    the range of a length input in ``inputs``), a direction not zero, a phase on the unit circle;
    else a SceneError naming the point."""
    _check_bits(scene, name, scene.points[name], bits)
    construction = _substituted(scene.points[name], substitution)
    for value in vars(construction).values():
        for item in value if isinstance(value, tuple) else (value,):
            _check_finite(scene, f"points.{name}", item)
    _check_lengths(scene, f"points.{name}", _lengths(construction), inputs)
    _check_direction(scene, name, construction)
    _check_phase(scene, name, construction)
    return construction


def checked_length(scene: Scene, element: str, length: sympy.Expr, *, substitution: Substitution,
                   inputs: Mapping[str, tuple[sympy.Symbol, ...]]) -> None:
    """A length that is not a point's (a constraint's), checked as a construction's lengths are by
    ``checked_construction``, ``substitution`` made: a SceneError naming ``element``."""
    value = length.xreplace(substitution)
    _check_finite(scene, element, value)
    _check_lengths(scene, element, (value,), inputs)


def refuse_solved_together(scene: Scene) -> None:
    """UsageError for a scene with points solved together, saying the commands and the Python
    functions that take it, whichever of the others refused it (a SceneError first if its groups
    are bad: bad input whatever the command)."""
    if scene.unknown_points:
        from .groups import compile_groups  # below: groups builds on this module

        compile_groups(scene)
        raise UsageError("scene", scene.name, f"has points solved together ({', '.join(scene.unknown_points)}): "
                         "show, solve, follow, derive, curve, verify, toggles, plot, export, sweep and accuracy take it, "
                         "and in Python derive, curve, solve, follow, rates and load_quantities; extremum and singular "
                         "do not yet, nor prepare and compile_scene")


def compile_scene(scene: SceneLike, outputs: Sequence[str] | None = None, params: Iterable[str] = ()) -> Compiled:
    """Compile ``scene`` for ``outputs`` (names, point names, ``dist(P, Q)``, ``P.x``).

    Parameters named in ``params`` stay symbolic; the others take their exact defaults. A scene
    with points solved together (``unknown = true``) is refused: ``algkin.derive``, ``curve``,
    ``solve`` and the others the refusal names take it, compiled by ``algkin.scene.groups``.
    """
    if not isinstance(scene, Scene):  # the public API's: a catalog name or a path, or a refusal naming it
        scene = as_scene(scene)
    outputs = validation.names("outputs", outputs, distinct=False)  # one asked twice is compiled once
    refuse_solved_together(scene)
    symbolic = validation.names("params", params) or ()
    defaults, substitution, bits = _parameter_values(scene, symbolic)
    resolved = resolve_outputs(scene, outputs)
    points = _needed_points(scene, resolved)
    inputs = _used_inputs(scene, points)
    turning = {n: pair for n, pair in inputs.items() if len(pair) == 2}
    builder = Builder(turning, driven_angles(scene, turning))
    coords: dict[str, Point] = {}
    # every dimension at its default, the symbolic ones too: where the checks and samples are
    everywhere = {symbol(n): defaults[n] for n in symbolic}
    never: dict[str, str] = {}
    for name in points:
        construction = checked_construction(scene, name, substitution=substitution, bits=bits, inputs=inputs)
        if isinstance(construction, Dyad):
            bases = [tuple(expanded(v.xreplace(everywhere)) for v in coords[b]) for b in construction.bases]
            _check_bases(scene, name, construction, bases)
            why = _never_meets(construction, bases, [length.xreplace(everywhere) for length in construction.lengths])
            if why:
                never[name] = why
        made = len(builder.equations)
        try:
            x, y = construction.build(name, coords, builder)
        except Unbuildable as err:
            raise SceneError(scene.source, f"points.{name}", str(err)) from None
        coords[name] = (expanded(x), expanded(y))
        _check_rational(scene, name, [*coords[name], *builder.equations[made:]])
        _check_reach(scene, name, coords[name])
    lengths = {v for c in scene.points.values() for length in _lengths(c) for v in length.free_symbols}
    definitions, output_unknowns, nonnegative, angles = _output_equations(resolved, coords, builder, lengths=lengths,
                                                                          source=scene.source)
    equations = [expanded(eq) for eq in builder.equations]
    equations += [pair[0]**2 + pair[1]**2 - 1 for pair in inputs.values() if len(pair) == 2]
    _check_polynomial(scene, equations, symbolic)
    used = set().union(*(eq.free_symbols for eq in equations)) if equations else set()
    system = System(
        unknowns=tuple(str(u) for u in builder.unknowns),
        parameters=tuple(p for p in symbolic if symbol(p) in used),
        inputs={n: tuple(str(v) for v in variables) for n, variables in inputs.items()},
        equations=tuple(equations),
        nonnegative=tuple(nonnegative),
    )
    return Compiled(scene, system, coords, tuple(builder.implicit.values()), tuple(builder.indicators), definitions,
                    output_unknowns, defaults, symbolic, angles, never)


def _used_inputs(scene: Scene, points: Sequence[str]) -> dict[str, tuple[sympy.Symbol, ...]]:
    """The inputs the ``points`` move with (a crank's angle, a length in an expression) -> their variables;
    a crank on a geared input moves with the input at the root of its gears."""
    used = {root_of(scene, p.input)[0] for p in (scene.points[n] for n in points) if isinstance(p, Crank)}
    for name in points:
        for value in vars(scene.points[name]).values():
            for item in value if isinstance(value, tuple) else (value,):
                if isinstance(item, sympy.Basic):
                    used.update(str(s) for s in item.free_symbols)
    return {n: i.symbols for n, i in scene.inputs.items() if n in used}


@attrs.frozen
class DimensionChecks:
    """What ``compile_scene`` checks of the values of the constructions it builds, in the dimensions it
    was asked to keep symbolic: a caller that compiles once with them symbolic and gives them many
    values (a sweep's family) checks these at each, as compiling with the values would.

    ``lengths`` must be positive, every value in ``numbers`` finite and zero or within
    ``MAGNITUDES``, each pair in ``directions`` not both zero, each pair in ``phases`` on the unit
    circle; ``reach`` bounds the bits of any of them, the dimensions at ``bits`` bits each."""

    lengths: tuple[sympy.Expr, ...]
    numbers: tuple[sympy.Expr, ...]
    directions: tuple[tuple[sympy.Expr, sympy.Expr], ...]
    phases: tuple[tuple[sympy.Expr, sympy.Expr], ...]

    def reach(self, bits: Mapping[str, int]) -> int:
        return max((bits_bound(v, bits) for v in (*self.lengths, *self.numbers)), default=0)

    def not_positive(self, values: Mapping[str, sympy.Expr]) -> tuple[sympy.Expr, sympy.Expr] | None:
        """The first of ``lengths`` that compiling with ``values`` (dimension name -> exact value)
        would refuse, with its value there; None if none (one still in a symbol is not decided).

        >>> from algkin.scene import load_scene
        >>> checks = dimension_checks(load_scene("fourbar"), ["P"], ["a", "l"])
        >>> checks.not_positive({"a": sympy.Integer(-1), "l": sympy.Integer(3)})
        (a, -1)
        >>> checks.not_positive({"a": sympy.Integer(1)}) is None
        True
        """
        for length in self.lengths:
            value = length.xreplace({s: values[s.name] for s in length.free_symbols
                                     if isinstance(s, sympy.Symbol) and s.name in values})
            if _not_positive(value):
                return length, value
        return None


def dimension_checks(scene: Scene, outputs: Sequence[str] | None, params: Iterable[str]) -> DimensionChecks:
    """The values ``compile_scene(scene, outputs, params)`` checks, of the constructions it builds,
    the dimensions ``params`` symbolic and the others at their defaults.

    >>> from algkin.scene import load_scene
    >>> checks = dimension_checks(load_scene("fourbar"), ["P"], ["a", "l"])
    >>> checks.lengths, checks.directions
    ((a, l, 7/2), ())
    """
    _, substitution, _ = _parameter_values(scene, tuple(params))
    constructions = [_substituted(scene.points[name], substitution)
                     for name in _needed_points(scene, resolve_outputs(scene, outputs))]
    numbers = tuple(item for c in constructions for value in vars(c).values()
                    for item in (value if isinstance(value, tuple) else (value,))
                    if isinstance(item, sympy.Expr) and not item.is_number)
    return DimensionChecks(
        lengths=tuple(length for c in constructions for length in _lengths(c)),
        numbers=numbers,
        directions=tuple(getattr(c, "direction") for c in constructions if getattr(c, "direction", None) is not None),
        phases=tuple(c.phase for c in constructions if isinstance(c, Crank) and not all(v.is_number for v in c.phase)))


def refuse_lengths_not_positive(scene: Scene, name: str, bounds: tuple[float, float], *, argument: str) -> None:
    """Refuse a span of the dimension ``name`` (``argument``'s, a slider's or a plot's) at either end
    of which a length of ``scene`` would not be positive (``length_not_positive``).

    >>> from algkin.scene import load_scene
    >>> refuse_lengths_not_positive(load_scene("fourbar"), "a", (-1.0, 1.0), argument="--range-of")
    Traceback (most recent call last):
    ...
    algkin.errors.UsageError: --range-of='a=-1:1': the length a of fourbar would be -1 at a = -1; a length must be positive
    >>> refuse_lengths_not_positive(load_scene("fourbar"), "d", (-5.0, 5.0), argument="--range-of")  # a pivot's coordinate
    """
    found = length_not_positive(scene, name, bounds)
    if found is not None:
        length, value, end = found
        raise UsageError(argument, f"{name}={bounds[0]:g}:{bounds[1]:g}",
                         f"the length {length} of {scene.name} would be {value} at {name} = {end:g}; "
                         "a length must be positive")


def length_not_positive(scene: Scene, name: str, bounds: tuple[float, float]) \
        -> tuple[sympy.Expr, sympy.Expr, float] | None:
    """A length of ``scene`` (a crank's, a dyad's, a distance's: positive by the scene format) that
    would not be positive at an end of the span ``bounds`` of its dimension ``name``, the other
    dimensions at their values (the check compiling the scene with that value makes): ``(length,
    its value, the end)``; None if none.

    >>> from algkin.scene import load_scene
    >>> length_not_positive(load_scene("fourbar"), "m", (-4.0, -1.0))
    (m, -4, -4.0)
    """
    checks = dimension_checks(scene, list(scene.points), [name])
    for end in bounds:
        found = checks.not_positive({name: sympy.Rational(repr(float(end)))})
        if found is not None:
            return (*found, float(end))
    return None


Span = tuple[Optional[float], Optional[float]]
"""An open interval of a dimension; an end None: unbounded."""


def lengths_in(scene: Scene, names: Sequence[str]) -> tuple[sympy.Expr, ...]:
    """The lengths of ``scene`` (``length_not_positive``'s) in the dimensions ``names`` alone, the others
    at their values: one in an input too is not decided by the dimensions.

    >>> from algkin.scene import load_scene
    >>> lengths_in(load_scene("fourbar"), ["a", "l"])
    (a, l)
    """
    return tuple(length for length in dimension_checks(scene, list(scene.points), list(names)).lengths
                 if length.free_symbols and {str(s) for s in length.free_symbols} <= set(names))


def spans_lengths_positive(scene: Scene, name: str) -> tuple[Span, ...] | None:
    """The open intervals of the dimension ``name`` over which every length of ``scene`` in it
    (``length_not_positive``'s, the other dimensions at their values) is positive, ascending;
    None where no length holds it (a coordinate: a mechanism has any real value of it).

    >>> from algkin.scene import load_scene
    >>> spans_lengths_positive(load_scene("fourbar"), "a")
    ((0.0, None),)
    >>> spans_lengths_positive(load_scene("fourbar"), "d") is None  # a pivot's coordinate
    True
    """
    lengths = lengths_in(scene, [name])
    if not lengths:
        return None
    (variable,) = lengths[0].free_symbols
    cuts = sorted({cut for length in lengths for part in sympy.fraction(sympy.together(length))
                   for cut in _real_roots_of(part, variable)})
    bounds: list[float | None] = [None, *cuts, None]
    return tuple((lo, hi) for lo, hi in zip(bounds, bounds[1:])
                 if all(length.xreplace({variable: sympy.Rational(simplest_between(lo, hi))}) > 0 for length in lengths))


def _real_roots_of(poly: sympy.Expr, variable: sympy.Symbol) -> list[float]:
    if not poly.has(variable):
        return []
    exact = [(r.exact(), r.ball) for r in real_roots(univariate(poly, variable), bits=128)]
    return [float(ball.mid()) if rational is None else float(rational) for rational, ball in exact]


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


def _check_reach(scene: Scene, name: str, coordinates: Point) -> None:
    """A coordinate with a coefficient past ``MAGNITUDES`` (each frame of a long chain multiplies
    them, by sqrt(2) at ``at = [1, 1]``) is a scene error, as such a dimension is: floats overflow on it."""
    for coordinate in coordinates:
        for coefficient in coordinate.as_coefficients_dict().values():
            if coefficient.is_number and abs(coefficient) > MAGNITUDES[1]:
                raise SceneError(scene.source, f"points.{name}", f"its coordinates reach {sympy.Float(abs(coefficient), 3)}"
                                 ", past the magnitude 1e100 that floating-point checks can square")


def _check_bases(scene: Scene, name: str, dyad: Dyad, bases: Sequence[Point]) -> None:
    """A dyad's bases that coincide for every input (two fixed points at one place, the same
    crank twice; ``bases``: their coordinates, every dimension at its default) make two circles
    about one centre: no point, or a whole circle of them. Bad input, refused by name."""
    (px, py), (qx, qy) = bases
    if expanded(px - qx) == 0 and expanded(py - qy) == 0:
        where = f" at ({px}, {py})" if px.is_number and py.is_number else ""
        raise SceneError(scene.source, f"points.{name}", f"bases coincide: {dyad.bases[0]} and {dyad.bases[1]} are "
                         f"one point{where} for every input (its two circles have one centre)")


def _never_meets(dyad: Dyad, bases: Sequence[Point], lengths: Sequence[sympy.Expr]) -> str | None:
    """Why a dyad on two fixed bases can never assemble, decided exactly; None when it can, or
    when a base moves (that needs the motion: ``derive`` checks the branch on a grid of inputs).

    Its circles meet where ``|l1 - l2| <= d <= l1 + l2`` (``d`` the bases' distance), that is
    where ``4 l1**2 d**2 - (d**2 + l1**2 - l2**2)**2 >= 0``: squares only, rational numbers.
    """
    (px, py), (qx, qy) = bases
    if not all(v.is_number for v in (px, py, qx, qy, *lengths)):
        return None
    d2, s1, s2 = sympy.expand((qx - px)**2 + (qy - py)**2), sympy.expand(lengths[0]**2), sympy.expand(lengths[1]**2)
    reach = sympy.expand(4 * s1 * d2 - (d2 + s1 - s2)**2)
    if not reach.is_Rational or reach >= 0:
        return None
    return (f"its fixed bases {dyad.bases[0]} and {dyad.bases[1]} are {sympy.sqrt(d2)} apart, out of the reach "
            f"of its lengths {lengths[0]} and {lengths[1]} (from |l1 - l2| to l1 + l2)")


def _check_rational(scene: Scene, name: str, expressions: Sequence[sympy.Expr]) -> None:
    """The point's coordinates and equations are over the rationals: an irrational number such as
    ``sqrt(2)`` in them (a fixed point's coordinate, a crank's length) is a scene error, named."""
    for expr in expressions:
        if rational_polynomial(expr):  # the common case, decided in python-flint; else sympy finds the number
            continue
        numbers = [p for p in sympy.expand(expr).atoms(sympy.Pow) if p.is_number and not p.is_Rational]
        if numbers:
            raise SceneError(scene.source, f"points.{name}", f"{numbers[0]} makes its coordinates irrational: "
                             "the systems are over the rationals; a square root may stand in a dyad's lengths "
                             "(squared away), not in a coordinate, a crank's length or a frame's at")


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
            raise UsageError("params", culprits[0],
                             f"{scene.source} is not polynomial in it (keep it exact): {eq} = 0")


def _lengths(construction: Construction) -> tuple[sympy.Expr, ...]:
    """The lengths a construction declares (positive by the scene format)."""
    lengths = getattr(construction, "lengths", None) or (getattr(construction, "length", None),)
    return tuple(length for length in lengths if isinstance(length, sympy.Expr))


def _check_lengths(scene: Scene, element: str, lengths: Sequence[sympy.Expr],
                   inputs: Mapping[str, tuple[sympy.Symbol, ...]]) -> None:
    """Each length positive, at both ends of a length input's range where it moves with one."""
    moving = [(variables[0], scene.inputs[n]) for n, variables in inputs.items() if len(variables) == 1]
    for length in lengths:
        ends = [length]
        for variable, given in moving:
            ends = [e.xreplace({variable: end}) for e in ends for end in (given.lo, given.hi)]
        for end in ends:
            if _not_positive(end):
                raise SceneError(scene.source, element, f"length must be positive, got {length}"
                                 + (f" = {end} at an end of its input's range" if end != length else ""))


def _not_positive(length: sympy.Expr) -> bool:
    """Whether ``length``, a number, is not positive (a length in a symbol is not decided here)."""
    return bool(length.is_number and not length > 0)


def _check_direction(scene: Scene, name: str, construction: Construction) -> None:
    direction = getattr(construction, "direction", None)
    if direction is not None and all(d.is_number and d == 0 for d in direction):
        raise SceneError(scene.source, f"points.{name}.slider.direction",
                         "direction must not be zero, got [0, 0] with the parameters' default values")


def _check_phase(scene: Scene, name: str, construction: Construction) -> None:
    """A crank's phase given by parameters must still be a point of the unit circle with their defaults."""
    if isinstance(construction, Crank) and all(v.is_number for v in construction.phase):
        norm = sympy.expand(construction.phase[0] ** 2 + construction.phase[1] ** 2)
        if norm != 1:
            raise SceneError(scene.source, f"points.{name}.phase", f"cos**2 + sin**2 must be 1 (a point of the unit "
                             f"circle), got {norm} with the parameters' default values")


def _output_equations(outputs: Sequence[Output], coords: Mapping[str, Point], builder: Builder, *,
                      lengths: set[sympy.Symbol], source: str = "<scene>") \
        -> tuple[dict[str, sympy.Expr], dict[str, tuple[str, ...]], list[str], dict[str, AngleOutput]]:
    definitions: dict[str, sympy.Expr] = {}
    output_unknowns: dict[str, tuple[str, ...]] = {}
    nonnegative: list[str] = []
    angles: dict[str, AngleOutput] = {}
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
        if output.kind == "angle":
            angles[output.name] = _angle_equations(output, coords, builder, lengths=lengths, definitions=definitions,
                                                   nonnegative=nonnegative, source=source)
            output_unknowns[output.name] = tuple(u for u in (angles[output.name].cos, angles[output.name].sin) if u)
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
    return definitions, output_unknowns, nonnegative, angles


def _angle_equations(output: Output, coords: Mapping[str, Point], builder: Builder, *, lengths: set[sympy.Symbol],
                     definitions: dict[str, sympy.Expr], nonnegative: list[str], source: str) -> AngleOutput:
    """The unknowns and equations of an angle output (see ``AngleOutput``).

    A direction of PQ: ``L*cos - (Q - P)_x = 0``, ``L*sin - (Q - P)_y = 0`` with L = |PQ|;
    an angle at Q: ``L*cos - dot(P - Q, R - Q) = 0`` with L = |QP|*|QR|. Where a length is
    a constant of the mechanism (a bar: a crank, a dyad's or slider's length), L is that
    constant and the equations are polynomial in the points' coordinates; otherwise the
    helper unknown ``len_<name>`` (>= 0, with ``len**2 = L**2``) takes its place. Where both
    sides at Q are bars, ``dot(P - Q, R - Q) = (|QP|**2 + |QR|**2 - |PR|**2) / 2``: the
    cosine is then a polynomial in P and R alone (a four-bar's transmission angle, the
    textbook's ``(l**2 + m**2 - a**2 - d**2 + 2*a*d*cos(theta)) / (2*l*m)``).
    """
    name = output.name
    if len(output.points) == 2:
        (px, py), (qx, qy) = (coords[p] for p in output.points)
        sides = [(qx - px, qy - py)]
        measures = [qx - px, qy - py]
    else:
        (px, py), (qx, qy), (rx, ry) = (coords[p] for p in output.points)
        sides = [(px - qx, py - qy), (rx - qx, ry - qy)]
        measures = [(px - qx) * (rx - qx) + (py - qy) * (ry - qy)]
    squares = [sympy.expand(dx**2 + dy**2) for dx, dy in sides]
    circles = list(builder.inputs.values())  # the angles' (cos, sin): the builder holds no length input
    if any(reduce_on_circles(square, circles) == 0 for square in squares):
        raise SceneError(source, f"outputs.{name}", f"{output.text}: its points coincide, so it has no angle")
    known = [_bar_square(square, builder) for square in squares]
    first, second = known[0], known[-1]
    if len(sides) == 2 and first is not None and second is not None:  # two bars at Q: the law of cosines
        measures = [reduce_on_circles(sympy.expand((first + second - (px - rx) ** 2 - (py - ry) ** 2) / 2),
                                      circles)]  # frees it of Q
    constant_square = sympy.Mul(*[k for k in known if k is not None])
    varying = sympy.expand(sympy.Mul(*[sq for sq, k in zip(squares, known) if k is None]))
    constant = _length_of(constant_square, lengths)
    if constant is None:  # an irrational length: left under the helper's square root
        constant, varying = sympy.Integer(1), sympy.expand(constant_square * varying)
    helper = None
    divisor: sympy.Expr = constant
    if any(k is None for k in known) or varying != 1:
        helper = f"len_{name}"
        unknown = builder.unknown(helper)
        builder.equations.append(unknown**2 - varying)
        definitions[helper] = sympy.sqrt(varying)
        nonnegative.append(helper)
        divisor = constant * unknown
    names = [f"cos_{name}", f"sin_{name}"][:len(measures)]
    for unknown_name, measure in zip(names, measures):
        unknown = builder.unknown(unknown_name)
        builder.equations.append(sympy.expand(divisor * unknown - measure))
        definitions[unknown_name] = measure / (constant * sympy.sqrt(varying))
    return AngleOutput(name, output.points, names[0], names[1] if len(names) > 1 else None,
                       None if helper else constant, helper)


def _bar_square(square: sympy.Expr, builder: Builder) -> sympy.Expr | None:
    """``square`` = |PQ|**2 when it is a constant of the mechanism (free of the unknowns and the
    inputs), else None.

    It is constant when it reduces, on the inputs' circles, to a constant (a crank about its
    centre, a frame point on a crank), or to a constant plus a multiple of one equation of the
    points (a dyad's or a slider's circle ``|X - P|**2 - l**2``, a frame point on a dyad's bar).
    """
    moving = sorted(set(builder.unknowns) | {v for pair in builder.inputs.values() for v in pair}, key=str)
    circles = list(builder.inputs.values())
    reduced = reduce_on_circles(square, circles)
    if not reduced.free_symbols & set(moving):
        return reduced
    monomial, coefficient = sympy.Poly(reduced, *moving).terms()[0]
    for equation in builder.equations:
        other = sympy.Poly(equation, *moving).coeff_monomial(monomial)
        if other != 0:
            rest = reduce_on_circles(sympy.expand(reduced - coefficient / other * equation), circles)
            if not rest.free_symbols & set(moving):
                return sympy.factor(rest)
    return None


def _length_of(square: sympy.Expr, lengths: set[sympy.Symbol]) -> sympy.Expr | None:
    """The positive square root of a constant ``square`` as a polynomial over the rationals in
    lengths the scene declares (so positive), or None (an irrational number, a coordinate)."""
    if not square.free_symbols <= lengths:
        return None
    positive = {v: sympy.Dummy(v.name, positive=True) for v in square.free_symbols}
    root = sympy.sqrt(sympy.factor(square).xreplace(positive)).xreplace({d: v for v, d in positive.items()})
    if root == 0 or not root.is_polynomial(*root.free_symbols):
        return None
    coefficients = sympy.Poly(root, *root.free_symbols).coeffs() if root.free_symbols else [root]
    return sympy.expand(root) if all(c.is_Rational for c in coefficients) else None
