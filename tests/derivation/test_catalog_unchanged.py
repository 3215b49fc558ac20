"""`derive` and `curve` on every catalog scene give the same JSON as before the refactor of issue 31.

The reference, catalog_before.json.gz, was written by this module's ``main`` at commit cd83528, before
the pipeline was split and its caches made explicit: a refactor changes how answers are reached, never
the answers. Timings are left out (they are the only part that differs between runs). A change meant to
alter an answer rewrites the reference (``python -m tests.derivation.test_catalog_unchanged``) in the
same commit, where the diff shows what changed (since: Hart's named crossed mode, each irreducible
curve's reason, the scenes added to the catalog, and the closed forms of a dyad built on another's
root, taken in a tower of roots: tests/branches/test_tower.py compares them with the old ones; and
the residuals' rounding, when a polynomial in three variables or more was evaluated a table of
coefficients at a time: every other value the same).

The verification's measured errors (``ROUNDING``: residuals and errors of 1e-40 and less, at 200 bits)
are rounding, not answers: evaluating a closed form's sums in another grouping moves them by tens of
percent. They are compared within a factor of ``ROUNDING_FACTOR``, every other value exactly.
"""

from __future__ import annotations

import gzip
import json
import sys
from pathlib import Path
from typing import Any

import pytest

import algkin
from algkin.scene import catalog_names
from algkin.scene.constructions import Fixed

REFERENCE = Path(__file__).with_name("catalog_before.json.gz")
ROUNDING = frozenset({"max_abs_error", "max_rel_error", "max_polynomial_residual", "smallest_factor_residual"})
ROUNDING_FACTOR = 4
# the scenes derive and curve take (points solved together: algkin solve only, for now)
DERIVED = [name for name in catalog_names() if not algkin.load_scene(name).unknown_points]


def _without_timings(document: Any) -> Any:
    if isinstance(document, dict):
        return {key: _without_timings(value) for key, value in document.items() if key != "timings"}
    if isinstance(document, list):
        return [_without_timings(value) for value in document]
    return document


def _plain(document: Any) -> Any:
    """As the JSON text would read it back (tuples as lists, numbers as written)."""
    return json.loads(json.dumps(document, sort_keys=True, default=str))


def same(now: Any, before: Any, *, rounding: bool = False) -> bool:
    """``now`` is ``before``, the errors under a ``ROUNDING`` key within ``ROUNDING_FACTOR`` of each other."""
    if isinstance(now, dict) and isinstance(before, dict):
        return now.keys() == before.keys() and all(
            same(now[key], before[key], rounding=rounding or key in ROUNDING) for key in now)
    if isinstance(now, list) and isinstance(before, list):
        return len(now) == len(before) and all(same(a, b, rounding=rounding) for a, b in zip(now, before))
    if rounding and isinstance(now, float) and isinstance(before, float) and now * before > 0:
        return max(now, before) <= ROUNDING_FACTOR * min(now, before)
    return bool(now == before)


def snapshot(name: str) -> dict[str, Any]:
    """The scene's `derive` and the `curve` of each moving point that traces one."""
    curves = {}
    for point, construction in algkin.load_scene(name).points.items():
        if isinstance(construction, Fixed):
            continue
        try:
            curves[point] = _without_timings(algkin.curve(name, point).to_json())
        except algkin.AlgkinError:  # a point of two inputs (a region), or one the scene cannot trace
            continue
    return _plain({"derive": _without_timings(algkin.derive(name).to_json()), "curve": curves})


@pytest.fixture(scope="module")
def reference() -> dict[str, Any]:
    with gzip.open(REFERENCE, "rt", encoding="utf-8") as text:
        return json.load(text)


def test_only_rounding_is_compared_loosely():
    assert same({"max_abs_error": 3e-56, "compared": 80}, {"max_abs_error": 2e-56, "compared": 80})
    assert same({"smallest_factor_residual": {"B_x": [1e-57]}}, {"smallest_factor_residual": {"B_x": [3e-57]}})
    assert not same({"max_abs_error": 1e-50}, {"max_abs_error": 2e-56})
    assert not same({"max_abs_error": 0.0}, {"max_abs_error": 2e-56})
    assert not same({"compared": 79.0}, {"compared": 80.0})
    assert not same({"failures": []}, {"failures": [], "passed": True})


def test_the_reference_covers_the_catalog(reference):
    # every scene of the reference is still derived; a scene added since has no answer before it
    assert set(reference) <= set(DERIVED)
    assert sum(len(entry["curve"]) for entry in reference.values()) >= 50


@pytest.mark.slow  # 40 s: the whole catalog derived and every curve traced (CI runs the slow set too)
@pytest.mark.parametrize("name", DERIVED)
def test_derive_and_curve_answer_as_before(name, reference):
    if name not in reference:
        pytest.skip(f"{name} was added to the catalog after the reference was written")
    now = snapshot(name)
    assert same(now["derive"], reference[name]["derive"]), (now["derive"], reference[name]["derive"])
    assert sorted(now["curve"]) == sorted(reference[name]["curve"])
    for point, document in now["curve"].items():
        assert same(document, reference[name]["curve"][point]), (point, document, reference[name]["curve"][point])


def main() -> None:
    documents = {name: snapshot(name) for name in DERIVED}
    with gzip.open(REFERENCE, "wt", encoding="utf-8") as text:
        json.dump(documents, text, sort_keys=True, indent=0)
    print(f"wrote {REFERENCE.name}: {len(documents)} scenes", file=sys.stderr)


if __name__ == "__main__":
    main()
