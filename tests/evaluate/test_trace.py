"""Tracing records the numpy form's own operations, in its order; what it cannot record, it refuses."""

import numpy as np
import pytest

from algkin.evaluate.trace import trace


def _run(program, **inputs):
    """The traced program executed line by line as numpy code: its outputs."""
    scope = {"np": np, **inputs}
    exec(program.body("numpy"), scope)  # noqa: S102 - the program under test
    return [scope[o] if isinstance(o, str) else o for o in program.outputs]


def test_the_trace_keeps_the_order_of_a_cancellation_free_difference():
    high, low = 1.0 + 2.0**-30, 2.0**-80  # (t - high) - low: t - high exact near the root (Sterbenz)
    program = trace(lambda t: [(t - high) - low], ["t"])
    assert [op for _, op, _ in program.lines] == ["sub", "sub"]
    t = np.array([1.0 + 2.0**-30 + 2.0**-52])
    assert _run(program, t=t)[0][0] == (t[0] - high) - low


def test_ufuncs_where_and_constants_replay_to_the_same_values():
    def f(x, y):
        d = np.hypot(x, y)
        return [np.where(np.copysign(1.0, x) == 1.0, d / y, -d), np.maximum(x, 2.0) * np.full_like(x, 3.0), 7]

    program = trace(f, ["x", "y"])
    x, y = np.array([1.5, -2.0, 0.0]), np.array([2.0, 3.0, -1.0])
    got = _run(program, x=x, y=y)
    for a, b in zip(got, f(x, y)):
        np.testing.assert_array_equal(a, b)
    assert program.outputs[2] == 7.0


def test_a_branch_on_a_traced_value_is_refused():
    with pytest.raises(TypeError, match="np.where"):
        trace(lambda t: [t if t > 0 else -t], ["t"])
    with pytest.raises(TypeError, match="cannot trace"):
        trace(lambda t: [np.exp(t)], ["t"])


def test_select_drops_what_no_kept_output_needs():
    program = trace(lambda t: [t * 2.0, np.sqrt(t) + 1.0], ["t"])
    second = program.select([1])
    assert [op for _, op, _ in second.lines] == ["sqrt", "add"] and second.outputs == [program.outputs[1]]


def test_an_input_named_like_a_temporary_gets_temporaries_of_another_name():
    program = trace(lambda v0, v1: [v0 * v1 + 1.0], ["v0", "v1"])
    assert [name for name, _, _ in program.lines] == ["v_0", "v_1"]
    assert _run(program, v0=np.array([2.0]), v1=np.array([3.0]))[0][0] == 7.0
