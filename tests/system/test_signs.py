"""``system.signs``: what it shows of a sign is what sympy's assumptions cannot know."""

import sympy
from hypothesis import given, strategies as st

from algkin.system.signs import signs_unknowable, takes_both_signs

C, S = sympy.symbols("c s", real=True)
# sums of monomials of any sign, sympy's known or not (c**2 + s**2 + 1 > 0, -c**2 <= 0)
HUGE = sympy.Integer(10) ** 400  # a coefficient of 400 digits, or its inverse
any_sums = st.lists(st.tuples(st.integers(-50, 50).filter(bool) | st.sampled_from([HUGE, -1 / HUGE]),
                              st.integers(0, 4), st.integers(0, 3)),
                    min_size=1, max_size=5).map(lambda terms: sympy.Add(*[k * C**i * S**j for k, i, j in terms])
                                                ).filter(lambda p: not p.is_number)


@given(any_sums)
def test_a_sum_said_to_take_both_signs_is_of_no_sign_sympy_knows(p):
    if takes_both_signs(p):
        assert p.is_extended_nonnegative is None and p.is_extended_nonpositive is None


@given(st.lists(any_sums | any_sums.map(sympy.sqrt), min_size=1, max_size=3))
def test_factors_said_unknowable_are_of_no_sign_sympy_knows(factors):
    if signs_unknowable(tuple(factors)):
        # what sympy's root of their product asks of each (``Pow._eval_expand_power_base``)
        assert all(f.is_extended_nonnegative is None for f in factors)
        assert sympy.Mul(*factors).is_imaginary is not True


def test_a_line_takes_both_signs_and_a_sum_of_squares_not():
    assert takes_both_signs(5 - 4 * C) and takes_both_signs(C * S**2 - 3 * S + C + 1)
    assert not takes_both_signs(C**2 + S**2 + 1) and not takes_both_signs(-C**4 - S**2)


def test_a_root_of_a_sign_taking_polynomial_is_unknowable_and_a_positive_factor_not():
    # sqrt(c): positive for c > 0, not real for c < 0; 5 - 4*c both signs; c**2 + 1 > 0 always
    assert signs_unknowable((5 - 4 * C, sympy.sqrt(C))) and signs_unknowable((5 - 4 * C, C + 5))  # c < -5 too
    assert not signs_unknowable((5 - 4 * C, C**2 + 1))
    assert not signs_unknowable((5 - 4 * sympy.Symbol("l", positive=True),))  # l < 0 is no value of l
