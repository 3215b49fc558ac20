"""A bounded cache of work keyed by values: what a computation built once, found again by what it was built from.

The keys are hashable values (scenes, compiled systems, branches: ``algkin.runtime.frozen``),
never ``id()`` nor ``repr``: a key equal to an earlier one is the same question, so the
answer kept for it is the right one, whatever ran in between.

>>> cache = BoundedCache(2)
>>> cache.get("a", lambda: 1), cache.get("a", lambda: 99), len(cache)
(1, 1, 1)
>>> cache.get("b", lambda: 2), cache.get("c", lambda: 3), "a" in cache  # the least recent goes
(2, 3, False)
>>> cache.clear(); len(cache)
0
"""

import collections
from collections.abc import Callable, Hashable
from typing import Generic, TypeVar

__all__ = ["BoundedCache"]

V = TypeVar("V")


class BoundedCache(Generic[V]):
    """At most ``size`` answers, the least recently used dropped first."""

    def __init__(self, size: int) -> None:
        self.size = size
        self._kept: collections.OrderedDict[Hashable, V] = collections.OrderedDict()

    def get(self, key: Hashable, build: Callable[[], V]) -> V:
        """The answer kept for ``key``, else ``build()``'s, kept (an error is not kept)."""
        if key in self._kept:
            self._kept.move_to_end(key)
            return self._kept[key]
        value = self._kept[key] = build()
        while len(self._kept) > self.size:
            self._kept.popitem(last=False)
        return value

    def __contains__(self, key: Hashable) -> bool:
        return key in self._kept

    def __len__(self) -> int:
        return len(self._kept)

    def clear(self) -> None:
        self._kept.clear()
