"""Stopping signals and stdout: one line and exit 128 + N on SIGINT, SIGTERM or SIGHUP, with every
``finally`` run on the way out (a budget's worker is killed); a closed stdout ends quietly."""

import contextlib
import os
import signal
import sys
import threading

__all__ = []


# What a stopping signal says on stderr; the exit code is 128 + its number, as a shell's.
_STOPS = {signal.SIGINT: "interrupted", signal.SIGTERM: "terminated (SIGTERM)", signal.SIGHUP: "hung up (SIGHUP)"}


# The reader of stdout went away (``algkin list | head -1``): 128 + SIGPIPE, what a shell reports
# for a program the closed pipe ended; 1 would say that the computation failed.
_STDOUT_CLOSED = 128 + signal.SIGPIPE


def _write(text, code):
    """Write ``text`` to stdout and flush it now, so that a closed pipe shows here and not at
    exit; the exit code: ``code``, or _STDOUT_CLOSED if the reader has gone."""
    try:
        sys.stdout.write(text)
        sys.stdout.flush()
    except BrokenPipeError:
        # The Python docs' recipe (signal module, "Note on SIGPIPE"): point stdout at devnull so
        # that the interpreter's own flush at exit finds no broken pipe either.
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return _STDOUT_CLOSED
    return code


class _Stopped(BaseException):
    """A stopping signal (SIGINT, SIGTERM, SIGHUP) while a command runs, raised so that every
    ``finally`` on the way out runs: a budget's child is killed and joined. Not an AlgkinError:
    like KeyboardInterrupt, no ``except Exception`` may swallow it."""

    def __init__(self, signum):
        super().__init__(_STOPS[signum])
        self.signum = signum


@contextlib.contextmanager
def _stopping_signals():
    """While the block runs, the stopping signals raise ``_Stopped``; then the handlers found are back."""
    if threading.current_thread() is not threading.main_thread():
        yield  # only the main thread may set handlers, and only it receives signals
        return
    found = {signum: signal.signal(signum, _stop) for signum in _STOPS}
    try:
        yield
    finally:
        for signum, handler in found.items():
            # None: a handler not set from Python; the default is the nearest we can put back.
            signal.signal(signum, signal.SIG_DFL if handler is None else handler)


def _stop(signum, frame):
    """Raise the signal as ``_Stopped``, once: a second signal must not cut the clean-up short."""
    for each in _STOPS:
        signal.signal(each, signal.SIG_IGN)
    raise _Stopped(signum)
