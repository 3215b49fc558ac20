"""Synthesis files (TOML): the wanted poses, angle pairs or path points, read exactly.

A file says its ``kind`` (``motion``, ``function`` or ``path``) and its data (SPEC, "Synthesis
files"); every number is exact (``"3/5"``, ``0.1`` is 1/10), every angle exact on the unit circle
(``{ cos, sin }``, ``{ tan_half }``) or a number of degrees, taken to 60 digits and said to be
(``Task.approximate``). Nothing in a file is executed; a fault is a SceneError naming the element.

>>> task = read_task_text('''
... kind = "motion"
... [[poses]]
... x = 0
... y = 0
... angle = 0
... [[poses]]
... x = "1/2"
... y = 1
... angle = { tan_half = "1/3" }
... ''', "two.toml")
>>> task.kind, len(task.poses), str(task.poses[1].angle.cos), task.approximate
('motion', 2, '4/5', False)
>>> read_task_text('kind = "motion"\\nposes = 3', "bad.toml")
Traceback (most recent call last):
...
algkin.errors.SceneError: bad.toml: poses: expected a list of tables ([[poses]]), got 3
"""

from __future__ import annotations

import os
import stat
import sys
from collections.abc import Mapping
from typing import Any, NoReturn

if sys.version_info >= (3, 11):
    import tomllib
else:  # Python 3.10
    import tomli as tomllib

import attrs
import flint

from ..errors import SceneError
from ..runtime import suggest
from ..runtime.terminal import shortened
from ..scene.expr import exact_number
from ..scene.load import MAX_SCENE_BYTES, toml_syntax_error
from .data import Angle, AnglePair, Point, Pose
from .fourbar import NAME_CHARS, safe_name

__all__ = ["Task", "read_task", "read_task_text", "example_names", "KINDS"]

KINDS = ("motion", "function", "path")
_EXAMPLES = os.path.join(os.path.dirname(__file__), "examples")
_KEYS = {"motion": {"poses"}, "function": {"pairs", "unknown_start", "ground"}, "path": {"pivots", "points"}}
_COMMON = {"kind", "name", "description"}
Table = dict[str, Any]


@attrs.frozen
class Task:
    """What a synthesis file asks: its ``kind`` and the data of that kind (the others empty)."""

    source: str
    kind: str
    name: str
    poses: tuple[Pose, ...] = ()
    pairs: tuple[AnglePair, ...] = ()
    unknown_start: bool = False
    ground: flint.fmpq = flint.fmpq(1)
    pivots: tuple[Point, Point] | None = None
    points: tuple[Point, ...] = ()

    @property
    def approximate(self) -> bool:
        """Whether an angle was given in degrees with irrational cos and sin (then taken to 60 digits)."""
        angles = [p.angle for p in self.poses] + [a for pair in self.pairs for a in (pair.input, pair.output)]
        return any(a.approximate for a in angles)


def example_names() -> list[str]:
    """The synthesis files shipped with algkin, by name (``read_task`` takes a name as a path)."""
    return sorted(f[:-5] for f in os.listdir(_EXAMPLES) if f.endswith(".toml"))


def read_task(path: str | os.PathLike[str]) -> Task:
    """The task of the synthesis file at ``path`` (a regular file of at most MAX_SCENE_BYTES), or
    of the example of that name (``example_names``) where no such file exists."""
    path = str(path)
    if not os.path.exists(path) and path in example_names():
        path = os.path.join(_EXAMPLES, path + ".toml")
    try:
        status = os.stat(path)
        if not stat.S_ISREG(status.st_mode):
            raise SceneError(path, "", "is not a regular file")
        if status.st_size > MAX_SCENE_BYTES:
            raise SceneError(path, "", f"file larger than {MAX_SCENE_BYTES} bytes")
        with open(path, "rb") as handle:
            data = handle.read(MAX_SCENE_BYTES + 1)
    except OSError as err:
        raise SceneError(path, "", f"cannot read: {err.strerror or err}"
                         + suggest.known(os.path.basename(path), example_names(), plural="examples")) from None
    try:
        text = data.decode("utf-8").removeprefix("\ufeff")  # a byte-order mark (Notepad writes one) is no text
    except UnicodeDecodeError as err:
        raise SceneError(path, "", f"not UTF-8 text ({err.reason} at byte {err.start})") from None
    return read_task_text(text, os.path.basename(path) if path.startswith(_EXAMPLES) else path)


def read_task_text(text: str, source: str = "<synthesis>") -> Task:
    """The task a synthesis file's TOML ``text`` asks; ``source`` names it in errors."""
    if len(text.encode("utf-8")) > MAX_SCENE_BYTES:
        raise SceneError(source, "", f"text larger than {MAX_SCENE_BYTES} bytes")
    try:
        data = tomllib.loads(text, parse_float=str)  # a float kept as its text: 0.1 stays 1/10
    except tomllib.TOMLDecodeError as err:
        raise SceneError(source, "", toml_syntax_error(text, err)) from None
    except (ValueError, RecursionError) as err:
        raise SceneError(source, "", f"TOML value not readable: {str(err).split(';')[0]}") from None
    return _Reader(source).task(data)


class _Reader:
    def __init__(self, source: str) -> None:
        self.source = source

    def fail(self, element: str, message: str) -> NoReturn:
        raise SceneError(self.source, element, message)

    def task(self, data: Table) -> Task:
        kind = data.get("kind")
        if kind not in KINDS:
            self.fail("kind", f"expected one of {', '.join(KINDS)}, got {kind!r}"
                      + (suggest.known(kind, KINDS, plural="valid") if isinstance(kind, str) else ""))
        allowed = _COMMON | _KEYS[kind]
        for key in data:
            if key not in allowed:
                self.fail(key, f"not a key of a {kind} file" + suggest.known(key, sorted(allowed), plural="valid"))
        name = data.get("name", safe_name(os.path.splitext(os.path.basename(self.source))[0]))
        if not isinstance(name, str) or not name or name != safe_name(name):
            self.fail("name", f"expected at most {NAME_CHARS} letters, digits, '-' and '_' (it names the scene "
                                  f"files written), got {shortened(repr(name))}")
        if not isinstance(data.get("description", ""), str):
            self.fail("description", "expected a string")
        task = Task(self.source, kind, name)
        if kind == "motion":
            return attrs.evolve(task, poses=tuple(self.pose(t, f"poses[{i}]") for i, t in
                                                  enumerate(self.tables(data, "poses"))))
        if kind == "function":
            unknown_start = data.get("unknown_start", False)
            if not isinstance(unknown_start, bool):
                self.fail("unknown_start", f"expected true or false, got {unknown_start!r}")
            ground = self.number(data.get("ground", 1), "ground")
            if ground <= 0:
                self.fail("ground", f"must be positive, got {ground}")
            pairs = tuple(AnglePair(self.angle(t.get("input"), f"pairs[{i}].input"),
                                    self.angle(t.get("output"), f"pairs[{i}].output"))
                          for i, t in enumerate(self.tables(data, "pairs", keys={"input", "output"})))
            return attrs.evolve(task, pairs=pairs, unknown_start=unknown_start, ground=ground)
        pivots = data.get("pivots")
        if not isinstance(pivots, dict) or set(pivots) != {"crank", "rocker"}:
            self.fail("pivots", 'expected { crank = [x, y], rocker = [x, y] }')
        points = tuple(self.point(t, f"points[{i}]") for i, t in enumerate(self.tables(data, "points", keys={"x", "y"})))
        return attrs.evolve(task, pivots=(self.pair(pivots["crank"], "pivots.crank"),
                                          self.pair(pivots["rocker"], "pivots.rocker")), points=points)

    def tables(self, data: Table, key: str, *, keys: set[str] | None = None) -> list[Table]:
        found = data.get(key)
        if not isinstance(found, list) or not all(isinstance(t, dict) for t in found):
            self.fail(key, f"expected a list of tables ([[{key}]]), got {found!r}")
        for index, table in enumerate(found):
            for extra in set(table) - (keys or {"x", "y", "angle"}):
                self.fail(f"{key}[{index}].{extra}", "unknown key" + suggest.known(extra, sorted(keys or {"x", "y", "angle"}),
                                                                                   plural="valid"))
        return found

    def pose(self, table: Table, element: str) -> Pose:
        x, y = self.point(table, element)
        return Pose(x, y, self.angle(table.get("angle"), f"{element}.angle"))

    def point(self, table: Table, element: str) -> Point:
        for key in ("x", "y"):
            if key not in table:
                self.fail(f"{element}.{key}", "missing")
        return self.number(table["x"], f"{element}.x"), self.number(table["y"], f"{element}.y")

    def pair(self, value: object, element: str) -> Point:
        if not isinstance(value, list) or len(value) != 2:
            self.fail(element, f"expected [x, y], got {value!r}")
        return self.number(value[0], f"{element}[0]"), self.number(value[1], f"{element}[1]")

    def number(self, value: object, element: str) -> flint.fmpq:
        if isinstance(value, bool) or not isinstance(value, (int, str)):
            self.fail(element, f"expected an exact number (3, \"3/5\", 0.25), got {value!r}")
        try:
            rational = exact_number(str(value))
        except (ValueError, ZeroDivisionError) as err:
            self.fail(element, f"not an exact number: {err}")
        return flint.fmpq(int(rational.p), int(rational.q))

    def angle(self, value: object, element: str) -> Angle:
        if value is None:
            self.fail(element, "missing")
        if not isinstance(value, Mapping):
            degrees = self.number(value, element)
            return Angle.of_degrees(degrees)
        if set(value) == {"tan_half"}:
            return Angle.of_tan_half(self.number(value["tan_half"], f"{element}.tan_half"))
        if set(value) != {"cos", "sin"}:
            self.fail(element, 'expected a number of degrees, { cos = "3/5", sin = "4/5" } or { tan_half = "1/2" }')
        cos, sin = self.number(value["cos"], f"{element}.cos"), self.number(value["sin"], f"{element}.sin")
        try:
            return Angle.of_cos_sin(cos, sin)
        except ValueError as err:
            self.fail(element, str(err))
