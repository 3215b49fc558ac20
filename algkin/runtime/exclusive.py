"""One computation at a time in a process, whatever thread asks for it.

python-flint's working precision (``flint.ctx.prec``, which ``flint.ctx.workprec`` sets and puts
back) and mpmath's (``mpmath.mp``) belong to the process, not to a thread: two threads deriving
at once ran each at the other's precision, and a verification at 53 bits in place of 192 said
"failed" on closed forms that are right. The public computations take this lock; python-flint and
the Python code around it hold the GIL anyway, so threads lose no speed by taking turns. The
lock is re-entrant (a derivation prepares its scene through ``prepare``, which takes it again).

>>> import flint
>>> @one_at_a_time
... def widest() -> int:
...     with flint.ctx.workprec(200):
...         return flint.ctx.prec
>>> widest(), flint.ctx.prec
(200, 53)
"""

import functools
import threading
from collections.abc import Callable
from typing import ParamSpec, TypeVar


__all__ = ["one_at_a_time"]

P = ParamSpec("P")
R = TypeVar("R")

_TURN = threading.RLock()


def one_at_a_time(function: Callable[P, R]) -> Callable[P, R]:
    """``function`` run holding the process's one computing lock."""

    @functools.wraps(function)
    def taking_turns(*args: P.args, **kwargs: P.kwargs) -> R:
        with _TURN:
            return function(*args, **kwargs)

    return taking_turns
