"""User text in generated code: identifiers and comments that are data, never code.

A name in a scene (its ``name``, a branch label, an input) may hold anything: a comment
terminator, a quote, a newline, a reserved word. Code written from it keeps it inert in two
ways. Every identifier the code declares comes from ``identifiers``: one rule, the same in
each target language, mapping any name to an identifier of that language which none of its
reserved words, none of the helpers the code uses and no other name of the file take. Every
piece of text in a comment or a docstring goes through ``escaped``, which leaves printable
ASCII alone and writes every other character, and the backslash, as its Python escape (so no
line ever ends inside user text); ``comment`` adds each language's own terminators' escapes.

>>> identifiers(["x */ f(); /*", "int", "a-b", "a_b"], "c")
{'x */ f(); /*': 'x_f', 'int': 'int_2', 'a-b': 'a_b_2', 'a_b': 'a_b'}
>>> print(comment("x */ f(); /*\\nline", "c"))
/* x *\\x2f f(); \\x2f*\\nline */
"""

import builtins
import keyword
import re
from collections.abc import Iterable, Sequence

__all__ = ["identifiers", "escaped", "comment", "docstring_text", "latex_text", "RESERVED"]

_MATH_H = """acos acosh asin asinh atan atan2 atanh cbrt ceil copysign cos cosh erf erfc exp exp2 expm1 fabs fdim
floor fma fmax fmin fmod frexp hypot ilogb ldexp lgamma llrint llround log log10 log1p log2 logb lrint lround modf
nan nearbyint nextafter nexttoward pow remainder remquo rint round scalbln scalbn sin sinh sqrt tan tanh tgamma trunc
j0 j1 jn y0 y1 yn gamma drem finite significand scalb exp10 pow10 sincos lgamma_r gamma_r
isnan isinf isfinite isnormal signbit fpclassify isgreater isgreaterequal isless islessequal islessgreater
isunordered iszero issignaling NAN INFINITY HUGE_VAL HUGE_VALF HUGE_VALL FP_NAN FP_INFINITE FP_ZERO FP_SUBNORMAL
FP_NORMAL FP_ILOGB0 FP_ILOGBNAN FP_FAST_FMA MATH_ERRNO MATH_ERREXCEPT math_errhandling float_t double_t signgam
M_E M_LOG2E M_LOG10E M_LN2 M_LN10 M_PI M_PI_2 M_PI_4 M_1_PI M_2_PI M_2_SQRTPI M_SQRT2 M_SQRT1_2"""
_C_WORDS = """auto break case char const continue default do double else enum extern float for goto if inline int
long register restrict return short signed sizeof static struct switch typedef union unsigned void volatile while
bool true false alignas alignof constexpr nullptr static_assert thread_local typeof typeof_unqual
and and_eq bitand bitor compl not not_eq or or_eq xor xor_eq
asm catch class delete explicit export friend mutable namespace new operator private protected public template this
throw try typename using virtual main errno NULL"""
_JS_WORDS = """break case catch class const continue debugger default delete do else enum export extends false
finally for function if import in instanceof new null return super switch this throw true try typeof var void while
with yield let static implements interface package private protected public await async of get set
arguments eval undefined NaN Infinity globalThis Math Number Object Array String Boolean Symbol BigInt Date RegExp
JSON Error TypeError RangeError SyntaxError ReferenceError EvalError URIError AggregateError Promise Proxy Reflect
Map Set WeakMap WeakSet WeakRef ArrayBuffer SharedArrayBuffer DataView Atomics Intl Function isNaN isFinite
parseFloat parseInt encodeURI decodeURI encodeURIComponent decodeURIComponent escape unescape
Float32Array Float64Array Int8Array Int16Array Int32Array Uint8Array Uint8ClampedArray Uint16Array Uint32Array
BigInt64Array BigUint64Array console window self document require module exports process global"""

# The words each language reserves, the library names the code calls and the helpers it defines.
RESERVED = {
    "c": frozenset((_C_WORDS + " " + _MATH_H).split()) | {"algkin_max", "algkin_min", "algkin_out"},
    "numpy": frozenset(keyword.kwlist) | frozenset(keyword.softkwlist) | frozenset(dir(builtins)) | {"np", "numpy"},
    "js": frozenset(_JS_WORDS.split()) | {"algkin_max", "algkin_min", "copysign"},
}

_PLAIN = re.compile(r"[A-Za-z][A-Za-z0-9_]*")


def identifiers(names: Sequence[str], to: str, taken: Iterable[str] = ()) -> dict[str, str]:
    """Each of ``names`` (distinct) as an identifier of the language ``to``, no two alike, none
    reserved in ``to`` (``RESERVED``) nor among ``taken``.

    A name keeps its spelling where it already is an ASCII identifier (a letter, then letters,
    digits, ``_``) that is free; these are served first, in their order. Every other name has
    each run of characters but ASCII letters and digits made one ``_``, the ``_`` at its ends
    dropped, and ``x`` put before it where it would be empty or begin with a digit; where that
    is not free, the first free of ``_2``, ``_3``, ... is appended.

    >>> identifiers(["3-bar", "", "np", "é"], "numpy")
    {'3-bar': 'x3_bar', '': 'x', 'np': 'np_2', 'é': 'x_2'}
    """
    busy = set(RESERVED[to]) | set(taken)
    chosen = {}
    for name in names:
        if _PLAIN.fullmatch(name) and name not in busy:
            chosen[name] = name
            busy.add(name)
    for name in names:
        if name in chosen:
            continue
        base = re.sub(r"[^A-Za-z0-9]+", "_", name).strip("_")
        base = base if base[:1].isalpha() else "x" + base
        candidate, k = base, 2
        while candidate in busy:
            candidate, k = f"{base}_{k}", k + 1
        chosen[name] = candidate
        busy.add(candidate)
    return {name: chosen[name] for name in names}


def escaped(text: str, also: str = "") -> str:
    """``text`` in printable ASCII on one line: each other character, the backslash and those in
    ``also`` written as a Python escape, so read as a Python string literal it is ``text`` again.

    >>> print(escaped('a"b\\\\\\u2028\\x1b]0;é', also='"'))
    a\\x22b\\\\\\u2028\\x1b]0;\\xe9
    """
    return "".join(_escape(c) if c in also or c == "\\" or not " " <= c <= "~" else c for c in text)


_SHORT = {"\\": "\\\\", "\n": "\\n", "\r": "\\r", "\t": "\\t"}


def _escape(c: str) -> str:
    if c in _SHORT:
        return _SHORT[c]
    code = ord(c)
    return f"\\x{code:02x}" if code < 0x100 else f"\\u{code:04x}" if code < 0x10000 else f"\\U{code:08x}"


# What would end or nest a comment of each language, or reach past it, and is escaped there besides:
# C's */ and /* (either slash beside a star) and the ?? of a trigraph (??/ is a backslash);
# JavaScript's </ and <! (a script element's end in HTML, or its comment). A % comment ends with its line only.
_TERMINATORS = {"c": re.compile(r"/(?=\*)|(?<=\*)/|(?<=\?)\?"), "js": re.compile(r"<(?=[/!])"), "latex": None}
_COMMENT = {"c": "/* {} */", "js": "// {}", "latex": "% {}"}


def comment(text: str, to: str) -> str:
    """``text`` as one comment line of ``to`` (``c``, ``js``, ``latex``), escaped."""
    terminators, text = _TERMINATORS[to], escaped(text)
    return _COMMENT[to].format(terminators.sub(lambda m: _escape(m.group()), text) if terminators else text)


def docstring_text(text: str) -> str:
    """``text`` for the inside of a Python ``\"\"\"`` string, which reads back as ``text``."""
    return escaped(text, also='"')


_LATEX_SPECIAL = {"\\": r"\textbackslash{}", "{": r"\{", "}": r"\}", "$": r"\$", "&": r"\&", "#": r"\#",
                  "^": r"\^{}", "_": r"\_", "%": r"\%", "~": r"\~{}"}


def latex_text(text: str) -> str:
    r"""``text`` for LaTeX's text mode: its special characters as the commands that print them.

    >>> latex_text("B_1 {x}")
    'B\\_1 \\{x\\}'
    """
    return "".join(_LATEX_SPECIAL.get(c, c) for c in escaped(text))
