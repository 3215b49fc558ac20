"""sympy expressions as text, exactly as ``str`` writes them, each shared subexpression written once.

A closed form's square root and denominators recur in every coordinate of every branch: sympy's
printer writes (and sorts the terms of) each occurrence again, half a second of a six-bar's
``derive``. ``ExpressionText`` keeps what it wrote for one document, and the order of each sum's terms
and each product's factors (``order.PrintOrder``), which sympy computes again for each occurrence.

>>> import sympy
>>> c = sympy.Symbol("c")
>>> root = sympy.sqrt(3 - 2*c)
>>> text = ExpressionText()
>>> text(c + root), text(c*root / (1 - c))
('c + sqrt(3 - 2*c)', 'c*sqrt(3 - 2*c)/(1 - c)')
"""

from typing import Any

import sympy
from sympy.core.function import Function
from sympy.core.mul import _keep_coeff
from sympy.printing.precedence import PRECEDENCE, precedence
from sympy.printing.str import StrPrinter

from .order import PrintOrder

__all__ = ["ExpressionText"]


class ExpressionText:
    """``str(expr)`` for the expressions of one document, each subexpression written once."""

    def __init__(self) -> None:
        self._printer = _SharingPrinter()

    def __call__(self, expr: sympy.Basic) -> str:
        text: str = self._printer.doprint(expr)
        return text


class _SharingPrinter(StrPrinter):  # type: ignore[misc, unused-ignore]  # sympy untyped for --strict
    """sympy's ``StrPrinter`` as ``str`` makes it (``order=None``), keeping the text of every
    compound subexpression. That text depends on the subexpression alone: only a Float's depends on
    its depth (trailing zeros kept at the top), and atoms are not kept."""

    def __init__(self) -> None:
        super().__init__({"order": None})
        self._written: dict[tuple[type, sympy.Basic], str] = {}
        self._order = PrintOrder()
        self._precedences: dict[tuple[type, sympy.Basic], int] = {}

    def _print(self, expr: Any, **kwargs: Any) -> str:
        if kwargs or not isinstance(expr, sympy.Basic) or expr.is_Atom:
            written: str = super()._print(expr, **kwargs)
            return written
        key = (type(expr), expr)  # the type too: sympy finds some numbers of other types equal
        text = self._written.get(key)
        if text is None:
            text = self._written[key] = super()._print(expr)
        return text

    def _precedence(self, item: Any) -> int:
        """``precedence(item)``, kept: sympy finds it by the item's classes, and a product's by its sign."""
        if not isinstance(item, sympy.Basic):
            return int(precedence(item))
        key = (type(item), item)
        found = self._precedences.get(key)
        if found is None:
            found = self._precedences[key] = _product_precedence(item) if type(item) is sympy.Mul else precedence(item)
        return found

    def parenthesize(self, item: Any, level: int, strict: bool = False) -> str:
        """sympy 1.14's ``StrPrinter.parenthesize``, the precedence kept."""
        if self._precedence(item) < level or (not strict and self._precedence(item) <= level):
            return "(%s)" % self._print(item)
        return self._print(item)

    def _print_Add(self, expr: sympy.Add, order: Any = None) -> str:
        """sympy 1.14's ``StrPrinter._print_Add`` (BSD licence), for ``order=None``, the terms in this
        document's order and precedences."""
        if order:
            written: str = super()._print_Add(expr, order=order)
            return written
        prec = self._precedence(expr)
        parts = []
        for term in self._order.terms(expr):
            t = self._print(term)
            if t.startswith("-") and not term.is_Add:
                sign = "-"
                t = t[1:]
            else:
                sign = "+"
            if self._precedence(term) < prec or term.is_Add:
                parts.extend([sign, "(%s)" % t])
            else:
                parts.extend([sign, t])
        sign = parts.pop(0)
        return ("" if sign == "+" else sign) + " ".join(parts)

    def _print_Mul(self, expr: sympy.Mul) -> str:
        """sympy 1.14's ``StrPrinter._print_Mul`` (BSD licence), for ``order=None``, the factors in
        this document's order: sympy sorts them again each time, asking the assumptions of each."""
        args = expr.args
        if args[0] is sympy.S.One or any(isinstance(a, sympy.Number) or a.is_Pow and all(ai.is_Integer for ai in a.args)
                                          for a in args[1:]):
            written: str = super()._print_Mul(expr)  # an unevaluated product: its factors as given
            return written
        prec = self._precedence(expr)
        c, e = expr.as_coeff_Mul()
        if (c.p < 0 if isinstance(c, sympy.Rational) else c < 0):  # a rational's sign without a comparison's sympify
            expr = _opposite(c, e)
            sign = "-"
        else:
            sign = ""
        numerator: list[sympy.Expr] = []
        denominator: list[sympy.Expr] = []
        pow_paren = []  # powers of a product or power to the -1: their base written in parentheses
        for item in self._order.factors(expr) if type(expr) is sympy.Mul else expr.as_ordered_factors():
            if item.is_commutative and isinstance(item, sympy.Pow) and bool(item.exp.as_coeff_Mul()[0] < 0):
                if item.exp is not sympy.S.NegativeOne:
                    denominator.append(_inverted(item))
                else:
                    if len(item.args[0].args) != 1 and isinstance(item.base, (sympy.Mul, sympy.Pow)):
                        pow_paren.append(item)
                    denominator.append(item.base)
            elif item.is_Rational and item is not sympy.S.Infinity:
                if item.p != 1:
                    numerator.append(sympy.Rational(item.p))
                if item.q != 1:
                    denominator.append(sympy.Rational(item.q))
            else:
                numerator.append(item)
        numerator = numerator or [sympy.S.One]
        a_str = [self.parenthesize(x, prec, strict=False) for x in numerator]
        b_str = [self.parenthesize(x, prec, strict=False) for x in denominator]
        for item in pow_paren:
            if item.base in denominator:
                b_str[denominator.index(item.base)] = "(%s)" % b_str[denominator.index(item.base)]
        if not denominator:
            return sign + "*".join(a_str)
        if len(denominator) == 1:
            return sign + "*".join(a_str) + "/" + b_str[0]
        return sign + "*".join(a_str) + "/(%s)" % "*".join(b_str)


def _product_precedence(product: sympy.Mul) -> int:
    """sympy 1.14's ``precedence_Mul``, a sum's where the product begins with a negative rational, without
    ``could_extract_minus_sign``'s new ``-product`` and the assumptions of its new number."""
    first = product.args[0]
    if not (isinstance(first, sympy.Rational) and first.p) or any(
            hasattr(arg, "precedence") and isinstance(arg, Function) for arg in product.args):
        return int(precedence(product))
    return int(PRECEDENCE["Add"] if first.p < 0 else PRECEDENCE["Mul"])


def _opposite(coefficient: sympy.Rational, rest: sympy.Expr) -> sympy.Expr:
    """``_keep_coeff(-coefficient, rest)``, a positive number times a variable or its power put together as
    sympy's product would be (number first): its constructor asks the power's assumptions (a closed form's
    terms, sympy's str in a six-bar's document: milliseconds)."""
    opposite = -coefficient
    if opposite is sympy.S.One:
        return rest
    if rest.is_Symbol or rest.is_Pow and rest.base.is_Symbol and rest.exp.is_Integer:
        return sympy.Mul._from_args((opposite, rest))
    return _keep_coeff(opposite, rest)


def _inverted(power: sympy.Expr) -> sympy.Expr:
    """``1/power`` of a power to a negative exponent, unevaluated (sympy's ``apow``)."""
    base, exp = power.as_base_exp()
    eargs = list(sympy.Mul.make_args(exp))
    if eargs[0] is sympy.S.NegativeOne:
        eargs = eargs[1:]
    else:
        eargs[0] = -eargs[0]
    return power.func(base, sympy.Mul._from_args(eargs), evaluate=False)
