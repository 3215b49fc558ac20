"""The command line run in this process (``algkin.ui.cli.main``), for tests of what a command
writes rather than of its process: no interpreter to start and no imports to pay again."""

import contextlib
import io
import subprocess

import pytest

from algkin.ui.cli import main


def run_main(args, cwd):
    """``algkin args...`` run in ``cwd`` by ``main``: a CompletedProcess as ``run_cli``'s (its exit
    code, and the text written to stdout and to stderr)."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.chdir(cwd), contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = main(list(args))
    return subprocess.CompletedProcess(list(args), code, out.getvalue(), err.getvalue())


def first_apart(cases, ids=None):
    """``cases`` of a parametrized test of what a command refuses, each with whether it runs as the
    program (the first: ``python -m algkin``, its process tested) or by ``run_main`` (the rest: the
    same exit code and stderr, the parsing and the checks being ``main``'s, without an interpreter
    started and algkin imported again for each)."""
    ids = ids or [str(k) for k in range(len(cases))]
    return [pytest.param(*(case if isinstance(case, tuple) else (case,)), k == 0,
                         id=f"{name}-{'apart' if k == 0 else 'in-process'}")
            for k, (case, name) in enumerate(zip(cases, ids))]
