"""Exact values given to a scene's dimensions from outside the file (``--set a=3/2``, ``set={"a": "3/2"}``).

>>> from algkin.scene import load_scene
>>> scene = with_values(load_scene("arm-string"), {"b": "0.1"})
>>> scene.parameters["b"]
1/10
>>> with_values(scene, {"zz": 1})
Traceback (most recent call last):
...
algkin.errors.UsageError: set='zz=1': not a parameter of arm-string (parameters: a, b, r, g)
>>> parse_settings(["a=1", "b=2", "a=1"])
Traceback (most recent call last):
...
algkin.errors.UsageError: set='a=1': a is set twice
>>> with_values(scene, {"b": 2**2000})
Traceback (most recent call last):
...
algkin.errors.UsageError: set='b=<an integer of 2001 bits>': number too large or too precise (more than 1024 bits)
"""

import math
import numbers
from collections.abc import Iterable, Mapping
from decimal import Decimal
from fractions import Fraction

import attrs
import numpy
import sympy

from ..runtime import suggest
from ..runtime.terminal import shortened
from ..runtime.validation import rational
from ..errors import UsageError
from .expr import MAX_NUMBER_BITS, irrational, parse
from .model import Scene

__all__ = ["with_values", "valued", "parse_settings"]

SHOWN = 80  # characters of a value an error line repeats
_SPACE = " \t\n\r\f\v"


def parse_settings(texts: Iterable[str] | None) -> dict[str, str]:
    """``{name: value text}`` from the command line's ``NAME=VALUE`` strings, each name once."""
    values: dict[str, str] = {}
    for text in texts or ():
        name, equals, value = text.partition("=")
        name = name.strip(_SPACE)  # ASCII spaces: a no-break space is no part of the language
        if not equals or not name or not value.strip(_SPACE):
            raise UsageError("set", _shown(text), "expected NAME=VALUE, e.g. a=3/2")
        if name in values:
            raise UsageError("set", _shown(text), f"{name} is set twice")
        values[name] = value
    return values


def with_values(scene: Scene, values: Mapping[str, object] | None, params: Iterable[str] | None = ()) -> Scene:
    """A new ``Scene``: ``scene`` with the defaults of the parameters in ``values`` replaced, checked again.

    Values are exact: strings in the scene files' expression language (``"3/2"``, ``"0.1"`` is
    1/10), integers, fractions, decimals or sympy rationals, numpy's integers too (see ``_exact``
    for their bounds); a float (numpy's too) is read as the decimal its shortest repr spells. A parameter that ``params`` keeps symbolic cannot also be set.
    The new scene goes through the loader again, so that a value which breaks it (a length
    that becomes negative...) fails as a scene file would.
    """
    if not values:
        return scene
    from .load import as_scene

    return as_scene(valued(scene, values, params))


def valued(scene: Scene, values: Mapping[str, object], params: Iterable[str] | None = ()) -> Scene:
    """``scene`` with the parameters in ``values`` given those values, checked as ``with_values``
    checks them, without going through the loader again: for a scene the loader made, the same
    scene (the loader reads a parameter's value only to parse it, as ``_exact`` does, and to refuse
    an irrational one; nothing else it checks depends on the values). A sweep's designs take it.

    >>> from algkin.scene import load_scene
    >>> scene = load_scene("arm-string")
    >>> valued(scene, {"b": "1/10"}) == with_values(scene, {"b": "1/10"})
    True
    """
    if not isinstance(values, Mapping):
        raise UsageError("set", values, "expected a mapping of parameter names to values")
    defaults = dict(scene.parameters)
    for name, value in values.items():
        if name not in defaults:
            raise UsageError("set", _given(name, value), f"not a parameter of {scene.name}"
                             + suggest.known(str(name), defaults, plural="parameters"))
        if name in (params or ()):
            raise UsageError("set", _given(name, value), f"{name} is also kept symbolic; give a value or keep it symbolic, not both")
        defaults[name] = _exact(name, value)
    return attrs.evolve(scene, parameters=defaults)


def _exact(name: str, value: object) -> sympy.Expr:
    """``value`` as an exact sympy number, read by the scene files' own parser (never eval).

    The scene is checked again as a file: a value keeps to its bounds, numerator and
    denominator of at most ``MAX_NUMBER_BITS`` bits, and ``p/q`` of at most
    ``MAX_EXPRESSION_LENGTH`` characters. An integer or fraction is measured before it is
    written out (Python writes no integer of more than 4300 digits).
    """
    if isinstance(value, Decimal):
        value = _decimal(name, value)
    if isinstance(value, (numbers.Rational, sympy.Rational)) and not isinstance(value, (bool, numpy.bool_)):
        numerator, denominator = int(value.numerator), int(value.denominator)  # numpy's integers too
        if _bits(numerator, denominator) > MAX_NUMBER_BITS:
            raise UsageError("set", _given(name, value),
                             f"number too large or too precise (more than {MAX_NUMBER_BITS} bits)")
        value = f"{numerator}/{denominator}"
    elif isinstance(value, (float, numpy.floating)):
        if not math.isfinite(value):  # its repr 'nan' or 'inf' would read as a name
            raise UsageError("set", _given(name, value), "not a finite number")
        value = repr(float(value))  # a numpy float as the float it equals (its repr is np.float64(1.5))
    try:
        exact = parse(value)
    except ValueError as err:
        raise UsageError("set", _given(name, value), str(err)) from None
    problem = irrational(exact)
    if problem:
        raise UsageError("set", _given(name, value), problem)
    return exact


def _decimal(name: str, value: Decimal) -> Fraction:
    """A ``Decimal`` exactly, as its text says (``Decimal("0.1")`` is 1/10), its exponent bounded
    before its digits are worked out."""
    if not value.is_finite():
        raise UsageError("set", _given(name, value), "not a finite number")
    try:
        return rational(str(value))
    except ValueError as err:
        raise UsageError("set", _given(name, value), str(err)) from None


def _bits(numerator: int, denominator: int) -> int:
    return max(abs(numerator).bit_length(), denominator.bit_length())


def _given(name: str, value: object) -> str:
    """``NAME=VALUE`` as an error line shows it: a huge number by its size (Python writes no
    integer of more than 4300 digits), a long text cut short."""
    if isinstance(value, (int, Fraction, sympy.Rational)) and not isinstance(value, bool):
        bits = _bits(int(value.numerator), int(value.denominator))
        if bits > MAX_NUMBER_BITS:
            return f"{name}=<{'an integer' if value.denominator == 1 else 'a fraction'} of {bits} bits>"
    return _shown(f"{name}={value}")


def _shown(text: str) -> str:
    """``text`` cut to ``SHOWN`` characters for an error line (a value may be 100000 digits long)."""
    return shortened(text, SHOWN)
