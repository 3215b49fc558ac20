"""The arm of the first seed, by hand geometry and brute force (no algkin code).

A = r (sin t, -cos t), B = (a, -b). |AB| is smallest where OA points at B:
(sin t, cos t) = (a, b) / |OB|, i.e. t = atan2(a, b), |AB| = | |OB| - r |.
"""

import math

import mpmath
import numpy as np

R = 350


def distance(theta_deg, a, b, r=R):
    t = mpmath.radians(theta_deg)
    return mpmath.hypot(r * mpmath.sin(t) - a, -r * mpmath.cos(t) + b)


def brute_minimum(a, b, lo=0, hi=180, r=R):
    """(value, degrees) of min |AB| over [lo, hi]: a dense scan, then golden section at 30 digits."""
    grid = np.linspace(lo, hi, 36001)
    theta = np.radians(grid)
    values = np.hypot(r * np.sin(theta) - a, -r * np.cos(theta) + b)
    k = int(np.argmin(values))
    left, right = grid[max(k - 1, 0)], grid[min(k + 1, len(grid) - 1)]
    with mpmath.workdps(30):
        x0, x1 = mpmath.mpf(left), mpmath.mpf(right)
        ratio = (mpmath.sqrt(5) - 1) / 2
        for _ in range(120):
            m0, m1 = x1 - ratio * (x1 - x0), x0 + ratio * (x1 - x0)
            if distance(m0, a, b, r) < distance(m1, a, b, r):
                x1 = m1
            else:
                x0 = m0
        best = (x0 + x1) / 2
        return float(distance(best, a, b, r)), float(best)


def hand_minimiser(a, b):
    return math.degrees(math.atan2(a, b))


def hand_minimum(a, b, r=R):
    return abs(math.hypot(a, b) - r)
