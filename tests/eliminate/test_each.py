"""Many specializations of one system eliminated in one call (``eliminate_each``).

Expected eliminants come from sympy's resultant of the specialized equations (a second
implementation), never from algkin's own elimination.
"""

import flint
import pytest
import sympy

from algkin.bench.problems import build
from algkin.eliminate import eliminate, eliminate_each
from algkin.errors import UsageError
from algkin.system import symbol

X, Y, C, S, R = sympy.symbols("x y c s r")
# the seed's two circles with the crank's cos and sin, and the coupler's length r, left symbolic
CIRCLES = [(X - C)**2 + (Y - S)**2 - R**2, X**2 - 4 * X + Y**2 - sympy.Rational(9, 4)]
POINTS = [{"c": flint.fmpq(3, 5), "s": flint.fmpq(4, 5), "r": flint.fmpq(5, 2)},
          {"c": flint.fmpq(5, 13), "s": flint.fmpq(-12, 13), "r": 2},
          {"c": 1, "s": 0, "r": flint.fmpq(1, 3)}]


def proportional(a, b):
    # read back from text: algkin's symbols are real, these are not
    ratio = sympy.cancel(sympy.sympify(str(a)) / sympy.sympify(str(b)))
    return ratio.is_number and ratio != 0


def at(point):
    return {sympy.Symbol(name): sympy.Rational(int(flint.fmpq(v).p), int(flint.fmpq(v).q)) for name, v in point.items()}


def test_each_specialization_gives_the_resultant_of_its_equations():
    results = eliminate_each(CIRCLES, ["x"], ["y", "c", "s", "r"], at=POINTS)
    assert len(results) == len(POINTS)
    for result, point in zip(results, POINTS):
        expected = sympy.sqf_part(sympy.resultant(*(e.subs(at(point)) for e in CIRCLES), X))
        assert proportional(result.polynomial, expected)


def test_each_result_is_what_eliminate_gives_on_the_specialized_equations():
    for result, point in zip(eliminate_each(CIRCLES, ["x"], ["y", "c", "s", "r"], at=POINTS), POINTS):
        alone = eliminate([e.subs(at(point)) for e in CIRCLES], ["x"], ["y", "c", "s", "r"])
        assert result.text == alone.text and result.log == alone.log and result.proof == alone.proof


def test_only_kept_variables_are_specialized():
    # x is eliminated: setting it would change the system, not specialize it
    with pytest.raises(UsageError, match="at='x': not a kept variable \\(kept: y, c, s, r\\)"):
        eliminate_each(CIRCLES, ["x"], ["y", "c", "s", "r"], at=[{"r": 1}, {"x": 2}])


def test_witnesses_are_given_for_each_specialization_or_not_at_all():
    with pytest.raises(UsageError, match="witnesses=1: expected one set of witness groups for each of the 3"):
        eliminate_each(CIRCLES, ["x"], ["y", "c", "s", "r"], at=POINTS, witnesses=[()])


def test_the_witnesses_of_each_specialization_choose_its_factors():
    # the seed's connector at its own input, as ``derive`` eliminates it: specialized at that
    # input with its witnesses, the kept factor is the resultant at that input (sympy's)
    task = build("two-circles").task
    exact = dict(task.witnesses[0][0].exact)
    result, = eliminate_each(task.polynomials, task.eliminate, task.keep, at=[exact], witnesses=[task.witnesses],
                             parameters=task.parameters)
    values = {symbol(name): sympy.Rational(int(v.p), int(v.q)) for name, v in exact.items()}
    expected = sympy.resultant(*(e.subs(values) for e in task.equations), symbol("B_x"))
    assert proportional(result.polynomial, expected) and result.proof is not None
