"""The names a lookup knows, said in an error, with the close match a typo most likely meant.

>>> known("gg", ["a", "b", "r", "g"], plural="parameters")
" (parameters: a, b, r, g); did you mean 'g'?"
>>> known("theta", [], plural="inputs")
' (inputs: none)'
>>> close_match("dervie", ["derive", "curve", "verify"]), close_match("zzz", ["derive"])
('derive', None)
>>> close_match("rates", ["atlas", "plot"]) is None   # a few letters shared is no match
True
>>> close_match("THETA", ["theta", "phi"])  # a case slip is a match however short the name
'theta'
"""

from __future__ import annotations

import difflib
from collections.abc import Iterable

__all__ = ["close_match", "did_you_mean", "known"]

CUTOFF = 0.6
"""difflib's similarity ratio a short name (4 characters or fewer) must reach to be suggested
(difflib's default: ``gg`` for ``g``); a longer one must reach ``LONG_CUTOFF``, or two words
sharing a few letters would be paired (``rates`` and ``atlas``: 0.6)."""
LONG_CUTOFF = 0.7


def close_match(word: object, names: Iterable[str]) -> str | None:
    """The name most like ``word`` (a name, or whatever was given in its place), if one is like it at all.

    >>> close_match(3, ["B", "P"]) is None
    True
    """
    word = str(word)
    names = [n for n in names if n != word]
    folded = [n for n in names if n.casefold() == word.casefold()]
    cutoff = CUTOFF if len(word) <= 4 else LONG_CUTOFF
    found = folded or difflib.get_close_matches(word, names, n=1, cutoff=cutoff)
    return found[0] if found else None


def did_you_mean(word: object, names: Iterable[str]) -> str:
    """``"; did you mean 'name'?"`` for the close match, else nothing."""
    match = close_match(word, names)
    return f"; did you mean {match!r}?" if match else ""


def known(word: object, names: Iterable[str], *, plural: str) -> str:
    """The known names in brackets (``plural``: what they are), then the close match if any."""
    names = list(names)
    return f" ({plural}: {', '.join(names) or 'none'})" + did_you_mean(word, names)
