"""algkin.runtime.cache: the work algkin keeps is in named caches, listed and cleared in one place; a
derivation made again with every cache cleared (the cold path) gives the same answer as warm."""

import algkin
from algkin.runtime.cache import BoundedCache, caches, clear_caches


def _json(derivation):
    document = derivation.to_json()
    document.pop("timings")
    return document


def test_a_derivation_made_cold_again_after_clear_caches_is_the_same():
    warm = _json(algkin.derive("chebyshev-lambda", ["B"], samples=5))
    kept = {cache.name: len(cache) for cache in caches()}
    for name in ("compiled programs", "scenes read", "systems' numeric blocks", "blocks' certifiers",
                 "eliminants' structure checks", "polynomials ready for balls"):
        assert kept.get(name), (name, kept)  # the derivation used, and filled, each of them
    clear_caches()
    assert not any(len(cache) for cache in caches())
    assert _json(algkin.derive("chebyshev-lambda", ["B"], samples=5)) == warm


def test_a_cache_gone_with_its_owner_is_no_longer_listed():
    cache = BoundedCache(1, name="a test's own")
    assert cache in caches()
    del cache
    assert "a test's own" not in [c.name for c in caches()]
