"""A stopping signal (SIGINT, SIGTERM, SIGHUP) as an exception, ``Stopped``, and the record of it.

The command line's handler raises ``Stopped`` wherever the main thread is. Where that is a
finaliser (a ``__del__``, a weak reference's callback: a library's objects collected), Python
prints the exception and goes on, and the command would run on with the signal spent. So the
handler records the signal first (``stop``), and long work asks again between its steps
(``raise_if_stopped``): a sweep between chunks, the command line before it writes its output.

>>> raise_if_stopped()  # nothing asked to stop
>>> try:
...     stop(2)
... except Stopped as err:
...     print(err, err.signum)
interrupted 2
>>> raise_if_stopped()
Traceback (most recent call last):
...
algkin.runtime.stopping.Stopped: interrupted
>>> forget()
"""

import signal

__all__ = ["Stopped", "stop", "raise_if_stopped", "forget"]

# What a stopping signal says on stderr; the exit code is 128 + its number, as a shell's.
SAID = {signal.SIGINT: "interrupted", signal.SIGTERM: "terminated (SIGTERM)", signal.SIGHUP: "hung up (SIGHUP)"}

# The signals received since ``forget``: the process's own, as signals are (one main thread).
_received: list[int] = []


class Stopped(BaseException):
    """A stopping signal while a command runs, raised so that every ``finally`` on the way out runs:
    a budget's child is killed and joined. Not an AlgkinError: like KeyboardInterrupt, no
    ``except Exception`` may swallow it."""

    def __init__(self, signum: int) -> None:
        super().__init__(SAID[signal.Signals(signum)])
        self.signum = signum


def stop(signum: int) -> None:
    """Record ``signum`` and raise it as ``Stopped``."""
    _received.append(signum)
    raise Stopped(signum)


def raise_if_stopped() -> None:
    """Raise ``Stopped`` again if a stopping signal came (its exception may have been swallowed)."""
    if _received:
        raise Stopped(_received[0])


def forget() -> None:
    """Forget the signals received: a new command starts (in tests, many run in one process)."""
    _received.clear()
