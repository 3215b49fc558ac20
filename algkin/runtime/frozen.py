"""An immutable, hashable mapping for algkin's values (scenes, systems, results).

It keeps its keys' order (a scene's points are in file order) and compares as a mapping
does; a value holding it can be hashed, so it is its own cache key.

>>> points = FrozenDict({"O": 0, "A": 1})
>>> list(points), points["A"], points == {"A": 1, "O": 0}
(['O', 'A'], 1, True)
>>> hash(points) == hash(FrozenDict({"A": 1, "O": 0}))
True
>>> points["B"] = 2
Traceback (most recent call last):
...
TypeError: 'FrozenDict' object does not support item assignment
>>> FrozenDict({**points, "B": 2})
FrozenDict({'O': 0, 'A': 1, 'B': 2})
"""

from collections.abc import Iterable, Iterator, Mapping
from typing import Any, TypeVar, Union

__all__ = ["FrozenDict", "frozen"]

K = TypeVar("K")
V = TypeVar("V")


class FrozenDict(Mapping[K, V]):
    """A read-only mapping whose hash is that of its items (the values must be hashable)."""

    __slots__ = ("_items", "_hash")

    def __init__(self, items: Union[Mapping[K, V], Iterable[tuple[K, V]]] = ()) -> None:
        self._items: dict[K, V] = dict(items)
        self._hash: int | None = None

    def __getitem__(self, key: K) -> V:
        return self._items[key]

    def __iter__(self) -> Iterator[K]:
        return iter(self._items)

    def __len__(self) -> int:
        return len(self._items)

    def __hash__(self) -> int:
        # Over the items as a set: equal mappings (in any order) hash alike, as they compare.
        if self._hash is None:
            self._hash = hash(frozenset(self._items.items()))
        return self._hash

    def __eq__(self, other: object) -> bool:
        if isinstance(other, FrozenDict):
            return self._items == other._items
        return isinstance(other, Mapping) and self._items == dict(other.items())

    def __repr__(self) -> str:
        return f"FrozenDict({self._items!r})"

    def __getstate__(self) -> dict[K, V]:
        return self._items

    def __setstate__(self, items: dict[K, V]) -> None:
        self._items, self._hash = items, None


# not generic: attrs' mypy plugin cannot solve a converter's type variables, and this is the value
# classes' converter
def frozen(items: Union[Mapping[Any, Any], Iterable[tuple[Any, Any]]] = ()) -> FrozenDict[Any, Any]:
    """``items`` as a ``FrozenDict`` (itself when it is one already): the converter of value classes' mappings.

    >>> frozen({"a": 1})
    FrozenDict({'a': 1})
    """
    return items if isinstance(items, FrozenDict) else FrozenDict(items)
