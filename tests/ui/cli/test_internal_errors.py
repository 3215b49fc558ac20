"""A defect of algkin's own (an exception no command expects) is said as every failure is: one line on
stderr, exit 1, with --json the one error document on stdout; ALGKIN_TRACEBACK set, the traceback."""

import json
import sys
from fractions import Fraction

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


@pytest.fixture
def int_digits_limit():
    """Python's limit on the digits of an integer written as text, put back after the test."""
    limit = sys.get_int_max_str_digits()
    yield sys.set_int_max_str_digits
    sys.set_int_max_str_digits(limit)


def test_an_integer_past_pythons_digits_limit_is_said_with_the_way_to_lift_it(capsys, int_digits_limit):
    # Dimensions of 150 digits near the default crank-rocker: the closed forms hold integers of more
    # than 640 digits (CPython's least limit, standing for its default 4300, which the rates of such
    # dimensions pass after a minute of work); writing one was an internal error.
    near = {"a": Fraction(1) + Fraction(1, 10**149 + 7), "d": Fraction(4) + Fraction(1, 10**149 + 9),
            "l": Fraction(3) + Fraction(1, 10**149 + 13)}
    argv = ["derive", "fourbar", "--json"] + [a for k, v in near.items() for a in ("--set", f"{k}={v}")]
    int_digits_limit(640)
    assert main(argv) == 1
    out, err = capsys.readouterr()
    assert err.count("\n") == 1 and "640 digits" in err and "PYTHONINTMAXSTRDIGITS=0" in err and "internal" not in err
    assert json.loads(out)["error"]["kind"] == "computation"
    int_digits_limit(0)  # what PYTHONINTMAXSTRDIGITS=0 sets
    assert main(argv) == 0
    assert json.loads(capsys.readouterr().out)["verification"]["passed"]
