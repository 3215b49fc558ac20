"""Exact values given to a scene's dimensions from outside the file (``--set a=3/2``, ``set={"a": "3/2"}``).

>>> from algkin.scene import load_scene
>>> scene = with_values(load_scene("arm-string"), {"b": "0.1"})
>>> scene.parameters["b"]
1/10
>>> with_values(scene, {"zz": 1})
Traceback (most recent call last):
...
algkin.errors.UsageError: set='zz=1': not a parameter of arm-string (parameters: a, b, r, g)
"""

import dataclasses
from collections.abc import Iterable, Mapping
from fractions import Fraction

import sympy

from ..errors import UsageError
from .expr import parse
from .model import Scene

__all__ = ["with_values", "parse_settings"]


def parse_settings(texts: Iterable[str] | None) -> dict[str, str]:
    """``{name: value text}`` from the command line's ``NAME=VALUE`` strings (the last of a name wins)."""
    values: dict[str, str] = {}
    for text in texts or ():
        name, equals, value = text.partition("=")
        if not equals or not name.strip() or not value.strip():
            raise UsageError("set", text, "expected NAME=VALUE, e.g. a=3/2")
        values[name.strip()] = value.strip()
    return values


def with_values(scene: Scene, values: Mapping[str, object] | None, params: Iterable[str] | None = ()) -> Scene:
    """A new ``Scene``: ``scene`` with the defaults of the parameters in ``values`` replaced, checked again.

    Values are exact: strings in the scene files' expression language (``"3/2"``, ``"0.1"`` is
    1/10, ``"sqrt(2)"``), integers, fractions or sympy rationals; a float is read as the decimal
    its shortest repr spells. A parameter that ``params`` keeps symbolic cannot also be set.
    The new scene goes through the loader again, so that a value which breaks it (a length
    that becomes negative...) fails as a scene file would.
    """
    if not values:
        return scene
    if not isinstance(values, dict):
        raise UsageError("set", values, "expected a mapping of parameter names to values")
    defaults = dict(scene.parameters)
    for name, value in values.items():
        if name not in defaults:
            raise UsageError("set", f"{name}={value}", f"not a parameter of {scene.name} "
                             f"(parameters: {', '.join(defaults) or 'none'})")
        if name in (params or ()):
            raise UsageError("set", f"{name}={value}", f"{name} is also kept symbolic; give a value or keep it symbolic, not both")
        defaults[name] = _exact(name, value)
    from .load import as_scene

    return as_scene(dataclasses.replace(scene, parameters=defaults))


def _exact(name: str, value: object) -> sympy.Expr:
    """``value`` as an exact sympy number, read by the scene files' own parser (never eval)."""
    if isinstance(value, float):
        value = repr(value)
    elif isinstance(value, (Fraction, sympy.Rational)):
        value = f"{value.numerator}/{value.denominator}"
    try:
        return parse(value)
    except ValueError as err:
        raise UsageError("set", f"{name}={value}", str(err)) from None
