"""Exact algebra the closed forms share: earlier points substituted and reduced on the circles, tidy factors."""

from collections.abc import Callable, Mapping
from functools import reduce

import sympy
from sympy.core.add import _addsort
from sympy.core.mul import _keep_coeff, _mulsort
from sympy.core.numbers import igcd, ilcm

from ..scene.implicit.algebra import Circles, reduce_on_circles
from ..system.signs import takes_both_signs
from ..system.text import ExpressionText
from .ratio import cancelled

__all__ = ["reducer", "tidy_ratio", "tidy_product", "factored_terms", "tidy_sqrt", "unsplit_root", "product_root", "product", "total", "readable", "Readable", "FormText",
           "times", "primitive_sum"]


def reducer(substitution: Mapping[sympy.Symbol, sympy.Expr], inputs: Circles) -> Callable[[sympy.Expr], sympy.Expr]:
    """``e -> e`` with earlier points' unknowns substituted, reduced on the circles."""
    return lambda expr: reduce_on_circles(expr.xreplace(substitution), inputs)


def _primitive(expr: sympy.Expr) -> tuple[sympy.Expr, sympy.Expr]:
    """``(content, part)`` with ``expr = content * part`` and integer coprime numbers in ``part``:
    a factor reads ``23 - 16*c``, not ``23/4 - 4*c`` (sympy would spread the 1/4 back in)."""
    return expr.primitive() if expr.is_Add else (sympy.Integer(1), expr)


def tidy_ratio(expr: sympy.Expr) -> sympy.Expr:
    """A ratio of polynomials as ``k * p / q`` with ``p``, ``q`` primitive: ``(80*c - 103)/(8*(20*c - 29))``;
    cancelled in python-flint where that gives sympy's expression for sure (``cancelled``).

    >>> c = sympy.Symbol("c")
    >>> tidy_ratio((sympy.Rational(55, 4) - 8*c) / (34 - 16*c))
    (32*c - 55)/(8*(8*c - 17))
    """
    fast = cancelled(expr)
    if fast is not None:
        k, p, q = fast
        return sympy.Mul(k, p, 1 / q)
    return _tidy_ratio_in_sympy(expr)


def _tidy_ratio_in_sympy(expr: sympy.Expr) -> sympy.Expr:
    numerator, denominator = sympy.fraction(sympy.cancel(expr))
    (cn, pn), (cd, pd) = _primitive(numerator), _primitive(denominator)
    return sympy.Mul(cn / cd, pn, 1 / pd)  # one Mul: a product by a number would spread it back in


def tidy_product(*factors: sympy.Expr) -> sympy.Expr:
    """The product of ``factors``, each expanded already (reduced on the circles), with every numeric
    content gathered in front."""
    parts = [_primitive(f) for f in factors]
    return sympy.Mul(*[c for c, _ in parts], *[factored_terms(p) for _, p in parts])


def factored_terms(expr: sympy.Expr) -> sympy.Expr:
    """``sympy.factor_terms(expr)``: ``expr`` itself where it is a sum of integer multiples of monomials
    with no factor it could take out (coprime coefficients, not all negative, no symbol in every
    term), seen directly; sympy's elsewhere (its Factors of every term, a millisecond a dyad cold).

    >>> c, s = sympy.symbols("c s", real=True)
    >>> [factored_terms(e) for e in (5 - 4*c, c*s + c, -4*c - 5)]
    [5 - 4*c, c*(s + 1), -(4*c + 5)]
    """
    if not expr.is_Add:
        return sympy.factor_terms(expr)
    coefficients, common = [], None
    for term in expr.args:
        coefficient, factors = term.as_coeff_mul()
        if not coefficient.is_Integer or not all(_monomial(f) for f in factors):
            return sympy.factor_terms(expr)
        coefficients.append(int(coefficient))
        bases = {f.as_base_exp()[0] for f in factors}
        common = bases if common is None else common & bases
    if common or all(k < 0 for k in coefficients) or reduce(igcd, coefficients) != 1:
        return sympy.factor_terms(expr)
    return expr


def _monomial(factor: sympy.Expr) -> bool:
    """A symbol or its positive integer power."""
    return bool(factor.is_Symbol or (factor.is_Pow and factor.base.is_Symbol and factor.exp.is_Integer
                                     and factor.exp > 0))


def tidy_sqrt(expr: sympy.Expr) -> sympy.Expr:
    """``sqrt(expr)`` with the square part of its numeric content in front: ``10*sqrt(30*s + 34)``
    for ``sqrt(3000*s + 3400)`` (sympy does so for a product, never for a sum).

    >>> s = sympy.Symbol("s")
    >>> tidy_sqrt(3000*s + 3400), tidy_sqrt(s/8 + sympy.Rational(1, 8))
    (10*sqrt(30*s + 34), sqrt(2*s + 2)/4)
    """
    if not expr.is_Add:  # a product keeps its factors (sympy takes a number's squares out of one)
        return sympy.sqrt(expr)
    content, part = _primitive(expr)
    if not (content.is_Rational and content > 0 and content != 1):
        return sympy.sqrt(expr)
    outside, inside = sympy.sqrt(content).as_coeff_Mul()  # sqrt(200) = 10 * sqrt(2)
    return outside * sympy.sqrt(sympy.expand(inside**2 * part))


def unsplit_root(expr: sympy.Expr) -> sympy.Expr:
    """``sqrt(expr)`` with the root of its positive number in front and the rest under one root, as written,
    without sympy's questions of each factor's sign (``sympy.sqrt`` asks them to take out the factors it
    proves nonnegative: minutes for a chain of three dyads' squared distance). The same expression as
    ``sympy.sqrt`` gives wherever no sign is known.

    >>> c = sympy.Symbol("c", real=True)
    >>> unsplit_root(sympy.Mul(sympy.Rational(3, 16), 5 - 4*c, 1 / (c + 5)))
    sqrt(3)*sqrt((5 - 4*c)/(c + 5))/4
    >>> unsplit_root(sympy.Mul(sympy.Rational(3, 16), 5 - 4*c, 1 / (c + 5))) == sympy.sqrt(sympy.Mul(3, 5 - 4*c, 1 / (c + 5))) / 4
    True
    """
    number, rest = expr.as_coeff_Mul()
    if rest == 1 or number < 0:  # sympy keeps a -1 under the root, its own way
        return sympy.sqrt(expr)
    # ``product``: sympy's constructor would ask the signs again (tens of milliseconds where the number
    # leaves a surd, sqrt(2) in front)
    return product(sympy.sqrt(number), sympy.Pow(rest, sympy.S.Half, evaluate=False))


def product_root(expr: sympy.Expr) -> sympy.Expr:
    """``sympy.sqrt(expr)`` of a positive number times polynomials in real symbols, without sympy's
    questions of each factor's sign where the answer is known: a factor that takes both signs
    (``takes_both_signs``) is one sympy cannot prove nonnegative or negative (it is sound), so it
    keeps every such factor under the root, as ``unsplit_root`` writes it. A millisecond and more
    of each dyad's closed form otherwise (its assumptions asked afresh of every new factor).

    >>> c = sympy.Symbol("c", real=True)
    >>> discriminant = sympy.Mul(4, 5 - 4*c, c + 5)
    >>> product_root(discriminant), product_root(discriminant) == sympy.sqrt(discriminant)
    (2*sqrt((5 - 4*c)*(c + 5)), True)
    >>> product_root(sympy.Mul(4, c**2 + 1, c + 5))   # c**2 + 1 > 0: sympy takes it out
    2*sqrt(c + 5)*sqrt(c**2 + 1)
    """
    number, rest = expr.as_coeff_Mul()
    if number > 0 and rest != 1 and all(takes_both_signs(f) for f in sympy.Mul.make_args(rest)):
        return unsplit_root(expr)
    return sympy.sqrt(expr)


def product(*factors: sympy.Expr) -> sympy.Expr:
    """``sympy.Mul(*factors)``, put in sympy's order directly where that is all its constructor would
    do: numbers gathered in front, no two factors of one base, no number left to spread over a sum.
    sympy's constructor evaluates each power again, and a root of a product asks the sign of each
    factor (most of a six-bar's closed forms' cost); elsewhere it is called.

    >>> c = sympy.Symbol("c", real=True)
    >>> root = unsplit_root(sympy.Mul(12, c - 2, 1 / (c + 5)))
    >>> product(sympy.Rational(1, 4), c**2 + 1, root)
    sqrt(3)*sqrt((c - 2)/(c + 5))*(c**2 + 1)/2
    >>> _.args == sympy.Mul(sympy.Rational(1, 4), c**2 + 1, root).args
    True
    >>> product(2, c + 1)   # a number spread over a sum: sympy's own
    2*c + 2
    """
    coefficient, rest = sympy.S.One, []
    for factor in factors:
        number, others = sympy.sympify(factor).as_coeff_mul()
        coefficient *= number
        rest.extend(others)
    bases = [r.as_base_exp()[0] for r in rest]
    if not coefficient or len(set(bases)) < len(bases) or sum(1 for b in bases if b.is_Number) > 1 \
            or (coefficient != 1 and len(rest) == 1 and rest[0].is_Add):
        return sympy.Mul(*factors)
    _mulsort(rest)
    args = rest if coefficient == 1 else [coefficient, *rest]
    return args[0] if len(args) == 1 else sympy.Mul._from_args(args, is_commutative=True)


def total(*terms: sympy.Expr) -> sympy.Expr:
    """``sympy.Add(*terms)``, put in sympy's order directly where that is all its constructor would do:
    sums opened, the number in front, no two terms alike (``product``'s reason; elsewhere it is called).

    >>> c = sympy.Symbol("c", real=True)
    >>> total(c**2 + 1, 3 * c * sympy.sqrt(c + 2)).args == sympy.Add(c**2 + 1, 3 * c * sympy.sqrt(c + 2)).args
    True
    """
    number, rest = sympy.S.Zero, []
    for term in terms:
        for part in sympy.Add.make_args(sympy.sympify(term)):
            if part.is_Number:
                number += part
            else:
                rest.append(part)
    if len(rest) < 2 or len({r.as_coeff_Mul()[1] for r in rest}) < len(rest):
        return sympy.Add(*terms)
    _addsort(rest)
    args = rest if number == 0 else [number, *rest]
    return sympy.Add._from_args(args, is_commutative=True)


def times(coefficient: sympy.Expr, part: sympy.Expr) -> sympy.Expr:
    """sympy's ``_keep_coeff(coefficient, part)``: a rational times a symbol or a symbol's integer power put
    together directly (sympy's constructor makes the same product, asking the new number's assumptions
    first: most of the time of ``readable``); elsewhere ``_keep_coeff``.

    >>> c = sympy.Symbol("c")
    >>> times(sympy.Rational(3, 4), c**2).args == _keep_coeff(sympy.Rational(3, 4), c**2).args
    True
    """
    if isinstance(coefficient, sympy.Rational) and coefficient.p and coefficient not in (1, -1) \
            and part.is_commutative and (part.is_Symbol or part.is_Pow and part.base.is_Symbol and part.exp.is_Integer):
        return sympy.Mul._from_args((coefficient, part), is_commutative=True)
    return _keep_coeff(coefficient, part)


def primitive_sum(add: sympy.Add) -> tuple[sympy.Expr, sympy.Expr]:
    """sympy 1.14's ``Add.primitive`` (BSD licence): ``(R, add/R)`` with ``R`` the rational content of the
    terms' coefficients, each term's new coefficient put on by ``times``.

    >>> c = sympy.Symbol("c")
    >>> primitive_sum(3*c/4 + sympy.Rational(9, 2)*c**2)
    (3/4, 6*c**2 + c)
    """
    terms = []
    for term in add.args:
        k, rest = term.as_coeff_Mul()
        if not k.is_Rational:
            k, rest = sympy.S.One, term
        if rest is sympy.S.ComplexInfinity:  # sympy's own handling of zoo
            sympys: tuple[sympy.Expr, sympy.Expr] = add.primitive()
            return sympys
        terms.append((k.p, k.q, rest))
    ngcd = reduce(igcd, [p for p, _, _ in terms], 0)
    dlcm = reduce(ilcm, [q for _, q, _ in terms], 1)
    if ngcd == dlcm == 1:
        return sympy.S.One, add
    made = [times(sympy.Rational((p // ngcd) * (dlcm // q)), rest) for p, q, rest in terms]
    number = made.pop(0) if made[0].is_Number else None  # the number stays first
    _addsort(made)
    if number:
        made.insert(0, number)
    return sympy.Rational(ngcd, dlcm), add._new_rawargs(*made)


def readable(expr: sympy.Expr) -> sympy.Expr:
    """``expr`` as written for a reader: each sum that is a factor (of a numerator, a denominator, under
    a root) primitive with integer coefficients, the rational contents gathered in one number in front of
    each term; the same function of the same symbols (sympy spreads ``9/2*(5 - 3*c)`` back into
    ``45/2 - 27*c/2``, and a dimension like 3/2 puts such contents everywhere).

    >>> c, s = sympy.symbols("c s")
    >>> readable(3*s / (16*(sympy.Rational(45, 2) - sympy.Rational(27, 2)*c)) + c/2)
    c/2 + s/(24*(5 - 3*c))
    >>> readable(sympy.sqrt((sympy.Rational(9, 2) - 3*c/2) * (c + 1)))
    sqrt(6)*sqrt((3 - c)*(c + 1))/2
    """
    return Readable()(expr)


class Readable:
    """``readable`` for the expressions of one document, each shared subexpression made readable once
    (a six-bar's root recurs in every coordinate of every branch)."""

    def __init__(self) -> None:
        self._made: dict[sympy.Expr, sympy.Expr] = {}
        self._parts: dict[sympy.Expr, tuple[sympy.Expr, sympy.Expr]] = {}

    def __call__(self, expr: sympy.Expr) -> sympy.Expr:
        made = self._made.get(expr)
        if made is None:
            if expr.is_Add:  # a sum of terms: each term read apart (a content pulled out of them all reads worse)
                made = total(*[self(term) for term in expr.args])
            else:
                made = times(*self._content_and_part(expr))
            self._made[expr] = made
        return made

    def _content_and_part(self, expr: sympy.Expr) -> tuple[sympy.Expr, sympy.Expr]:
        """``(k, p)`` with ``expr = k * p``, ``k`` a number and every sum among ``p``'s factors primitive."""
        found = self._parts.get(expr)
        if found is None:
            found = self._parts[expr] = self._split(expr)
        return found

    def _split(self, expr: sympy.Expr) -> tuple[sympy.Expr, sympy.Expr]:
        if expr.is_Number:
            return expr, sympy.Integer(1)
        if expr.is_Atom:
            return sympy.Integer(1), expr
        if expr.is_Add:
            terms = self(expr)
            return primitive_sum(terms) if terms.is_Add else self._content_and_part(terms)
        if expr.is_Mul:
            parts = [self._content_and_part(factor) for factor in expr.args]
            return sympy.Mul(*[k for k, _ in parts]), product(*[p for _, p in parts])
        if expr.is_Pow:
            content, part = self._content_and_part(expr.base)
            if expr.exp.is_Integer:
                return content**expr.exp, part**expr.exp
            base = _keep_coeff(content, part)
            root = unsplit_root(base) if expr.exp == sympy.S.Half else sympy.Pow(base, expr.exp)
            number, rest = root.as_coeff_Mul()
            return number, rest
        return sympy.Integer(1), expr.func(*[self(a) for a in expr.args])


class FormText:
    """Closed forms of one document as text: made ``readable``, then written as ``str`` writes them,
    each shared subexpression done once.

    >>> c = sympy.Symbol("c")
    >>> FormText()(sympy.sqrt(sympy.Rational(9, 2) - 3*c/2))
    'sqrt(6)*sqrt(3 - c)/2'
    """

    def __init__(self) -> None:
        self.readable = Readable()
        self.text = ExpressionText()

    def __call__(self, expr: sympy.Expr) -> str:
        return self.text(self.readable(expr))
