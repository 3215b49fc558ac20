"""derive's and curve's results are immutable, hashable values (issue 31)."""

import json

import attrs
import pytest

from algkin.derivation.pipeline import curve, derive
from algkin.verify.check import Status, Verification


@pytest.fixture(scope="module")
def lambda_b():
    return derive("chebyshev-lambda", outputs=["B"], samples=5, certify=False)


def test_a_derivation_cannot_be_changed(lambda_b):
    with pytest.raises(attrs.exceptions.FrozenInstanceError):
        lambda_b.method = "groebner"
    with pytest.raises(TypeError):
        lambda_b.branches[0].values["B_x"] = 0
    with pytest.raises(TypeError):
        lambda_b.eliminations["B_x"] = None
    with pytest.raises(TypeError):
        lambda_b.timings["total"] = 0.0
    with pytest.raises(attrs.exceptions.FrozenInstanceError):
        lambda_b.verification.status = Status.FAILED


def test_results_hash_and_their_json_is_plain(lambda_b):
    found = curve("chebyshev-lambda", "P", samples=5)
    assert isinstance(hash(lambda_b), int) and isinstance(hash(found), int)
    assert hash(lambda_b.verification) == hash(attrs.evolve(lambda_b.verification))
    text = json.loads(json.dumps(lambda_b.to_json()))
    assert text["verification"]["status"] == "passed" and text["verification"]["passed"] is True
    assert json.loads(json.dumps(found.to_json()))["verification"]["status"] == "passed"


def test_the_status_says_passed_once_built():
    skipped = Verification.skipped()
    assert skipped.status is Status.SKIPPED and not skipped.passed
    assert skipped.to_json()["status"] == "skipped"
    assert attrs.evolve(skipped, status=Status.PASSED).passed
