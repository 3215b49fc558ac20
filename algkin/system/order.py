"""sympy's order of a sum's terms and of a product's factors as its printer takes them (sympy 1.14's
``Expr.as_ordered_terms``, ``Mul.as_ordered_factors`` and ``Expr.sort_key``, ``order=None``), kept for
the expressions of one document.

sympy computes a sum's order again wherever the sum is a factor's sort key or printed, and converts every
term's coefficient to a complex (through ``evalf``) although the coefficients only break ties between terms
of one monomial, which a sum never has but for number factors like ``sqrt(2)``: most of the time of
writing a closed form. ``PrintOrder`` keeps each order and key, and converts the coefficients of a sum
only where two of its terms tie. A root of a product among a term's factors is evaluated once
(``decompose_power``): the assumptions it asks of each factor's sign decide the generator sympy sorts by;
where balls at rational points show that no sign can be known, its answer is known without asking.

>>> c = sympy.Symbol("c")
>>> expr = 3*c**2 - c*sympy.sqrt(c + 1) + 5
>>> PrintOrder().terms(expr) == expr.as_ordered_terms()
True
"""

from collections.abc import Callable
from typing import Any

import sympy
from sympy.core.exprtools import decompose_power
from sympy.core.numbers import NumberSymbol
from sympy.core.sorting import default_sort_key

from .signs import signs_unknowable

__all__ = ["PrintOrder"]

_NUMBERS = (sympy.Number, NumberSymbol)
# the key kept here; a class with a sort_key of its own (atoms among them) is keyed by that
_EXPR_SORT_KEY: Callable[..., Any] = sympy.Expr.sort_key


class PrintOrder:
    """The terms of each sum and the factors of each product in the order sympy's printer writes them,
    for one document; each order and sort key computed once (sympy evaluates them each time)."""

    def __init__(self) -> None:
        self._keys: dict[tuple[type, sympy.Basic], Any] = {}
        self._terms: dict[sympy.Add, list[sympy.Expr]] = {}
        self._powers: dict[tuple[type, sympy.Expr], tuple[sympy.Expr, int]] = {}
        self._complexes: dict[tuple[type, sympy.Expr], complex | None] = {}
        self._atom_texts: dict[tuple[type, sympy.Expr], str] = {}

    def terms(self, add: sympy.Add) -> list[sympy.Expr]:
        """``add.as_ordered_terms()``."""
        ordered = self._terms.get(add)
        if ordered is None:
            ordered = self._terms[add] = self._ordered_terms(add)
        return ordered

    def factors(self, mul: sympy.Mul) -> list[sympy.Expr]:
        """``mul.as_ordered_factors()``."""
        commutative, noncommutative = _split_commutative(mul)
        commutative.sort(key=self.sort_key)
        return [*commutative, *noncommutative]

    def sort_key(self, expr: Any) -> Any:
        """``default_sort_key(expr)``."""
        if not isinstance(expr, sympy.Expr) or expr.is_Atom or type(expr).sort_key is not _EXPR_SORT_KEY:
            return default_sort_key(expr)
        key = (type(expr), expr)  # the type too: sympy finds some numbers of other types equal
        found = self._keys.get(key)
        if found is None:
            found = self._keys[key] = self._expr_sort_key(expr)
        return found

    def _expr_sort_key(self, whole: sympy.Expr) -> Any:
        """``Expr.sort_key``, its orders of terms and factors taken from this document's."""
        coefficient, expr = whole.as_coeff_Mul()
        exponent = sympy.S.One
        if expr.is_Pow:
            base, exponent = expr.as_base_exp()
            if base is sympy.S.Exp1:  # sympy sorts E**x as exp(x)
                base, exponent = sympy.Function("exp")(exponent), sympy.S.One
            expr = base
        if expr.is_Dummy:
            args: tuple[Any, ...] = (expr.sort_key(),)
        elif expr.is_Atom:
            args = (self._atom_text(expr),)
        else:
            args = tuple(self.sort_key(arg) for arg in self._ordered_args(expr))
        return expr.class_key(), (len(args), args), exponent.sort_key(), coefficient

    def _atom_text(self, atom: sympy.Expr) -> str:
        """``str(atom)``, a symbol's kept (a number's text may differ between equal numbers: a Float's digits)."""
        if not atom.is_Symbol:
            return str(atom)
        key = (type(atom), atom)
        text = self._atom_texts.get(key)
        if text is None:
            text = self._atom_texts[key] = str(atom)
        return text

    def _ordered_args(self, expr: sympy.Expr) -> list[sympy.Basic]:
        if expr.is_Add:
            return self.terms(expr) if type(expr) is sympy.Add else list(expr.as_ordered_terms())
        if expr.is_Mul:
            return self.factors(expr) if type(expr) is sympy.Mul else list(expr.as_ordered_factors())
        return list(expr.args)

    def _ordered_terms(self, add: sympy.Add) -> list[sympy.Expr]:
        if type(add) is not sympy.Add:
            return list(add.as_ordered_terms())
        args = add.args
        special = _number_then_negative_product(args)
        if special is not None:
            return special
        if any(term.is_Order for term in args):
            return list(add.as_ordered_terms())
        return self._sorted_by_monomials(args)

    def _sorted_by_monomials(self, terms: tuple[sympy.Expr, ...]) -> list[sympy.Expr]:
        """``Expr._parse_order(None)``'s key on ``Expr.as_terms``: the exponents in lex order on the
        generators, descending; then the noncommutative factors; then the complex coefficient."""
        read = [self._term(term) for term in terms]
        generators = sorted({g for _, powers, _ in read for g in powers}, key=self.sort_key)
        index = {g: i for i, g in enumerate(generators)}
        keys: list[tuple[Any, ...]] = []
        for _, powers, noncommutative in read:
            monomial = [0] * len(generators)
            for generator, exponent in powers.items():
                monomial[index[generator]] = -exponent
            keys.append((tuple(monomial), tuple(self.sort_key(f) for f in noncommutative)))
        if len(set(keys)) < len(keys):  # a tie: the coefficients decide (sympy's complex of each)
            keys = [(*key, self._coefficient_key(term, numbers)) for key, term, (numbers, _, _) in zip(keys, terms, read)]
        order = sorted(range(len(terms)), key=keys.__getitem__)
        return [terms[i] for i in order]

    def _term(self, term: sympy.Expr) -> tuple[list[sympy.Expr], dict[sympy.Expr, int], list[sympy.Expr]]:
        """``Expr.as_terms``'s reading of one term, but its numbers: the number factors that go into its
        coefficient, its commutative factors as generator -> exponent, its noncommutative factors."""
        _, rest = term.as_coeff_Mul()
        numbers: list[sympy.Expr] = []
        powers: dict[sympy.Expr, int] = {}
        noncommutative: list[sympy.Expr] = []
        if rest is not sympy.S.One:
            for factor in sympy.Mul.make_args(rest):
                if factor.is_number and self._complex(factor) is not None:
                    numbers.append(factor)
                elif factor.is_commutative:
                    base, exponent = self._power(factor)
                    powers[base] = exponent
                else:
                    noncommutative.append(factor)
        return numbers, powers, noncommutative

    def _coefficient_key(self, term: sympy.Expr, numbers: list[sympy.Expr]) -> Any:
        value = complex(term.as_coeff_Mul()[0])
        for number in numbers:
            value *= self._complex(number)  # type: ignore[operator]  # not None: kept only then
        return (bool(value.imag), value.imag), (value.real, value.imag)

    def _complex(self, number: sympy.Expr) -> complex | None:
        """``complex(number)``, None where sympy cannot convert it (the factor is then a generator)."""
        key = (type(number), number)
        if key not in self._complexes:
            try:
                self._complexes[key] = complex(number)
            except (TypeError, ValueError):
                self._complexes[key] = None
        return self._complexes[key]

    def _power(self, factor: sympy.Expr) -> tuple[sympy.Expr, int]:
        """``decompose_power(factor)``: a root's base is evaluated, once per document."""
        key = (type(factor), factor)
        found = self._powers.get(key)
        if found is None:
            found = self._powers[key] = _whole_root(factor) or decompose_power(factor)
        return found


def _whole_root(factor: sympy.Expr) -> tuple[sympy.Expr, int] | None:
    """``decompose_power(factor)`` for a power of a square root of a product of real symbols' expressions
    whose signs sympy cannot know, without its questions of them (tens of milliseconds for a six-bar's root
    over roots): None where not shown so (sympy then answers).

    sympy's root of a product (``Mul._eval_power``, ``Pow._eval_expand_power_base``) takes out the factors it
    proves nonnegative (a number among them) or negative, and an imaginary unit where it proves the product
    imaginary; else it keeps the root whole. Its assumptions hold for every real value of the symbols: a
    factor positive at one real point and negative or not real at another is neither, and a product real
    and not 0 at one point is not imaginary."""
    if not (factor.is_Pow and factor.exp.is_Rational and factor.exp.q == 2 and type(factor.base) is sympy.Mul):
        return None
    base = factor.base
    if not signs_unknowable(base.args):
        return None
    return sympy.Pow(sympy.Mul(*base.args), sympy.S.Half, evaluate=False), int(factor.exp.p)


def _split_commutative(mul: sympy.Mul) -> tuple[list[sympy.Expr], list[sympy.Expr]]:
    """``mul.args_cnc()``: its commutative factors, a negative rational in front split as -1 and its
    opposite, then the others; read from the rational itself where there is one (sympy asks the new
    number's assumptions)."""
    first = mul.args[0]
    if not (mul.is_commutative and isinstance(first, sympy.Rational)):
        commutative, noncommutative = mul.args_cnc()
        return commutative, noncommutative
    if first.p < 0 and first is not sympy.S.NegativeOne:
        return [sympy.S.NegativeOne, -first, *mul.args[1:]], []
    return list(mul.args), []


def _number_then_negative_product(terms: tuple[sympy.Expr, ...]) -> list[sympy.Expr] | None:
    """``as_ordered_terms``'s special case: a positive number and a negative number times one factor
    (``1 - c``) keep that order."""
    if len(terms) != 2:  # the case's sums only
        return None
    def not_number(x: sympy.Basic) -> bool:
        return not isinstance(x, _NUMBERS)
    ordered = sorted(terms, key=not_number)
    if len(ordered) == 2 and isinstance(ordered[0], _NUMBERS) and isinstance(ordered[1], sympy.Mul):
        factors = sorted(sympy.Mul.make_args(ordered[1]), key=not_number)
        if len(factors) == 2 and isinstance(factors[0], sympy.Number) and ordered[0].is_positive \
                and factors[0].is_negative:
            return ordered
    return None
