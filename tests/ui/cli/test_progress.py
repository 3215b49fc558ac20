"""Progress on the command line (issue 16): a terminal's stderr shows the stage while a command
runs, the line cleared before anything else is said; a pipe, a log and --quiet get nothing; stdout
is the same either way.

Each command runs in a session of its own (``tests/processes.py``), its stderr a pseudo-terminal
where a test says so; a timeout there is a hang guard, not a bound on the time.
"""

import json
import re

import pytest

from algkin.runtime.budget import MAX_SECONDS

from ...processes import algkin, run, run_on_terminal

DERIVE = ("derive", "chebyshev-lambda", "--outputs", "B")
SHOW = ("show", "chebyshev-lambda", "--outputs", "B")
# Nothing but status lines, each drawn over the one before (``\r``), the last one blanked: no newline left.
CLEARED = r"(\r[^\r\n]*)*\r *\r"


# A time budget, so a forked worker, whose deadline cannot come: the longest budget, a week.
WEEK = ("--max-seconds", str(MAX_SECONDS))
# The command line, its budget's deadline passed once the worker says it eliminates (tests/clocks.py).
LATE = """
import sys
import pytest
from tests.clocks import late_budgets
from algkin.ui.cli import main

late_budgets(pytest.MonkeyPatch(), doing="eliminating")
sys.exit(main(sys.argv[1:]))
"""


@pytest.mark.parametrize("budget", [(), WEEK], ids=["in-process", "forked-worker"])
def test_a_terminal_sees_the_stages_then_a_cleared_line(budget):
    # With a time budget the work runs in a forked worker: its parent shows what the worker notes.
    code, out, err, _ = run_on_terminal(algkin(*DERIVE, *budget), timeout=300)
    assert code == 0, err
    assert "algkin: starting derive" in err and "algkin: compiling chebyshev-lambda" in err, err
    assert re.fullmatch(CLEARED, err), err
    assert out.startswith("scene chebyshev-lambda") and "\r" not in out and "algkin:" not in out


def test_json_on_stdout_stays_one_document_while_progress_shows():
    code, out, err, _ = run_on_terminal(algkin(*DERIVE, "--json", *WEEK), timeout=300)
    assert code == 0 and "algkin: compiling chebyshev-lambda" in err, err
    assert json.loads(out)["scene"] == "chebyshev-lambda"


def test_the_error_line_follows_a_cleared_progress_line():
    code, out, err, _ = run_on_terminal(["-c", LATE, "derive", "stephenson-iii", "--max-seconds", "1"], timeout=300)
    assert code == 1 and out == ""
    assert re.fullmatch(CLEARED + r"algkin: failed: max_seconds=1: stopped after 3600\.00 s while eliminating [^\r\n]*\r\n",
                        err), err


@pytest.mark.parametrize("argv", [(*SHOW, "--quiet"), ("--quiet", *SHOW)], ids=["after", "before"])
def test_quiet_shows_nothing_even_on_a_terminal(argv):
    code, out, err, _ = run_on_terminal(algkin(*argv), timeout=300)
    assert (code, err) == (0, ""), err
    assert out.startswith("scene chebyshev-lambda")


def test_a_pipe_gets_no_progress():
    code, out, err, _ = run(algkin(*SHOW, *WEEK), timeout=300)
    assert (code, err) == (0, "") and out.startswith("scene chebyshev-lambda")


def test_a_call_from_python_stays_silent_on_a_terminal():
    code, _, err, _ = run_on_terminal(["-c", "import algkin; algkin.derive('chebyshev-lambda', outputs=['B'])"],
                                      timeout=300)
    assert (code, err) == (0, ""), err
