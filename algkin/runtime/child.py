"""Work in a forked child process, its answer or its error sent back pickled: the one way a
computation is run apart, whether to be stopped at a deadline (a budget's, a bench row's) or
beside the parent (an interpolation's second prime).

A python-flint resultant or Gröbner basis is one C call that no signal interrupts: work that
may have to be stopped runs in a child that the parent kills. The child's error comes back as
the exception itself, raised in the parent (one that cannot travel becomes a
ComputationError naming it); a child that dies without an answer is a ComputationError too.
On the way the child may ``tell`` its parent notes (what it is doing), and its progress shows
through the parent (``algkin.runtime.progress``) or nowhere.

No child outlives its parent: the kernel kills it when the parent dies (Linux,
``bind_to_parent``), and the parent kills and joins it however the ``forked`` block ends, an
exception raised by a signal included.

>>> with forked(lambda tell: sum(range(10))) as child:
...     child.answer()
45
>>> with forked(lambda tell: 1 // 0) as child:
...     child.answer()
Traceback (most recent call last):
...
ZeroDivisionError: integer division or modulo by zero

Notes told reach ``heard``, in order, before the answer:

>>> def work(tell):
...     tell("halfway")
...     return "done"
>>> heard = []
>>> with forked(work) as child:
...     child.answer(heard=heard.append)
'done'
>>> heard
['halfway']
"""

import contextlib
import ctypes
import multiprocessing
import os
import pickle
import signal
import sys
from collections.abc import Callable, Iterator
from multiprocessing.connection import Connection
from typing import Any, Generic, TypeVar, cast

from ..errors import ComputationError
from . import progress

__all__ = ["forked", "Child", "TimeUp", "Tell", "can_fork", "bind_to_parent"]

T = TypeVar("T")

Tell = Callable[[Any], None]
"""How the work in a child tells its parent a note (any picklable value)."""

_PR_SET_PDEATHSIG = 1  # <linux/prctl.h>
# Signals that stop a command: the parent turns them into an exception (algkin.ui.cli); the child,
# which would otherwise inherit that handler, just dies (Ctrl-C reaches the whole process group).
_STOPPING = (signal.SIGINT, signal.SIGTERM, signal.SIGHUP)


class TimeUp(Exception):
    """No answer came before the time the parent waited for had passed (the child is killed)."""


def can_fork() -> bool:
    """Whether this process can fork a child: the platform forks, and this process is no
    child itself (a daemonic process may have none)."""
    return "fork" in multiprocessing.get_all_start_methods() and not multiprocessing.current_process().daemon


@contextlib.contextmanager
def forked(work: Callable[[Tell], T], *, shows_progress: bool = False) -> Iterator["Child[T]"]:
    """Within the block, ``work(tell)`` computing in a forked child (``Child.answer`` waits for it);
    the child killed if still alive and joined when the block ends. With ``shows_progress``, its
    progress shows through this process while it waits, else nowhere."""
    context = multiprocessing.get_context("fork")
    receive, send = context.Pipe(duplex=False)
    process = context.Process(target=_main, args=(work, send, os.getpid(), shows_progress), daemon=True)
    process.start()
    send.close()
    try:
        yield Child(receive, process)
    finally:  # however the block ended (answer, deadline, error, a signal's exception): no child left
        if process.is_alive():
            process.kill()
        process.join()
        receive.close()


class Child(Generic[T]):
    """A forked child computing; ``answer()`` is what it computed."""

    def __init__(self, pipe: Connection, process: multiprocessing.process.BaseProcess) -> None:
        self._pipe, self._process = pipe, process

    def answer(self, *, left: Callable[[], float] | None = None, heard: Tell = lambda note: None) -> T:
        """The child's result (its error raised here), each note it tells passed to ``heard`` on
        the way; TimeUp once ``left()`` (the seconds left, read on the caller's clock) is not
        positive, the child killed. A poll may wake early: ``left()`` alone says when time is up."""
        while True:
            seconds = None if left is None else left()
            if seconds is not None and seconds <= 0:
                return self._overtime(heard)
            if not self._pipe.poll(seconds):
                continue
            try:
                message = self._pipe.recv()
            except (EOFError, OSError):  # OSError: the pipe closed in the middle of a message
                self._process.join()
                raise ComputationError(f"the child process ended without an answer "
                                       f"(exit code {self._process.exitcode})") from None
            done, value = _take(message, heard)
            if done:
                return cast(T, value)  # what ``work`` returned, unpickled

    def _overtime(self, heard: Tell) -> T:
        """Past the time: kill the child, then read only what it had sent already.

        Once the child is dead the pipe holds a bounded amount, so this cannot spin or wait:
        an answer that came in time is still taken, a late note is still heard."""
        self._process.kill()
        self._process.join()
        for message in _already_sent(self._pipe):
            done, value = _take(message, heard)
            if done:
                return cast(T, value)
        raise TimeUp


def _take(message: tuple[str, Any], heard: Tell) -> tuple[bool, Any]:
    """``(True, result)`` if ``message`` is the answer (an error is raised); else the note or the
    progress taken, and ``(False, None)``."""
    kind, value = message
    if kind == "done":
        return True, value
    if kind == "error":
        raise value
    if kind == "note":
        heard(value)
    else:
        progress.replay(value)
    return False, None


def _already_sent(pipe: Connection) -> Iterator[tuple[str, Any]]:
    """The messages in ``pipe`` now, up to the end of what was written or a message cut off."""
    try:
        while pipe.poll(0):
            yield pipe.recv()
    except (EOFError, OSError):
        return


def _main(work: Callable[[Tell], Any], pipe: Connection, parent_pid: int, shows_progress: bool) -> None:
    """The child: bound to its parent, its progress handed over, its answer or error sent."""
    bind_to_parent(parent_pid)
    progress.hand_over((lambda event: pipe.send(("progress", event))) if shows_progress else None)
    try:
        outcome: tuple[str, Any] = ("done", work(lambda note: pipe.send(("note", note))))
    except BaseException as err:  # noqa: BLE001 - every failure goes back to the parent
        outcome = ("error", _portable(err))
    try:
        pipe.send(outcome)
    except (pickle.PicklingError, TypeError, AttributeError) as err:
        pipe.send(("error", ComputationError(f"the result could not be sent back: {err}")))


def _portable(err: BaseException) -> BaseException:
    """``err`` if it survives pickling (as it must to reach the parent), else a ComputationError naming it."""
    try:
        pickle.loads(pickle.dumps(err))
    except Exception:  # noqa: BLE001 - whatever stops it travelling, the parent still hears what it was
        return ComputationError(f"{type(err).__name__}: {err}")
    return err


def bind_to_parent(parent_pid: int) -> None:
    """In a child just forked by ``parent_pid``: die with the parent, and of a stopping signal.

    On Linux the kernel kills the child when its parent dies (elsewhere only the parent's own
    clean-up stops it). Strictly the kernel watches the parent's thread that forked, which
    waits for the child, so it ends no sooner. A parent killed before the request took
    effect is caught by the check that follows it: the child has then been re-parented, and
    leaves at once.
    """
    if sys.platform.startswith("linux"):
        ctypes.CDLL(None, use_errno=True).prctl(_PR_SET_PDEATHSIG, signal.SIGKILL)
    if os.getppid() != parent_pid:
        os._exit(1)
    for signum in _STOPPING:
        signal.signal(signum, signal.SIG_DFL)
