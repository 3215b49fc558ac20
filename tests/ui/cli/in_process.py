"""The command line run in this process (``algkin.ui.cli.main``), for tests of what a command
writes rather than of its process: no interpreter to start and no imports to pay again."""

import contextlib
import io
import subprocess

from algkin.ui.cli import main


def run_main(args, cwd):
    """``algkin args...`` run in ``cwd`` by ``main``: a CompletedProcess as ``run_cli``'s (its exit
    code, and the text written to stdout and to stderr)."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.chdir(cwd), contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = main(list(args))
    return subprocess.CompletedProcess(list(args), code, out.getvalue(), err.getvalue())
