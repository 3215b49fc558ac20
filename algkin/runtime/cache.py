"""Bounded caches of work keyed by values: what a computation built once, found again by what it was built from.

The keys are hashable values (scenes, compiled systems, expressions: ``algkin.runtime.frozen``),
never ``id()`` nor ``repr``: a key equal to an earlier one is the same question, so the
answer kept for it is the right one, whatever ran in between.

>>> cache = BoundedCache(2, name="doctest letters")
>>> cache.get("a", lambda: 1), cache.get("a", lambda: 99), len(cache)
(1, 1, 1)
>>> cache.get("b", lambda: 2), cache.get("c", lambda: 3), "a" in cache  # the least recent goes
(2, 3, False)
>>> cache.clear(); len(cache)
0

Every cache is named, and ``caches()`` lists the living ones: a process's kept work is seen,
measured and dropped in one place (``clear_caches()``: a benchmark of the cold path in one
process, a test that must not see an earlier test's work).

>>> cache.get("a", lambda: 1)
1
>>> cache in caches()
True
>>> clear_caches(); len(cache)
0
"""

import collections
import weakref
from collections.abc import Callable, Hashable
from typing import Any, Generic, TypeVar

__all__ = ["BoundedCache", "caches", "clear_caches"]

V = TypeVar("V")


class BoundedCache(Generic[V]):
    """At most ``size`` answers, the least recently used dropped first; ``name`` says what it keeps."""

    def __init__(self, size: int, *, name: str) -> None:
        self.size = size
        self.name = name
        self._kept: collections.OrderedDict[Hashable, V] = collections.OrderedDict()
        _LIVING.add(self)

    def get(self, key: Hashable, build: Callable[[], V]) -> V:
        """The answer kept for ``key``, else ``build()``'s, kept (an error is not kept)."""
        kept = self._kept
        if key in kept:
            kept.move_to_end(key)
            return kept[key]
        value = kept[key] = build()
        while len(kept) > self.size:
            kept.popitem(last=False)
        return value

    def __contains__(self, key: Hashable) -> bool:
        return key in self._kept

    def __len__(self) -> int:
        return len(self._kept)

    def clear(self) -> None:
        self._kept.clear()


# Weakly: a cache made for one sweep's worker, or one test, goes when its owner does.
_LIVING: "weakref.WeakSet[BoundedCache[Any]]" = weakref.WeakSet()


def caches() -> list["BoundedCache[Any]"]:
    """The living caches, by name."""
    return sorted(_LIVING, key=lambda cache: cache.name)


def clear_caches() -> None:
    """Drop every living cache's answers."""
    for cache in list(_LIVING):
        cache.clear()
