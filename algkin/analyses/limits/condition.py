"""The stationarity condition of a point on a fixed path, and its eliminant in the input alone.

A point X with one equation in X alone, ``C(X) = 0`` (its *path*: a circle or a line), and
another ``G(X, u, c, s) = 0`` tying it to the moving points stops on its path where
``dG/dtheta`` with X held vanishes, the earlier unknowns' rates ``u'`` from the implicit function
theorem; times ``det J_u`` a polynomial (the package's text has the derivation).

>>> import sympy
>>> x, y = sympy.symbols("x y")
>>> path(x**2 + y**2 - 2*x - 3, x, y).centre, path(x + 2*y - 1, x, y).direction
((1, 0), (2, -1))
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy

from ...eliminate import eliminate
from ...runtime.budget import Deadline
from ...scene import Compiled
from ...system import symbol

__all__ = ["Path", "Stationary", "path", "stationary_condition", "eliminant"]


@dataclass(frozen=True)
class Path:
    """The curve an implicit point moves on, ``C(X) = 0``: a circle about a centre, or a line."""

    equation: sympy.Expr
    centre: tuple[sympy.Expr, sympy.Expr] | None  # a circle's
    direction: tuple[sympy.Expr, sympy.Expr] | None  # a line's


@dataclass(frozen=True)
class Stationary:
    """What the limit positions of one point are computed from."""

    point: str
    unknowns: tuple[sympy.Symbol, sympy.Symbol]
    path: Path
    coupling: sympy.Expr  # X's other equation
    condition: sympy.Expr  # zero where X stops on its path (polynomial in X, earlier unknowns, c, s)
    earlier: tuple[sympy.Expr, ...]  # the earlier points' equations
    earlier_unknowns: tuple[sympy.Symbol, ...]


def _along_theta(f: sympy.Expr, c: sympy.Symbol, s: sympy.Symbol) -> sympy.Expr:
    """``d f / d theta`` through ``c = cos(theta)``, ``s = sin(theta)`` alone (``c' = -s``, ``s' = c``)."""
    return sympy.expand(c * sympy.diff(f, s) - s * sympy.diff(f, c))


def path(equation: sympy.Expr, x: sympy.Symbol, y: sympy.Symbol) -> Path | None:
    """``equation`` as a circle (centre) or a line (direction); None for any other curve."""
    poly = sympy.Poly(equation, x, y)
    if poly.total_degree() == 1:
        a, b = poly.coeff_monomial(x), poly.coeff_monomial(y)
        return Path(equation, None, (b, -a))  # a x + b y + k = 0 runs along (b, -a)
    quadratic = poly.coeff_monomial(x**2)
    if (poly.total_degree() == 2 and quadratic != 0 and poly.coeff_monomial(y**2) == quadratic
            and poly.coeff_monomial(x * y) == 0):
        return Path(equation, (-poly.coeff_monomial(x) / (2 * quadratic), -poly.coeff_monomial(y) / (2 * quadratic)),
                    None)
    return None


def stationary_condition(compiled: Compiled, point: str) -> Stationary | str:
    """The stationarity condition of ``point`` (see the package's text), or why it has none.

    ``compiled`` holds ``point`` and what it is built on; dimensions are at their defaults.
    """
    (c_name, s_name), = compiled.system.inputs.values()
    c, s = symbol(c_name), symbol(s_name)
    spec = next(p for p in compiled.implicit if p.point == point)
    x, y = (symbol(u) for u in spec.unknowns)
    equations = [e for e in compiled.system.equations if e.free_symbols - {c, s}]  # not the circle's
    own = [e for e in equations if e.has(x) or e.has(y)]
    fixed = [e for e in own if e.free_symbols <= {x, y}]
    if len(own) != 2 or len(fixed) != 1:
        return ("its path is not fixed: both its equations involve moving points" if not fixed
                else "it does not move")
    curve = path(fixed[0], x, y)
    if curve is None:
        return "its path is neither a circle nor a line"
    coupling = next(e for e in own if e is not fixed[0])
    earlier = [e for e in equations if not (e.has(x) or e.has(y))]
    unknowns = [symbol(u) for u in compiled.system.unknowns if u not in spec.unknowns]
    condition = _along_theta(coupling, c, s)
    if unknowns:
        # u' = -adj(J) r / det(J); times det(J), the condition stays a polynomial
        jacobian = sympy.Matrix([[sympy.diff(f, u) for u in unknowns] for f in earlier])
        rates = sympy.Matrix([_along_theta(f, c, s) for f in earlier])
        gradient = sympy.Matrix([[sympy.diff(coupling, u) for u in unknowns]])
        determinant = jacobian.det(method="berkowitz")
        condition = sympy.expand(determinant * condition
                                 - (gradient * jacobian.adjugate(method="berkowitz") * rates)[0])
    return Stationary(point, (x, y), curve, coupling, condition, tuple(earlier), tuple(unknowns))


def eliminant(stationary: Stationary, c: sympy.Symbol, s: sympy.Symbol, deadline: Deadline | None = None
              ) -> tuple[sympy.Expr, list[sympy.Expr]]:
    """The condition with every unknown eliminated (keeping to ``deadline``, if any), and the factors
    the elimination dropped (in ``c, s``)."""
    equations = [stationary.condition, stationary.coupling, stationary.path.equation, *stationary.earlier]
    names = [str(u) for u in (*stationary.unknowns, *stationary.earlier_unknowns)]
    result = eliminate(equations, names, [str(c), str(s)], budget=deadline)
    dropped = [f for f in result.dropped if f.free_symbols <= {c, s} and f.free_symbols]
    return result.polynomial, dropped
