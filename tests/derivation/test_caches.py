"""What the pipeline keeps between calls is keyed by values: a call's answer does not depend on
the calls before it (issue 31)."""

import pytest

from algkin.derivation import assembles, pipeline
from algkin.derivation.pipeline import curve, derive
from algkin.scene import load_scene, with_values


def _cold() -> None:
    for cache in (pipeline.PREPARED, pipeline.CHECKED, assembles.FOUND):
        cache.clear()


def _answer(result) -> dict:
    document = result.to_json()
    document.pop("timings")
    return document


@pytest.mark.parametrize("run", [
    lambda **kw: derive("fourbar", outputs=["B"], samples=5, certify=False, **kw),
    lambda **kw: curve("fourbar", "P", samples=5, **kw),
])
def test_an_answer_is_the_same_after_a_call_with_other_values(run):
    _cold()
    fresh = _answer(run())
    _cold()
    other = _answer(run(set={"a": "1/2"}))
    assert other != fresh  # the other dimensions give another answer ...
    assert _answer(run()) == fresh  # ... and the default's is the default's still


def test_the_kept_work_is_found_by_value_not_by_object():
    _cold()
    derive(load_scene("fourbar"), outputs=["B"], samples=5, certify=False)
    kept = len(pipeline.PREPARED)
    derive(with_values(load_scene("fourbar"), {"a": "1"}), outputs=["B"], samples=5, certify=False)  # a = 1: equal
    assert len(pipeline.PREPARED) == kept
