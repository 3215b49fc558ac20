"""Nothing of one call is kept for the next: a command's answer and its work do not depend on
what ran before it in the process, unless its caller hands it a ``Prepared`` scene (issue 31)."""

import pytest

import algkin
from algkin.derivation import assembles, pipeline, prepared
from algkin.derivation.pipeline import curve, derive

from .work import counting

DERIVE = lambda **kw: derive("fourbar", outputs=["B"], samples=5, certify=False, **kw)  # noqa: E731
CURVE = lambda **kw: curve("fourbar", "P", samples=5, **kw)  # noqa: E731
# One compilation and one set of branches per call; an eliminant per unknown: B_x and B_y for
# the dyad B, the curve alone for P.
ALONE = {DERIVE: {"compile_scene": 1, "closed_forms": 1, "eliminate": 2},
         CURVE: {"compile_scene": 1, "closed_forms": 1, "eliminate": 1}}


@pytest.fixture
def work(monkeypatch):
    return counting(monkeypatch)


def _answer(result) -> dict:
    document = result.to_json()
    document.pop("timings")
    return document


@pytest.mark.parametrize("run", [DERIVE, CURVE], ids=["derive", "curve"])
def test_a_call_does_the_same_work_and_answers_the_same_whatever_ran_before(run, work):
    first, first_work = work(run)
    other, other_work = work(lambda: run(set={"a": "1/2"}))
    again, again_work = work(run)
    assert _answer(other) != _answer(first)  # other dimensions, another answer ...
    assert _answer(again) == _answer(first)  # ... and the default's is the default's still
    assert first_work == other_work == again_work == ALONE[run]  # nothing kept: each call does all its work


def test_a_prepared_scene_is_compiled_and_branched_once_for_every_question(work):
    scene, preparing = work(lambda: algkin.prepare("fourbar", outputs=["P"]))
    assert preparing == {"compile_scene": 1, "closed_forms": 1, "eliminate": 0}
    for _ in range(2):
        found, asked = work(lambda: curve(scene, "P", samples=5))
        assert asked == {"compile_scene": 0, "closed_forms": 0, "eliminate": 1}
        assert _answer(found) == _answer(CURVE())


def test_the_derivation_package_keeps_nothing_at_module_level():
    from algkin.runtime.cache import BoundedCache

    for module in (assembles, pipeline, prepared):
        assert not [n for n, v in vars(module).items() if isinstance(v, (BoundedCache, dict)) and not n.startswith("__")]


def test_a_prepared_scene_says_what_it_was_prepared_with_and_refuses_it_again():
    scene = algkin.prepare("fourbar", outputs=["B"])
    with pytest.raises(algkin.AlgkinError, match=r"^params=\['a'\]: given with a Prepared scene"):
        derive(scene, params=["a"])
    with pytest.raises(algkin.AlgkinError, match=r"^point='P': not an output fourbar was prepared for \(outputs: B\)"):
        curve(scene, "P")


def test_a_prepared_scene_is_a_value():
    scene = algkin.prepare("fourbar", outputs=["B"])
    assert scene == algkin.prepare("fourbar", outputs=["B"]) and len({scene, algkin.prepare("fourbar", outputs=["B"])}) == 1
    assert scene != algkin.prepare("fourbar", outputs=["B"], set={"a": "1/2"})
    with pytest.raises(AttributeError):
        scene.branches = ()  # type: ignore[misc]
