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

from .constructions import Construction, Crank, Dyad, Fixed, Frame, Meet, Mode, Slider, Unknown
from .driven import root_of
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
        return (f"crank = {_string(construction.center)}, length = {_string(construction.length)}, "
                f"input = {_string(construction.input)}, phase = {phase_text(construction, scene)}")
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
    if isinstance(construction, Meet):
        return f"meet = [{_exprs(construction.lines[0])}, {_exprs(construction.lines[1])}]"
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


def phase_text(crank: Crank, scene: Scene) -> str:
    """A crank's phase as the file writes it: degrees for a quarter turn of a crank in degrees, 0 for
    none, else its exact ``{ cos = ..., sin = ... }``.

    >>> from algkin.scene import load_scene
    >>> phase_text(load_scene("arm-string").points["A"], load_scene("arm-string"))
    '-90'
    """
    unit = scene.inputs[root_of(scene, crank.input)[0]].unit
    turns = crank.quarter_turns
    if turns is not None and (unit == "deg" or turns == 0):
        return str([0, 90, 180, -90][turns])
    return f"{{ cos = {_string(crank.phase[0])}, sin = {_string(crank.phase[1])} }}"


def _parameter(name: str, value: object, bounds: Iterable[object] | None) -> str:
    """``a = 1``, or ``a = { default = 1, range = [lo, hi] }`` when a range is declared."""
    if bounds is None:
        return f"{name} = {_string(value)}"
    return f"{name} = {{ default = {_string(value)}, range = {_exprs(bounds)} }}"


def dump_scene(scene: Scene) -> str:
    """TOML text of ``scene``; ``load_scene_text(dump_scene(scene)) == scene``."""
    lines = [f"name = {_string(scene.name)}", f"description = {_string(scene.description)}"]
    lines += [f"unit = {_string(scene.unit)}"] if scene.unit else []
    lines += ["", "[parameters]"]
    lines += [_parameter(name, value, scene.parameter_ranges.get(name)) for name, value in scene.parameters.items()]
    lines += ["", "[inputs]"]
    lines += [f"{name} = {{ range = {_exprs((i.lo, i.hi))}, unit = {_string(i.unit)} }}"
              for name, i in scene.inputs.items()]
    lines += [f"{name} = {{ driven_by = {_string(d.driver)}, ratio = {_string(d.ratio)} }}"
              for name, d in scene.driven.items()]
    lines += ["", "[points]"]
    lines += [f"{name} = {{ {_point(c, scene)} }}" for name, c in scene.points.items()]
    if scene.constraints:
        lines += ["", "[constraints]"]
        lines += [f"{name} = {_string(c.text)}" for name, c in scene.constraints.items()]
    lines += ["", "[outputs]"]
    lines += [f"{name} = {_string(output.text)}" for name, output in scene.outputs.items()]
    return "\n".join(lines) + "\n"
