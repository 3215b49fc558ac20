"""Hand geometry for the catalog tests, written from the definitions and nothing of algkin.

Points are pairs of mpmath numbers (or floats); ``side = +1`` puts the apex of a triangle to the
left of the directed base line, ``-1`` to its right.
"""

import contextlib
import functools
import io
import json
import os
import subprocess
import sys
from pathlib import Path

import mpmath
import sympy

from algkin.ui.cli import main

ROOT = Path(__file__).resolve().parents[2]


def circles(p, r1, q, r2, side):
    """The point at distance r1 from p and r2 from q, on ``side`` of p -> q (law of cosines)."""
    dx, dy = q[0] - p[0], q[1] - p[1]
    base = mpmath.sqrt(dx**2 + dy**2)
    cos_a = (r1**2 + base**2 - r2**2) / (2 * r1 * base)
    if not -1 <= cos_a <= 1:
        return None
    angle = mpmath.atan2(dy, dx) + side * mpmath.acos(cos_a)
    return (p[0] + r1 * mpmath.cos(angle), p[1] + r1 * mpmath.sin(angle))


def rigid(p, q, u, v):
    """The point at (u, v) in the frame of the bar p -> q (v along the bar turned by +90 deg)."""
    dx, dy = q[0] - p[0], q[1] - p[1]
    return (p[0] + u * dx - v * dy, p[1] + u * dy + v * dx)


def on_circle(center, radius, degrees):
    t = mpmath.radians(degrees)
    return (center[0] + radius * mpmath.cos(t), center[1] + radius * mpmath.sin(t))


def run(*args):
    """The command line's JSON document, run in this process (``algkin.ui.cli.main``)."""
    stdout = io.StringIO()
    with contextlib.redirect_stdout(stdout):
        code = main([*map(str, args), "--json"])
    assert code == 0, stdout.getvalue()[-2000:]
    return json.loads(stdout.getvalue())


def run_process(*args):
    """The command line as a user runs it, in a process of its own; its JSON document."""
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    out = subprocess.run([sys.executable, "-m", "algkin", *map(str, args), "--json"],
                         capture_output=True, text=True, env=env)
    assert out.returncode == 0, out.stderr
    return json.loads(out.stdout)


def branch(document, label):
    return next(b for b in document["branches"] if b["label"] == label)


@functools.lru_cache(maxsize=None)
def _compiled(expression, name):
    symbols = (sympy.Symbol(f"c_{name}"), sympy.Symbol(f"s_{name}"))
    return sympy.lambdify(symbols, sympy.parse_expr(expression), "mpmath")


def at_angle(expression, degrees, name="theta", digits=40):
    """An expression string of algkin's output (in c_name, s_name) at an input angle, in mpmath."""
    with mpmath.workdps(digits):
        t = mpmath.radians(degrees)
        return _compiled(expression, name)(mpmath.cos(t), mpmath.sin(t))


def exact_at(expression, cos, sin, name="theta"):
    """An expression string evaluated exactly at rational (cos, sin)."""
    expr = sympy.parse_expr(expression)
    return expr.subs({sympy.Symbol(f"c_{name}"): sympy.S(cos), sympy.Symbol(f"s_{name}"): sympy.S(sin)})


def same(a, b, digits=60):
    """Exact expressions equal to ``digits`` digits (radicals nested differently still compare)."""
    return abs(sympy.N(sympy.S(a) - sympy.S(b), digits)) < sympy.Float(10) ** (10 - digits)


def curve_at(document, point):
    """The implicit curve of a ``curve`` document at ``point``, relative to the size of its
    coefficients at that distance from the origin."""
    x, y = (sympy.Symbol(v) for v in document["variables"])
    poly = sympy.Poly(sympy.parse_expr(document["curve"]), x, y)
    with mpmath.workdps(60):
        px, py = mpmath.mpf(point[0]), mpmath.mpf(point[1])
        radius = max(1, abs(px), abs(py))
        total = size = mpmath.mpf(0)
        for (i, j), coef in poly.terms():
            value = mpmath.mpf(int(coef.p)) / int(coef.q)
            total += value * px**i * py**j
            size += abs(value) * radius ** (i + j)
        return total / size
