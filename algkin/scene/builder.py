"""Scenes from Python: each table of a scene file is one ``SceneBuilder`` call.

The builder writes down the data a scene file parses to (tables as dicts, arrays as
lists, floats as the decimals they spell) and hands it to the loader's own checks: a
built scene equals the one loaded from the same TOML, dumps and loads back equal, and a
mistake raises the same one-line ``SceneError``, at ``build()``. A name given twice in a
table (a TOML syntax error in a file) is refused at once, by the call that repeats it.

Each call takes the table's keys by their TOML names; the construction's own key comes
first. ``B = { dyad = ["A", "D"], lengths = ["5/2", "5/2"], branch = "left" }`` is
``b.dyad("B", ["A", "D"], lengths=["5/2", "5/2"], branch="left")``, or generically
``b.point("B", dyad=["A", "D"], lengths=...)``. Expressions are strings or numbers as in a
file, or exact Python numbers (``Fraction``, ``Decimal``, sympy), numpy's numbers too; tuples
and numpy arrays do for arrays.

>>> from algkin.scene import load_scene
>>> b = SceneBuilder("chebyshev-lambda", "Chebyshev lambda linkage: crank 1, ground 2, rocker 5/2, coupler 5.",
...                  unit="mm")
>>> b.input("angle", range=(0, 360), unit="deg")
>>> b.fixed("O", (0, 0))
>>> b.fixed("D", (2, 0))
>>> b.crank("A", "O", length=1, input="angle")
>>> b.dyad("B", ("A", "D"), lengths=(Fraction(5, 2), "5/2"), branch="left")
>>> b.frame("P", ("A", "B"), at=(2.0, 0))
>>> b.output("P")
>>> b.build() == load_scene("chebyshev-lambda")
True
>>> b.dyad("Q", ("A", "X"), lengths=(1, 1))
>>> b.build()
Traceback (most recent call last):
...
algkin.errors.SceneError: chebyshev-lambda: points.Q.dyad: unknown point 'X'
>>> b.fixed("O", (1, 1))
Traceback (most recent call last):
...
algkin.errors.SceneError: chebyshev-lambda: points.O: given twice (a table names each entry once)
"""

from __future__ import annotations

import copy
import numbers
from collections.abc import Mapping, Sequence
from decimal import Decimal
from fractions import Fraction
from typing import Any, Union

import sympy

from ..errors import SceneError
from .load import float_text, scene_from_data
from .model import Scene

__all__ = ["SceneBuilder"]

# What an expression may be given as; anything else reaches the loader, which refuses it
# with the message a file would get.
Expr = Union[str, int, float, Fraction, sympy.Expr]
Pair = Sequence[Expr]

_TABLES = ("parameters", "inputs", "points", "constraints", "outputs")


def _data(value: object) -> object:
    """``value`` as ``tomllib`` would give it: exact numbers as their text, arrays as lists."""
    if isinstance(value, bool):  # before Integral: a TOML true is refused by the loader, so is True
        return value
    if isinstance(value, sympy.Basic):
        return str(value)  # sympy prints what the expression language reads back (see dump.py)
    if isinstance(value, numbers.Integral):
        return int(value)
    if isinstance(value, numbers.Rational):
        return f"{value.numerator}/{value.denominator}"
    if isinstance(value, numbers.Real):  # float, numpy's floats: the decimal repr spells, as in a file
        return float_text(float(value))
    if isinstance(value, Decimal) and value.is_finite():
        return str(value)  # exactly the decimal it spells, as the expression language reads it ('1E+3' too)
    if isinstance(value, (list, tuple)):
        return [_data(item) for item in value]
    if getattr(value, "ndim", 0) == 1 and hasattr(value, "tolist"):  # a numpy array for a pair
        return _data(value.tolist())
    if isinstance(value, Mapping):
        return {str(key): _data(item) for key, item in value.items()}
    return value


def _given(table: Mapping[str, object]) -> dict[str, object]:
    """The keys given: None stands for a key left out (TOML has no null), so defaults apply."""
    return {key: value for key, value in table.items() if value is not None}


class SceneBuilder:
    """A scene written in Python, one call per table of the scene file; ``build()`` checks it.

    ``source`` names the scene in errors (a file's name does for a file); the scene's name
    by default. The calls and the table each one writes: docs/scene-format.md, "From Python".
    """

    def __init__(self, name: str, description: str = "", *, source: str | None = None, unit: str = "") -> None:
        self.name = name
        self.description = description
        self.unit = unit  # the lengths' unit, ``unit = "mm"``
        self.source = source if source is not None else (name if isinstance(name, str) and name else "<scene>")
        self._tables: dict[str, dict[str, object]] = {table: {} for table in _TABLES}

    def parameter(self, name: str, default: Expr, *, range: Pair | None = None, **extra: Any) -> None:
        """``a = 1``, or ``a = { default = 1, range = [lo, hi] }`` with a ``range``."""
        plain = range is None and not extra
        self._add("parameters", name, default if plain else _given({"default": default, "range": range, **extra}))

    def input(self, name: str, *, range: Pair | None = None, unit: str | None = None,
              **extra: Any) -> None:
        """``t = { range = [lo, hi], unit = "deg" }``; left out, each takes the file's default."""
        self._add("inputs", name, _given({"range": range, "unit": unit, **extra}))

    def point(self, name: str, **table: Any) -> None:
        """A point as its table: ``point("A", crank="O", length=1, input="t")``."""
        self._add("points", name, _given(table))

    def fixed(self, name: str, fixed: Pair, **extra: Any) -> None:
        """``P = { fixed = [x, y] }``."""
        self.point(name, fixed=fixed, **extra)

    def crank(self, name: str, crank: str, *, length: Expr | None = None, input: str | None = None,
              phase: Expr | None = None, **extra: Any) -> None:
        """``A = { crank = "O", length = L, input = "t", phase = 90 }``."""
        self.point(name, crank=crank, length=length, input=input, phase=phase, **extra)

    def dyad(self, name: str, dyad: Sequence[str], *, lengths: Pair | None = None, branch: str | None = None,
             **extra: Any) -> None:
        """``B = { dyad = ["A", "D"], lengths = [l1, l2], branch = "left" }``."""
        self.point(name, dyad=dyad, lengths=lengths, branch=branch, **extra)

    def frame(self, name: str, frame: Sequence[str], *, at: Pair | None = None, **extra: Any) -> None:
        """``P = { frame = ["A", "B"], at = [u, v] }``."""
        self.point(name, frame=frame, at=at, **extra)

    def slider(self, name: str, slider: Mapping[str, Any], *, distance: Mapping[str, Any] | None = None,
               branch: str | None = None, **extra: Any) -> None:
        """``B = { slider = { through = "L", direction = [1, 0] }, distance = { to = "A", length = "l" },
        branch = "ahead" }``: the two sub-tables as mappings, e.g. ``dict(through="L", direction=(1, 0))``,
        or ``dict(through="C", toward="A")`` for the line through two points (a key given as None is
        left out, so ``dict(through=P, direction=None, toward="A")`` is the line toward A)."""
        line = _given(slider) if isinstance(slider, Mapping) else slider
        self.point(name, slider=line, distance=distance, branch=branch, **extra)

    def meet(self, name: str, meet: Sequence[Sequence[str]], **extra: Any) -> None:
        """``I = { meet = [["O", "A"], ["D", "B"]] }``: where the line OA meets the line DB."""
        self.point(name, meet=meet, **extra)

    def unknown(self, name: str, unknown: bool = True, **extra: Any) -> None:
        """``P1 = { unknown = true }``: a point solved together with others, held by constraints."""
        self.point(name, unknown=unknown, **extra)

    def constraint(self, name: str, text: str) -> None:
        """``leg1 = "dist(A1, P1) = r1"`` in ``[constraints]`` (also ``dist(P, Q)**2 = L2``, ``on(P, line(A, B))``)."""
        self._add("constraints", name, text)

    def output(self, name: str, text: str | None = None) -> None:
        """``AB = "dist(A, B)"``; without ``text``, the point of the same name (``P = "P"``)."""
        self._add("outputs", name, name if text is None else text)

    def data(self) -> dict[str, Any]:
        """The scene as a parsed scene file: what ``build()`` checks (a copy)."""
        tables = {table: rows for table, rows in copy.deepcopy(self._tables).items() if rows or table != "constraints"}
        unit = {"unit": self.unit} if self.unit else {}
        return {"name": self.name, "description": self.description, **unit, **tables}

    def build(self) -> Scene:
        """The ``Scene``, checked as a loaded file is (``SceneError`` on the first problem)."""
        scene: Scene = scene_from_data(self.data(), self.source)
        return scene

    def _add(self, table: str, name: str, value: object) -> None:
        # A dict keeps one value per key: the repeat is caught here, where a file's parser catches it.
        element = f"{table}.{name}"
        if not isinstance(name, str):
            raise SceneError(self.source, element, f"a name is a string, got {type(name).__name__}")
        if name in self._tables[table]:
            raise SceneError(self.source, element, "given twice (a table names each entry once)")
        self._tables[table][name] = _data(value)
