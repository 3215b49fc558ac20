"""Closed forms match the independent numeric solution (``algkin.verify``) on every branch."""

import pytest
from hypothesis import given, settings, strategies as st

from algkin.derivation.pipeline import derive
from algkin.testing import strategies

SAMPLES = 2


@pytest.mark.slow  # one of the largest property runs (10-25 s): the slow set, which CI runs
@settings(max_examples=60)
@given(strategies.scenes(), st.integers(0, 2**16))
def test_branches_match_numeric_solutions(scene, seed):
    result = derive(scene, ["B", "P"], samples=SAMPLES, seed=seed, certify=False)
    assert result.verification.passed, result.verification.failures
    assert result.verification.compared > 0  # a pass means a closed-form value was compared
    assert [b.label for b in result.branches] in (["left", "right"], ["ahead", "behind"])


turning = st.one_of(strategies.four_bars("crank-rocker"), strategies.four_bars("double-crank"),
                    strategies.slider_cranks())


@settings(max_examples=50)
@given(turning, st.integers(0, 2**16))
def test_every_branch_is_compared_when_the_crank_turns(scene, seed):
    # The crank turns fully: at every sampled angle both branches are real and compared.
    verification = derive(scene, ["B"], samples=SAMPLES, seed=seed, certify=False).verification
    assert verification.passed, verification.failures
    assert verification.near_degenerate == 0
    assert verification.compared == 2 * verification.samples >= 2 * SAMPLES


@pytest.mark.slow  # one of the largest property runs (10-25 s): the slow set, which CI runs
@settings(max_examples=30)
@given(strategies.with_symbolic(max_symbols=2), st.integers(0, 2**16))
def test_symbolic_closed_forms_at_the_defaults(scene_and_params, seed):
    scene, params = scene_and_params
    result = derive(scene, ["B", "P"], params=params, samples=SAMPLES, seed=seed, certify=False)
    assert result.verification.passed, result.verification.failures
    assert result.verification.compared > 0
    assert set(result.compiled.system.parameters) <= set(params)
