"""Results' JSON-like parts frozen for keeping, and thawed back for ``to_json``.

A result holds nested mappings and lists (a limit's position, a region of a closed form): it keeps
them as ``FrozenDict`` and tuples, so it cannot be changed and can be hashed; its JSON is the
plain dicts and lists again.

>>> kept = deep_frozen({"x": 1.5, "strokes": [{"from": 0}, {"from": 180}]})
>>> kept["strokes"][1]["from"], hash(kept) == hash(deep_frozen(thawed(kept)))
(180, True)
>>> thawed(kept)
{'x': 1.5, 'strokes': [{'from': 0}, {'from': 180}]}
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from ..runtime.frozen import FrozenDict

__all__ = ["deep_frozen", "frozen_rows", "thawed"]


def deep_frozen(value: Any) -> Any:
    """``value`` with every mapping a ``FrozenDict`` and every list a tuple, all the way down."""
    if isinstance(value, Mapping):
        return FrozenDict((k, deep_frozen(v)) for k, v in value.items())
    if isinstance(value, (list, tuple)):
        return tuple(deep_frozen(v) for v in value)
    return value


def frozen_rows(rows: Any) -> tuple[Any, ...]:
    """A list of JSON-like rows (mappings) as a tuple of frozen ones: a results' converter.

    >>> frozen_rows([{"why": "no path"}])
    (FrozenDict({'why': 'no path'}),)
    """
    return tuple(deep_frozen(r) for r in rows)


def thawed(value: Any) -> Any:
    """``value`` with every mapping a dict and every tuple a list again, for JSON."""
    if isinstance(value, Mapping):
        return {k: thawed(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [thawed(v) for v in value]
    return value
