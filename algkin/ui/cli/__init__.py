"""The ``algkin`` command line (docs/cli): readable reports, or one JSON document with --json.

Exit codes: 0 done, 1 a computation failed, a check did not hold, the budget ran out or stdout
could not be written (full, closed), 2 bad input (an output that cannot be written or is an
input, ``paths``), 128 + N stopped by signal N (130 Ctrl-C, 143 SIGTERM, 129 SIGHUP) at any
moment, its imports included, 141 the reader of stdout gone. Whatever the outcome, stderr
holds at most one line once the command ends, and with --json stdout holds one JSON document
(``{"error": ...}`` when there is no result). While it runs, a terminal's stderr shows its
progress (not with --quiet), cleared before that line and before anything is written to stdout.

A command computes its whole output, text or JSON, inside its budget (``--max-seconds``),
in a forked child when there is a time budget; the parent only starts it, waits, and writes.

The package: ``parser`` the grammar, ``commands`` one function per command, ``reports``
the text a person reads, ``paths`` the files read and written, ``flags`` the flag of each Python
parameter an error names, ``signals`` the stopping signals and stdout; here ``main``.
"""

from __future__ import annotations

import argparse
import functools
import gc
import importlib
import os
import sys
import warnings
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING

from ...errors import AlgkinError, BudgetExceeded, SceneError, UsageError
from ...runtime.stopping import raise_if_stopped
from ...runtime.strict_json import json_text
from .flags import as_typed
from .signals import Stopped, say, stopping_signals, write_stdout

if TYPE_CHECKING:  # loaded when a command runs, after the signal handlers
    from .commands import File, Outcome

__all__ = ["main", "usage", "build_parser", "terminal_safe"]

_ERROR_KINDS = ((UsageError, "usage"), (SceneError, "scene"), (BudgetExceeded, "budget"))
# Most of a computing command's imports, loaded before it runs (``_with_algebra``); ``list`` needs none.
# numpy loads numpy.random on first use: there, it was 9 ms of the first verification's stage; sympy
# loads the three modules after it on its first sum (``Add.flatten``), 25 ms of the first stage.
ALGEBRA = ("sympy", "numpy", "numpy.random", "flint", "sympy.calculus.accumulationbounds",
           "sympy.matrices.expressions", "sympy.tensor.tensor")
NO_ALGEBRA = frozenset({"list"})
# A command's own heavy modules, loaded with the algebra and frozen with it: loaded by the command,
# their objects sat in the young generations, walked by the collector while it computed (a
# millisecond and more of a cold derive's total, the first time the collector reached them).
OWN_MODULES = {command: ("algkin.derivation.pipeline",) for command in ("derive", "curve", "verify")}
# Set (to anything), an unexpected exception propagates with its traceback instead of one line
TRACEBACK = "ALGKIN_TRACEBACK"


def __getattr__(name: str) -> object:
    # Loaded on first use: the command line's own imports come after its signal handlers (``main``).
    if name in ("usage", "build_parser"):
        from . import parser

        return getattr(parser, name)
    if name == "terminal_safe":
        from .reports import terminal_safe

        return terminal_safe
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def main(argv: Sequence[str] | None = None) -> int:
    """Run one command line (``argv``, by default the process's) and return its exit code.

    Called with a command line, as in tests, it installs its signal handlers only while it runs and
    then puts the caller's back. Called as the program (no ``argv``), it installs them before it
    imports anything more, and leaves the default ones after it (a signal then ends the
    process as it would any program, without a traceback).
    """
    with stopping_signals(restore=argv is not None):
        try:
            return _main(sys.argv[1:] if argv is None else list(argv), apart=argv is None)
        except Stopped as stop:  # while an error's line was said: that line is all
            return 128 + stop.signum


def _main(argv: list[str], *, apart: bool = False) -> int:
    args: argparse.Namespace | None = None  # until parsed: an error before then still says what it can
    try:
        from .parser import Shown, build_parser

        if not argv:
            # Bare ``algkin`` is a question ("what can it do?"), not a mistake: the help listing the
            # commands, on stdout, exit 0 (as ``--help``); a wrong command line is still exit 2.
            return write_stdout(build_parser().format_help(), 0)
        try:
            args = build_parser().parse_args(argv)
        except Shown as shown:  # --help, --version
            return write_stdout(shown.text, 0)
        return _command(args, apart=apart)
    except Stopped as stop:
        return write_stdout(_failed(argv, args, "interrupted", str(stop), str(stop)), 128 + stop.signum, failed=True)
    except (SceneError, UsageError) as err:
        err = as_typed(err) if isinstance(err, UsageError) else err  # the flag typed, not the Python name
        return write_stdout(_failed(argv, args, _kind(err), str(err), f"error: {err}"), 2, failed=True)
    except AlgkinError as err:
        return write_stdout(_failed(argv, args, _kind(err), str(err), f"failed: {err}"), 1, failed=True)
    except Exception as err:  # a defect of algkin's: said as every failure is (--json's one document too)
        if os.environ.get(TRACEBACK):
            raise
        kind, message = _unforeseen(err)
        return write_stdout(_failed(argv, args, kind, message, f"failed: {message}"), 1, failed=True)


def _unforeseen(err: Exception) -> tuple[str, str]:
    """The kind and message of a failure no error of algkin's said: the machine's limits, else a defect."""
    if isinstance(err, MemoryError):
        return "internal", "out of memory"
    if isinstance(err, ValueError) and "int_max_str_digits" in str(err):  # CPython's limit on writing an integer
        return "computation", (f"the result holds an integer of more than {sys.get_int_max_str_digits()} digits, "
                               "Python's limit for writing one: PYTHONINTMAXSTRDIGITS=0 lifts it")
    return "internal", f"internal error, {type(err).__name__}: {err} (a defect of algkin: {TRACEBACK}=1 shows where)"


def _command(args: argparse.Namespace, *, apart: bool = False) -> int:
    """Run the parsed command: its paths checked, its work done (``apart``: see ``_run``), its files
    saved, its output written."""
    from ...runtime import progress
    from .paths import check_paths

    if sys.stdout is None:  # closed (``>&-``): no work whose result could not be written
        return write_stdout("", 0)
    check_paths(args)  # before any work: every output writable, none over an input
    with progress.shown(args.quiet), warnings.catch_warnings():  # ended, and its line cleared, before anything is said
        # A library's warning is two lines on stderr, which holds at most one: matplotlib's of a glyph its
        # font lacks (a scene named in another script), numpy's of a float overflow (what it means, the
        # report says: a verification that could not evaluate, a figure's box).
        warnings.simplefilter("ignore")
        text, code, *files = _run(args, apart=apart)
    raise_if_stopped()  # a signal whose exception a library swallowed (in a finaliser) still stops it
    _save(*files)
    return write_stdout(text, code)  # a signal while writing (to a slow reader) is caught too


def _run(args: argparse.Namespace, *, apart: bool = False) -> Outcome:
    """The command's output and exit code, all of its work (imports, loading, compiling, the algebra,
    formatting) done within its budget: in a child process killed at the deadline, if it has one.
    The command finds the deadline it keeps to (and passes on) as ``args.deadline``.

    ``apart`` (the program, not a call from Python): a command that eliminates (it takes
    ``--max-seconds``) works in a child even with no time budget, so that Ctrl-C stops it at once,
    not after the python-flint call under way (a Gröbner basis can be minutes of one C call)."""
    from ...runtime.budget import Budget
    from .commands import COMMANDS

    args.deadline = Budget(seconds=getattr(args, "max_seconds", None), terms=getattr(args, "max_terms", None),
                           apart=apart and hasattr(args, "max_seconds")).start()
    args.deadline.note(f"starting {args.command}")  # until the command says more (its imports come first)
    work = functools.partial(COMMANDS[args.command], args)
    return args.deadline.run(work if args.command in NO_ALGEBRA else
                             functools.partial(_with_algebra, work, OWN_MODULES.get(args.command, ())))


def _with_algebra(work: Callable[[], Outcome], modules: Sequence[str] = ()) -> Outcome:
    """``work()`` once the algebra it computes with (``ALGEBRA``) and the command's own ``modules`` are
    imported, with the cyclic garbage collector paused meanwhile and what was loaded then frozen out
    of its later collections (``gc.freeze``): walking sympy's hundreds of thousands of objects again
    and again took about a tenth of a cold command's wall time. Nothing to do where they are loaded
    already (in-process)."""
    loaded = (*ALGEBRA, *modules)
    if all(name in sys.modules for name in loaded):
        return work()
    collecting = gc.isenabled()
    gc.disable()
    try:
        for name in loaded:
            importlib.import_module(name)
        gc.freeze()
    finally:
        if collecting:
            gc.enable()
    return work()


def _save(files: Sequence[File] = ()) -> None:
    """Write the files a command made (path, bytes), each replacing its target only when whole."""
    from ...runtime.files import write_atomic

    for path, data in files:
        path.parent.mkdir(parents=True, exist_ok=True)  # a directory asked for (``--out DIR``), checked writable
        write_atomic(path, data)


def _failed(argv: list[str], args: argparse.Namespace | None, kind: str, message: str, line: str) -> str:
    """Say ``line`` on stderr; what stdout gets: with --json, the error as the one JSON document."""
    from .commands import COMMANDS
    from ...runtime.terminal import clipped, one_line

    say(clipped(one_line(line)))
    if not (getattr(args, "json", False) if args is not None else "--json" in argv):
        return ""
    command = args.command if args is not None else next(iter(argv), None)
    document = {"error": {"kind": kind, "message": message},
                "command": command if command in COMMANDS else None, "scene": getattr(args, "scene", None)}
    return json_text(document)


def _kind(err: AlgkinError) -> str:
    """The error's kind in a JSON error document: usage, scene, budget or computation (interrupted and
    internal are the command line's own)."""
    return next((kind for cls, kind in _ERROR_KINDS if isinstance(err, cls)), "computation")
