"""The scene files' tiny expression language (docs/scene-format.md): exact, small, never executed.

Expected values come from Python's ``fractions.Fraction`` or from hand arithmetic,
never from the parser itself.
"""

import builtins
import inspect
from fractions import Fraction
from unittest import mock

import pytest
import sympy
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from algkin.scene import expr as expr_module
from algkin.scene.expr import MAX_EXPRESSION_LENGTH, exact_number, parse

CHEAP = settings(max_examples=200, deadline=None)


def as_fraction(value):
    """A sympy Rational as a Fraction; fails the test on anything else."""
    assert isinstance(value, sympy.Rational), f"not an exact rational: {value!r}"
    return Fraction(int(value.p), int(value.q))


# --- (a) rationals p/q ----------------------------------------------------------------


@CHEAP
@given(st.integers(-(10**30), 10**30), st.integers(-(10**30), 10**30).filter(bool))
def test_rational_literal_is_exact(p, q):
    value = parse(f"{p}/{q}")
    assert value == sympy.Rational(p, q)
    assert as_fraction(value) == Fraction(p, q)


@CHEAP
@given(st.fractions(max_denominator=10**12))
def test_fraction_str_round_trips(fraction):
    # str(Fraction) is "n/d", "-n/d" or "n"
    assert as_fraction(parse(str(fraction))) == fraction


# --- (b) decimal literals are exact -----------------------------------------------------


def decimal_text(m, k):
    """The decimal string of m / 10**k, written by hand (no float anywhere)."""
    digits = str(abs(m)).rjust(k + 1, "0")
    text = f"{digits[:-k]}.{digits[-k:]}" if k else digits
    return ("-" if m < 0 else "") + text


@CHEAP
@given(st.integers(-(10**25), 10**25), st.integers(0, 30))
def test_decimal_literal_is_exact(m, k):
    text = decimal_text(m, k)
    assert parse(text) == sympy.Rational(m, 10**k)
    assert as_fraction(parse(text)) == Fraction(m, 10**k)
    unsigned = text.lstrip("-")
    assert as_fraction(exact_number(unsigned)) == Fraction(abs(m), 10**k)


@CHEAP
@given(st.integers(0, 10**20), st.integers(-40, 40))
def test_exponent_literal_is_exact(m, e):
    expected = Fraction(m) * Fraction(10) ** e
    assert as_fraction(parse(f"{m}e{e}")) == expected
    assert as_fraction(parse(f"{m}E{e:+d}")) == expected
    assert as_fraction(exact_number(f"{m}e{e}")) == expected


@pytest.mark.parametrize(
    "text, expected",
    [
        ("0.1", Fraction(1, 10)),
        ("0.3", Fraction(3, 10)),
        ("1.1", Fraction(11, 10)),
        (".5", Fraction(1, 2)),
        ("5.", Fraction(5)),
        ("2.5e-1", Fraction(1, 4)),
        ("1e3", Fraction(1000)),
        ("1_000.5", Fraction(2001, 2)),
        ("0.1 + 0.2", Fraction(3, 10)),  # the binary-float classic: exactly 3/10 here
        ("  7  ", Fraction(7)),
    ],
)
def test_decimals_by_hand(text, expected):
    assert as_fraction(parse(text)) == expected


def test_point_one_is_not_the_binary_float():
    value = parse("0.1")
    assert value == sympy.Rational(1, 10)
    assert value != sympy.Rational(0.1)  # 3602879701896397/36028797018963968
    assert exact_number("0.1") == sympy.Rational(1, 10)


def test_python_float_is_refused():
    # a float object has already lost the decimal it was written as
    with pytest.raises(ValueError):
        parse(0.1)


def test_python_int_and_bool():
    assert parse(12) == 12 and isinstance(parse(12), sympy.Integer)
    with pytest.raises(ValueError):
        parse(True)


# --- (c) arithmetic trees against Fraction arithmetic --------------------------------------


class TooBig(Exception):
    pass


LIMIT_BITS = 300


def _small(value):
    if max(abs(value.numerator).bit_length(), value.denominator.bit_length()) > LIMIT_BITS:
        raise TooBig
    return value


def evaluate(tree):
    """Fraction arithmetic on a tree; ZeroDivisionError / TooBig reject the example."""
    kind = tree[0]
    if kind == "int":
        return Fraction(tree[1])
    if kind == "neg":
        return -evaluate(tree[1])
    if kind == "pow":
        base = evaluate(tree[1])
        return _small(base ** tree[2])  # Fraction(0) ** -k raises ZeroDivisionError
    a, b = evaluate(tree[1]), evaluate(tree[2])
    if kind == "+":
        return _small(a + b)
    if kind == "-":
        return _small(a - b)
    if kind == "*":
        return _small(a * b)
    return _small(a / b)  # "/": ZeroDivisionError on b == 0


ATOM, POWER, UNARY, PRODUCT, SUM = 5, 4, 3, 2, 1


def render_full(tree):
    """Every operation parenthesised; negative numbers too."""
    kind = tree[0]
    if kind == "int":
        return str(tree[1])
    if kind == "neg":
        return f"(-{render_full(tree[1])})"
    if kind == "pow":
        return f"(({render_full(tree[1])})**({tree[2]}))"
    return f"({render_full(tree[1])} {kind} {render_full(tree[2])})"


def render_min(tree):
    """As few parentheses as the usual precedence needs: ** binds tighter than unary minus
    (-2**2 is -4), ** takes a unary exponent (2**-1), * / and + - associate to the left."""

    def go(node):
        kind = node[0]
        if kind == "int":
            return str(node[1]), ATOM
        if kind == "neg":
            return "-" + wrap(node[1], UNARY), UNARY
        if kind == "pow":
            return f"{wrap(node[1], ATOM)}**{node[2]}", POWER
        level = SUM if kind in "+-" else PRODUCT
        return f"{wrap(node[1], level)}{kind}{wrap(node[2], level + 1)}", level

    def wrap(node, needed):
        text, level = go(node)
        return text if level >= needed else f"({text})"

    return go(tree)[0]


trees = st.recursive(
    st.builds(lambda n: ("int", n), st.integers(0, 12)),
    lambda sub: st.one_of(
        st.tuples(st.sampled_from("+-*/"), sub, sub),
        st.builds(lambda t: ("neg", t), sub),
        st.builds(lambda t, k: ("pow", t, k), sub, st.integers(-3, 3)),
    ),
    max_leaves=10,
)


@settings(max_examples=300, deadline=None)
@given(trees, st.booleans())
def test_arithmetic_matches_fractions(tree, minimal):
    try:
        expected = evaluate(tree)
    except (ZeroDivisionError, TooBig):
        assume(False)
    text = render_min(tree) if minimal else render_full(tree)
    assume(len(text) <= MAX_EXPRESSION_LENGTH)
    assert as_fraction(parse(text)) == expected, text


def test_division_by_zero_inside_a_tree_is_refused():
    tree = ("/", ("int", 1), ("-", ("int", 2), ("int", 2)))
    with pytest.raises(ZeroDivisionError):
        evaluate(tree)
    for text in (render_full(tree), render_min(tree), "0**-1", "(3-3)**-2"):
        with pytest.raises(ValueError):
            parse(text)


@pytest.mark.parametrize(
    "text, expected",
    [
        ("-2**2", -4),
        ("(-2)**2", 4),
        ("2**2**3", 256),  # right-associative: 2**(2**3)
        ("2**-1", Fraction(1, 2)),
        ("2*3**2", 18),
        ("8/4/2", 1),  # left-associative
        ("8-4-2", 2),
        ("1+2*3", 7),
        ("(1+2)*3", 9),
        ("--3", 3),
        ("2*-3", -6),
        ("10/4", Fraction(5, 2)),
    ],
)
def test_precedence_by_hand(text, expected):
    assert as_fraction(parse(text)) == Fraction(expected)


def test_names_and_sqrt():
    a, b = sympy.symbols("a b", real=True)
    assert parse("a*b - 2*a", {"a": a, "b": b}) == a * b - 2 * a
    assert parse("sqrt(b**2 + 9)", {"b": 4}) == 5  # 3-4-5
    assert parse("sqrt(8)") == 2 * sympy.sqrt(2)
    assert parse("sqrt(1/4)") == sympy.Rational(1, 2)
    # plain Python ints as values: still exact (120/350 must not become a float)
    assert as_fraction(parse("g/r", {"g": 120, "r": 350})) == Fraction(12, 35)
    assert as_fraction(parse("g", {"g": 120})) == 120


def test_string_values_for_names_are_not_evaluated(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    with pytest.raises(ValueError):
        parse_guarded("a + 1", {"a": "__import__('os').mkdir('PWNED')"})
    assert not (tmp_path / "PWNED").exists()


def test_long_but_allowed_expression():
    text = "+".join(["1"] * 250)  # 499 characters
    assert len(text) <= MAX_EXPRESSION_LENGTH
    assert parse(text) == 250


def test_moderate_nesting_is_fine():
    assert parse("(" * 10 + "7" + ")" * 10) == 7
    assert parse("-" * 10 + "7") == 7


# --- (d) arbitrary text: ValueError or a value, nothing executed ---------------------------


FORBIDDEN = ("eval", "exec", "compile")  # (not __import__: sympy imports lazily)


def _tripwire(name):
    def trip(*args, **kwargs):
        raise AssertionError(f"parse called {name}")

    return trip


_real_sympify = sympy.sympify


def _sympify_no_strings(value, *args, **kwargs):
    # sympify(str) is eval in disguise; sympify(number or symbol) is harmless, and
    # sympify(str, strict=True) refuses to parse
    if isinstance(value, str) and not kwargs.get("strict"):
        raise AssertionError(f"parse called sympify on the string {value!r}")
    return _real_sympify(value, *args, **kwargs)


def parse_guarded(text, names=None):
    """parse with eval/exec/compile and sympy's string parsers booby-trapped."""
    patches = [mock.patch.object(builtins, n, _tripwire(n)) for n in FORBIDDEN]
    patches += [
        mock.patch.object(sympy, "sympify", _sympify_no_strings),
        mock.patch.object(sympy, "parse_expr", _tripwire("parse_expr")),
        mock.patch("sympy.parsing.sympy_parser.parse_expr", _tripwire("parse_expr")),
    ]
    for p in patches:
        p.start()
    try:
        return parse(text, names)
    finally:
        for p in reversed(patches):
            p.stop()


def _accept_or_value_error(text, names=None):
    try:
        value = parse_guarded(text, names)
    except ValueError as err:
        message = str(err)
        assert message and "\n" not in message
        return None
    assert isinstance(value, sympy.Basic)
    return value


@CHEAP
@given(st.text())
def test_arbitrary_text_only_raises_value_error(text):
    _accept_or_value_error(text)


@CHEAP
@given(st.text(alphabet="0123456789.eE_+-*/() ,xsqrt", max_size=60))
def test_language_alphabet_soup_only_raises_value_error(text):
    x = sympy.Symbol("x", real=True)
    _accept_or_value_error(text, {"x": x})


def test_tripwires_work():
    with pytest.raises(AssertionError):
        with mock.patch.object(builtins, "eval", _tripwire("eval")):
            eval("1")  # noqa: S307 - checks the tripwire itself


def test_parser_source_has_no_eval():
    source = inspect.getsource(expr_module)
    for word in ("eval(", "exec(", "parse_expr", "__import__(", "getattr", "compile(", "S("):
        # the docstring shows __import__ being refused; look at code lines only
        code = "\n".join(line for line in source.splitlines() if not line.lstrip().startswith(">>>"))
        assert word not in code.replace("re.compile(", ""), word


# --- plain rejections -----------------------------------------------------------------------


@pytest.mark.parametrize(
    "text",
    [
        "__import__('os')",
        "os.system",
        "a.b",
        "lambda: 1",
        "[1]",
        "2**100000",
        "1/0",
        "sqrt(-4)",
        "foo(2)",
        "1" + "+1" * 250,  # 501 characters
        "(" * 100 + "1" + ")" * 100,
        "-" * 100 + "1",
        "",
        "   ",
        "1 2",
        "2**(1/2)",
        "2**0.5",
        "1e",
        "()",
        "sqrt 4",
        "sqrt(4, 9)",
        "1 +",
        "\"1\"",
        "0x10",
        "1; 2",
        "(1",
        "1)",
        "x if 1 else 2",
        "1e999999999",  # would be a gigabyte-sized integer
        "((2**64)**64)**64",  # 2**262144, and a few more levels run out of memory
        "(2**64)**16*(2**64)**16",
    ],
)
def test_rejected(text):
    with pytest.raises(ValueError):
        parse_guarded(text)


def test_too_long_message():
    with pytest.raises(ValueError, match=str(MAX_EXPRESSION_LENGTH)):
        parse("1" + "+1" * 250)


def test_too_deep_message():
    with pytest.raises(ValueError, match="nest"):
        parse("(" * 100 + "1" + ")" * 100)


def test_exponent_too_big_message():
    with pytest.raises(ValueError, match="exponent"):
        parse("2**100000")


def test_division_by_zero_message():
    with pytest.raises(ValueError, match="zero"):
        parse("1/0")


def test_sqrt_negative_message():
    with pytest.raises(ValueError, match="negative"):
        parse("sqrt(-4)")


@pytest.mark.parametrize("text, name", [("foo + 1", "foo"), ("2*height", "height"), ("os", "os")])
def test_unknown_name_is_named(text, name):
    with pytest.raises(ValueError, match=f"'{name}'"):
        parse(text, {"a": sympy.Symbol("a")})


@pytest.mark.parametrize("text, name", [("foo(2)", "foo"), ("cos(1)", "cos"), ("exp(a)", "exp")])
def test_unknown_function_is_named(text, name):
    with pytest.raises(ValueError, match=f"'{name}'"):
        parse(text, {"a": sympy.Symbol("a")})


@pytest.mark.parametrize("text", ["inf", "nan", "-inf", "abc", "1/0", "", "1e99999999999"])
def test_exact_number_rejects(text):
    with pytest.raises(ValueError):
        exact_number(text)


def test_huge_numbers_are_refused_before_they_are_made():
    # Measured in memory, not time (the machine may be loaded): 10**999999999 alone is 415 MB.
    import tracemalloc

    tracemalloc.start()
    for text in ("1e999999999", "9" * 400, "((((((2**64)**64)**64)**64)**64)**64)"):
        with pytest.raises(ValueError):
            parse(text)
    with pytest.raises(ValueError):
        parse(10**400)
    with pytest.raises(ValueError):
        exact_number("1e999999999")
    _, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    assert peak < 2**20, peak  # a megabyte: what a parse takes, and no huge number


@pytest.mark.parametrize("text", ["\u0661", "\uff11/2", "1\u00a0", "\u00a01", "2*\u0663", "1.5\u2003", "a + \uff12"])
def test_numbers_are_ascii(text):
    """Python's int() and Fraction() read other scripts' digits and strip a no-break space; the
    tiny language is ASCII, so these are refused, not read as numbers."""
    with pytest.raises(ValueError, match="ASCII"):
        parse(text, {"a": 1})


@pytest.mark.parametrize("text", ["\u0661.5", "1.5\u00a0", "\uff11e3"])
def test_float_literals_are_ascii(text):
    with pytest.raises(ValueError, match="ASCII"):
        exact_number(text)


def test_ascii_spaces_around_a_number_still_do():
    assert parse(" 3/2\t ") == sympy.Rational(3, 2)
