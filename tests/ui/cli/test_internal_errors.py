"""A defect of algkin's own (an exception no command expects) is said as every failure is: one line on
stderr, exit 1, with --json the one error document on stdout; ALGKIN_TRACEBACK set, the traceback."""

import json

import pytest

from algkin.ui.cli import TRACEBACK, commands, main


def _broken(args):
    raise KeyError("a defect\nwith a second line")


@pytest.fixture
def defect(monkeypatch):
    """``derive`` raising what no command expects (as a bug would)."""
    monkeypatch.setitem(commands.COMMANDS, "derive", _broken)
    monkeypatch.delenv(TRACEBACK, raising=False)


@pytest.mark.parametrize("budget", [[], ["--max-seconds", "60"]], ids=["in-process", "in-a-child"])
def test_a_defect_is_one_line_and_exit_1(capsys, defect, budget):
    code = main(["derive", "chebyshev-lambda", *budget])
    out, err = capsys.readouterr()
    assert (code, out) == (1, "")
    assert err == ("algkin: failed: internal error, KeyError: 'a defect\\nwith a second line' "
                   f"(a defect of algkin: {TRACEBACK}=1 shows where)\n")


def test_with_json_a_defect_is_the_one_error_document(capsys, defect):
    code = main(["derive", "chebyshev-lambda", "--json"])
    out, _ = capsys.readouterr()
    assert code == 1
    document = json.loads(out)
    assert document["error"]["kind"] == "internal" and document["command"] == "derive"
    assert document["error"]["message"].startswith("internal error, KeyError: ")


def test_the_traceback_on_request(defect, monkeypatch):
    monkeypatch.setenv(TRACEBACK, "1")
    with pytest.raises(KeyError, match="a defect"):
        main(["derive", "chebyshev-lambda"])
