"""What sympy's assumptions cannot know of a sign, shown without asking them.

sympy's assumptions are sound: an expression in symbols assumed real (and nothing more) that is positive
at one real point and negative (or not real) at another is one sympy can prove neither nonnegative nor
negative. Where such a point pair is found, the answer sympy would reach after asking (milliseconds of
assumption queries for each new factor of a closed form's root) is known: the root of such factors stays
whole. ``takes_both_signs`` finds the pair exactly for a polynomial; ``signs_unknowable`` in balls for any
expression closed forms hold (roots of roots).

>>> c = sympy.Symbol("c", real=True)
>>> takes_both_signs(5 - 4*c), signs_unknowable((5 - 4*c, sympy.sqrt(c))), signs_unknowable((c**2 + 1,))
(True, True, False)
"""

import random

import flint
import sympy

from ..evaluate import ARB, NumberKind, evaluate
from .convert import flint_context, to_flint

__all__ = ["plain_real", "takes_both_signs", "signs_unknowable"]

_PLAIN_REAL = sympy.Symbol("x", real=True).assumptions0  # what sympy knows of a real symbol, and no more
_WITNESSES = 32  # points tried before sympy is asked: a tower's roots show their sides in the first few
_SPREAD = 64  # each symbol's value k/16 for an integer |k| <= _SPREAD
_POSITIVE, _NEGATIVE, _NOT_REAL = "positive", "negative", "not real"


def _no_absolute(value: flint.acb) -> flint.acb:
    raise TypeError("an absolute value: its complex ball is not the one sympy means")


_COMPLEX: NumberKind[flint.acb] = NumberKind("acb", number=lambda p, q: flint.acb(flint.fmpq(p, q)),
                                             sqrt=lambda v: v.sqrt(), absolute=_no_absolute)


def plain_real(variable: sympy.Basic) -> bool:
    """A symbol assumed real and nothing more, as algkin makes them: any real value is one it may take."""
    return type(variable) is sympy.Symbol and variable.assumptions0 == _PLAIN_REAL


def signs_unknowable(factors: tuple[sympy.Expr, ...]) -> bool:
    """Whether sympy can know neither the sign of any of ``factors`` (is it nonnegative?) nor that their
    product is imaginary: each, in symbols assumed real and nothing more, is shown positive at some real
    point and negative or not real at another (exactly for a polynomial, ``takes_both_signs``; else in balls
    at rational points, the same ones each time), and all of them real and not 0 at one point. False
    where that is not shown."""
    if not all(plain_real(v) for f in factors for v in f.free_symbols):
        return False
    exact = [takes_both_signs(f) for f in factors]
    names = sorted({v.name for f in factors for v in f.free_symbols})
    seen: list[set[str | None]] = [set() for _ in factors]
    all_real = False
    chooser = random.Random(0)  # seeded: a document is written the same way each time
    for _ in range(_WITNESSES):
        values = {n: flint.fmpq(chooser.randint(-_SPREAD, _SPREAD), 16) for n in names}
        try:
            sides = [_side(f, values) for f in factors]
        except TypeError:  # what closed forms do not hold: sympy is asked
            return False
        all_real = all_real or all(side in (_POSITIVE, _NEGATIVE) for side in sides)
        for found, side in zip(seen, sides):
            found.add(side)
        if all_real and all(shown or _POSITIVE in found and (_NEGATIVE in found or _NOT_REAL in found)
                            for shown, found in zip(exact, seen)):
            return True
    return False


def _side(expr: sympy.Expr, values: dict[str, flint.fmpq]) -> str | None:
    """Where ``expr``'s value at the rational point ``values`` certainly is: positive, negative, not real;
    None where the balls do not decide (or the value is 0)."""
    real = evaluate(expr, {n: flint.arb(v) for n, v in values.items()}, ARB)  # nan where a root is of < 0
    if real > 0:
        return _POSITIVE
    if real < 0:
        return _NEGATIVE
    value = evaluate(expr, {n: flint.acb(v) for n, v in values.items()}, _COMPLEX)
    return _NOT_REAL if value.imag > 0 or value.imag < 0 else None


def takes_both_signs(expr: sympy.Expr) -> bool:
    """Whether ``expr``, a polynomial with rational coefficients in real symbols, is shown to be
    positive somewhere and negative somewhere: at two exact points on the line of a variable of odd
    degree, the others at 0, beyond every root there (Cauchy's bound). False where nothing is shown.

    >>> c, s = sympy.symbols("c s", real=True)
    >>> takes_both_signs(5 - 4*c), takes_both_signs(c**2 + s**2), takes_both_signs(s**2 * c + 1)
    (True, False, False)
    >>> takes_both_signs(5 - 4*sympy.Symbol("l", positive=True))   # true, but l < 0 is no witness
    False
    """
    names = [v.name for v in expr.free_symbols]
    # any real value is one sympy must allow: no symbol is known positive, an integer...
    if not names or len(set(names)) != len(names) or not all(plain_real(v) for v in expr.free_symbols):
        return False
    try:
        poly = to_flint(expr, flint_context(sorted(names)))
    except TypeError:  # a root, a quotient: not a polynomial
        return False
    for k, degree in enumerate(poly.degrees()):
        if degree % 2:
            line = poly.subs({n: 0 for j, n in enumerate(poly.context().names()) if j != k})
            coefficients = dict(zip((m[k] for m in line.monoms()), line.coeffs()))
            lead = coefficients.get(degree)
            if lead:
                bound = 1 + sum(abs(c) for c in coefficients.values()) / abs(lead)
                point = [flint.fmpq(0)] * len(names)
                signs = []
                for end in (bound, -bound):
                    point[k] = end
                    signs.append(line(*point) > 0)
                return signs[0] != signs[1]
    return False
