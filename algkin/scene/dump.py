"""Write a scene back as TOML text that ``load_scene_text`` reads into an equal scene.

Expressions are written as sympy prints them, which the scene's expression language
reads back to the same expression (``+ - * / **``, ``sqrt``, exact rationals).

>>> from algkin.scene import load_scene, load_scene_text
>>> scene = load_scene("slider-crank")
>>> print(next(line for line in dump_scene(scene).splitlines() if line.startswith("B =")))
B = { slider = { through = "L", direction = ["1", "0"] }, distance = { to = "A", length = "l" }, branch = "ahead" }
>>> load_scene_text(dump_scene(scene)) == scene
True
"""

import json
from collections.abc import Iterable

from .constructions import Construction, Crank, Dyad, Fixed, Frame, Mode, Slider, Unknown
from .model import Scene

__all__ = ["dump_scene"]


def _string(text: object) -> str:
    # A JSON string is a TOML basic string, except that TOML wants DEL escaped too.
    return json.dumps(str(text), ensure_ascii=False).replace("\x7f", "\\u007f")


def _exprs(values: Iterable[object]) -> str:
    return "[" + ", ".join(_string(v) for v in values) + "]"


def _point(construction: Construction, scene: Scene) -> str:
    if isinstance(construction, Fixed):
        return f"fixed = {_exprs((construction.x, construction.y))}"
    if isinstance(construction, Crank):
        unit = scene.inputs[construction.input].unit
        phase = construction.quarter_turns * 90 if unit == "deg" else 0
        return (f"crank = {_string(construction.center)}, length = {_string(construction.length)}, "
                f"input = {_string(construction.input)}, phase = {phase}")
    if isinstance(construction, Dyad):
        return (f"dyad = {_exprs(construction.bases)}, lengths = {_exprs(construction.lengths)}, "
                f"{_branch(construction.branch, construction.mode)}")
    if isinstance(construction, Frame):
        return f"frame = {_exprs(construction.bases)}, at = {_exprs(construction.at)}"
    if isinstance(construction, Slider):
        line = f"toward = {_string(construction.toward)}" if construction.direction is None \
            else f"direction = {_exprs(construction.direction)}"
        return (f"slider = {{ through = {_string(construction.through)}, {line} }}, "
                f"distance = {{ to = {_string(construction.to)}, length = {_string(construction.length)} }}, "
                f"{_branch(construction.branch, construction.mode)}")
    if isinstance(construction, Unknown):
        return "unknown = true" + (f", {_branch('', construction.mode)}" if construction.mode else "")
    raise TypeError(f"no TOML form for a {type(construction).__name__} construction")


def _branch(branch: str, mode: Mode | None) -> str:
    """``branch = "left"``, or the ``mode = { at = .., near = [..] }`` that names it."""
    if mode is None:
        return f"branch = {_string(branch)}"
    at = _string(mode.at[0][1]) if len(mode.at) == 1 else \
        "{ " + ", ".join(f"{name} = {_string(value)}" for name, value in mode.at) + " }"
    return f"mode = {{ at = {at}, near = {_exprs(mode.near)} }}"


def _parameter(name: str, value: object, bounds: Iterable[object] | None) -> str:
    """``a = 1``, or ``a = { default = 1, range = [lo, hi] }`` when a range is declared."""
    if bounds is None:
        return f"{name} = {_string(value)}"
    return f"{name} = {{ default = {_string(value)}, range = {_exprs(bounds)} }}"


def dump_scene(scene: Scene) -> str:
    """TOML text of ``scene``; ``load_scene_text(dump_scene(scene)) == scene``."""
    lines = [f"name = {_string(scene.name)}", f"description = {_string(scene.description)}", "",
             "[parameters]"]
    lines += [_parameter(name, value, scene.parameter_ranges.get(name)) for name, value in scene.parameters.items()]
    lines += ["", "[inputs]"]
    lines += [f"{name} = {{ range = {_exprs((i.lo, i.hi))}, unit = {_string(i.unit)} }}"
              for name, i in scene.inputs.items()]
    lines += ["", "[points]"]
    lines += [f"{name} = {{ {_point(c, scene)} }}" for name, c in scene.points.items()]
    if scene.constraints:
        lines += ["", "[constraints]"]
        lines += [f"{name} = {_string(c.text)}" for name, c in scene.constraints.items()]
    lines += ["", "[outputs]"]
    lines += [f"{name} = {_string(output.text)}" for name, output in scene.outputs.items()]
    return "\n".join(lines) + "\n"
