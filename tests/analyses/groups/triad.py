"""The Stephenson six-bar driven from its other binary link (catalog ``stephenson-iii-triad``),
written out by hand: what the tests check algkin's answers against."""

import sympy

R = sympy.Rational
c, s, ax, ay, bx, by, px, py = sympy.symbols("c s A_x A_y B_x B_y P_x P_y")


def frame(a, b, u, v):
    """``a + u*(b - a) + v*rot90(b - a)``, rot90(x, y) = (-y, x): the scene's ``frame``."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    return a[0] + u * dx - v * dy, a[1] + u * dy + v * dx


A, B = (ax, ay), (bx, by)
C = frame(A, B, R(1, 2), R(1, 2))
P = frame(A, B, R(1, 2), R(-1, 4))
F = (-1 + 2 * c, 5 + 2 * s)  # the crank EF: E = (-1, 5), length 2
LOOPS = [ax**2 + ay**2 - 1,                                # |OA| = 1, O = (0, 0)
         (bx - 4)**2 + by**2 - R(49, 4),                    # |DB| = 7/2, D = (4, 0)
         (ax - bx)**2 + (ay - by)**2 - 9,                   # |AB| = 3
         (C[0] - F[0])**2 + (C[1] - F[1])**2 - 9,           # |CF| = 3
         c**2 + s**2 - 1]
POINT = [px - P[0], py - P[1]]
