"""One exception root for algkin; each subclass also derives from the builtin that fits.

Messages name the argument (or file and element) and the offending value, on one line,
so the command line can print them as they are. A ``UsageError`` names the Python parameter
(``point=``); the command line prints it with the flag its user typed (``--point=``, from the
table in ``algkin.ui.cli.flags``).

>>> err = SceneError("lambda.toml", "points.B.lengths", "length must be positive, got -1")
>>> str(err)
'lambda.toml: points.B.lengths: length must be positive, got -1'
>>> isinstance(err, ValueError) and isinstance(err, AlgkinError)
True
>>> import pickle
>>> str(pickle.loads(pickle.dumps(UsageError("point", "P", "not a point"))))
"point='P': not a point"
>>> str(UsageError("samples", 10**5000, "expected a whole number"))  # Python writes no integer past 4300 digits
'samples=<an int of 16610 bits>: expected a whole number'
>>> err = pickle.loads(pickle.dumps(OutputError("/dev/full", "No space left on device")))
>>> str(err), isinstance(err, OSError)
("cannot write '/dev/full': No space left on device", True)
"""

from __future__ import annotations

import contextlib
import numbers
import os
from collections.abc import Callable, Iterator

__all__ = [
    "AlgkinError",
    "SceneError",
    "UsageError",
    "renamed",
    "BudgetExceeded",
    "ComputationError",
    "OutputError",
    "written",
]


class AlgkinError(Exception):
    """Root of every error algkin raises on purpose."""


def written(value: object, *, write: Callable[[object], str] = repr) -> str:
    """``write(value)`` for a message, or what the value is where Python refuses to write it (an
    integer of more than 4300 digits, or a fraction of one, raises ValueError): never an error
    raised while telling of another."""
    try:
        return write(value)
    except ValueError:
        kind = type(value).__name__
        if isinstance(value, numbers.Rational):
            size = max(abs(int(value.numerator)).bit_length(), int(value.denominator).bit_length())
            return f"<{'an' if kind[0] in 'aeiou' else 'a'} {kind} of {size} bits>"
        return f"<a {kind} holding a number too large to write>"


class SceneError(AlgkinError, ValueError):
    """A scene file or scene element is malformed; names the source and the element."""

    def __init__(self, source: str, element: str, message: str) -> None:
        self.source = source
        self.element = element
        self.message = message
        where = f"{source}: {element}" if element else str(source)
        super().__init__(f"{where}: {message}")

    def __reduce__(self) -> tuple[type[SceneError], tuple[str, str, str]]:  # pickled back from a budget's child process
        return type(self), (self.source, self.element, self.message)


class UsageError(AlgkinError, ValueError):
    """An argument (method name, parameter name, range...) is not acceptable."""

    def __init__(self, argument: str, value: object, message: str) -> None:
        self.argument = argument
        self.value = value
        self.message = message
        super().__init__(f"{argument}={written(value)}: {message}")

    def __reduce__(self) -> tuple[type[UsageError], tuple[str, object, str]]:
        return type(self), (self.argument, self.value, self.message)



@contextlib.contextmanager
def renamed(argument: str, *, to: str) -> Iterator[None]:
    """A UsageError raised within that names ``argument`` names ``to`` instead: a caller's own
    parameter, passed on under the other name.

    >>> with renamed("outputs", to="output"):
    ...     raise UsageError("outputs", "|AB|", "unknown point")
    Traceback (most recent call last):
    algkin.errors.UsageError: output='|AB|': unknown point
    """
    try:
        yield
    except UsageError as err:
        if err.argument != argument:
            raise
        raise UsageError(to, err.value, err.message) from None


class BudgetExceeded(AlgkinError, RuntimeError):
    """A computation went past its time or size budget and was stopped."""


class ComputationError(AlgkinError, ArithmeticError):
    """The algebra could not be completed (inconsistent system, failed selection...)."""


class OutputError(AlgkinError, OSError):
    """A file could not be written (disk full, permission lost...); any earlier file is left as it was."""

    def __init__(self, path: str | os.PathLike[str], message: str) -> None:
        self.path = str(path)
        self.message = message
        super().__init__(f"cannot write {self.path!r}: {message}")

    def __reduce__(self) -> tuple[type[OutputError], tuple[str, str]]:
        return type(self), (self.path, self.message)
