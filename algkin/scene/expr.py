"""The scene files' tiny expression language, parsed without eval.

Numbers (integers, decimals, exponents, all read exactly), names, ``+ - * / **``,
parentheses and ``sqrt(...)``, in ASCII: Python's ``int`` and ``Fraction`` would also read
other scripts' digits (``'١'``, ``'１'``) and strip a no-break space, the language does not. The result is a sympy expression built from sympy
constructors directly, so nothing in a scene file is ever executed.

>>> parse("0.1 + 1/5")
3/10
>>> parse("sqrt(b**2 + 9)", {"b": 4})
5
>>> parse("-2**2")
-4
>>> parse("__import__(1)")
Traceback (most recent call last):
...
ValueError: unknown function '__import__' (only sqrt)
>>> parse("\uff11/2")
Traceback (most recent call last):
...
ValueError: unexpected character '１' at 0 (numbers and names are ASCII: digits 0-9, letters A-Z a-z)
"""

import re
from collections.abc import Callable, Mapping

import sympy

from ..runtime.validation import MAX_NUMBER_BITS, NumberTooLarge, rational

__all__ = ["parse", "exact_number", "bits_bound", "irrational", "MAX_EXPRESSION_LENGTH", "MAX_NUMBER_BITS", "MAX_VALUE_BITS"]

MAX_EXPRESSION_LENGTH = 500
MAX_DEPTH = 40
MAX_EXPONENT = 64
MAX_VALUE_BITS = 64 * MAX_NUMBER_BITS  # a value after parameters are substituted into it

Token = tuple[str, str]  # (kind: num, name or op; its text)

_NUMBER = r"(?:\d[\d_]*(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?"
# ASCII: without it \d and \s match other scripts' digits and spaces (a no-break space)
_TOKEN = re.compile(rf"\s*(?:(?P<num>{_NUMBER})|(?P<name>[A-Za-z_][A-Za-z0-9_]*)|(?P<op>\*\*|[-+*/(),]))", re.ASCII)
_SPACE = " \t\n\r\f\v"  # str.strip() would also take a no-break space


def exact_number(text: str) -> sympy.Rational:
    """The exact rational a decimal literal spells: ``exact_number('0.1')`` is 1/10.

    >>> exact_number("2.5e-1")
    1/4
    """
    if not str(text).isascii():  # Fraction would read other scripts' digits
        raise ValueError(f"not a number in ASCII digits 0-9: {text!r}")
    try:
        value = rational(str(text).replace("_", ""))
    except NumberTooLarge:
        raise
    except (ValueError, ZeroDivisionError):
        raise ValueError(f"not a finite number: {text!r}") from None
    return sympy.Rational(value.numerator, value.denominator)


def bits_bound(expr: sympy.Expr, bits: Mapping[str, int]) -> int:
    """An upper bound on the bits of ``expr``'s value once its symbols take values of
    ``bits[name]`` bits, found before anything is evaluated: chained powers such as
    ``p2 = p1**64`` grow past memory unless refused in advance.

    >>> import sympy
    >>> p = sympy.Symbol("p")
    >>> bits_bound(p**64 + 1, {"p": 65})   # 65 * 64 bits, one for the 1, a carry per term
    4163
    """
    if expr.is_Rational:
        return max(int(expr.p).bit_length(), int(expr.q).bit_length())
    if expr.is_Symbol:
        return bits.get(expr.name, 1)
    if expr.is_Pow and expr.exp.is_Integer:
        return bits_bound(expr.base, bits) * abs(int(expr.exp))
    # A sum or product of rationals has at most the summed bits of its parts (plus carries).
    return sum(bits_bound(arg, bits) for arg in expr.args) + len(expr.args)


def irrational(value: sympy.Expr) -> str | None:
    """Why ``value``, a dimension's value, is not one (an irrational number), else None.

    The systems are over the rationals: a dimension is a rational number. A square root that is
    not rational belongs where it is squared away, a dyad's lengths (``lengths = ["sqrt(2)", 1]``).

    >>> irrational(parse("sqrt(9/4)")) is None
    True
    >>> print(irrational(parse("1 + sqrt(2)")))
    1 + sqrt(2) is not rational: a dimension is a rational number (3/2, 0.1, sqrt(9/4)); write an irrational length in a dyad's lengths, where it is squared
    """
    if not value.is_number or value.is_Rational:
        return None
    return (f"{value} is not rational: a dimension is a rational number (3/2, 0.1, sqrt(9/4)); "
            "write an irrational length in a dyad's lengths, where it is squared")


def _check_size(numerator: int, denominator: int = 1) -> None:
    if max(abs(numerator).bit_length(), abs(denominator).bit_length()) > MAX_NUMBER_BITS:
        raise ValueError(f"number too large or too precise (more than {MAX_NUMBER_BITS} bits)")


def _check_result(value: sympy.Expr) -> None:
    """Bound what a parse may hand on: numbers of at most MAX_NUMBER_BITS, small powers."""
    for number in value.atoms(sympy.Rational):
        _check_size(number.p, number.q)
    for power in value.atoms(sympy.Pow):
        if power.exp.is_Rational and abs(power.exp) > MAX_EXPONENT:
            raise ValueError(f"exponent must be of size at most {MAX_EXPONENT}, got {power.exp}")


def _tokenize(text: str) -> list[Token]:
    tokens: list[Token] = []
    pos = 0
    text = text.rstrip(_SPACE)
    while pos < len(text):
        match = _TOKEN.match(text, pos)
        if not match or match.end() == pos:
            where = pos + len(text[pos:]) - len(text[pos:].lstrip(_SPACE))
            ascii_hint = "" if text[where].isascii() else " (numbers and names are ASCII: digits 0-9, letters A-Z a-z)"
            raise ValueError(f"unexpected character {text[where]!r} at {where}{ascii_hint}")
        kind = match.lastgroup
        assert kind is not None  # every alternative of _TOKEN is a named group
        tokens.append((kind, match.group(kind)))
        pos = match.end()
    return tokens


class _Parser:
    """Recursive descent over the tokens, one method per rule of the grammar."""

    def __init__(self, tokens: list[Token], names: Mapping[str, sympy.Expr]) -> None:
        self.tokens = tokens
        self.pos = 0
        self.names = names
        self.depth = 0

    def peek(self) -> tuple[str | None, str | None]:
        return self.tokens[self.pos] if self.pos < len(self.tokens) else (None, None)

    def take(self, op: str | None = None) -> Token:
        if self.pos >= len(self.tokens):
            raise ValueError("unexpected end of expression")
        kind, value = self.tokens[self.pos]
        if op is not None and value != op:
            raise ValueError(f"expected {op!r}, found {value!r}")
        self.pos += 1
        return kind, value

    def expr(self) -> sympy.Expr:
        value = self.term()
        while self.peek()[1] in ("+", "-"):
            op = self.take()[1]
            rhs = self.term()
            value = value + rhs if op == "+" else value - rhs
        return value

    def term(self) -> sympy.Expr:
        value = self.unary()
        while self.peek()[1] in ("*", "/"):
            op = self.take()[1]
            rhs = self.unary()
            if op == "/":
                if rhs == 0:
                    raise ValueError("division by zero")
                value = value / rhs
            else:
                value = value * rhs
        return value

    def unary(self) -> sympy.Expr:
        if self.peek()[1] in ("+", "-"):
            op = self.take()[1]
            value = self.nested(self.unary)
            return -value if op == "-" else value
        return self.power()

    def power(self) -> sympy.Expr:
        base = self.atom()
        if self.peek()[1] == "**":
            self.take()
            exponent = self.nested(self.unary)
            if not (exponent.is_Integer and abs(exponent) <= MAX_EXPONENT):
                raise ValueError(
                    f"exponent must be an integer of size at most {MAX_EXPONENT}, got {exponent}"
                )
            if base == 0 and exponent < 0:
                raise ValueError("division by zero")
            if base.is_Rational:  # check before computing: (2**64)**64... grows fast
                bits = max(base.p.bit_length(), base.q.bit_length()) * abs(int(exponent))
                if bits > MAX_NUMBER_BITS + abs(int(exponent)):
                    raise ValueError(f"number too large or too precise (more than {MAX_NUMBER_BITS} bits)")
            return base**exponent
        return base

    def nested(self, rule: Callable[[], sympy.Expr]) -> sympy.Expr:
        self.depth += 1
        if self.depth > MAX_DEPTH:
            raise ValueError(f"expression nested deeper than {MAX_DEPTH}")
        try:
            return rule()
        finally:
            self.depth -= 1

    def atom(self) -> sympy.Expr:
        kind, value = self.take()
        if kind == "num":
            return exact_number(value)
        if kind == "name":
            if self.peek()[1] == "(":
                return self.call(value)
            if value not in self.names:
                known = ", ".join(sorted(self.names)) or "none"
                raise ValueError(f"unknown name {value!r} (known: {known})")
            return self.names[value]
        if value == "(":
            inner = self.nested(self.expr)
            self.take(")")
            return inner
        raise ValueError(f"unexpected {value!r}")

    def call(self, function: str) -> sympy.Expr:
        if function != "sqrt":
            raise ValueError(f"unknown function {function!r} (only sqrt)")
        self.take("(")
        argument = self.nested(self.expr)
        self.take(")")
        if argument.is_number and argument < 0:
            raise ValueError(f"sqrt of a negative number {argument}")
        return sympy.sqrt(argument)


def parse(text: object, names: Mapping[str, object] | None = None) -> sympy.Expr:
    """Parse ``text`` (a string, int, or exact float literal) into a sympy expression.

    ``names`` maps the allowed names to their values (symbols or numbers). Raises
    ValueError with a one-line message on anything outside the language.
    """
    if isinstance(text, bool):
        raise ValueError(f"expected a number or expression, got {text!r}")
    if isinstance(text, int):
        _check_size(text)
        return sympy.Integer(text)
    if not isinstance(text, str):
        raise ValueError(f"expected a number or expression, got {type(text).__name__}")
    if len(text) > MAX_EXPRESSION_LENGTH:
        raise ValueError(f"expression longer than {MAX_EXPRESSION_LENGTH} characters")
    tokens = _tokenize(text)
    if not tokens:
        raise ValueError("empty expression")
    # strict: values are numbers or symbols; a string value would be eval-ed, so it is refused
    parser = _Parser(tokens, {k: sympy.sympify(v, strict=True) for k, v in (names or {}).items()})
    value = parser.expr()
    if parser.pos != len(tokens):
        raise ValueError(f"unexpected {parser.peek()[1]!r} after a complete expression")
    _check_result(value)
    return value
