"""algkin.runtime.strict_json: every document is strict JSON, a non-finite float read back as null and
every other value as it was."""

import json
import math

from hypothesis import given, strategies as st

from algkin.runtime.strict_json import json_text

SCALARS = st.none() | st.booleans() | st.integers() | st.floats() | st.text()
DOCUMENTS = st.recursive(SCALARS, lambda children: st.lists(children, max_size=4)
                         | st.dictionaries(st.text(max_size=5), children, max_size=4), max_leaves=20)


def _refuse(constant):
    raise ValueError(f"not strict JSON: {constant}")


def _expected(value):
    """The document as a strict reader must get it back, written from the definition."""
    if isinstance(value, float) and (math.isnan(value) or math.isinf(value)):
        return None
    if isinstance(value, dict):
        return {k: _expected(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_expected(v) for v in value]
    return value


@given(DOCUMENTS)
def test_a_document_is_strict_json_with_null_for_each_number_that_is_not_finite(document):
    text = json_text(document)
    assert text.endswith("\n")
    assert json.loads(text, parse_constant=_refuse) == _expected(document)


def test_a_verification_measured_on_nothing_reads_as_null():
    # an unsolved accuracy row's error, a factor residual no root was evaluated at
    text = json_text({"max_rel_error": float("inf"), "smallest_factor_residual": {"B_x": (float("inf"),)}})
    assert json.loads(text, parse_constant=_refuse) == {"max_rel_error": None, "smallest_factor_residual": {"B_x": [None]}}
