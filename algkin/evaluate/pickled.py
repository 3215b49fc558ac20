"""python-flint's balls and rational polynomials pickled, so that a result holding them (a prepared
scene's witnesses, a followed mode's samples, a singular point's enclosure, a group's curve) pickles,
as it must to come back from a budget's child process: python-flint 0.9 pickles neither.

A ball travels as its midpoint and radius, each an exact mantissa and exponent. The midpoint comes
back exactly; python-flint rounds a radius it is given up to its 30-bit magnitudes, so the radius
may come back one unit in its last place larger: the ball still holds every value it held.

>>> import pickle
>>> with flint.ctx.workprec(200):
...     third = flint.arb(1) / 3
>>> back = pickle.loads(pickle.dumps(third))
>>> back.mid() == third.mid() and back.rad() >= third.rad() and back.contains(third)
True
>>> [pickle.loads(pickle.dumps(ball)).repr() for ball in (flint.arb("nan"), flint.arb("-inf"), flint.arb(2, "inf"))]
["arb('nan')", "arb('-inf')", "arb((0x1, 0x1), '+inf')"]

A polynomial travels as its context's names and ordering, and its terms:

>>> ctx = flint.fmpq_mpoly_ctx.get(("x", "y"), "lex")
>>> x, y = ctx.gens()
>>> pickle.loads(pickle.dumps(x**2 - y / 3)) == x**2 - y / 3
True
"""

import copyreg
from collections.abc import Callable
from typing import Any

import flint

__all__ = ["arb_from", "polynomial_from"]

Part = tuple[int, int] | str  # mantissa and exponent (mantissa * 2**exponent), or 'nan', 'inf', '-inf'


def _ball_reduced(ball: flint.arb) -> tuple[Callable[[Part, Part], flint.arb], tuple[Part, Part]]:
    return arb_from, (_part(ball.mid()), _part(ball.rad()))


def _part(value: flint.arb) -> Part:
    if not value.is_finite():
        return repr(float(value))
    mantissa, exponent = value.man_exp()
    return int(mantissa), int(exponent)


def arb_from(mid: Part, rad: Part) -> flint.arb:
    """The ball ``_ball_reduced`` wrote, at the precision its midpoint needs, so that it is not rounded."""
    bits = mid[0].bit_length() if isinstance(mid, tuple) else 2
    with flint.ctx.workprec(max(bits, 2)):
        return flint.arb(flint.arf(mid), flint.arf(rad))


def _polynomial_reduced(poly: flint.fmpq_mpoly) -> tuple[Callable[..., flint.fmpq_mpoly], tuple[Any, ...]]:
    ctx = poly.context()
    return polynomial_from, (tuple(ctx.names()), ctx.ordering().name, poly.to_dict())


def polynomial_from(names: tuple[str, ...], ordering: str, terms: dict[tuple[int, ...], Any]) -> flint.fmpq_mpoly:
    """The polynomial ``_polynomial_reduced`` wrote: ``terms`` (exponents -> coefficient) over ``names``."""
    return flint.fmpq_mpoly_ctx.get(names, ordering).from_dict(terms)


copyreg.pickle(flint.arb, _ball_reduced)
copyreg.pickle(flint.fmpq_mpoly, _polynomial_reduced)
