"""One conformance suite that every method x backend passes (names from the tables)."""

import flint
import pytest
import sympy

from algkin.eliminate import BACKENDS, METHODS, eliminate
from algkin.errors import ComputationError, UsageError

x, y, t, c, s, r = (sympy.Symbol(n, real=True) for n in ("x", "y", "t", "c", "s", "r"))

ALL = pytest.mark.parametrize("method,backend", [(m, b) for m in sorted(METHODS) for b in sorted(BACKENDS)])


def proportional(a, b):
    ratio = sympy.cancel(sympy.sympify(a) / sympy.sympify(b))
    return ratio.is_number and ratio != 0


@ALL
def test_radical_axis_of_two_circles(method, backend):
    # Circles about (0,0) radius 3 and (4,0) radius 2 meet where x = (9 - 4 + 16)/8 = 21/8.
    eqs = [x**2 + y**2 - 9, (x - 4) ** 2 + y**2 - 4]
    result = eliminate(eqs, ["y"], ["x"], method=method, backend=backend)
    assert proportional(result.polynomial, 8 * x - 21)
    # and then y**2 = 9 - (21/8)**2 = 135/64.
    result = eliminate(eqs, ["x"], ["y"], method=method, backend=backend)
    assert proportional(result.polynomial, 64 * y**2 - 135)


@ALL
def test_symbolic_radius(method, backend):
    # x**2 + y**2 = r**2 and y = x: x**2 = r**2 / 2, by hand.
    result = eliminate([x**2 + y**2 - r**2, y - x], ["y"], ["x", "r"], method=method, backend=backend)
    assert proportional(result.polynomial, 2 * x**2 - r**2)
    assert result.degree == 2 and result.terms == 2


@ALL
def test_witnesses_drop_the_factor_the_motion_misses(method, backend):
    # (x - t)(x + t - 10) = 0 with t = 1: the motion sits on x = 1, not on x = 9.
    eqs = [(x - t) * (x + t - 10), t - 1]
    with flint.ctx.workprec(128):
        witness = {"x": flint.arb(1), "t": flint.arb(1)}
    result = eliminate(eqs, ["t"], ["x"], method=method, backend=backend, witnesses=[[witness]])
    assert proportional(result.polynomial, x - 1)
    assert [sympy.expand(f) for f in result.dropped] == [x - 9]


@ALL
def test_witnesses_keep_both_branches(method, backend):
    # Two branches, one witness each: x = +sqrt(2) and x = -sqrt(2) both stay.
    with flint.ctx.workprec(128):
        plus = {"x": flint.arb(2).sqrt(), "t": flint.arb(2)}
        minus = {"x": -flint.arb(2).sqrt(), "t": flint.arb(2)}
    result = eliminate([x**2 - t, t - 2], ["t"], ["x"], method=method, backend=backend, witnesses=[[plus], [minus]])
    assert proportional(result.polynomial, x**2 - 2)
    assert result.dropped == []


@ALL
def test_parametrised_circle_gives_the_unit_circle(method, backend):
    # c = (1 - t**2)/(1 + t**2), s = 2t/(1 + t**2) traces c**2 + s**2 = 1.
    eqs = [c * (1 + t**2) - (1 - t**2), s * (1 + t**2) - 2 * t]
    result = eliminate(eqs, ["t"], ["c", "s"], method=method, backend=backend)
    factors = [f for f, _ in sympy.factor_list(result.polynomial)[1]]
    assert any(proportional(f, c**2 + s**2 - 1) for f in factors)


@ALL
def test_inconsistent_system_fails_loudly(method, backend):
    with pytest.raises(ComputationError):
        eliminate([x - 1, x - 2, y - x], ["x"], ["y"], method=method, backend=backend)


def test_unknown_names_list_the_valid_ones():
    with pytest.raises(UsageError, match="valid: groebner, interpolate, linear, resultant"):
        eliminate([x - 1], [], ["x"], method="magic")
    with pytest.raises(UsageError, match="valid: flint, sympy"):
        eliminate([x - 1], [], ["x"], backend="maple")
