"""Budgets: a time budget stops even a single long C call, a terms budget stops big eliminants.

The deadlines here are read on clocks the tests move (``tests/clocks.py``); the one test on the
machine's own clock (how soon a long C call is stopped) is in the slow set, run alone (marked alone).
"""

import multiprocessing
import re
import time
from pathlib import Path

import pytest
import sympy

from algkin.derivation import pipeline
from algkin.eliminate import Budget, eliminate
from algkin.errors import BudgetExceeded, SceneError, UsageError
from algkin.runtime.budget import MAX_SECONDS
from algkin.scene import compile_scene, load_scene

from ..clocks import Clock, late_budgets, still
from ..processes import run

ROOT = Path(__file__).resolve().parents[2]
BAD = ROOT / "tests" / "scene" / "bad"
x, y, c, s = (sympy.Symbol(n, real=True) for n in "xycs")
CIRCLES = [(x - c) ** 2 + (y - s) ** 2 - 4, x**2 + y**2 - 1]
# P_x of Stephenson III from its whole system, no witnesses: about 15 s of resultants in C calls
# that no signal interrupts.
P_X = "eliminating B_x, B_y, F_x, F_y, P_y (keeping P_x, c_theta, s_theta)"


def long_elimination(budget):
    system = compile_scene(load_scene("stephenson-iii"), ["P"]).system
    others = [u for u in system.unknowns if u != "P_x"]
    return eliminate(system.equations, others, ["P_x", "c_theta", "s_theta"], method="resultant", budget=budget)


def test_derive_stops_when_the_deadline_passes_while_it_eliminates():
    # Unbudgeted, `derive stephenson-iii` on 10,000 samples takes several seconds of eliminations
    # and sampling; the deadline passes as soon as the parent hears that the worker eliminates.
    deadline = Budget(seconds=1, clock=Clock(late=1.25, passed=lambda: deadline.doing.startswith("eliminating"))).start()
    with pytest.raises(BudgetExceeded, match=r"max_seconds=1: stopped after 1\.25 s while eliminating "):
        pipeline.derive("stephenson-iii", samples=10_000, budget=deadline)
    assert multiprocessing.active_children() == []  # the worker killed and joined


def test_one_long_elimination_stops_when_the_deadline_passes():
    deadline = Budget(seconds=1, clock=Clock(late=1.5, passed=lambda: deadline.doing.startswith("eliminating"))).start()
    with pytest.raises(BudgetExceeded, match=re.escape(f"max_seconds=1: stopped after 1.50 s while {P_X}")):
        long_elimination(deadline)
    assert multiprocessing.active_children() == []


@pytest.mark.slow
@pytest.mark.alone
def test_one_long_elimination_stops_near_the_deadline_on_the_machines_clock():
    # The one test of the time a stop takes (the kill, the join): its bound is generous, for a loaded machine.
    start = time.monotonic()
    with pytest.raises(BudgetExceeded, match=re.escape("max_seconds=1: stopped after ") + r"\d+\.\d\d s while "
                                             + re.escape(P_X)):
        long_elimination(Budget(seconds=1))
    assert time.monotonic() - start < 1 + 10


def test_command_line_stops_with_one_line_and_exit_1(monkeypatch, capsys):
    from algkin.ui.cli import main

    late_budgets(monkeypatch, doing="eliminating")
    assert main(["derive", "stephenson-iii", "--max-seconds", "1"]) == 1
    captured = capsys.readouterr()
    assert captured.out == "" and captured.err.count("\n") == 1, captured.err
    assert captured.err.startswith("algkin: failed: max_seconds=1: stopped after 3600.00 s while eliminating ")


# A child that sends notes as fast as it can and never an answer: at the deadline its pipe is
# never empty. The watchdog must still stop at the deadline (it once polled the pipe forever
# without reading it). In a process of its own, so that a spinning watchdog fails the test.
CHATTER = """
import itertools
from algkin.eliminate import Budget
from tests.clocks import Clock

readings = itertools.count()  # the parent reads the clock once a note: the deadline passes at the 100th
deadline = Budget(seconds=0.2, clock=Clock(late=0.25, passed=lambda: next(readings) >= 100)).start()

def chatter():
    for count in range(10**9):
        deadline.note(f"saying {count}")

try:
    deadline.run(chatter)
except Exception as err:
    print(type(err).__name__, err)
"""


def test_a_child_that_keeps_talking_is_stopped_at_the_deadline():
    code, out, err, _ = run(["-c", CHATTER], timeout=120)  # a hang guard, not a bound on the time
    assert code == 0 and err == "", err
    said = int(re.fullmatch(r"BudgetExceeded max_seconds=0\.2: stopped after 0\.25 s while saying (\d+)\n", out)[1])
    assert said >= 99  # what the parent heard before the deadline, and perhaps a few notes sent before the kill


def test_a_generous_budget_changes_nothing():
    plain = pipeline.derive("chebyshev-lambda", ["B"], samples=3, certify=False)
    budgeted = pipeline.derive("chebyshev-lambda", ["B"], samples=3, certify=False,
                               budget=Budget(seconds=120, terms=10_000, clock=still))
    assert {u: e.polynomial for u, e in budgeted.eliminations.items()} == \
        {u: e.polynomial for u, e in plain.eliminations.items()}
    assert [b.values for b in budgeted.branches] == [b.values for b in plain.branches]
    assert budgeted.verification.passed


def test_terms_budget_at_the_exact_size_of_the_resultant():
    # sympy's resultant of the two circles in x (a second implementation) counts the terms.
    terms = len(sympy.Poly(sympy.resultant(*CIRCLES, x), y, c, s).terms())
    assert terms == 11
    eliminate(CIRCLES, ["x"], ["y", "c", "s"], method="resultant", budget=Budget(terms=terms))
    with pytest.raises(BudgetExceeded, match="max_terms=10: the resultant in x has 11 terms, while eliminating x"):
        eliminate(CIRCLES, ["x"], ["y", "c", "s"], method="resultant", budget=Budget(terms=terms - 1))


def test_terms_budget_names_the_stephenson_resultant():
    with pytest.raises(BudgetExceeded, match=r"max_terms=50: the resultant in \w+ has \d+ terms"):
        pipeline.curve("stephenson-iii", "P", samples=0, budget=Budget(terms=50))


def test_bad_input_found_in_the_child_is_still_bad_input():
    # never_assembles.toml fails the assembly check, which runs inside the budget's child.
    with pytest.raises(SceneError, match="can never assemble"):
        pipeline.derive(str(BAD / "never_assembles.toml"), budget=Budget(seconds=60, clock=still))


@pytest.mark.parametrize("seconds,terms", [(0, None), (-1, None), (None, 0), (None, 2.5), (float("inf"), None),
                                          (float("nan"), None), (1e10, None), (1e30, None), (MAX_SECONDS * 1.001, None)])
def test_budget_must_be_positive_and_at_most_a_week(seconds, terms):
    with pytest.raises(UsageError, match="^(seconds|terms)="):  # the arguments' own names
        Budget(seconds=seconds, terms=terms)


def test_the_longest_budget_is_kept():
    # a week, on the machine's clock: a poll's timeout past 24 days overflowed (OverflowError)
    assert MAX_SECONDS == 7 * 24 * 3600
    assert Budget(seconds=MAX_SECONDS).start().run(lambda: sum(range(10))) == 45


@pytest.mark.parametrize("command,option,value", [
    *((["curve", "chebyshev-lambda", "--point", "P"], "--max-seconds", v)
      for v in ["0", "soon", "1e10", "1" + "0" * 23, "inf", "nan", str(MAX_SECONDS + 1)]),
    (["curve", "chebyshev-lambda", "--point", "P"], "--max-terms", "-3"),
    (["curve", "chebyshev-lambda", "--point", "P"], "--max-terms", "1e3"),
    *((["bench", "--no-peers", "--problems", "two-circles"], "--budget", v) for v in ["1e30", "inf", "nan", "0"]),
    *((["sweep", "fourbar", "--grid", "a=1:2:2", "--executor", "serial"], "--budget", v)
      for v in ["1e12", "inf", "nan", "-1"]),
])
def test_command_line_refuses_a_bad_budget(command, option, value, capsys, tmp_path, monkeypatch):
    from algkin.ui.cli import main

    def measured(*args, **options):
        raise AssertionError("a bench ran")

    monkeypatch.setattr("algkin.bench.measure", measured)
    out = ["--out", str(tmp_path / "out")] if command[0] == "sweep" else []
    assert main([*command, *out, option, value]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and option in err and (repr(value) in err or f"={float(value)!r}:" in err), err
    assert list(tmp_path.iterdir()) == []  # nothing written


@pytest.mark.parametrize("args,words", [
    (["toggles", "chebyshev-lambda", "--max-terms", "3"], "max_terms=3: the resultant in B_"),  # the dyad's two circles: one resultant
    (["extremum", "arm-string", "--of", "AB", "--param", "b", "--max-terms", "4"],
     "max_terms=4: the resultant in"),  # the first elimination past 4 terms stops it
])
def test_every_eliminating_command_keeps_to_its_budget(args, words, capsys):
    from algkin.ui.cli import main

    assert main(args) == 1
    captured = capsys.readouterr()
    assert captured.out == "" and captured.err.count("\n") == 1 and words in captured.err, captured.err


def test_accuracy_keeps_to_its_time_budget(monkeypatch, capsys):
    from algkin.ui.cli import main

    late_budgets(monkeypatch, doing="measuring")  # the deadline passes while it measures
    assert main(["accuracy", "chebyshev-lambda", "--samples", "10", "--max-seconds", "0.5"]) == 1
    captured = capsys.readouterr()
    assert captured.out == "" and captured.err == \
        "algkin: failed: max_seconds=0.5: stopped after 3600.00 s while measuring each strategy on chebyshev-lambda\n"


class Dial:
    """A clock that reads what the test sets: ``dial.now``."""

    def __init__(self):
        self.now = 0.0

    def __call__(self):
        return self.now


def test_a_budget_serves_again_later():
    # One Budget(seconds=10), two eliminations an hour apart on its clock: each starts its own
    # deadline (the budget once kept the first start's, and the second failed at once).
    dial = Dial()
    budget = Budget(seconds=10, clock=dial)
    first = eliminate(CIRCLES, ["x"], ["y", "c", "s"], method="resultant", budget=budget)
    dial.now = 3600.0
    again = eliminate(CIRCLES, ["x"], ["y", "c", "s"], method="resultant", budget=budget)
    assert again.polynomial == first.polynomial
    assert budget == Budget(seconds=10, clock=dial)  # nothing in it changed


def test_a_budget_is_a_frozen_hashable_value():
    import attrs

    budget = Budget(seconds=5, terms=100)
    assert budget == Budget(5, 100) and hash(budget) == hash(Budget(5, 100)) and len({budget, Budget(5, 100)}) == 1
    with pytest.raises(attrs.exceptions.FrozenInstanceError):
        budget.seconds = 50
    assert repr(budget) == "Budget(seconds=5, terms=100)"


def test_deadlines_of_one_budget_are_apart():
    # each start reads the clock once; the time left is counted from each one's own start
    dial = Dial()
    budget = Budget(seconds=10, clock=dial)
    first = budget.start()
    dial.now = 4.0
    second = budget.start()
    dial.now = 12.0
    assert (first.left(), second.left()) == (-2.0, 2.0)
    first.note("a note of the first")
    assert (first.doing, second.doing) == ("a note of the first", "computing")


def test_budget_is_importable_from_the_package_and_from_where_it_was():
    import algkin
    import algkin.eliminate
    from algkin.runtime import budget as runtime_budget

    assert algkin.Budget is algkin.eliminate.Budget is runtime_budget.Budget
    assert "Budget" in algkin.__all__


def test_a_budget_where_none_is_expected_is_refused_by_name():
    with pytest.raises(UsageError, match=r"^budget=10: expected an algkin\.Budget"):
        pipeline.derive("chebyshev-lambda", ["B"], samples=0, budget=10)
    with pytest.raises(UsageError, match=r"^budget='soon': expected an algkin\.Budget"):
        eliminate(CIRCLES, ["x"], ["y", "c", "s"], budget="soon")


@pytest.mark.parametrize("analysis", ["toggles", "limits", "extremum", "singular"])
def test_every_eliminating_analysis_keeps_to_a_budget_from_python(analysis):
    # once found through a global stack, only under the command line's run(); now passed on
    from algkin import extremum, singular
    from algkin.analyses.limits import limits
    from algkin.analyses.toggles import toggles

    calls = {"toggles": lambda b: toggles("chebyshev-lambda", budget=b),
             "limits": lambda b: limits("fourbar", budget=b),
             "extremum": lambda b: extremum("arm-string", "AB", params=["b"], budget=b),
             "singular": lambda b: singular("fourbar", "P", samples=0, budget=b)}
    with pytest.raises(BudgetExceeded, match=r"^max_terms=3: .* has \d+ terms, while eliminating "):
        calls[analysis](Budget(terms=3))


def test_an_extremums_own_eliminations_keep_to_its_budget():
    # the derivation of AB (b symbolic) keeps to 8 terms a step; the extremum's own eliminations do not (its
    # stationary condition, taken in AB's square, does; the values' resultant in t has 9 terms)
    budget = Budget(terms=8)
    pipeline.derive("arm-string", ["AB"], params=["b"], samples=0, budget=budget)
    from algkin import extremum

    with pytest.raises(BudgetExceeded, match=r"^max_terms=8: the resultant in \w+ has \d+ terms"):
        extremum("arm-string", "AB", params=["b"], budget=budget)
