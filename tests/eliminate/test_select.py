"""Factor selection at witnesses: decided at a precision the factor needs, not at 53 bits."""

import flint
import sympy
from hypothesis import given, settings, strategies as st

from algkin.eliminate.backends import BACKENDS
from algkin.eliminate.select import Evaluator, Horner, select_factors
from algkin.system import symbol


def _engine(name):
    return BACKENDS[name](("x", "y"))


def test_a_factor_with_huge_coefficients_is_dropped_where_it_is_one():
    # At x = 3, y = 5 (exact witnesses): 2**200*(x - 3) + 1 is exactly 1. At python-flint's
    # default 53 bits its ball would be about 2**149 wide, "containing" zero.
    x = symbol("x")
    for name in BACKENDS:
        engine = _engine(name)
        curve, spurious = engine.from_sympy(x - 3), engine.from_sympy(2**200 * (x - 3) + 1)
        witness = {"x": flint.arb(3), "y": flint.arb(5)}
        kept, dropped = select_factors(engine, [curve, spurious], [[witness]])
        assert [engine.to_sympy(f) for f in kept] == [x - 3]
        assert [engine.to_sympy(f) for f in dropped] == [2**200 * (x - 3) + 1]


def test_a_high_degree_factor_vanishing_at_an_irrational_witness_is_kept():
    # x = sqrt(2) at 256 bits: (x**2 - 2)**5 * 3**40 vanishes; x**10 - 31 does not (sqrt(2)**10 = 32).
    x = symbol("x")
    with flint.ctx.workprec(256):
        witness = {"x": flint.arb(2).sqrt(), "y": flint.arb(1)}
    for name in BACKENDS:
        engine = _engine(name)
        vanishing, other = engine.from_sympy(3**40 * (x**2 - 2) ** 5), engine.from_sympy(x**10 - 31)
        kept, dropped = select_factors(engine, [vanishing, other], [[witness]])
        assert len(kept) == 1 and len(dropped) == 1
        assert engine.to_sympy(dropped[0]) == x**10 - 31


def test_exact_coordinates_decide_where_balls_cannot():
    # t = 1/3 is a rational input. As a 256-bit ball its radius is about 2**-258, so the ball of
    # t - 1/3 - 2**-300 contains zero; substituting t exactly gives -2**-300, proved non-zero.
    from algkin.eliminate.select import Witness

    t = symbol("t")
    engine = BACKENDS["flint"](("x", "t"))
    near = engine.from_sympy(t - sympy.Rational(1, 3) - sympy.Rational(1, 2**300))
    with flint.ctx.workprec(256):
        balls = {"x": flint.arb(2).sqrt(), "t": flint.arb(1) / 3}
    kept, dropped = select_factors(engine, [near], [[balls]])
    assert kept == [near] and dropped == []  # the ball cannot tell
    with flint.ctx.workprec(256):
        exact = Witness(balls, {"t": flint.fmpq(1, 3)})
    curve = engine.from_sympy(3 * t - 1)
    kept, dropped = select_factors(engine, [curve, near], [[exact]])
    assert kept == [curve] and dropped == [near]


def test_witnesses_with_and_without_exact_coordinates_agree_on_the_symbolic_four_bar():
    from algkin.bench.problems import build

    task = build("fourbar-symbolic").task
    plain = tuple(tuple(dict(point) for point in group) for group in task.witnesses)
    exact = task.run("linear", "flint")
    balls = type(task)(task.equations, task.eliminate, task.keep, task.parameters, plain).run("linear", "flint")
    assert exact.raw == balls.raw and exact.raw_dropped == balls.raw_dropped


@settings(max_examples=100, deadline=None)
@given(st.lists(st.fractions(max_denominator=50).filter(lambda f: abs(f) < 1000), min_size=1, max_size=12),
       st.fractions(max_denominator=50).filter(lambda f: abs(f) < 10))
def test_horners_rule_and_the_evaluator_enclose_the_exact_value(coefficients, at):
    # the value computed exactly over QQ (python-flint's fmpq_poly) lies in both balls, and both are narrow
    terms = [((k, 0), c.numerator, c.denominator) for k, c in enumerate(coefficients) if c][::-1] or [((0, 0), 0, 1)]
    x = flint.fmpq(at.numerator, at.denominator)
    exact = flint.fmpq_poly([flint.fmpq(c.numerator, c.denominator) for c in coefficients])(x)
    with flint.ctx.workprec(200):
        point = {"x": flint.arb(x), "y": flint.arb(7)}
    for evaluate in (Horner(terms, ("x", "y"), 128, 4, variable=0), Evaluator(terms, ("x", "y"), 128, 4)):
        value = evaluate(point)
        with flint.ctx.workprec(400):  # the exact value as a ball far narrower than either
            assert (value - flint.arb(exact)).contains(0) and value.rad() < flint.arb(2) ** -100
