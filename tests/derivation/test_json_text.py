"""The JSON documents of ``derive`` and ``curve`` written from python-flint where sympy's printing was
most of writing them (issue 34: a cold command's wall time): the same text, no sympy form built."""

import pytest

import algkin
from algkin.eliminate.backends import FlintBackend
from algkin.runtime.cache import clear_caches


def _refuse_sympy(self, poly):
    raise AssertionError(f"converted to sympy while writing the JSON: {str(poly)[:60]}...")


@pytest.fixture
def cold():
    """Nothing a previous test converted to sympy is reused: every elimination made afresh."""
    clear_caches()
    yield
    clear_caches()


@pytest.mark.parametrize(("scene", "point"), [("watt-i", "P"), ("fourbar", "P"), ("chebyshev-lambda", "P")])
def test_a_curves_dropped_factors_are_written_as_sympy_writes_them(scene, point, cold):
    result = algkin.curve(scene, point, samples=0)
    written = result.to_json()["dropped_factors"]
    assert written  # each of these curves drops an extraneous factor
    assert written == [str(f) for f in result.elimination.dropped]  # sympy's conversion and printing


@pytest.mark.parametrize("scene", ["watt-i", "hart-inversor"])
def test_a_derivations_dropped_factors_are_written_as_sympy_writes_them(scene, cold):
    result = algkin.derive(scene, samples=0)
    figures = result.to_json()["eliminant_figures"]
    assert any(f["dropped_factors"] for f in figures.values())
    assert {u: f["dropped_factors"] for u, f in figures.items()} == \
        {u: [str(f) for f in e.dropped] for u, e in result.eliminations.items()}


def test_a_curves_json_converts_no_dropped_factor_to_sympy(cold, monkeypatch):
    result = algkin.curve("watt-i", "P", samples=0)
    monkeypatch.setattr(FlintBackend, "to_sympy", _refuse_sympy)
    assert len(result.to_json()["dropped_factors"]) == 3
