"""The designs of a sweep: a grid of exact parameter values, or seeded random draws.

``NAME=LO:HI:COUNT`` spaces COUNT exact values from LO to HI, both included (LO and HI exact:
``0.1`` is 1/10, ``3/2`` is 3/2); several ``--grid`` options make their product, the first
varying slowest. With ``--random N`` each ``NAME=LO:HI`` is a range and N distinct designs are
drawn with a seed, each value ``LO + (HI - LO) * k / 10**6`` for a drawn whole ``k``: exact,
and the same on every machine.

>>> axes = parse_grid(["a=1:2:3", "l=3/2:3/2:1"])
>>> [str(v) for v in axes["a"]], [str(v) for v in axes["l"]]
(['1', '3/2', '2'], ['3/2'])
>>> [{k: str(v) for k, v in d.items()} for d in grid_designs(axes)][:2]
[{'a': '1', 'l': '3/2'}, {'a': '3/2', 'l': '3/2'}]
>>> parse_grid(["a=1:1:3"])
Traceback (most recent call last):
...
algkin.errors.UsageError: grid='a=1:1:3': LO = HI is one value, not 3: give COUNT 1
>>> parse_grid(["a=2:1:3"])
Traceback (most recent call last):
...
algkin.errors.UsageError: grid='a=2:1:3': LO must not exceed HI
>>> [str(d["a"]) for d in random_designs(parse_ranges(["a=0:1"]), 3, seed=7)]
['...', '...', '...']
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Mapping, Sequence
from fractions import Fraction
from typing import overload

import numpy as np

from ..errors import UsageError
from ..runtime.validation import NumberTooLarge, rational

__all__ = ["parse_grid", "parse_ranges", "grid_designs", "random_designs", "first_repeat", "Designs", "RANDOM_STEPS",
           "MAX_DESIGNS", "DRAW_SCHEME"]

RANDOM_STEPS = 10**6  # a random value is LO + (HI - LO) * k / RANDOM_STEPS, k drawn whole
# How random designs are drawn, recorded in a sweep's manifest: 2, distinct designs (a repeat drawn
# again); 1, recorded by no number, the generator's first rows, repeats kept (algkin before 2 was).
DRAW_SCHEME = 2
# designs of one sweep at most: each is held in memory while planned (the grid's or the draws'
# values, about half a gigabyte at this many), and a million four-bars take days already
MAX_DESIGNS = 10**6
COUNT_DIGITS = 100  # a COUNT longer is refused by its length: its product would be past what Python writes


def _exact(text: str, spec: str) -> Fraction:
    """An exact rational from a decimal or a fraction (``0.1``, ``3/2``, ``-2``), never a float's binary value."""
    try:
        value = rational(text)
    except NumberTooLarge as err:
        raise UsageError("grid", spec, str(err)) from None
    except (ValueError, ZeroDivisionError):
        raise UsageError("grid", spec, f"{text.strip()!r} is not a number (e.g. 1.5 or 3/2)") from None
    if abs(value) > 10**100 or (value and abs(value) < Fraction(1, 10**100)):
        raise UsageError("grid", spec, f"{text.strip()} is outside 1e-100 to 1e100")
    return value


def _split(spec: str, parts: int) -> tuple[str, list[str]]:
    name, equals, rest = spec.partition("=")
    fields = rest.split(":")
    if not equals or not name.strip().isidentifier() or len(fields) != parts:
        shape = "NAME=LO:HI:COUNT, e.g. a=1:2:5" if parts == 3 else "NAME=LO:HI, e.g. a=1:2 (for random draws)"
        raise UsageError("grid", spec, f"expected {shape}")
    return name.strip(), fields


def _bounds(spec: str, fields: Sequence[str]) -> tuple[Fraction, Fraction]:
    lo, hi = _exact(fields[0], spec), _exact(fields[1], spec)
    if lo > hi:
        raise UsageError("grid", spec, "LO must not exceed HI")
    return lo, hi


def _once(specs: Iterable[str]) -> list[str]:
    specs = list(specs)
    if not specs:
        raise UsageError("grid", "", "give at least one NAME=LO:HI:COUNT")
    names = [s.partition("=")[0].strip() for s in specs]
    for name in names:
        if names.count(name) > 1:
            raise UsageError("grid", name, "given twice")
    return specs


def parse_grid(specs: Iterable[str]) -> dict[str, list[Fraction]]:
    """``{name: exact values}`` from ``NAME=LO:HI:COUNT`` strings; their product counted (and refused
    past ``MAX_DESIGNS``) before any value is made.

    >>> parse_grid(["a=1:2:1000000000"])
    Traceback (most recent call last):
    ...
    algkin.errors.UsageError: grid='a=1:2:1000000000': 1000000000 designs, more than 1000000
    """
    specs = _once(specs)
    axes = [_axis(spec) for spec in specs]
    total = math.prod(n for _, _, _, n in axes)
    if total > MAX_DESIGNS:
        raise UsageError("grid", " ".join(specs), f"{total} designs, more than {MAX_DESIGNS}")
    return {name: [lo] if n == 1 else [lo + (hi - lo) * k / (n - 1) for k in range(n)] for name, lo, hi, n in axes}


def _axis(spec: str) -> tuple[str, Fraction, Fraction, int]:
    """``(name, lo, hi, count)`` of one ``NAME=LO:HI:COUNT``: COUNT distinct values, so LO = HI with COUNT 1
    and only then."""
    name, fields = _split(spec, 3)
    lo, hi = _bounds(spec, fields)
    count = fields[2].strip()
    digits = count.lstrip("0")
    if not (count.isascii() and count.isdigit()) or not digits:
        raise UsageError("grid", spec, f"COUNT must be a whole number from 1, got {count!r}")
    if len(digits) > COUNT_DIGITS:  # before int(): Python reads no integer of more than 4300 digits
        raise UsageError("grid", spec, f"COUNT has {len(digits)} digits: more than {MAX_DESIGNS} designs")
    n = int(digits)
    if n == 1 and lo != hi:
        raise UsageError("grid", spec, "COUNT 1 needs LO = HI (one value)")
    if n > 1 and lo == hi:
        raise UsageError("grid", spec, f"LO = HI is one value, not {n}: give COUNT 1")
    return name, lo, hi, n


def parse_ranges(specs: Iterable[str]) -> dict[str, tuple[Fraction, Fraction]]:
    """``{name: (lo, hi)}`` from ``NAME=LO:HI`` strings (the ranges of ``--random`` draws)."""
    ranges = {}
    for spec in _once(specs):
        name, fields = _split(spec, 2)
        ranges[name] = _bounds(spec, fields)
    return ranges


class Designs(Sequence[dict[str, Fraction]]):
    """A sweep's designs, each ``{name: exact value}`` made only when asked for by its index: a plan
    of a million designs holds their recipe, not a million dictionaries.

    >>> designs = grid_designs({"a": [Fraction(1), Fraction(2)], "l": [Fraction(5), Fraction(6), Fraction(7)]})
    >>> len(designs), designs[4], designs[-1] == designs[5]
    (6, {'a': Fraction(2, 1), 'l': Fraction(6, 1)}, True)
    """

    def __init__(self, names: Sequence[str], count: int, values: Callable[[int], Sequence[Fraction]]) -> None:
        self.names, self.size, self.values = list(names), count, values

    def __len__(self) -> int:
        return self.size

    @overload
    def __getitem__(self, index: int) -> dict[str, Fraction]: ...

    @overload
    def __getitem__(self, index: slice) -> list[dict[str, Fraction]]: ...

    def __getitem__(self, index: int | slice) -> dict[str, Fraction] | list[dict[str, Fraction]]:
        if isinstance(index, slice):
            return [self[k] for k in range(*index.indices(self.size))]
        k = index + self.size if index < 0 else index
        if not 0 <= k < self.size:
            raise IndexError(index)
        return dict(zip(self.names, self.values(k)))

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Sequence) and len(self) == len(other) and all(a == b for a, b in zip(self, other))

    __hash__ = None  # type: ignore[assignment]  # compared by value, as a list is


def grid_designs(axes: Mapping[str, Sequence[Fraction]]) -> Designs:
    """Every combination of the axes' values, the first axis varying slowest."""
    lists = [list(values) for values in axes.values()]

    def values(k: int) -> list[Fraction]:
        found = []
        for axis in reversed(lists):  # the last axis varies fastest: the lowest digit of k
            k, digit = divmod(k, len(axis))
            found.append(axis[digit])
        return found[::-1]

    return Designs(list(axes), math.prod(len(v) for v in lists), values)


def random_designs(ranges: Mapping[str, tuple[Fraction, Fraction]], count: int, seed: int) -> Designs:
    """``count`` distinct designs drawn uniformly (on a lattice of RANDOM_STEPS steps) in ``ranges``, from
    ``seed``: a draw that repeats an earlier design is dropped and drawn again, further on in the seed's
    sequence. More designs than the ranges hold (a range LO = HI is one value) are refused.

    >>> random_designs({"a": (Fraction(1), Fraction(1))}, 2, seed=0)
    Traceback (most recent call last):
    ...
    algkin.errors.UsageError: random=2: the ranges hold 1 distinct design at most (a=1:1: one value)
    """
    if not 1 <= count <= MAX_DESIGNS:
        raise UsageError("random", count, f"expected a number of designs from 1 to {MAX_DESIGNS}")
    if seed < 0:
        raise UsageError("seed", seed, "expected a whole number from 0")
    bounds = list(ranges.values())
    spread = np.array([lo < hi for lo, hi in bounds])
    held = (RANDOM_STEPS + 1) ** int(spread.sum())
    if count > held:
        single = [f"{n}={lo}:{hi}" for n, (lo, hi) in ranges.items() if lo == hi]
        raise UsageError("random", count, f"the ranges hold {held} distinct design{'s' if held > 1 else ''} at most "
                                          f"({', '.join(single)}: {'one value' if len(single) == 1 else 'one value each'})")
    steps = _distinct_steps(_generator(seed), spread, count)
    return Designs(list(ranges), count, lambda k: [lo + (hi - lo) * Fraction(int(step), RANDOM_STEPS)
                                                   for (lo, hi), step in zip(bounds, steps[k])])


# Rows drawn at once to replace repeats: enough that a sweep near all its ranges hold ends in few rounds.
_REDRAW = 2**16


def _distinct_steps(generator: np.random.Generator, spread: np.ndarray, count: int) -> np.ndarray:
    """``count`` rows of whole steps in [0, RANDOM_STEPS], one per range, no two alike where the ranges of
    more than one value (``spread``) are concerned, the others' steps 0: the generator's first ``count``
    rows in order, each repeat dropped, then new rows drawn in turn until there are ``count``."""
    rows: list[np.ndarray] = []
    seen: set[tuple[int, ...]] = set()
    size = count
    while len(rows) < count:
        for row in generator.integers(0, RANDOM_STEPS, size=(size, len(spread)), endpoint=True) * spread:
            key = tuple(row.tolist())
            if key not in seen and len(rows) < count:
                seen.add(key)
                rows.append(row)
        size = max(count - len(rows), _REDRAW)
    return np.array(rows).reshape(count, len(spread))


def first_repeat(ranges: Mapping[str, tuple[Fraction, Fraction]], count: int, seed: int) -> int | None:
    """The first of the ``count`` designs drawn in ``ranges`` from ``seed`` by draw scheme 1 (the
    generator's first rows, repeats kept) that repeats an earlier one; None if none does, and then
    scheme 2 (``random_designs``) draws the same designs.

    >>> first_repeat({"a": (Fraction(1), Fraction(2))}, 8, seed=23365), first_repeat({"a": (Fraction(1), Fraction(2))}, 8, seed=0)
    (7, None)
    """
    spread = np.array([lo < hi for lo, hi in ranges.values()])
    rows = _generator(seed).integers(0, RANDOM_STEPS, size=(count, len(spread)), endpoint=True) * spread
    seen: set[tuple[int, ...]] = set()
    for index, row in enumerate(rows.tolist()):
        if tuple(row) in seen:
            return index
        seen.add(tuple(row))
    return None


def _generator(seed: int) -> np.random.Generator:
    """The random draws' generator from ``seed``: PCG64, the same sequence on every machine."""
    return np.random.Generator(np.random.PCG64(seed))
