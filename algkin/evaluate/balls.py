"""python-flint's balls pickled, so that a result holding them (a prepared scene's witnesses, a
followed mode's samples, a singular point's enclosure) pickles: python-flint 0.9 pickles no ``arb``.

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
"""

import copyreg
from collections.abc import Callable

import flint

__all__ = ["arb_from"]

Part = tuple[int, int] | str  # mantissa and exponent (mantissa * 2**exponent), or 'nan', 'inf', '-inf'


def _reduced(ball: flint.arb) -> tuple[Callable[[Part, Part], flint.arb], tuple[Part, Part]]:
    return arb_from, (_part(ball.mid()), _part(ball.rad()))


def _part(value: flint.arb) -> Part:
    if not value.is_finite():
        return repr(float(value))
    mantissa, exponent = value.man_exp()
    return int(mantissa), int(exponent)


def arb_from(mid: Part, rad: Part) -> flint.arb:
    """The ball ``_reduced`` wrote, at the precision its midpoint needs, so that it is not rounded."""
    bits = mid[0].bit_length() if isinstance(mid, tuple) else 2
    with flint.ctx.workprec(max(bits, 2)):
        return flint.arb(flint.arf(mid), flint.arf(rad))


copyreg.pickle(flint.arb, _reduced)
