r"""A self-contained interactive page: sliders move the mechanism in the browser, no Python behind it.

The page is one HTML file with inline CSS, JavaScript and SVG (no server, no network).
Each branch's closed forms (derived once, dimensions symbolic) are printed as a
JavaScript function (``algkin.ui.html.jscode``); sliders for every input and symbolic
dimension call them, the trajectory is swept the same way, and where a discriminant is
negative the page says the configuration cannot assemble. The drawn positions are
written to ``<output id="state" data-positions=...>`` and to each joint's circle, and the
page reads starting slider values from its URL query (``page.html?angle=30&l=2``), so a
headless browser can check it.

>>> from algkin.analyses.motion import Motion
>>> text = page(Motion("chebyshev-lambda"))
>>> text.startswith("<!DOCTYPE html>") and "src=" not in text and "<link" not in text
True
>>> import re   # the only address is SVG's namespace name, which is never fetched
>>> sorted(set(re.findall(r'https?://[^"\s]+', text)))
['http://www.w3.org/2000/svg']

Text from the scene is escaped wherever it lands: HTML-escaped in the markup, its control
and bidi characters written out (``markup``), and in the script's JSON no ``<``, ``>`` or ``&`` that could close the script or open a comment.
The template is filled in one pass, so a slot's text is never read as another slot.

>>> fill("<p>{{a}} {{b}}</p>", {"a": "{{b}}", "b": "x"})
'<p>{{b}} x</p>'
>>> script_json({"name": "</script><!--"})
'{"name": "\\u003c/script\\u003e\\u003c!--"}'
"""

from __future__ import annotations

import html
import json
import os
import re
from collections.abc import Mapping
from importlib import resources
from typing import TYPE_CHECKING, TypedDict, TypeVar, Union

import sympy

from ...runtime.files import write_atomic
from ...runtime.terminal import one_line, terminal_safe
from ...scene import Scene
from ...scene.constructions import Dyad
from ...system import symbol
from .jscode import branch_function

if TYPE_CHECKING:
    from ...analyses.motion import Motion

_PathT = TypeVar("_PathT", bound=Union[str, "os.PathLike[str]"])  # a path given back as it came
Ranges = Mapping[str, tuple[float, float]]  # a dimension's slider bounds, by name

__all__ = ["page", "document", "model", "slider_range", "parameter_range", "parameter_slider", "write", "markup", "fill",
           "script_json", "Slider"]

_SLOT = re.compile(r"\{\{(\w+)\}\}")
# Inside <script>, "<" could close the element or open a comment, and U+2028/U+2029 end a
# line in older JavaScript; the control characters JSON leaves raw (DEL, C1) and the bidi marks are
# written out as in the markup (``markup``). All as \uXXXX escapes, which JSON reads back the same.
_SCRIPT_UNSAFE = re.compile("[<>&\x7f-\x9f\u061c\u200e\u200f\u2028\u2029\u202a-\u202e\u2066-\u2069]")


class Slider(TypedDict):
    """A slider: what it moves, its bounds and where it starts."""

    name: str
    lo: float
    hi: float
    value: float


def slider_range(default: float) -> tuple[float, float]:
    """Slider bounds around a dimension's default: a quarter to twice it (either sign)."""
    if default == 0:
        return -1.0, 1.0
    lo, hi = sorted((default / 4, 2 * default))
    return lo, hi


def parameter_range(motion: Motion, name: str, ranges: Ranges | None = None) -> tuple[float, float]:
    """A dimension's slider bounds: given in ``ranges`` (name -> (lo, hi)), else declared in the
    scene, else around its default."""
    from ...errors import UsageError

    for given in (ranges or {}):
        if given not in motion.params:
            raise UsageError("ranges", given, f"not a symbolic dimension of {motion.scene.name} "
                                                  f"(symbolic: {', '.join(motion.params) or 'none'})")
    if ranges and name in ranges:
        from ...scene.compile import refuse_lengths_not_positive

        refuse_lengths_not_positive(motion.scene, name, ranges[name], argument="ranges")
        return (float(ranges[name][0]), float(ranges[name][1]))
    declared = motion.scene.parameter_ranges.get(name)
    if declared is None:
        return slider_range(motion.defaults[name])
    bounds = (float(declared[0]), float(declared[1]))
    _refuse_declared_lengths_not_positive(motion.scene, name, bounds)
    return bounds


def _refuse_declared_lengths_not_positive(scene: Scene, name: str, bounds: tuple[float, float]) -> None:
    """A range the scene file declares for a length, reaching zero or below: the file's error."""
    from ...errors import SceneError
    from ...scene.compile import length_not_positive

    found = length_not_positive(scene, name, bounds)
    if found is not None:
        length, value, end = found
        raise SceneError(scene.source, f"parameters.{name}.range",
                         f"the length {length} would be {value} at {name} = {end:g}; a length must be positive")


def parameter_slider(motion: Motion, name: str, ranges: Ranges | None = None) -> Slider:
    """A symbolic dimension's slider, ``{name, lo, hi, value}``: its bounds (``parameter_range``)
    and its default.

    >>> from algkin.analyses.motion import Motion
    >>> parameter_slider(Motion("fourbar", ["a"]), "a", {"a": (1, 3)})
    {'name': 'a', 'lo': 1.0, 'hi': 3.0, 'value': 1.0}
    """
    lo, hi = parameter_range(motion, name, ranges)
    return {"name": name, "lo": lo, "hi": hi, "value": motion.defaults[name]}


def model(motion: Motion, inputs: Mapping[str, float] | None = None, branch: str | None = None,
          ranges: Ranges | None = None) -> dict[str, object]:
    """The page's data: sliders, points, bars, branches (everything but the closed forms)."""
    names = list(motion.points[0])
    starts, _ = motion.complete(inputs or motion.start(branch=branch))
    return {
        "scene": motion.scene.name,
        "description": motion.scene.description,
        "inputs": [{"name": n, "lo": s.span[0], "hi": s.span[1], "value": starts[n], "angle": s.is_angle}
                   for n, s in motion.inputs.items()],
        "params": [parameter_slider(motion, p, ranges) for p in motion.params],
        "branches": [{"label": b.label, "selected": b.selected, "blocks": list(b.discriminants)}
                     for b in motion.branches],
        "start": motion.branch_index(branch),
        "points": names,
        "bars": [[names.index(p), names.index(q)] for p, q in motion.bars],
        "strings": [[names.index(p), names.index(q)] for p, q in motion.strings],
        "guides": [[names.index(p), names.index(t), dx, dy] for p, t, (dx, dy) in motion.guides],
        "ground": [names.index(g) for g in motion.ground if g not in motion.anchors],
        "anchors": [names.index(g) for g in motion.anchors],  # a slider's line placed: its rail drawn, no pivot
        "length_unit": motion.scene.unit,  # the scene's ``unit`` of length ("" when not said)
        "traced": [names.index(t) for t in motion.traced],
        # where a dyad cannot assemble its two circles are drawn: its point, its bases, its radii as written
        "dyads": [[names.index(n), names.index(c.bases[0]), names.index(c.bases[1]), *map(str, c.lengths)]
                  for n, c in _dyads(motion)],
    }


def _dyads(motion: Motion) -> list[tuple[str, Dyad]]:
    return [(n, c) for n, c in motion.scene.points.items() if isinstance(c, Dyad)]


def _radii(motion: Motion) -> list[tuple[sympy.Expr, sympy.Expr]]:
    """Each dyad's two radii, in the page's variables (a dimension that is not one at its value):
    computed after the points, as extra pairs the page reads only where a dyad fails."""
    fixed = {symbol(n): v for n, v in motion.compiled.parameter_values.items() if n not in motion.params}
    return [(sympy.sympify(a).xreplace(fixed), sympy.sympify(b).xreplace(fixed)) for _, c in _dyads(motion)
            for a, b in [c.lengths]]


def _functions(motion: Motion) -> list[str]:
    variables = [name for pair in motion.compiled.system.inputs.values() for name in pair] + list(motion.params)
    return [branch_function(list(b.discriminants.values()), [*forms.values(), *_radii(motion)], variables)
            for b, forms in zip(motion.branches, motion.points)]


def page(motion: Motion, inputs: Mapping[str, float] | None = None, branch: str | None = None,
         ranges: Ranges | None = None) -> str:
    """The HTML text of the interactive page for ``motion`` (a ``Motion``)."""
    data = script_json(model(motion, inputs, branch, ranges))
    return document(motion.scene, f"const MODEL = {data};\nconst BRANCHES = [\n" + ",\n".join(_functions(motion))
                    + "];\n", "page.js")


def document(scene: Scene, data: str, script: str) -> str:
    """The HTML text of an interactive page of ``scene``: ``data`` (its JavaScript constants), the
    JavaScript every page shares (``draw.js``), then the page's own, ``script`` (a file beside it)."""
    folder = resources.files(__name__)
    code = data + "".join(folder.joinpath(name).read_text(encoding="utf-8") for name in ("draw.js", script))
    return fill(folder.joinpath("page.html").read_text(encoding="utf-8"), {
        "title": markup(f"algkin: {scene.name}", line=True),
        "description": markup(scene.description),
        "style": folder.joinpath("page.css").read_text(encoding="utf-8"),
        "script": code,
    })


def markup(text: str, *, line: bool = False) -> str:
    r"""Scene text as a page shows it: HTML-escaped, its control and bidi characters written out as on a
    terminal (``terminal_safe``; with ``line``, for a title, its newlines and tabs too: ``one_line``),
    never raw bytes in the page.

    >>> markup("<b>four\x1b[31mbar\x00\nx</b>", line=True)
    '&lt;b&gt;four\\x1b[31mbar\\x00\\nx&lt;/b&gt;'
    """
    return html.escape(one_line(text) if line else terminal_safe(text), quote=True)


def fill(template: str, slots: Mapping[str, str]) -> str:
    """``template`` with each ``{{key}}`` replaced by ``slots[key]``, in a single pass."""
    return _SLOT.sub(lambda match: slots[match.group(1)], template)


def script_json(value: object) -> str:
    """``value`` as JSON that can sit inside ``<script>``: nothing in it ends the element."""
    text = json.dumps(value, ensure_ascii=False)
    return _SCRIPT_UNSAFE.sub(lambda match: f"\\u{ord(match.group()):04x}", text)


def write(motion: Motion, out: _PathT, inputs: Mapping[str, float] | None = None, branch: str | None = None,
          ranges: Ranges | None = None) -> _PathT:
    """Write the page to ``out``, replacing any earlier file only once complete; returns ``out``."""
    write_atomic(out, page(motion, inputs, branch, ranges))
    return out
