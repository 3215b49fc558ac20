"""Load scene files (TOML): validated element by element, nothing executed.

>>> scene = load_scene("chebyshev-lambda")
>>> list(scene.points)
['O', 'D', 'A', 'B', 'P']
>>> load_scene_text('[points]\\nA = { fixed = [0, "q"] }', "bad.toml")
Traceback (most recent call last):
...
algkin.errors.SceneError: bad.toml: points.A.fixed: unknown name 'q' (known: none)
"""

import os
import re
import stat
import sys
from collections.abc import Collection, Mapping
from fractions import Fraction
from typing import Any, NoReturn, Union

if sys.version_info >= (3, 11):
    import tomllib
else:  # Python 3.10
    import tomli as tomllib

import sympy

from ..catalog import CATALOG as _CATALOG, catalog_names, catalog_path
from ..runtime import suggest
from ..runtime.terminal import shortened
from ..runtime.cache import BoundedCache
from ..errors import SceneError, UsageError
from .constraints import Constraint, parse_constraint
from .constructions import CONSTRUCTIONS, QUARTER_TURNS, Construction, Crank, Dyad, Fixed, Frame, Meet, Mode, Slider, \
    Unknown
from .expr import MAX_VALUE_BITS, bits_bound, exact_number, irrational, parse
from .model import DrivenInput, Input, Output, Scene, length_range_problem, range_problem
from .names import check_names

__all__ = ["load_scene", "load_scene_text", "toml_syntax_error", "as_scene", "catalog_names", "MAX_SCENE_BYTES", "SceneLike",
           "Values"]

MAX_SCENE_BYTES = 256 * 1024
_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*")  # matched whole (fullmatch): a $ lets a name end in "\n"
_TOP_KEYS = {"name", "description", "unit", "parameters", "inputs", "points", "constraints", "outputs"}
Table = dict[str, Any]
SceneLike = Union[str, "os.PathLike[str]", Scene]  # what the public functions take for a scene
Values = Mapping[str, Union[str, int, Fraction]]  # ``set=``: dimensions given exact values  # a TOML table as tomllib reads it: values of any TOML type, checked here
Ranges = dict[str, tuple[sympy.Rational, sympy.Rational]]

_EXTRA_KEYS = {
    "fixed": set(),
    "crank": {"length", "input", "phase"},
    "dyad": {"lengths", "branch", "mode"},
    "frame": {"at"},
    "slider": {"distance", "branch", "mode"},
    "meet": set(),
    "unknown": {"mode"},
}
_PHASE_FORMS = ('a multiple of 90 degrees (0 in radians), { cos = "3/5", sin = "4/5" } (exact, '
                'cos**2 + sin**2 = 1) or { tan_half = "1/2" } (the tangent of half the phase)')


class _FloatText(str):
    """A TOML float kept as the text it spells, so that 0.1 stays 1/10."""


def load_scene(name_or_path: str | os.PathLike[str]) -> Scene:
    """Load a catalog scene by name, or a scene file by path."""
    path = str(name_or_path)
    if not os.path.lexists(path):  # a link that leads nowhere (or round in a loop) is read, to say so
        if path in catalog_names():
            path = catalog_path(path)
        else:
            raise SceneError(shortened(path), "", "no such file and no catalog scene of that name"
                             + _catalog_hint(path))
    data = _read(path)
    try:
        text = data.decode("utf-8").removeprefix("\ufeff")  # a byte-order mark (Notepad writes one) is no text
    except UnicodeDecodeError as err:
        raise SceneError(path, "", f"not UTF-8 text ({err.reason} at byte {err.start})") from None
    label = os.path.basename(path) if path.startswith(_CATALOG) else path
    return load_scene_text(text, label)


def _value_of(default: sympy.Expr, defaults: Mapping[str, sympy.Expr]) -> sympy.Rational | None:
    """A default's exact value: itself if a number; in other parameters, where each of theirs is a
    number and the value's bits stay within ``MAX_VALUE_BITS`` (chained powers, a default in a
    default in..., may cost gigabytes: those are left to the bits checks of compiling); else None."""
    used = {symbol: defaults[symbol.name] for symbol in default.free_symbols if isinstance(symbol, sympy.Symbol)}
    if not all(value.is_Rational for value in used.values()):
        return None
    bits = {symbol.name: bits_bound(value, {}) for symbol, value in used.items()}
    if bits_bound(default, bits) > MAX_VALUE_BITS:
        return None
    value = default.xreplace(used)
    return value if value.is_Rational else None  # 1/0 or an irrational is said where it is checked


def _catalog_hint(path: str) -> str:
    """The catalog, and the catalog name a missing ``path`` likely means: its file name without
    ``.toml`` (``scenes/3rpr.toml``: the catalog's ``3rpr``), or the name closest to that."""
    names = catalog_names()
    stem = os.path.basename(path).removesuffix(".toml") or path
    match = stem if stem in names else suggest.close_match(stem, names)
    return f" (catalog: {', '.join(names)})" + (f"; did you mean {match!r}?" if match else "")


def _read(path: str) -> bytes:
    """The bytes of a scene file: a regular file (a FIFO or device would block or never end)."""
    try:
        status = os.stat(path)
        if stat.S_ISDIR(status.st_mode):
            raise SceneError(path, "", "is a directory, not a scene file")
        if not stat.S_ISREG(status.st_mode):
            raise SceneError(path, "", "is not a regular file (a pipe or a device?)")
        if status.st_size > MAX_SCENE_BYTES:
            raise SceneError(path, "", f"file larger than {MAX_SCENE_BYTES} bytes")
        with open(path, "rb") as handle:
            return handle.read(MAX_SCENE_BYTES + 1)
    except OSError as err:
        raise SceneError(path, "", f"cannot read: {err.strerror or err}") from None


def load_scene_text(text: str, source: str = "<scene>") -> Scene:
    """Parse and validate a scene given as TOML text; ``source`` names it in errors.

    A text read before gives the same (immutable) scene again, without parsing it twice."""
    if not isinstance(text, str) or not isinstance(source, str):
        return _parse(text, source)
    return SCENE_TEXTS.get((text, source), lambda: _parse(text, source))


# Scenes by their text and source: the same text is parsed once.
SCENE_TEXTS: BoundedCache[Scene] = BoundedCache(64, name="scenes read")


_STOPPED_AT = re.compile(r"\(at line (\d+), column (\d+)\)$")
_NUMBER_BEFORE = re.compile(r"(\d+(?:\.\d+)?)\s*$")
_SLASH_NUMBER = re.compile(r"/\s*(\d+(?:\.\d+)?)")


def toml_syntax_error(text: str, err: tomllib.TOMLDecodeError) -> str:
    """tomllib's message; where it stopped at the slash of a fraction written bare (``[1/2, 2]``,
    as the expressions inside strings write it), how a TOML file takes one: as a string."""
    said = f"TOML syntax error: {err}"
    stopped = _STOPPED_AT.search(str(err))
    if stopped is None:
        return said
    row, column = int(stopped.group(1)), int(stopped.group(2))
    lines = text.split("\n")
    line = lines[row - 1] if row <= len(lines) else ""
    before, after = _NUMBER_BEFORE.search(line[:column - 1]), _SLASH_NUMBER.match(line, column - 1)
    if before is None or after is None:
        return said
    return f'{said}; TOML has no fractions: write the fraction as a string: "{before.group(1)}/{after.group(1)}"'


def _parse(text: str, source: str) -> Scene:
    if len(text.encode("utf-8")) > MAX_SCENE_BYTES:
        raise SceneError(source, "", f"text larger than {MAX_SCENE_BYTES} bytes")
    try:
        data = tomllib.loads(text, parse_float=_FloatText)
    except tomllib.TOMLDecodeError as err:
        raise SceneError(source, "", toml_syntax_error(text, err)) from None
    except ValueError as err:  # tomllib's own int(): more digits than Python converts
        raise SceneError(source, "", f"TOML value not readable: {str(err).split(';')[0]}") from None
    except RecursionError:
        raise SceneError(source, "", "TOML nested too deeply") from None
    return _Loader(source).scene(data)


class _Loader:
    """Reads one scene's TOML tables into a ``Scene``, failing with the element at fault."""

    def __init__(self, source: str) -> None:
        self.source = source
        self.names: dict[str, sympy.Expr] = {}  # parameters read so far, as symbols
        self.driven: dict[str, DrivenInput] = {}  # geared inputs, once read

    def fail(self, element: str, message: str) -> NoReturn:
        raise SceneError(self.source, element, message)

    def table(self, data: Table, key: str, element: str) -> Table:
        value = data.get(key, {})
        if not isinstance(value, dict):
            self.fail(element, f"expected a table, got {type(value).__name__}")
        return value

    def expr(self, value: object, element: str) -> sympy.Expr:
        if isinstance(value, _FloatText):
            try:
                return exact_number(value)
            except ValueError as err:
                self.fail(element, str(err))
        try:
            return parse(value, self.names)
        except ValueError as err:
            self.fail(element, str(err))

    def identifier(self, name: str, element: str) -> str:
        if not _NAME.fullmatch(name):
            self.fail(element, f"name {name!r} is not an identifier (letters, digits, _)")
        return name

    def scene(self, data: Table) -> Scene:
        unknown = set(data) - _TOP_KEYS
        if unknown:
            self.fail(sorted(unknown)[0], f"unknown key (expected one of {', '.join(sorted(_TOP_KEYS))})")
        name = data.get("name", os.path.splitext(os.path.basename(self.source))[0])
        description = data.get("description", "")
        if not isinstance(name, str) or not isinstance(description, str):
            self.fail("name", "name and description must be strings")
        unit = data.get("unit", "")
        if unit != "" and not (isinstance(unit, str) and len(unit) <= 16 and unit.isalpha()):
            self.fail("unit", f"expected a unit of length as a short word, e.g. \"mm\"; got {unit!r}")
        parameters, ranges = self.parameters(self.table(data, "parameters", "parameters"))
        table = self.table(data, "inputs", "inputs")
        geared = {n: spec for n, spec in table.items() if isinstance(spec, dict) and "driven_by" in spec}
        inputs = self.inputs({n: spec for n, spec in table.items() if n not in geared})
        self.driven = self.geared(geared, inputs)
        points = self.points(self.table(data, "points", "points"), inputs)
        constraints = self.constraints(self.table(data, "constraints", "constraints"), points)
        outputs = self.outputs(self.table(data, "outputs", "outputs"), points, inputs, parameters)
        scene = Scene(name, description, parameters, inputs, points, outputs, self.source, ranges, constraints,
                      self.driven, unit)
        check_names(scene)
        return scene

    def parameters(self, table: Table) -> tuple[dict[str, sympy.Expr], Ranges]:
        """Defaults (``a = 1``, or ``a = { default = 1, range = [lo, hi] }``) and declared ranges."""
        defaults: dict[str, sympy.Expr] = {}
        ranges: Ranges = {}
        for name, value in table.items():
            element = f"parameters.{name}"
            self.identifier(name, element)
            if name.startswith(("c_", "s_")):
                self.fail(element, "names starting with c_ or s_ are kept for input angles")
            if isinstance(value, dict):
                value, ranges[name] = self.ranged(value, element)
            # A default may use the parameters above it; the name itself stays a symbol.
            defaults[name] = self.expr(value, element)
            problem = irrational(defaults[name])  # one in the parameters above it: when they are resolved
            if problem:
                self.fail(element, problem)
            self.names[name] = sympy.Symbol(name, real=True)
            if name in ranges:
                self.check_default_in_range(defaults[name], defaults, ranges[name], element)
        return defaults, ranges

    def check_default_in_range(self, default: sympy.Expr, defaults: Mapping[str, sympy.Expr],
                               bounds: tuple[sympy.Rational, sympy.Rational], element: str) -> None:
        """A declared range holds its parameter's default (a page's slider starts there): a number, or
        one in other parameters whose ``defaults`` are numbers, where its value is cheap (``_value_of``)."""
        lo, hi = bounds
        value = _value_of(default, defaults)
        if value is not None and not lo <= value <= hi:
            said = f"{default} = {value}" if value != default else f"{value}"
            self.fail(f"{element}.default", f"{said} is outside its range [{lo}, {hi}]")

    def ranged(self, spec: Table, element: str) -> tuple[object, tuple[sympy.Rational, sympy.Rational]]:
        """``{ default = d, range = [lo, hi] }``: the default's text and (lo, hi), two exact numbers."""
        extra = set(spec) - {"default", "range"}
        if extra:
            self.fail(f"{element}.{sorted(extra)[0]}", "unknown key (expected default, range)")
        if "default" not in spec:
            self.fail(f"{element}.default", "missing: a ranged parameter still needs its default")
        bounds = spec.get("range")
        if not isinstance(bounds, list) or len(bounds) != 2:
            self.fail(f"{element}.range", "expected [lo, hi], two numbers")
        lo, hi = (self.number(b, f"{element}.range") for b in bounds)
        if not lo < hi:
            self.fail(f"{element}.range", f"empty range [{lo}, {hi}]: expected lo < hi")
        return spec["default"], (lo, hi)

    def inputs(self, table: Table) -> dict[str, Input]:
        inputs: dict[str, Input] = {}
        for name, spec in table.items():
            element = f"inputs.{name}"
            self.identifier(name, element)
            if name in self.names:
                self.fail(element, f"input {name!r} has the name of a parameter")
            if not isinstance(spec, dict):
                self.fail(element, "expected a table like { range = [0, 360], unit = \"deg\" }")
            extra = set(spec) - {"range", "unit"}
            if extra:
                self.fail(f"{element}.{sorted(extra)[0]}", "unknown key (expected range, unit)")
            unit = spec.get("unit", "deg")
            if unit not in ("deg", "rad", "length"):
                self.fail(f"{element}.unit", f"unit must be 'deg', 'rad' or 'length', got {unit!r}")
            if unit == "length" and "range" not in spec:
                self.fail(f"{element}.range", "a length input needs its range = [lo, hi]")
            bounds = spec.get("range", [0, 360] if unit == "deg" else [0, "6283185307/1000000000"])
            if not isinstance(bounds, list) or len(bounds) != 2:
                self.fail(f"{element}.range", "expected [lo, hi]")
            lo, hi = (self.number(b, f"{element}.range") for b in bounds)
            if not lo < hi:
                self.fail(f"{element}.range", f"empty range [{lo}, {hi}]")
            inputs[name] = Input(name, lo, hi, unit)
            problem = range_problem(*inputs[name].span) if unit != "length" else length_range_problem(lo, hi)
            if problem:
                self.fail(f"{element}.range", f"[{float(lo):g}, {float(hi):g}] {unit} {problem}")
        # a length input is a dimension that moves: the points' expressions may use it
        self.names.update({name: i.symbols[0] for name, i in inputs.items() if not i.is_angle})
        return inputs

    def geared(self, table: Table, inputs: Mapping[str, Input]) -> dict[str, DrivenInput]:
        """``t2 = { driven_by = "t1", ratio = "-2" }``: angle inputs geared to others, ``t2 = ratio * t1``."""
        driven: dict[str, DrivenInput] = {}
        for name, spec in table.items():
            element = f"inputs.{name}"
            self.identifier(name, element)
            if name in self.names:
                self.fail(element, f"input {name!r} has the name of a parameter")
            extra = set(spec) - {"driven_by", "ratio"}
            if extra:
                self.fail(f"{element}.{sorted(extra)[0]}", "unknown key for a geared input (expected driven_by, "
                          "ratio; its range and unit are its driver's)")
            driver = spec["driven_by"]
            if not isinstance(driver, str):
                self.fail(f"{element}.driven_by", f"expected the name of an input, got {driver!r}")
            if driver == name:
                self.fail(f"{element}.driven_by", f"{name!r} cannot drive itself")
            if driver not in inputs and driver not in table:
                others = [n for n in [*inputs, *table] if n != name]
                self.fail(f"{element}.driven_by", f"unknown input {driver!r}" + suggest.known(driver, others, plural="inputs"))
            if driver in inputs and not inputs[driver].is_angle:
                self.fail(f"{element}.driven_by", f"{driver!r} is a length input: gears turn with an angle")
            driven[name] = DrivenInput(name, driver, self.ratio(spec.get("ratio"), f"{element}.ratio", (name, driver)))
        for name in driven:
            self.check_gears(name, driven)
        return driven

    def ratio(self, value: object, element: str, gear: tuple[str, str]) -> sympy.Integer:
        """A gear ratio: a nonzero integer (a fraction p/q would need the driver's angle over q as the variable)."""
        if value is None:
            self.fail(element, 'missing: the gear ratio, a nonzero integer such as "2" or "-1"')
        try:
            ratio = parse(value, {}) if not isinstance(value, _FloatText) else exact_number(value)
        except ValueError:
            ratio = None
        if ratio is None or not ratio.is_Rational or ratio == 0:
            self.fail(element, f'expected a nonzero integer such as "2" or "-1" (negative: external gears), got '
                      f'{value!r}')
        if not ratio.is_Integer:
            name, driver = gear
            self.fail(element, f"ratio {ratio} is not an integer (the system would not stay polynomial): drive both "
                      f"from a slower input u, {driver} = {{ driven_by = \"u\", ratio = \"{ratio.q}\" }} and "
                      f"{name} = {{ driven_by = \"u\", ratio = \"{ratio.p}\" }}")
        return ratio

    def check_gears(self, name: str, driven: Mapping[str, DrivenInput]) -> None:
        """Refuse inputs that drive each other in a cycle (``t2 -> t3 -> t2``)."""
        chain = [name]
        while chain[-1] in driven:
            chain.append(driven[chain[-1]].driver)
            if chain[-1] == name:
                self.fail(f"inputs.{name}.driven_by", f"inputs drive each other in a cycle: {' -> '.join(chain)}")
            if chain[-1] in chain[:-1]:
                return  # a cycle further up the chain: reported from its own inputs

    def number(self, value: object, element: str) -> sympy.Rational:
        saved, self.names = self.names, {}
        try:
            number = self.expr(value, element)
        finally:
            self.names = saved
        if not number.is_Rational:
            self.fail(element, f"expected a rational number, got {number}")
        return number

    def pair(self, spec: Table, key: str, element: str) -> list[Any]:
        value = spec.get(key)
        if not isinstance(value, list) or len(value) != 2:
            self.fail(f"{element}.{key}", f"expected a list of two, got {value!r}")
        return value

    def point_pair(self, spec: Table, key: str, element: str, names: set[str]) -> tuple[str, str]:
        """``key = [P, Q]``: two different points."""
        first, second = (self.point_ref(p, f"{element}.{key}", names) for p in self.pair(spec, key, element))
        if first == second:
            self.fail(f"{element}.{key}", f"the two base points must differ, got {first!r} twice")
        return first, second

    def point_ref(self, value: object, element: str, names: Collection[str]) -> str:
        if not isinstance(value, str) or value not in names:
            self.fail(element, f"unknown point {value!r}" + suggest.did_you_mean(str(value), names))
        return value

    def positive(self, value: object, element: str) -> sympy.Expr:
        expr = self.expr(value, element)
        if expr.is_number and not expr > 0:
            self.fail(element, f"length must be positive, got {expr}")
        return expr

    def points(self, table: Table, inputs: dict[str, Input]) -> dict[str, Construction]:
        names = set(table)
        points: dict[str, Construction] = {}
        for name, spec in table.items():
            element = f"points.{name}"
            self.identifier(name, element)
            if not isinstance(spec, dict):
                self.fail(element, "expected a table such as { fixed = [0, 0] }")
            kinds = [k for k in spec if k in CONSTRUCTIONS]
            if len(kinds) != 1:
                self.fail(element, f"needs exactly one of {', '.join(CONSTRUCTIONS)}, found {kinds or 'none'}")
            kind = kinds[0]
            extra = set(spec) - {kind} - _EXTRA_KEYS[kind]
            if extra:
                self.fail(f"{element}.{sorted(extra)[0]}", f"unknown key for a {kind} point")
            points[name] = getattr(self, kind)(spec, f"{element}", names, inputs)
        self.check_acyclic(points)
        return points

    def fixed(self, spec: Table, element: str, names: set[str], inputs: dict[str, Input]) -> Fixed:
        x, y = self.pair(spec, "fixed", element)
        return Fixed(self.expr(x, f"{element}.fixed"), self.expr(y, f"{element}.fixed"))

    def crank(self, spec: Table, element: str, names: set[str], inputs: dict[str, Input]) -> Crank:
        center = self.point_ref(spec["crank"], f"{element}.crank", names)
        if "length" not in spec:
            self.fail(f"{element}.length", "a crank needs a length")
        length = self.positive(spec["length"], f"{element}.length")
        name = spec.get("input")
        if name not in inputs and name not in self.driven:
            self.fail(f"{element}.input", f"unknown input {name!r}"
                      + suggest.known(str(name), [*inputs, *self.driven], plural="inputs"))
        root = inputs[self.root(name)]
        if not root.is_angle:
            self.fail(f"{element}.input", f"{name!r} is a length input: a crank turns with an angle "
                                          "(use the length in a dyad's lengths or a frame's at)")
        return Crank(center, length, name, self.phase(spec.get("phase", 0), f"{element}.phase", root.unit))

    def root(self, name: str) -> str:
        """The input at the root of ``name``'s gears (checked acyclic)."""
        while name in self.driven:
            name = self.driven[name].driver
        return name

    def phase(self, value: object, element: str, unit: str) -> tuple[sympy.Expr, sympy.Expr]:
        """A crank's phase as its exact (cos, sin): see ``_PHASE_FORMS``."""
        if isinstance(value, dict):
            return self.phase_table(value, element)
        phase = self.number(value, element)
        quarter = phase / 90 if unit == "deg" else phase
        if not quarter.is_Integer or (unit == "rad" and phase != 0):
            self.fail(element, f"phase {shortened(str(phase), 40)} {unit} has no rational cos and sin: give {_PHASE_FORMS}")
        cos, sin = QUARTER_TURNS[int(quarter) % 4]
        return sympy.Integer(cos), sympy.Integer(sin)

    def phase_table(self, value: Table, element: str) -> tuple[sympy.Expr, sympy.Expr]:
        """``{ cos = c, sin = s }`` (c**2 + s**2 = 1 where both are numbers) or ``{ tan_half = t }``."""
        if set(value) == {"tan_half"}:
            half = self.expr(value["tan_half"], f"{element}.tan_half")
            return sympy.cancel((1 - half**2) / (1 + half**2)), sympy.cancel(2 * half / (1 + half**2))
        if set(value) != {"cos", "sin"}:
            self.fail(element, f"expected {_PHASE_FORMS}, got the keys {', '.join(sorted(value)) or 'none'}")
        cos, sin = (self.expr(value[k], f"{element}.{k}") for k in ("cos", "sin"))
        if cos.is_number and sin.is_number and cos**2 + sin**2 != 1:
            self.fail(element, f"cos**2 + sin**2 must be 1 (a point of the unit circle), got {cos**2 + sin**2} "
                      f"for cos = {cos}, sin = {sin}")
        return cos, sin

    def dyad(self, spec: Table, element: str, names: set[str], inputs: dict[str, Input]) -> Dyad:
        bases = self.point_pair(spec, "dyad", element, names)
        lengths = tuple(self.positive(v, f"{element}.lengths") for v in self.pair(spec, "lengths", element))
        mode = self.mode(spec, element, inputs)
        branch = spec.get("branch", "left")
        if branch not in Dyad.labels:
            self.fail(f"{element}.branch", f"branch must be 'left' or 'right', got {branch!r}")
        return Dyad(bases, lengths, branch, mode)

    def mode(self, spec: Table, element: str, inputs: Mapping[str, Input]) -> Mode | None:
        """``mode = { at = v, near = [x, y] }`` (``at = { t1 = v1, t2 = v2 }`` with several inputs),
        exact numbers; refused beside a ``branch``, which it replaces."""
        if "mode" not in spec:
            return None
        if "branch" in spec:
            self.fail(f"{element}.mode", "give branch or mode, not both (mode names the branch by a configuration)")
        table = self.subtable(spec, "mode", element, keys=("at", "near"), example="{ at = 0, near = [1, 2] }")
        near = tuple(self.number(v, f"{element}.mode.near") for v in self.pair(table, "near", f"{element}.mode"))
        return Mode(self.mode_at(table["at"], f"{element}.mode.at", inputs), (near[0], near[1]))

    def mode_at(self, value: object, element: str, inputs: Mapping[str, Input]) -> tuple[tuple[str, sympy.Rational], ...]:
        """The inputs' values where a mode is named: a number for the one input, else {input = value} for each."""
        if not inputs:
            self.fail(element, "the scene has no input: a mode is named at the inputs' values")
        if not isinstance(value, dict):
            if len(inputs) > 1:
                self.fail(element, f"expected a table {{ {' = .., '.join(inputs)} = .. }}: the scene has "
                          f"{len(inputs)} inputs")
            value = {next(iter(inputs)): value}
        if set(value) != set(inputs):
            missing = sorted(set(inputs) - set(value)) or sorted(set(value) - set(inputs))
            self.fail(f"{element}.{missing[0]}", f"expected a value for each input ({', '.join(inputs)}), no other")
        at = []
        for name, given in value.items():
            number, spec = self.number(given, f"{element}.{name}"), inputs[name]
            if not spec.lo <= number <= spec.hi:
                self.fail(f"{element}.{name}", f"{number} is outside the input's range [{spec.lo}, {spec.hi}]")
            at.append((name, number))
        return tuple(at)

    def subtable(self, spec: Table, key: str, element: str, *, keys: tuple[str, ...], example: str) -> Table:
        value = spec.get(key)
        if not isinstance(value, dict):
            self.fail(f"{element}.{key}", f"expected a table like {example}, got {value!r}")
        extra = set(value) - set(keys)
        if extra:
            self.fail(f"{element}.{key}.{sorted(extra)[0]}", f"unknown key (expected {', '.join(keys)})")
        for name in keys:
            if name not in value:
                self.fail(f"{element}.{key}.{name}", f"missing (expected {example})")
        return value

    def slider(self, spec: Table, element: str, names: set[str], inputs: dict[str, Input]) -> Slider:
        line = spec.get("slider")
        given = [key for key in ("direction", "toward") if isinstance(line, dict) and key in line]
        if isinstance(line, dict) and len(given) != 1:
            extra = sorted(set(line) - {"through", "direction", "toward"})
            where, what = (f"{element}.slider.{extra[0]}", "unknown key (expected through, and direction or toward)") \
                if extra else (f"{element}.slider", "give either direction = [dx, dy] (a fixed line) or "
                               "toward = \"R\" (the line through two points, moving with them)"
                               + (", not both" if given else ""))
            self.fail(where, what)
        keys = ("through", given[0]) if given else ("through", "direction")
        example = '{ through = "O", toward = "A" }' if given == ["toward"] else '{ through = "O", direction = [1, 0] }'
        line = self.subtable(spec, "slider", element, keys=keys, example=example)
        through = self.point_ref(line["through"], f"{element}.slider.through", names)
        direction: tuple[sympy.Expr, sympy.Expr] | None = None
        toward: str | None = None
        if given == ["toward"]:
            toward = self.point_ref(line["toward"], f"{element}.slider.toward", names)
            if toward == through:
                self.fail(f"{element}.slider.toward", f"the line through {through} toward {toward} has no "
                          "direction: name two different points")
        else:
            x, y = (self.expr(v, f"{element}.slider.direction") for v in self.pair(line, "direction", f"{element}.slider"))
            direction = (x, y)
            if all(d.is_number and d == 0 for d in direction):
                self.fail(f"{element}.slider.direction", "direction must not be zero, got [0, 0]")
        distance = self.subtable(spec, "distance", element, keys=("to", "length"), example='{ to = "A", length = 3 }')
        to = self.point_ref(distance["to"], f"{element}.distance.to", names)
        length = self.positive(distance["length"], f"{element}.distance.length")
        mode = self.mode(spec, element, inputs)
        branch = spec.get("branch", "ahead")
        if branch not in Slider.labels:
            self.fail(f"{element}.branch", "branch must be 'ahead' or 'behind' (along the direction, "
                      f"from the foot of the perpendicular from {to}), got {branch!r}")
        return Slider(through, direction, to, length, branch, toward, mode)

    def frame(self, spec: Table, element: str, names: set[str], inputs: dict[str, Input]) -> Frame:
        bases = self.point_pair(spec, "frame", element, names)
        at = tuple(self.expr(v, f"{element}.at") for v in self.pair(spec, "at", element))
        return Frame(bases, at)

    def meet(self, spec: Table, element: str, names: set[str], inputs: dict[str, Input]) -> Meet:
        """``meet = [["A", "B"], ["C", "D"]]``: two lines, each through two different points, not the same line."""
        lines = self.pair(spec, "meet", element)
        pairs = []
        for line in lines:
            if not isinstance(line, list) or len(line) != 2:
                self.fail(f"{element}.meet", f'expected two lines, each two points: [["A", "B"], ["C", "D"]], got {lines!r}')
            first, second = (self.point_ref(p, f"{element}.meet", names) for p in line)
            if first == second:
                self.fail(f"{element}.meet", f"the line through {first} and {second} has no direction: name two "
                          "different points")
            pairs.append((first, second))
        if set(pairs[0]) == set(pairs[1]):
            self.fail(f"{element}.meet", f"a line meets itself everywhere: {'-'.join(pairs[0])} and "
                      f"{'-'.join(pairs[1])} are the same line")
        return Meet((pairs[0], pairs[1]))

    def unknown(self, spec: Table, element: str, names: set[str], inputs: dict[str, Input]) -> Unknown:
        if spec["unknown"] is not True:
            self.fail(f"{element}.unknown", f"expected true (a point solved together with others), got {spec['unknown']!r}")
        return Unknown(self.mode(spec, element, inputs))

    def constraints(self, table: Table, points: Mapping[str, Construction]) -> dict[str, Constraint]:
        """``name = "dist(P, Q) = L"`` and the like (``algkin.scene.constraints``); each must hold a
        point solved together (``unknown = true``) or one built on such points."""
        constraints: dict[str, Constraint] = {}
        for name, text in table.items():
            element = f"constraints.{name}"
            self.identifier(name, element)
            if not isinstance(text, str):
                self.fail(element, "expected a string such as \"dist(A1, P1) = r1\"")
            try:
                constraints[name] = parse_constraint(text, names=self.names, points=points)
            except ValueError as err:
                self.fail(element, str(err))
            if not any(_moves_with_unknowns(p, points) for p in constraints[name].points):
                self.fail(element, "holds no point solved together (unknown = true) nor one built on such points")
            self.check_not_again(name, constraints)
        return constraints

    def check_not_again(self, name: str, constraints: Mapping[str, Constraint]) -> None:
        """Bad input: a second constraint on the same distance, or the same three points on a line
        (the same equation again, or one that contradicts it: the group's equations, one short,
        left a curve of solutions, an elimination's failure)."""
        constraint = constraints[name]
        for other, earlier in constraints.items():
            if other != name and (earlier.kind == "on") == (constraint.kind == "on") \
                    and set(earlier.points) == set(constraint.points):
                what = "three points on one line" if constraint.kind == "on" else "distance"
                self.fail(f"constraints.{name}", f"{constraint.text}: the same {what} as constraints.{other} "
                                                 f"({earlier.text}); give each once")

    def check_acyclic(self, points: Mapping[str, Construction]) -> None:
        state: dict[str, str] = {}  # point -> 'active' (on the path) or 'done'

        def visit(name: str, path: list[str]) -> None:
            if state.get(name) == "done":
                return
            if state.get(name) == "active":
                cycle = " -> ".join(path[path.index(name):] + [name])
                self.fail(f"points.{name}", f"points depend on each other in a cycle: {cycle}")
            state[name] = "active"
            for ref in points[name].references:
                visit(ref, path + [name])
            state[name] = "done"

        for name in points:
            visit(name, [])

    def outputs(self, table: Table, points: Mapping[str, Construction], inputs: Mapping[str, Input],
                parameters: Mapping[str, sympy.Expr]) -> dict[str, Output]:
        outputs: dict[str, Output] = {}
        taken = set(points) | set(inputs) | set(parameters)
        for name, text in table.items():
            element = f"outputs.{name}"
            self.identifier(name, element)
            if not isinstance(text, str):
                self.fail(element, "expected a string such as \"P\", \"dist(A, B)\", \"P.x\" or \"angle(A, B)\"")
            outputs[name] = parse_output(name, text, points, source=self.source, element=element)
            if outputs[name].kind == "dist" and name in taken:
                self.fail(element, f"a distance output needs a name of its own, {name!r} is taken")
        return outputs


def _moves_with_unknowns(point: str, points: Mapping[str, Construction]) -> bool:
    """Whether ``point`` is solved together or built, through its references, on such a point."""
    construction = points[point]
    return isinstance(construction, Unknown) or any(_moves_with_unknowns(r, points) for r in construction.references)


_DIST = re.compile(r"^\s*dist\(\s*(\w+)\s*,\s*(\w+)\s*\)\s*$")
_COORD = re.compile(r"^\s*(\w+)\.([xy])\s*$")
_ANGLE = re.compile(r"^\s*angle\s*\((.*)\)\s*$", re.DOTALL)
_ANGLE_FORMS = "angle(P, Q) (the direction of PQ) or angle(P, Q, R) (the angle at Q between QP and QR)"


def parse_output(name: str, text: str, points: Collection[str], *, source: str = "<scene>",
                 element: str | None = None) -> Output:
    """Read an output string: a point name, ``dist(P, Q)``, ``P.x``, ``P.y``, ``angle(P, Q)``
    (the direction of PQ) or ``angle(P, Q, R)`` (the angle at Q between QP and QR, in [0, 180] deg).

    >>> parse_output("mu", "angle(A, B, D)", "ABD")
    Output(name='mu', kind='angle', points=('A', 'B', 'D'), text='angle(A, B, D)')
    >>> parse_output("phi", "angle(D, D)", "D", source="s.toml")
    Traceback (most recent call last):
    ...
    algkin.errors.SceneError: s.toml: outputs.phi: angle(D, D) has no direction: its two points are the same point
    >>> parse_output("r", "dist(D, D)", "D", source="s.toml")
    Traceback (most recent call last):
    ...
    algkin.errors.SceneError: s.toml: outputs.r: dist(D, D) is always 0: its two points are the same point
    """
    element = element or f"outputs.{name}"
    if match := _DIST.match(text):
        kind, refs = "dist", match.groups()
        if refs[0] == refs[1]:  # its eliminant, r**2 = 0, has only a double root: nothing to prove it by
            raise SceneError(source, element, f"{text.strip()} is always 0: its two points are the same point")
    elif match := _ANGLE.match(text):
        kind, refs = "angle", _angle_points(text, match.group(1), source, element)
    elif match := _COORD.match(text):
        kind, refs = match.group(2), (match.group(1),)
    else:
        kind, refs = "point", (text.strip(),)
    for ref in refs:
        if ref not in points:
            raise SceneError(source, element, f"unknown point {ref!r} in {text!r}" + suggest.did_you_mean(ref, points))
    return Output(name, kind, tuple(refs), text)


def _angle_points(text: str, inside: str, source: str, element: str) -> tuple[str, ...]:
    """The points of ``angle(...)``: two or three distinct names (the vertex apart from both ends)."""
    refs = tuple(part.strip() for part in inside.split(","))
    if len(refs) not in (2, 3) or not all(re.fullmatch(r"\w+", r) for r in refs):
        raise SceneError(source, element, f"{text.strip()!r}: expected {_ANGLE_FORMS}")
    if len(refs) == 2 and refs[0] == refs[1]:
        raise SceneError(source, element, f"{text.strip()} has no direction: its two points are the same point")
    if len(refs) == 3 and refs[1] in (refs[0], refs[2]):
        raise SceneError(source, element, f"{text.strip()} has no angle at {refs[1]}: a side from {refs[1]} "
                                          "to itself has no direction")
    if len(refs) == 3 and refs[0] == refs[2]:
        raise SceneError(source, element, f"{text.strip()} is the angle between a segment and itself (always 0)")
    return refs


def as_scene(scene: SceneLike) -> Scene:
    """A ``Scene`` from a catalog name, a path, or a ``Scene`` (checked as a loaded file is).

    A scene built or changed in Python has not been through the loader: it is written
    out and read back, so it meets the same checks and one-line errors as a file.

    >>> as_scene(42)
    Traceback (most recent call last):
    ...
    algkin.errors.UsageError: scene=42: expected a catalog name, a path or a Scene
    """
    from .dump import dump_scene

    if isinstance(scene, (str, os.PathLike)):
        return load_scene(scene)
    if not isinstance(scene, Scene):
        raise UsageError("scene", scene, "expected a catalog name, a path or a Scene")
    source = scene.source if isinstance(scene.source, str) else "<scene>"
    try:
        text = dump_scene(scene)
    except (AttributeError, KeyError, TypeError, ValueError) as err:
        raise SceneError(source, "", f"not a valid scene: {err}") from None
    return load_scene_text(text, source)


# Shared with ``algkin.scene.builder``: a scene built in Python goes through the same checks.

def scene_from_data(data: Table, source: str = "<scene>") -> Scene:
    """A ``Scene`` from ``data`` shaped as a parsed scene file (tables as dicts, arrays as
    lists, floats as ``float_text``), with the same checks and errors as ``load_scene_text``."""
    return _Loader(source).scene(data)


def float_text(value: float) -> str:
    """A float as a scene file's float literal: read back as the decimal that ``repr`` spells (0.1 is 1/10)."""
    return _FloatText(repr(float(value)))
