"""``algkin plot`` under its budget (``--max-seconds``, ``--max-terms``) as every computing command:
past it, one line and exit 1, no file written or begun, an earlier file intact, no process left."""

import json
import os
import signal

import pytest

from algkin.ui.cli import main

from ...clocks import late_budgets
from ...processes import algkin, alive, busy_children, finish, kill_group, run, start

pytest.importorskip("matplotlib")

# The minimum of |PO| against the family's dimension u: over ten minutes of eliminations (measured),
# where any budget given here runs out.
FAMILY_MINIMUM = ("stephenson-iii-family", "--of", "dist(P, O)", "--against", "u=0:1")


def one_line(err):
    return err.count("\n") == 1 and err.endswith("\n") and "Traceback" not in err


def no_process_in_group(pgid):
    """Whether no process is left in the process group ``pgid`` (a test's command's session)."""
    try:
        os.killpg(pgid, 0)
    except ProcessLookupError:
        return True
    return False


def test_a_plot_past_its_time_budget_stops_with_one_line_and_leaves_the_earlier_file(tmp_path):
    out = tmp_path / "minimum.png"
    out.write_bytes(b"an earlier drawing")
    process = start(algkin("plot", *FAMILY_MINIMUM, "--out", out, "--max-seconds", "0.5"))
    try:
        code, stdout, err, _ = finish(process, timeout=120)  # a hang guard: it stops at 0.5 s
        assert (code, stdout) == (1, "") and one_line(err), err
        assert err.startswith("algkin: failed: max_seconds=0.5: stopped after "), err
        assert out.read_bytes() == b"an earlier drawing" and list(tmp_path.iterdir()) == [out]
        assert no_process_in_group(process.pid)
    finally:
        kill_group(process)


@pytest.mark.parametrize("args", [("chebyshev-lambda", "--input", "63"), FAMILY_MINIMUM],
                         ids=["mechanism", "quantity"])
def test_a_late_budget_writes_nothing(monkeypatch, capsys, tmp_path, args):
    late_budgets(monkeypatch)  # the deadline has passed once the work starts
    out = tmp_path / "drawing.png"
    assert main(["plot", *args, "--out", str(out), "--max-seconds", "5", "--json"]) == 1
    stdout, err = capsys.readouterr()
    assert one_line(err) and err.startswith("algkin: failed: max_seconds=5: stopped after 3600.00 s while "), err
    assert json.loads(stdout)["error"]["kind"] == "budget"
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("args", [("chebyshev-lambda", "--out", "lambda.png"),
                                  ("fourbar", "--of", "dist(B, D)", "--out", "bd.png")], ids=["curve", "extremum"])
def test_a_terms_budget_reaches_the_eliminations(capsys, tmp_path, args):
    # Each eliminates from a dyad's circles, (B_x - a c)^2 + (B_y - a s)^2 = l^2 and one about a fixed
    # pivot: by hand, every polynomial on the way has more than 3 terms.
    args = [str(tmp_path / a) if a.endswith(".png") else a for a in args]
    assert main(["plot", *args, "--max-terms", "3"]) == 1
    err = capsys.readouterr().err
    assert one_line(err) and err.startswith("algkin: failed: max_terms=3: "), err
    assert list(tmp_path.iterdir()) == []


def test_sigterm_stops_a_long_plot_at_once(tmp_path):
    # The work runs in a child even with no time budget: a python-flint call under way (minutes of one
    # C call) would otherwise hold the signal's handler back until it returned.
    process = start(algkin("plot", *FAMILY_MINIMUM, "--out", tmp_path / "minimum.png"))
    try:
        workers = busy_children(process.pid, 1.5)  # past its imports, into the algebra
        process.send_signal(signal.SIGTERM)
        code, _, err, _ = finish(process, timeout=60)
        assert (code, err) == (143, "algkin: terminated (SIGTERM)\n")
        assert not alive(workers, within=30)
    finally:
        kill_group(process)


def test_plot_help_names_its_budget_options():
    code, out, _, _ = run(algkin("plot", "--help"), timeout=60)
    assert code == 0 and "--max-seconds" in out and "--max-terms" in out


@pytest.mark.parametrize(("against", "said"), [
    # arm-string's r is the arm's length: r = 0 made every angle's |AB| one value ("does not depend on the
    # input"), a negative r a mechanism the scene format refuses
    ("r=-400:400", "--against='r=-400:400': the length r of arm-string would be -400 at r = -400; "
                   "a length must be positive"),
    ("r=0:4", "--against='r=0:4': the length r of arm-string would be 0 at r = 0; a length must be positive"),
    # the dimension is --against's, made symbolic: the message names that flag, not --param
    ("rr=1:4", "--against='rr': not a parameter of arm-string (parameters: a, b, r, g); did you mean 'r'?"),
])
def test_a_bad_against_names_it_in_one_line_and_exits_2(tmp_path, against, said):
    out = tmp_path / "minimum.png"
    code, stdout, err, _ = run(algkin("plot", "arm-string", "--of", "AB", "--against", against, "--out", out),
                               timeout=120)
    assert (code, stdout, err) == (2, "", f"algkin: error: {said}\n")
    assert not out.exists()
