"""Reading a peer engine's polynomials back: its syntax, and text it cannot be."""

import pytest

from algkin.bench.peers import parse, polynomial_ring


def test_a_polynomial_in_an_engines_syntax_reads_back():
    ring = polynomial_ring(["x", "y"])
    x, y = ring.gens
    assert parse("(x^2+3*y)/2-(-y)**2", ring) == (x**2 + 3 * y) / 2 - y**2


@pytest.mark.parametrize("text", ["x^y", "x/y", "x^", "x/"])
def test_an_exponent_or_divisor_that_is_no_number_is_a_value_error(text):
    with pytest.raises(ValueError, match="cannot read polynomial"):
        parse(text, polynomial_ring(["x", "y"]))
