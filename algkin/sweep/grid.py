"""The designs of a sweep: a grid of exact parameter values, or seeded random draws.

``NAME=LO:HI:COUNT`` spaces COUNT exact values from LO to HI, both included (LO and HI exact:
``0.1`` is 1/10, ``3/2`` is 3/2); several ``--grid`` options make their product, the first
varying slowest. With ``--random N`` each ``NAME=LO:HI`` is a range and the N designs are
drawn with a seed, each value ``LO + (HI - LO) * k / 10**6`` for a drawn whole ``k``: exact,
and the same on every machine.

>>> axes = parse_grid(["a=1:2:3", "l=3/2:3/2:1"])
>>> [str(v) for v in axes["a"]], [str(v) for v in axes["l"]]
(['1', '3/2', '2'], ['3/2'])
>>> [{k: str(v) for k, v in d.items()} for d in grid_designs(axes)][:2]
[{'a': '1', 'l': '3/2'}, {'a': '3/2', 'l': '3/2'}]
>>> parse_grid(["a=2:1:3"])
Traceback (most recent call last):
...
algkin.errors.UsageError: --grid='a=2:1:3': LO must not exceed HI
>>> [str(d["a"]) for d in random_designs(parse_ranges(["a=0:1"]), 3, seed=7)]
['...', '...', '...']
"""

from __future__ import annotations

import itertools
from collections.abc import Iterable, Mapping, Sequence
from fractions import Fraction

import numpy as np

from ..errors import UsageError
from ..runtime.validation import rational

__all__ = ["parse_grid", "parse_ranges", "grid_designs", "random_designs", "RANDOM_STEPS", "MAX_DESIGNS"]

RANDOM_STEPS = 10**6  # a random value is LO + (HI - LO) * k / RANDOM_STEPS, k drawn whole
MAX_DESIGNS = 10**7  # more rows than one Parquet dataset of a sweep is meant to hold


def _exact(text: str, spec: str) -> Fraction:
    """An exact rational from a decimal or a fraction (``0.1``, ``3/2``, ``-2``), never a float's binary value."""
    try:
        value = rational(text)
    except (ValueError, ZeroDivisionError):
        raise UsageError("--grid", spec, f"{text.strip()!r} is not a number (e.g. 1.5 or 3/2)") from None
    if abs(value) > 10**100 or (value and abs(value) < Fraction(1, 10**100)):
        raise UsageError("--grid", spec, f"{text.strip()} is outside 1e-100 to 1e100")
    return value


def _split(spec: str, parts: int) -> tuple[str, list[str]]:
    name, equals, rest = spec.partition("=")
    fields = rest.split(":")
    if not equals or not name.strip().isidentifier() or len(fields) != parts:
        shape = "NAME=LO:HI:COUNT, e.g. a=1:2:5" if parts == 3 else "NAME=LO:HI, e.g. a=1:2 (with --random)"
        raise UsageError("--grid", spec, f"expected {shape}")
    return name.strip(), fields


def _bounds(spec: str, fields: Sequence[str]) -> tuple[Fraction, Fraction]:
    lo, hi = _exact(fields[0], spec), _exact(fields[1], spec)
    if lo > hi:
        raise UsageError("--grid", spec, "LO must not exceed HI")
    return lo, hi


def _once(specs: Iterable[str]) -> list[str]:
    specs = list(specs)
    if not specs:
        raise UsageError("--grid", "", "give at least one NAME=LO:HI:COUNT")
    names = [s.partition("=")[0].strip() for s in specs]
    for name in names:
        if names.count(name) > 1:
            raise UsageError("--grid", name, "given twice")
    return specs


def parse_grid(specs: Iterable[str]) -> dict[str, list[Fraction]]:
    """``{name: exact values}`` from ``NAME=LO:HI:COUNT`` strings."""
    axes = {}
    for spec in _once(specs):
        name, fields = _split(spec, 3)
        lo, hi = _bounds(spec, fields)
        count = fields[2].strip()
        if not (count.isascii() and count.isdigit()) or int(count) < 1:
            raise UsageError("--grid", spec, f"COUNT must be a whole number from 1, got {count!r}")
        n = int(count)
        if n == 1 and lo != hi:
            raise UsageError("--grid", spec, "COUNT 1 needs LO = HI (one value)")
        axes[name] = [lo] if n == 1 else [lo + (hi - lo) * k / (n - 1) for k in range(n)]
    if np.prod([len(v) for v in axes.values()], dtype=float) > MAX_DESIGNS:
        raise UsageError("--grid", " ".join(specs), f"more than {MAX_DESIGNS} designs")
    return axes


def parse_ranges(specs: Iterable[str]) -> dict[str, tuple[Fraction, Fraction]]:
    """``{name: (lo, hi)}`` from ``NAME=LO:HI`` strings (the ranges of ``--random`` draws)."""
    ranges = {}
    for spec in _once(specs):
        name, fields = _split(spec, 2)
        ranges[name] = _bounds(spec, fields)
    return ranges


def grid_designs(axes: Mapping[str, Sequence[Fraction]]) -> list[dict[str, Fraction]]:
    """Every combination of the axes' values, the first axis varying slowest."""
    names = list(axes)
    return [dict(zip(names, values)) for values in itertools.product(*(axes[n] for n in names))]


def random_designs(ranges: Mapping[str, tuple[Fraction, Fraction]], count: int, seed: int) -> list[dict[str, Fraction]]:
    """``count`` designs drawn uniformly (on a lattice of RANDOM_STEPS steps) in ``ranges``, from ``seed``."""
    if not 1 <= count <= MAX_DESIGNS:
        raise UsageError("--random", count, f"expected a number of designs from 1 to {MAX_DESIGNS}")
    if seed < 0:
        raise UsageError("--seed", seed, "expected a whole number from 0")
    steps = np.random.Generator(np.random.PCG64(seed)).integers(0, RANDOM_STEPS, size=(count, len(ranges)),
                                                                endpoint=True)
    return [{name: lo + (hi - lo) * Fraction(int(k), RANDOM_STEPS) for (name, (lo, hi)), k in zip(ranges.items(), row)}
            for row in steps]
