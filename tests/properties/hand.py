"""Hand geometry of the random scenes of ``algkin.testing.strategies``, in mpmath.

Written from the constructions' definitions (law of cosines, a line meeting a circle), with
nothing of algkin but reading the scene's numbers.
"""

import mpmath
import sympy


def numbers(scene):
    """Every parameter and fixed point of ``scene`` at its exact default, as mpmath numbers."""
    exact = {}
    for name, default in scene.parameters.items():
        exact[sympy.Symbol(name, real=True)] = default.xreplace(exact)

    def number(expr):
        value = sympy.Rational(expr.xreplace(exact))
        return mpmath.mpf(value.p) / value.q

    fixed = {n: (number(p.x), number(p.y)) for n, p in scene.points.items() if type(p).__name__ == "Fixed"}
    return {str(k): number(v) for k, v in exact.items()}, fixed


def frame(p, q, u, v):
    dx, dy = q[0] - p[0], q[1] - p[1]
    return (p[0] + u * dx - v * dy, p[1] + u * dy + v * dx)


def dyad(p, r1, q, r2, side):
    """The point at r1 from p and r2 from q, left (side +1) or right (-1) of p -> q; None if apart."""
    dx, dy = q[0] - p[0], q[1] - p[1]
    base = mpmath.hypot(dx, dy)
    cos_a = (r1**2 + base**2 - r2**2) / (2 * r1 * base)
    if not -1 < cos_a < 1:
        return None
    angle = mpmath.atan2(dy, dx) + side * mpmath.acos(cos_a)
    return (p[0] + r1 * mpmath.cos(angle), p[1] + r1 * mpmath.sin(angle))


def slider(through, direction, center, length, sign):
    """On the line ``through + t*direction`` at ``length`` from ``center``: the larger t (+1) or smaller."""
    d = [mpmath.mpf(v) for v in direction]
    w = (through[0] - center[0], through[1] - center[1])
    a, b, c = d[0] ** 2 + d[1] ** 2, 2 * (d[0] * w[0] + d[1] * w[1]), w[0] ** 2 + w[1] ** 2 - length**2
    disc = b * b - 4 * a * c
    if disc <= 0:
        return None
    t = (-b + sign * mpmath.sqrt(disc)) / (2 * a)
    return (through[0] + t * d[0], through[1] + t * d[1])


def trajectory(scene, degrees, label):
    """The scene's points B and P (and A, and an inversor's twin E) at the input angle, on the branch
    ``label``; None where B is not."""
    values, fixed = numbers(scene)
    crank = scene.points["A"]
    angle = mpmath.radians(degrees + 90 * crank.quarter_turns)
    center = fixed[crank.center]
    length = values["a"] if "a" in values else values["r"]
    a = (center[0] + length * mpmath.cos(angle), center[1] + length * mpmath.sin(angle))
    points = {"A": a, **fixed}
    if "D" in scene.points:  # a four-bar, or an inversor on one
        side = 1 if label == "left" else -1
        b = dyad(a, values["l"], fixed["D"], values["m"], side)
        if b is None:
            return None
        points["B"] = b
        if "E" in scene.points:  # the twin: the same two circles, the other side
            points["E"] = e = dyad(a, values["l"], fixed["D"], values["m"], -side)
            if scene.name == "inversor-cell":  # the rhombus A B P E closed at P
                points["P"] = (b[0] + e[0] - a[0], b[1] + e[1] - a[1])
            else:  # a kite: P on the bar A E
                points["P"] = frame(a, e, values["p"], values["q"])
            return points
    else:
        line = scene.points["B"]
        if line.direction is not None:  # a fixed line through L
            through, direction = fixed["L"], [int(v) for v in line.direction]
        else:  # the line through L and A, toward the other one
            through, toward = points[line.through], points[line.toward]
            direction = [toward[0] - through[0], toward[1] - through[1]]
        b = slider(through, direction, points[line.to], values["l"], 1 if label == "ahead" else -1)
        if b is None:
            return None
        points["B"] = b
    points["P"] = frame(a, points["B"], values["p"], values["q"])
    return points

