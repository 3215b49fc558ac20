"""algkin.runtime.budget: a command without a time budget does not load the child process's machinery."""

import subprocess
import sys

from ..processes import ENV


def test_a_command_without_a_time_budget_leaves_multiprocessing_unloaded():
    # multiprocessing (sockets, pickling, ctypes) is milliseconds of a cold command's imports that
    # only a time budget's forked child uses
    code = ("import sys, io, contextlib; from algkin.ui.cli import main\n"
            "with contextlib.redirect_stdout(io.StringIO()):\n"
            "    main(['derive', 'chebyshev-lambda', '--outputs', 'B'])\n"
            "print('multiprocessing' in sys.modules)")
    done = subprocess.run([sys.executable, "-c", code], env=ENV, capture_output=True, text=True, timeout=300,
                          check=False)  # a hang guard
    assert done.stdout.splitlines()[-1] == "False", done.stderr
