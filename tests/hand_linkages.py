"""Four-bar configurations by hand (law of cosines, tests.catalog.geometry), nothing of algkin."""

import mpmath

from .catalog.geometry import circles, on_circle, rigid

CHEBYSHEV = dict(a=1, d=2, l=mpmath.mpf(5) / 2, m=mpmath.mpf(5) / 2, p=2, q=0)
FOURBAR = dict(a=1, d=4, l=3, m=mpmath.mpf(7) / 2, p=mpmath.mpf(1) / 2, q=mpmath.mpf(1) / 2)
SIDES = {"left": +1, "right": -1}


def fourbar(theta, a, d, l, m, p, q, branch="left"):
    """O, D, A, B, P as float pairs, or None if the two circles do not meet."""
    with mpmath.workdps(40):
        O, D = (mpmath.mpf(0), mpmath.mpf(0)), (mpmath.mpf(d), mpmath.mpf(0))
        A = on_circle(O, a, theta)
        B = circles(A, l, D, m, SIDES[branch])
        if B is None:
            return None
        P = rigid(A, B, p, q)
        return {n: (float(x), float(y)) for n, (x, y) in dict(O=O, D=D, A=A, B=B, P=P).items()}
