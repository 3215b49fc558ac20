"""Closed forms as text in sympy's syntax, fast on large shared expression trees.

A six-bar's acceleration is a tree that shares its parts (each distinct subexpression is
one object) but prints to some 190,000 characters. sympy's printer visits every printed
node and works out its precedence and term order each time: seconds per form. Here each
distinct node is printed once (memoised), terms in the order sympy holds them; the text
reads back with ``sympy.parse_expr`` to the same value. Small forms keep ``str``'s
familiar, sorted text.

>>> import sympy
>>> x, y = sympy.symbols("x y")
>>> quick(-3 * x * sympy.sqrt(y) / (2 * (x - 1)) + x**-2)
'1/x**2 - 3*x*sqrt(y)/(-2 + 2*x)'
>>> e = (x + 1) ** sympy.Rational(3, 2) - sympy.Rational(1, 3)
>>> sympy.parse_expr(quick(e)) == e
True
"""

from __future__ import annotations

from collections.abc import Callable

import sympy

__all__ = ["text", "quick", "printed_size", "SMALL"]

Show = Callable[[sympy.Basic], str]  # a node's text, memoised

SMALL = 2_000  # nodes (counted as printed): up to this, ``str``'s sorted terms (a four-bar's forms)


def text(expr: sympy.Expr) -> str:
    """``expr`` in sympy's syntax: ``str`` when small, ``quick`` when large."""
    return str(expr) if printed_size(expr) <= SMALL else quick(expr)


def printed_size(expr: sympy.Basic) -> int:
    """Nodes in ``expr`` written out as a tree (a shared part counted each time it is printed)."""
    counts: dict[sympy.Basic, int] = {}

    def walk(node: sympy.Basic) -> int:
        if node not in counts:
            counts[node] = 1 + sum(walk(a) for a in node.args)
        return counts[node]
    return walk(expr)


def quick(expr: sympy.Expr) -> str:
    """``expr`` printed with each distinct subexpression printed once (sums, products, powers,
    square roots, ``Abs``, rationals and symbols: what closed forms hold)."""
    memo: dict[sympy.Basic, str] = {}

    def show(node: sympy.Basic) -> str:
        if node not in memo:
            memo[node] = _show(node, show)
        return memo[node]
    return show(expr)


def _show(node: sympy.Basic, show: Show) -> str:
    if node.is_Symbol or node.is_Integer:
        return str(node)
    if node.is_Rational:
        return f"{node.p}/{node.q}"
    if node.is_Add:
        parts = [show(a) for a in node.args]
        return parts[0] + "".join(f" - {p[1:]}" if p.startswith("-") else f" + {p}" for p in parts[1:])
    if node.is_Mul:
        return _product(node, show)
    if node.is_Pow:
        return _power(node, show)
    if isinstance(node, sympy.Abs):
        return f"Abs({show(node.args[0])})"
    raise TypeError(f"cannot print {type(node).__name__} in a closed form")


def _factors(node: sympy.Basic) -> list[sympy.Basic]:
    """A product's factors, nested products (built unevaluated) flattened."""
    return [f for a in node.args for f in (_factors(a) if a.is_Mul else [a])]


def _product(node: sympy.Basic, show: Show) -> str:
    number, above, below = sympy.Integer(1), [], []
    for factor in _factors(node):
        if factor.is_Rational:
            number *= factor
        elif factor.is_Pow and factor.exp.is_Rational and factor.exp < 0:
            below.append(_operand(_inverse(factor), show))
        else:
            above.append(_operand(factor, show))
    if abs(number.p) != 1 or not above:
        above.insert(0, str(abs(number.p)))
    if number.q != 1:
        below.insert(0, str(number.q))
    sign = "-" if number < 0 else ""
    if not below:
        return sign + "*".join(above)
    under = below[0] if len(below) == 1 else "(" + "*".join(below) + ")"
    return f"{sign}{'*'.join(above)}/{under}"


def _power(node: sympy.Basic, show: Show) -> str:
    base, exponent = node.base, node.exp
    if exponent == sympy.Rational(1, 2):
        return f"sqrt({show(base)})"
    if exponent.is_Rational and exponent < 0:  # alone, not in a product: 1/x**2
        return f"1/{_operand(_inverse(node), show)}"
    raised = _operand(base, show) if not base.is_Pow else f"({show(base)})"
    return f"{raised}**{exponent}" if exponent.is_Integer else f"{raised}**({exponent})"


def _inverse(power: sympy.Basic) -> sympy.Basic:
    """``1 / power`` for a power with a negative exponent, kept as the same base raised."""
    return power.base if power.exp == -1 else sympy.Pow(power.base, -power.exp, evaluate=False)


def _operand(node: sympy.Basic, show: Show) -> str:
    """``node`` as a factor or a power's base: in parentheses unless it is a name, a natural
    number, a function call or a power (whose ``**`` binds tighter than ``*`` and ``/``)."""
    shown = show(node)
    if node.is_Symbol or (node.is_Integer and node >= 0) or (node.is_Pow and not shown.startswith("1/")):
        return shown
    if isinstance(node, sympy.Abs):
        return shown
    return f"({shown})"
