"""Stopping signals and stdout: one line and exit 128 + N on SIGINT, SIGTERM or SIGHUP, with every
``finally`` run on the way out (a budget's worker is killed); a reader of stdout gone ends quietly,
a stdout that cannot be written (closed, a full disk) is one line and exit 1.

Nothing here imports more than the standard library (and ``algkin.runtime.stopping``, which
imports nothing more): ``main`` sets these handlers before its other imports (sympy's take half a
second, long enough for a Ctrl-C)."""

import contextlib
import errno
import os
import signal
import sys
import threading
from collections.abc import Callable, Iterator
from types import FrameType

from ...runtime.stopping import SAID, Stopped, forget, stop

__all__ = ["stopping_signals", "Stopped", "write_stdout", "say"]


# The reader of stdout went away (``algkin list | head -1``): 128 + SIGPIPE, what a shell reports
# for a program the closed pipe ended; 1 would say that the computation failed.
_STDOUT_CLOSED = 128 + signal.SIGPIPE


# Stdout cannot take the output (``> /dev/full``, closed): the environment failed the command, not
# its input, so 1, as for a file that cannot be written (OutputError).
_STDOUT_FAILED = 1


def write_stdout(text: str, code: int, failed: bool = False) -> int:
    """Write ``text`` to stdout and flush it now, so that a closed pipe shows here and not at
    exit; the exit code: ``code``, _STDOUT_CLOSED if the reader has gone, _STDOUT_FAILED (and one
    line on stderr) if stdout cannot be written. A command that ``failed`` has said its line and
    keeps its code: stderr's one line is the first cause.

    >>> write_stdout("done\\n", 0)
    done
    0
    """
    try:
        if sys.stdout is None:
            raise OSError(errno.EBADF, "it is closed")
        sys.stdout.write(text)
        sys.stdout.flush()
    except BrokenPipeError:
        _drop_stdout()
        return code if failed else _STDOUT_CLOSED
    except OSError as err:
        _drop_stdout()
        if failed:
            return code
        say(f"cannot write to standard output: {err.strerror or err}")
        return _STDOUT_FAILED
    return code


def _drop_stdout() -> None:
    """The Python docs' recipe (signal module, "Note on SIGPIPE"): point stdout at devnull so that
    the interpreter's own flush at exit, of what could not be written, fails no more."""
    with contextlib.suppress(OSError, ValueError, AttributeError):  # AttributeError: no stdout at all
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())


def say(line: str) -> None:
    """``line`` on stderr, after ``algkin: ``; nothing if stderr cannot take it (closed or full)."""
    if sys.stderr is None:
        return  # print(file=None) would write to stdout
    with contextlib.suppress(OSError, ValueError):
        print(f"algkin: {line}", file=sys.stderr, flush=True)


@contextlib.contextmanager
def stopping_signals(restore: bool = True) -> Iterator[None]:
    """While the block runs, the stopping signals raise ``Stopped``; then the handlers found are back,
    or unless ``restore``, the system's defaults: a signal while the process ends (its exit
    handlers) ends it as any program, with no ``KeyboardInterrupt`` traceback."""
    if threading.current_thread() is not threading.main_thread():
        yield  # only the main thread may set handlers, and only it receives signals
        return
    forget()  # a signal to an earlier command (in this process) stops no later one
    found = {signum: signal.signal(signum, _stop) for signum in SAID}  # every stopping signal
    unraisable, sys.unraisablehook = sys.unraisablehook, _quiet_stops(sys.unraisablehook)
    try:
        yield
    finally:
        sys.unraisablehook = unraisable
        for signum, handler in found.items():
            # None: a handler not set from Python; the default is the nearest we can put back.
            signal.signal(signum, signal.SIG_DFL if handler is None or not restore else handler)


def _quiet_stops(hook: Callable[["sys.UnraisableHookArgs"], object]) -> Callable[["sys.UnraisableHookArgs"], None]:
    """``hook``, but silent on a ``Stopped`` raised where Python drops it (a finaliser, a collector's
    callback such as Dask's GC diagnosis): the signal is recorded and stops the work at its next
    question, and its message is the command's one line, not an "Exception ignored" traceback."""
    def quiet(unraisable: "sys.UnraisableHookArgs") -> None:
        if not isinstance(unraisable.exc_value, Stopped):
            hook(unraisable)
    return quiet


def _stop(signum: int, frame: FrameType | None) -> None:
    """Raise the signal as ``Stopped``, once: a second signal must not cut the clean-up short. It is
    recorded first (``runtime.stopping``): where the exception is swallowed, the work asks again."""
    for each in SAID:
        signal.signal(each, signal.SIG_IGN)
    stop(signum)
