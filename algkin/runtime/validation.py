"""Checks of the public API's arguments: a misuse raises algkin's own error, naming the argument.

>>> names("outputs", ["B", "P"])
('B', 'P')
>>> names("outputs", "PB")
Traceback (most recent call last):
...
algkin.errors.UsageError: outputs='PB': expected a list of names such as ['PB'], not a string
>>> count("samples", -1, MAX_VERIFY_SAMPLES)
Traceback (most recent call last):
...
algkin.errors.UsageError: samples=-1: expected a whole number from 0 to 10000
>>> seed(2.5)
Traceback (most recent call last):
...
algkin.errors.UsageError: seed=2.5: expected a whole number from 0 to 18446744073709551615
>>> names("params", ["a", "b", "a"])
Traceback (most recent call last):
...
algkin.errors.UsageError: params='a': given twice
>>> real("1.5e3"), whole("12"), rational("3/2")
(1500.0, 12, Fraction(3, 2))
>>> real("\u0661")   # Python's float() reads the Arabic-Indic digit one as 1
Traceback (most recent call last):
...
ValueError: not a number in ASCII: '١'
"""

from __future__ import annotations

import numbers
from collections.abc import Iterable, Mapping
from fractions import Fraction
from typing import TYPE_CHECKING

from ..errors import UsageError

if TYPE_CHECKING:
    from .budget import Budget, Deadline

__all__ = ["names", "count", "seed", "flag", "budget", "real", "whole", "rational", "NumberTooLarge", "MAX_VERIFY_SAMPLES",
           "MAX_ACCURACY_SAMPLES", "MAX_NUMBER_BITS", "MAX_DECIMAL_EXPONENT"]

# Each verification sample is solved at 50 digits (milliseconds); each accuracy sample
# holds a few floats per strategy and case. Past these a run takes hours or the memory.
MAX_VERIFY_SAMPLES = 10_000
MAX_ACCURACY_SAMPLES = 1_000_000
MAX_NUMBER_BITS = 1024  # an exact number's numerator and denominator, about 308 decimal digits
MAX_DECIMAL_EXPONENT = 4 * MAX_NUMBER_BITS  # keeps Fraction("1e...") cheap before the bit check


def names(argument: str, value: Iterable[str] | None, *, distinct: bool = True) -> tuple[str, ...] | None:
    """A tuple of names from a list (a lone string is a mistake: it would split into letters), each
    once unless not ``distinct``."""
    if value is None:
        return None
    if isinstance(value, str):
        raise UsageError(argument, value, f"expected a list of names such as [{value!r}], not a string")
    if isinstance(value, Mapping):
        raise UsageError(argument, value, "expected a list of names, not a mapping (values come from the scene)")
    try:
        items = tuple(value)
    except TypeError:
        raise UsageError(argument, value, "expected a list of names") from None
    seen: set[str] = set()
    for item in items:
        if not isinstance(item, str):
            raise UsageError(argument, value, f"expected names (strings), got {item!r}")
        if distinct and item in seen:  # sympy refuses a generator twice, after the work before it
            raise UsageError(argument, item, "given twice")
        seen.add(item)
    return items


def count(argument: str, value: object, limit: int, *, minimum: int = 0) -> int:
    """A whole number from ``minimum`` to ``limit``."""
    if isinstance(value, bool) or not isinstance(value, numbers.Integral) or not minimum <= int(value) <= limit:
        raise UsageError(argument, value, f"expected a whole number from {minimum} to {limit}")
    return int(value)


def seed(value: object) -> int:
    """A random seed numpy accepts: a whole number from 0 to 2**64 - 1."""
    return count("seed", value, 2**64 - 1)


def flag(argument: str, value: object) -> bool:
    """True or False (numpy's too); a UsageError for anything else: ``certify="no"`` would be true.

    >>> flag("certify", "no")
    Traceback (most recent call last):
    ...
    algkin.errors.UsageError: certify='no': expected True or False
    """
    numpy_bool = type(value).__module__ == "numpy" and type(value).__name__ in ("bool", "bool_")  # no numpy import
    if not (isinstance(value, bool) or numpy_bool):
        raise UsageError(argument, value, "expected True or False")
    return bool(value)


def budget(value: object, argument: str = "budget") -> Budget | Deadline | None:
    """None, a ``Budget`` or the ``Deadline`` of one started; UsageError naming ``argument`` otherwise."""
    from .budget import Budget, Deadline

    if value is not None and not isinstance(value, (Budget, Deadline)):
        raise UsageError(argument, value, "expected an algkin.Budget, e.g. Budget(seconds=10)")
    return value


# Numbers in text (command-line values) are ASCII: Python's float(), int() and Fraction() also
# read other scripts' digits ('١', '１') and strip a no-break space, the tiny language does not.

def real(text: str) -> float:
    """``float(text)`` of an ASCII ``text``; ValueError otherwise."""
    return float(_ascii(text))


def whole(text: str) -> int:
    """``int(text)`` of an ASCII ``text``; ValueError otherwise."""
    return int(_ascii(text))


class NumberTooLarge(ValueError):
    """An exact number past the sizes algkin reads (the message says which)."""


def rational(text: str) -> Fraction:
    """``Fraction(text)`` of an ASCII ``text`` (``"3/2"``, ``"0.1"`` is 1/10); ValueError otherwise,
    NumberTooLarge past MAX_NUMBER_BITS. The decimal exponent is bounded first: ``Fraction("1e-1000000000")``
    would compute 10**1000000000, and one of 10**100000 cannot even be printed."""
    plain = _ascii(text)
    _mantissa, _, exponent = plain.replace("_", "").lower().partition("e")
    try:
        too_far = bool(exponent) and abs(int(exponent)) > MAX_DECIMAL_EXPONENT
    except ValueError:
        too_far = False  # no decimal exponent: Fraction says what is wrong
    if too_far:
        raise NumberTooLarge(f"decimal exponent out of range (at most {MAX_DECIMAL_EXPONENT}): {text!r}")
    value = Fraction(plain)
    if max(abs(value.numerator).bit_length(), value.denominator.bit_length()) > MAX_NUMBER_BITS:
        raise NumberTooLarge(f"number too large or too precise (more than {MAX_NUMBER_BITS} bits)")
    return value


def _ascii(text: object) -> str:
    if not isinstance(text, str) or not text.isascii():
        raise ValueError(f"not a number in ASCII: {text!r}")
    return text
