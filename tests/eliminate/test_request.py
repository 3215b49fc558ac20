"""The methods called as ``method(backend, polys, request) -> MethodOutcome``, and outcomes chained."""

import pytest
import sympy

from algkin.eliminate import BACKENDS, METHODS
from algkin.eliminate.request import EliminationRequest, MethodOutcome
from algkin.system import symbol

x, y = symbol("x"), symbol("y")


@pytest.mark.parametrize("backend", sorted(BACKENDS))
@pytest.mark.parametrize("method", sorted(METHODS))
def test_every_method_answers_an_outcome(method, backend):
    # Circles about (0,0) radius 3 and (4,0) radius 2 meet where x = 21/8 (see test_conformance).
    engine = BACKENDS[backend](("y", "x"))
    polys = [engine.from_sympy(e) for e in (x**2 + y**2 - 9, (x - 4) ** 2 + y**2 - 4)]
    outcome = METHODS[method](engine, polys, EliminationRequest(("y",)))
    assert isinstance(outcome, MethodOutcome) and outcome.left and outcome.dropped == []
    assert all(sympy.factor(engine.to_sympy(p)).has(8 * x - 21) for p in outcome.left)
    # linear too: the radical axis (x = 21/8) holds no y to substitute, so it takes one resultant
    assert [kind for kind, _ in outcome.log] == ["groebner" if method == "groebner" else "resultant"]


def test_then_keeps_the_last_equations_and_everything_found_on_the_way():
    first = MethodOutcome(["a"], ["d1"], [("substituted", "u")], ["m1"])
    second = MethodOutcome(["b"], ["d2"], [("resultant", "v")], ["m2"])
    assert first.then(second) == MethodOutcome(["b"], ["d1", "d2"], [("substituted", "u"), ("resultant", "v")],
                                               ["m1", "m2"])
