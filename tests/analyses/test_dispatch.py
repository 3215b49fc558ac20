"""The public ``algkin.derive`` and ``algkin.curve`` on a scene with points solved together: what
the commands give (the second path: the command line's JSON document), the arguments only a
chain takes refused by name, and a budget of seconds kept.

The group results themselves are checked against geometry in ``tests/analyses/groups``; here the
test is that the Python API gives what the command gives."""

import json
import threading

import pytest

import algkin
from algkin.analyses.groups.curve import GroupCurve
from algkin.analyses.groups.derive import GroupDerivation
from algkin.errors import BudgetExceeded, UsageError
from algkin.runtime.budget import Budget
from algkin.ui.cli import main

from ..clocks import Clock, still


def _without_timings(document):
    return {key: value for key, value in document.items() if key != "timings"}


def _command(capsys, argv):
    assert main([*argv, "--json"]) == 0
    return json.loads(capsys.readouterr().out)


def test_derive_on_3rpr_gives_the_commands_document(capsys):
    found = algkin.derive("3rpr", samples=3, seed=7)
    assert type(found) is GroupDerivation and found.passed
    document = _command(capsys, ["derive", "3rpr", "--samples", "3", "--seed", "7"])
    assert [m["label"] for g in document["groups"] for m in g["modes"]] == ["---", "+++"]
    assert _without_timings(json.loads(json.dumps(found.to_json()))) == _without_timings(document)


@pytest.mark.parametrize("point", ["P1", "P3"])
def test_curve_on_3rpr_gives_the_commands_document(capsys, point):
    found = algkin.curve("3rpr", point, samples=2, seed=5)
    assert type(found) is GroupCurve and found.passed
    document = _command(capsys, ["curve", "3rpr", "--point", point, "--samples", "2", "--seed", "5"])
    assert _without_timings(json.loads(json.dumps(found.to_json()))) == _without_timings(document)


def test_set_gives_the_commands_document_with_set(capsys):
    found = algkin.derive("3rpr", samples=0, set={"r2": 8})
    document = _command(capsys, ["derive", "3rpr", "--samples", "0", "--set", "r2=8"])
    assert _without_timings(json.loads(json.dumps(found.to_json()))) == _without_timings(document)
    assert found.to_json()["groups"] != algkin.derive("3rpr", samples=0).to_json()["groups"]  # r2 was set


@pytest.mark.parametrize(("function", "arguments", "named"), [
    (algkin.derive, {"outputs": ["P1"]}, "outputs=['P1']"),
    (algkin.derive, {"params": ["r2"]}, "params=['r2']"),
    (algkin.derive, {"method": "groebner"}, "method='groebner'"),
    (algkin.derive, {"backend": "sympy"}, "backend='sympy'"),
    (algkin.derive, {"certify": False}, "certify=False"),
    (algkin.curve, {"params": ["r2"]}, "params=['r2']"),
    (algkin.curve, {"method": "resultant"}, "method='resultant'"),
    (algkin.curve, {"backend": "sympy"}, "backend='sympy'"),
], ids=lambda a: "" if callable(a) or isinstance(a, dict) else a)
def test_what_only_a_chain_takes_is_refused_by_name(function, arguments, named):
    point = ("P3",) if function is algkin.curve else ()
    with pytest.raises(UsageError) as caught:
        function("3rpr", *point, samples=0, **arguments)
    said = str(caught.value)
    assert said.startswith(named + ": ") and "points solved together" in said and "\n" not in said


@pytest.mark.parametrize("budget", [Budget(terms=1000), Budget(seconds=60, terms=1000, clock=still).start()],
                         ids=["Budget", "Deadline"])
def test_a_terms_budget_is_refused_by_name_not_ignored(budget):
    with pytest.raises(UsageError, match=r"^budget=.*terms.*points solved together"):
        algkin.derive("3rpr", samples=0, budget=budget)


def test_a_seconds_budget_runs_the_work_and_gives_its_result():
    budgeted = algkin.curve("3rpr", "P3", samples=0, budget=Budget(seconds=60, clock=still))
    assert _without_timings(budgeted.to_json()) == _without_timings(algkin.curve("3rpr", "P3", samples=0).to_json())


@pytest.mark.parametrize("function, point, group_function", [
    (algkin.derive, (), "derive_groups"),
    (algkin.curve, ("P3",), "curve_groups"),
])
def test_a_seconds_budget_stops_the_group_work_at_its_deadline(monkeypatch, function, point, group_function):
    from algkin.analyses import dispatch

    # work that never ends, on a clock whose deadline has passed at its next reading
    monkeypatch.setattr(dispatch, group_function, lambda *_, **__: threading.Event().wait())
    with pytest.raises(BudgetExceeded, match="max_seconds=10: stopped after 3600.00 s"):
        function("3rpr", *point, samples=0, budget=Budget(seconds=10, clock=Clock()))


def test_a_chain_still_goes_through_the_pipeline_with_its_arguments():
    derived = algkin.derive("chebyshev-lambda", ["B"], method="groebner", samples=2, certify=False)
    assert type(derived) is algkin.Derivation and derived.method == "groebner" and derived.verification.passed
    assert [b.label for b in derived.branches] == ["left", "right"]
    assert type(algkin.curve("chebyshev-lambda", "P", samples=0, backend="flint")) is algkin.CurveResult


@pytest.mark.parametrize(("arguments", "named"), [({"samples": -1}, "samples=-1"), ({"seed": 2.5}, "seed=2.5"),
                                                  ({"budget": 10}, "budget=10")])
def test_the_group_paths_own_arguments_are_checked_by_name(arguments, named):
    with pytest.raises(UsageError, match="^" + named + ": "):
        algkin.derive("3rpr", **arguments)


TAKEN = {"derive": lambda: algkin.derive("3rpr", samples=0), "curve": lambda: algkin.curve("3rpr", "P3", samples=0),
         "solve": lambda: algkin.solve("3rpr", at={"r1": 6}),
         "follow": lambda: algkin.follow("3rpr", mode="+++", start={"r1": 6}, stop=7),
         "rates": lambda: algkin.rates("3rpr", samples=0), "load_quantities": lambda: algkin.load_quantities("3rpr")}
REFUSED = {"extremum": lambda: algkin.extremum("3rpr", "P1.x"), "singular": lambda: algkin.singular("3rpr", "P3"),
           "prepare": lambda: algkin.prepare("3rpr"), "compile_scene": lambda: algkin.compile_scene("3rpr")}


def _named(listing):
    return listing.replace(" and ", ", ").split(", ")


def test_the_refusal_names_what_takes_the_scene_in_python_and_what_does_not():
    with pytest.raises(UsageError) as caught:
        algkin.prepare("3rpr")
    said = str(caught.value)
    taken = _named(said.split("and in Python ")[1].split("; ")[0])
    refused = _named(said.split("; ")[1].replace(" do not yet, nor ", ", "))
    assert sorted(taken) == sorted(TAKEN) and sorted(refused) == sorted(REFUSED)
    for name in taken:
        TAKEN[name]()  # no refusal
    for name in refused:
        with pytest.raises(UsageError, match="has points solved together"):
            REFUSED[name]()
