"""python-flint's balls pickle (``algkin.evaluate.pickled``): the midpoint exactly, the radius no smaller."""

import pickle

import flint
import pytest
from hypothesis import given
from hypothesis import strategies as st


@given(numerator=st.integers(-10**60, 10**60), denominator=st.integers(1, 10**40), bits=st.sampled_from([53, 200, 3000]))
def test_a_ball_comes_back_with_its_midpoint_and_at_least_its_radius(numerator, denominator, bits):
    with flint.ctx.workprec(bits):
        ball = flint.arb(flint.fmpq(numerator, denominator)).sqrt() if numerator >= 0 \
            else flint.arb(flint.fmpq(numerator, denominator))
    back = pickle.loads(pickle.dumps(ball))
    assert back.mid() == ball.mid() and back.rad() >= ball.rad()
    assert back.rad() <= ball.rad() * (1 + flint.arb(2) ** -28)  # one unit of its 30 bits at most
    assert back.contains(ball)


@pytest.mark.parametrize("text", ["nan", "+inf", "-inf"])
def test_what_is_not_a_finite_ball_comes_back_as_it_was(text):
    assert pickle.loads(pickle.dumps(flint.arb(text))).repr() == flint.arb(text).repr()
