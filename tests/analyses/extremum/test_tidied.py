"""A closed form's value tidied: each square root's radicand one factored fraction, the terms over it
collected; kept as it was unless shorter and equal (50 digits)."""

import sympy

from algkin.analyses.extremum.closed import tidied

DIGITS = 50
# fourbar's B.y with a symbolic, on 3.57 < a < 4.03 (its folded dead centre), as it was written
OLD_FORM = ("7*a**2*sqrt(-4*a**2/(4*a**2 + 32*a + 63) + 32*a/(4*a**2 + 32*a + 63) - 63/(4*a**2 + 32*a + 63))/8"
            " + 7*a*sqrt(-4*a**2/(4*a**2 + 32*a + 63) + 32*a/(4*a**2 + 32*a + 63) - 63/(4*a**2 + 32*a + 63))"
            " + 441*sqrt(-4*a**2/(4*a**2 + 32*a + 63) + 32*a/(4*a**2 + 32*a + 63) - 63/(4*a**2 + 32*a + 63))/32")


def test_tidied_writes_the_root_once_over_one_factored_fraction():
    a = sympy.Symbol("a", real=True)
    old = sympy.sympify(OLD_FORM, locals={"a": a})
    tidy = tidied(old)
    # by hand: the radicand is -(4a**2 - 32a + 63) / (4a**2 + 32a + 63), the coefficients sum to
    # 7 (4a**2 + 32a + 63) / 32, and 4a**2 + 32a + 63 = (2a + 7)(2a + 9)
    hand = 7 * (2 * a + 7) * (2 * a + 9) / 32 * sympy.sqrt(-(2 * a - 7) * (2 * a - 9) / ((2 * a + 7) * (2 * a + 9)))
    assert sympy.cancel(tidy**2 - hand**2) == 0 and str(tidy).count("sqrt") == 1
    assert sympy.count_ops(tidy) <= sympy.count_ops(old) / 3
    for value in ("-4", "-37/10", "5", "1/3"):  # either side of the roots, real and not
        at = {a: sympy.Rational(value)}
        assert abs(sympy.N(tidy.xreplace(at) - old.xreplace(at), DIGITS)) < 1e-45


def test_tidied_keeps_a_form_it_cannot_shorten():
    b = sympy.Symbol("b", real=True)
    for expr in (sympy.sqrt(b**2 + 160000) - 350, sympy.sqrt(2) / 3 + sympy.Rational(1, 2), b):
        assert tidied(expr) is expr
