"""First and second derivatives of closed forms with respect to their input angle.

An input angle ``theta`` enters a closed form only through ``c = cos(theta)`` and
``s = sin(theta)``, so the chain rule gives ``d/dtheta = -s d/dc + c d/ds``: the velocity
of an output for a unit input rate (one radian per unit of time) and, applied twice, its
acceleration. A crank point ``A = (3c, 3s)`` moves at ``(-3s, 3c)`` and accelerates
towards the pivot:

>>> from algkin.system import symbol
>>> c, s = symbol("c_t"), symbol("s_t")
>>> [rate_of(x, (c, s)) for x in (3 * c, 3 * s)]
[Rate(velocity=-3*s_t, acceleration=-3*c_t), Rate(velocity=3*c_t, acceleration=-3*s_t)]

Small forms are then tidied: over one denominator, reduced with ``c**2 + s**2 = 1`` and
with ``sqrt(D)**2 = D``, kept only where that reads shorter (``tidy``). A length input ``x``
is its own variable: ``d/dx`` is the plain derivative (per unit of length), no circle.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import flint
import sympy

from ...system import symbol
from ...system.convert import flint_context, fmpq_to_rational, to_sympy
from .text import printed_size

__all__ = ["Rate", "rate_of", "rates_of_values", "Derivative", "tidy"]

SMALL = 1000  # a derivative with more nodes than this is left as the chain rule gives it


@dataclass(frozen=True)
class Rate:
    """One coordinate's first and second derivatives in the input (per radian, per radian**2 of an
    angle; per unit, per unit**2 of a length)."""

    velocity: sympy.Expr
    acceleration: sympy.Expr


class Derivative:
    """``d/dtheta`` on expressions in ``c``, ``s`` and constants, memoised per subexpression
    (``d/dx`` given a length input's one variable ``x``).

    A six-bar's closed form repeats the first dyad's form many times over: each distinct
    subexpression is differentiated once, and the result shares the derivatives of the
    repeated parts (sympy.diff would redo them, and its result reads five times longer).

    >>> from algkin.system import symbol
    >>> c, s = symbol("c"), symbol("s")
    >>> Derivative((c, s))(sympy.sqrt(5 - 4 * c)), Derivative((c,))(sympy.sqrt(5 - 4 * c))
    (2*s/sqrt(5 - 4*c), -2/sqrt(5 - 4*c))
    """

    def __init__(self, variables: tuple[sympy.Symbol, ...]) -> None:
        self.memo: dict[sympy.Basic, sympy.Expr] = \
            {variables[0]: -variables[1], variables[1]: variables[0]} if len(variables) == 2 \
            else {variables[0]: sympy.Integer(1)}

    def __call__(self, node: sympy.Expr) -> sympy.Expr:
        known = self.memo.get(node)
        if known is None:
            known = self.memo[node] = self._rule(node)
        return known

    def _rule(self, node: sympy.Expr) -> sympy.Expr:
        if node.is_Atom:  # a parameter or a number: constant along the motion
            return sympy.Integer(0)
        if node.is_Add:
            return sympy.Add(*[self(a) for a in node.args])
        if node.is_Mul:  # the product rule, one term per factor that moves
            args = node.args
            return sympy.Add(*[sympy.Mul(*args[:k], d, *args[k + 1:])
                               for k, d in enumerate(self(a) for a in args) if d != 0])
        if node.is_Pow and node.exp.is_Number:
            inner = self(node.base)
            return node.exp * node.base ** (node.exp - 1) * inner if inner != 0 else sympy.Integer(0)
        if all(self(a) == 0 for a in node.args):  # Abs(r) of a dimension, say
            return sympy.Integer(0)
        raise TypeError(f"cannot differentiate {type(node).__name__} in a closed form: {node}")


def rate_of(expr: sympy.Expr, variables: tuple[sympy.Symbol, ...], derivative: Derivative | None = None) -> Rate:
    """The velocity and acceleration of ``expr`` (in the input's ``variables``: an angle's cos and
    sin, or a length), tidied."""
    d = derivative or Derivative(variables)
    velocity = d(expr)
    acceleration = d(velocity)  # from the untidied velocity: its derivatives are memoised
    return Rate(tidy(velocity, variables), tidy(acceleration, variables))


def rates_of_values(values: Mapping[str, sympy.Expr], unknowns: Sequence[str],
                    variables: tuple[sympy.Symbol, ...]) -> dict[str, Rate]:
    """``unknown -> Rate`` for ``unknowns`` of one branch (``values``: its closed forms); the
    coordinates share one memo, since a point's two coordinates share most of their parts."""
    derivative = Derivative(variables)
    return {u: rate_of(values[u], variables, derivative) for u in unknowns}


def tidy(expr: sympy.Expr, variables: tuple[sympy.Symbol, ...]) -> sympy.Expr:
    """``expr`` over one denominator, reduced on the circle and by each root's square, where that
    is shorter; a large form as it is (over one denominator it would only grow).

    The algebra is python-flint's: each square root ``sqrt(D)`` becomes a generator ``r``, the
    form a ratio of polynomials in ``r``, ``s``, ``c`` and the dimensions, and each polynomial
    is divided by ``r**2 - D`` and ``s**2 + c**2 - 1`` (lex, ``r`` first: the remainders are
    of degree 1 in every ``r`` and in ``s``; no circle for a length input's ``variables``), the
    ratio cancelled and factored.

    >>> from algkin.system import symbol
    >>> c, s = symbol("c"), symbol("s")
    >>> tidy(c * c / sympy.sqrt(2 - c) + s * s / sympy.sqrt(2 - c), (c, s))
    1/sqrt(2 - c)
    """
    if printed_size(expr) > SMALL:
        return expr
    roots: list[tuple[sympy.Symbol, sympy.Expr]] = []
    try:
        atomic = _atomize(expr, roots)
        tidied = _Rational(atomic, [r for r, _ in reversed(roots)], variables).tidied(roots)
    except _NotRational:
        return expr
    # python-flint knows names only: the form's own symbols back, whatever their assumptions
    tidied = tidied.xreplace({symbol(str(v)): v for v in expr.free_symbols})
    return tidied if len(str(tidied)) < len(str(expr)) else expr


class _NotRational(Exception):
    """The form holds something other than sums, products, integer powers and square roots of polynomials."""


class _Rational:
    """A rational function of the roots, ``s``, ``c`` (or a length) and the dimensions, as two
    python-flint polynomials."""

    def __init__(self, atomic: sympy.Expr, roots: Sequence[sympy.Symbol], variables: tuple[sympy.Symbol, ...]) -> None:
        rest = sorted(atomic.free_symbols - {*roots, *variables}, key=str)
        self.names = [str(v) for v in (*roots, *variables[::-1], *rest)]
        self.turning = len(variables) == 2
        self.ctx = flint_context(self.names)
        self.gens = dict(zip(self.names, self.ctx.gens()))
        self.numerator, self.denominator = self._convert(atomic)

    def tidied(self, roots: Sequence[tuple[sympy.Symbol, sympy.Expr]]) -> sympy.Expr:
        """The function reduced by the roots' squares (outer roots first) and the circle, as sympy."""
        relations = []
        for root, base in reversed(roots):
            value, one = self._convert(base)
            if not one.is_one():
                raise _NotRational(base)
            relations.append(self.gens[str(root)] ** 2 - value)
        if self.turning:
            sin, cos = self.gens[self.names[len(roots)]], self.gens[self.names[len(roots) + 1]]
            relations.append(sin**2 + cos**2 - 1)
        numerator, denominator = (_remainder(p, relations) for p in (self.numerator, self.denominator))
        common = numerator.gcd(denominator)
        return _restored(self._ratio(numerator / common, denominator / common), roots)

    def _convert(self, node: sympy.Expr) -> tuple[flint.fmpq_mpoly, flint.fmpq_mpoly]:
        one = self.ctx.from_dict({}) + 1
        if node.is_Symbol:
            return self.gens[str(node)], one
        if node.is_Rational:
            return one * flint.fmpq(int(node.p), int(node.q)), one
        if node.is_Add or node.is_Mul:
            parts = [self._convert(a) for a in node.args]
            numerator, denominator = parts[0]
            for n, d in parts[1:]:
                numerator, denominator = (numerator * d + n * denominator if node.is_Add else numerator * n,
                                          denominator * d)
            common = numerator.gcd(denominator)
            return numerator / common, denominator / common
        if node.is_Pow and node.exp.is_Integer:
            n, d = self._convert(node.base)
            k = int(node.exp)
            return (n**k, d**k) if k >= 0 else (d ** -k, n ** -k)
        raise _NotRational(node)

    def _ratio(self, numerator: flint.fmpq_mpoly, denominator: flint.fmpq_mpoly) -> sympy.Expr:
        """``numerator / denominator`` factored, one number in front (a minus sign taken into a
        lone factor: ``(5 - 4*c)``, not ``-(4*c - 5)``)."""
        (top, above), (bottom, below) = numerator.factor(), denominator.factor()
        number = fmpq_to_rational(top / bottom)
        if number < 0 and len(above) == 1 and above[0][1] == 1:
            above, number = [(-above[0][0], 1)], -number
        parts = [to_sympy(f, self.ctx) ** e for f, e in above] + [to_sympy(f, self.ctx) ** -e for f, e in below]
        return sympy.Mul(*([number] if number != 1 else []), *parts, evaluate=False) if parts else number


def _remainder(poly: flint.fmpq_mpoly, relations: Sequence[flint.fmpq_mpoly]) -> flint.fmpq_mpoly:
    """``poly`` divided by each relation in turn (lex order: by its leading square)."""
    for relation in relations:
        poly = divmod(poly, relation)[1]
    return poly


def _atomize(expr: sympy.Expr, roots: list[tuple[sympy.Symbol, sympy.Expr]]) -> sympy.Expr:
    """``expr`` with each ``sqrt(D)**k`` written ``r**k`` for a symbol ``r`` (``roots``: ``(r, D)``,
    inner roots first), so that it is a rational function of ``c``, ``s`` and the ``r``."""
    if expr.is_Atom:
        return expr
    args = [_atomize(a, roots) for a in expr.args]
    if expr.is_Pow and expr.exp.is_Rational and expr.exp.q == 2:
        base = args[0]
        root = next((r for r, b in roots if b == base), None)
        if root is None:  # a name no scene can use (scene names start with a letter)
            root = symbol(f"_root{len(roots)}")
            roots.append((root, base))
        return root ** expr.exp.p
    return expr.func(*args)


def _restored(expr: sympy.Expr, roots: Sequence[tuple[sympy.Symbol, sympy.Expr]]) -> sympy.Expr:
    """``expr`` with each root symbol back as the square root it stands for (inner ones first)."""
    full: dict[sympy.Basic, sympy.Expr] = {}
    for root, base in roots:
        full[root] = sympy.sqrt(base.xreplace(full))
    return expr.xreplace(full)
