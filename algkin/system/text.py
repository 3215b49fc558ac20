"""sympy expressions as text, exactly as ``str`` writes them, each shared subexpression written once.

A closed form's square root and denominators recur in every coordinate of every branch: sympy's
printer writes (and sorts the terms of) each occurrence again, half a second of a six-bar's
``derive``. ``ExpressionText`` keeps what it wrote for one document.

>>> import sympy
>>> c = sympy.Symbol("c")
>>> root = sympy.sqrt(3 - 2*c)
>>> text = ExpressionText()
>>> text(c + root), text(c*root / (1 - c))
('c + sqrt(3 - 2*c)', 'c*sqrt(3 - 2*c)/(1 - c)')
"""

from typing import Any

import sympy
from sympy.printing.str import StrPrinter

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

    def _print(self, expr: Any, **kwargs: Any) -> str:
        if kwargs or not isinstance(expr, sympy.Basic) or expr.is_Atom:
            written: str = super()._print(expr, **kwargs)
            return written
        key = (type(expr), expr)  # the type too: sympy finds some numbers of other types equal
        text = self._written.get(key)
        if text is None:
            text = self._written[key] = super()._print(expr)
        return text
