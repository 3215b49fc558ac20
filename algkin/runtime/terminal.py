"""Text from a scene shown on a terminal without obeying what it may hide."""

import re

__all__ = ["terminal_safe", "one_line", "shortened", "clipped"]

# Control characters (ESC starts terminal commands) and bidirectional overrides (which
# reorder what is shown) from a scene's names and text are shown escaped, never obeyed.
_UNSAFE = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\u061c\u200e\u200f\u2028\u2029\u202a-\u202e\u2066-\u2069]")


def terminal_safe(text: str) -> str:
    r"""``text`` with control and bidi characters escaped; newlines and tabs kept.

    >>> terminal_safe("scene \x1b[31mred\u202e\n")
    'scene \\x1b[31mred\\u202e\n'
    """
    return _UNSAFE.sub(lambda m: m.group().encode("unicode_escape").decode("ascii"), text)


def shortened(text: str, limit: int = 80) -> str:
    """``text`` cut to ``limit`` characters for an error line, saying how long it was (a value, or a
    name given as a scene, may be 100000 characters long).

    >>> shortened("x=" + "9" * 100, 30)
    'x=99999999...(102 characters)'
    """
    return text if len(text) <= limit else f"{text[:limit - 20]}...({len(text)} characters)"


def one_line(text: str) -> str:
    r"""``text`` as one terminal line: newlines and tabs escaped as well (an error message quoting a
    scene's key or name must not start a second line that reads as algkin's own).

    >>> one_line("points.B\nimport os: not a name\x1b[2J")
    'points.B\\nimport os: not a name\\x1b[2J'
    """
    return terminal_safe(text).replace("\n", "\\n").replace("\t", "\\t")


def clipped(text: str, limit: int = 1000) -> str:
    """``text`` with its middle left out past ``limit`` characters (about that many kept), saying how
    much: an error line keeps the flag it starts with and the reason it ends with (a value 100000
    characters long may stand between them, once or more).

    >>> clipped("--outputs='" + "B" * 3000 + "': unknown point", 60)
    "--outputs='BBBBBBBB...(2988 characters left out)...BBBB': unknown point"
    """
    if len(text) <= limit:
        return text
    head, tail = limit // 2, limit // 3
    return f"{text[:head - 11]}...({len(text) - head - tail + 11} characters left out)...{text[-tail:]}"
