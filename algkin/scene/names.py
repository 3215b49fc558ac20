"""Names algkin generates beside the scene's own, kept apart from them.

A point ``P`` brings the variables ``P_x`` and ``P_y``, an input ``t`` the pair ``c_t``,
``s_t`` (and ``t_t``, its half-angle tangent, where an extremum is sought), and a
distance output its own name as an unknown, an angle output ``phi`` the unknowns
``cos_phi`` (and ``sin_phi`` for a direction; ``len_phi`` where a side's length varies). A parameter or output that takes one of
those names, or two generated names that coincide (a point ``c`` and an input ``x`` both
give ``c_x``), would silently merge two variables into one: that is bad input. So is a
symbol name that ``sympy.parse_expr`` reads back as something else (``E``, ``I``,
``lambda``), since the expression strings in ``--json`` must read back as written.

>>> from algkin.scene import load_scene_text
>>> load_scene_text('[parameters]\\nB_x = 1\\n[points]\\nB = { fixed = [0, 0] }', "s.toml")
Traceback (most recent call last):
...
algkin.errors.SceneError: s.toml: parameters.B_x: the name 'B_x' is taken by the x coordinate of point B
>>> misread("E"), misread("lambda"), misread("e")
(True, True, False)
"""

import keyword
from collections.abc import Mapping
from functools import lru_cache

from ..errors import SceneError
from .model import Output, Scene

__all__ = ["generated_names", "check_names", "check_symbol_name", "check_output_unknowns", "misread", "angle_unknowns"]


@lru_cache(maxsize=1)
def _sympy_namespace() -> frozenset[str]:
    import sympy

    return frozenset(sympy.__all__)  # what ``parse_expr`` sees: ``from sympy import *``


def misread(name: str) -> bool:
    """Whether ``sympy.parse_expr(name)`` gives something other than the symbol ``name``."""
    return keyword.iskeyword(name) or name in _sympy_namespace()


def generated_names(scene: Scene) -> dict[str, str]:
    """Every variable name algkin makes for ``scene``, with what it stands for."""
    made: dict[str, str] = {}
    owners = [(f"{p}_{axis}", f"the {axis} coordinate of point {p}", f"points.{p}")
              for p in scene.points for axis in "xy"]
    owners += [(f"{prefix}_{t}", f"the {what} of input {t}", f"inputs.{t}")
               for t, given in scene.inputs.items() if given.is_angle for prefix, what in
               (("c", "cosine"), ("s", "sine"), ("t", "half-angle tangent"))]
    owners += [(t, f"the length input {t}", f"inputs.{t}") for t, given in scene.inputs.items() if not given.is_angle]
    for name, meaning, element in owners:
        if name in made:
            raise SceneError(scene.source, element,
                             f"generates the variable {name!r}, which is already {made[name]}; rename one of them")
        made[name] = meaning
    return made


def check_symbol_name(source: str, element: str, name: str, generated: Mapping[str, str]) -> None:
    """Refuse a user name that would stand for a generated variable or read back wrongly."""
    if name in generated:
        raise SceneError(source, element, f"the name {name!r} is taken by {generated[name]}")
    _refuse_misread(source, element, name)


def _refuse_misread(source: str, element: str, name: str) -> None:
    if misread(name):
        what = "a Python keyword" if keyword.iskeyword(name) else f"sympy's {name}"
        raise SceneError(source, element, f"the name {name!r} would read back as {what}, not as a symbol, "
                                          "from expression strings; choose another")


def angle_unknowns(name: str, output: Output) -> tuple[str, ...]:
    """The unknowns an angle output named ``name`` may bring: ``cos_<name>``, for a direction
    ``sin_<name>`` too, and ``len_<name>``, the length its cosine is divided by where that is
    not a constant of the mechanism (a helper, known to be >= 0).

    >>> from algkin.scene.load import parse_output
    >>> angle_unknowns("phi", parse_output("phi", "angle(D, B)", "DB"))
    ('cos_phi', 'sin_phi', 'len_phi')
    """
    direction = len(output.points) == 2
    return (f"cos_{name}",) + ((f"sin_{name}",) if direction else ()) + (f"len_{name}",)


def check_output_unknowns(source: str, element: str, unknowns: tuple[str, ...], *, generated: Mapping[str, str],
                          parameters: Mapping[str, object], taken: dict[str, str], owner: str) -> None:
    """Refuse unknowns (of the output ``owner``) that would merge with a generated variable, a
    parameter or another output's unknown (``taken``: unknown -> its output, updated here)."""
    for unknown in unknowns:
        check_symbol_name(source, element, unknown, generated)
        if unknown in parameters:
            raise SceneError(source, element, f"its unknown {unknown!r} is the name of a parameter; rename one")
        if taken.get(unknown, owner) != owner:
            raise SceneError(source, element, f"its unknown {unknown!r} is already an unknown of output "
                                              f"{taken[unknown]!r}; rename one")
        taken[unknown] = owner


def check_names(scene: Scene) -> dict[str, str]:
    """Raise SceneError if any scene name collides with a generated one (see the module doc)."""
    generated = generated_names(scene)
    for name, given in scene.inputs.items():
        if not given.is_angle:  # a length input is a variable of its own name
            _refuse_misread(scene.source, f"inputs.{name}", name)
    for name in scene.parameters:
        check_symbol_name(scene.source, f"parameters.{name}", name, generated)
    taken: dict[str, str] = {}
    for name, output in scene.outputs.items():
        element = f"outputs.{name}"
        if output.kind == "dist":
            check_symbol_name(scene.source, element, name, generated)
            check_output_unknowns(scene.source, element, (name,), generated=generated, parameters=scene.parameters,
                                  taken=taken, owner=name)
        elif output.kind == "angle":
            check_output_unknowns(scene.source, element, angle_unknowns(name, output), generated=generated,
                                  parameters=scene.parameters, taken=taken, owner=name)
        elif name in generated and name != _coordinate_name(output):
            raise SceneError(scene.source, element, f"the name {name!r} is taken by {generated[name]}")
    return generated


def _coordinate_name(output: Output) -> str | None:
    """The variable an ``P.x``/``P.y`` output stands for (None for other kinds)."""
    return f"{output.points[0]}_{output.kind}" if output.kind in ("x", "y") else None
