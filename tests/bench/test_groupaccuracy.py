"""``algkin accuracy`` on a scene with points solved together (3rpr): rows per strategy and case."""

import json
import math

import pytest

from algkin.bench.accuracy import accuracy
from algkin.bench.groupaccuracy import DIGITS, STRATEGIES, group_accuracy
from algkin.ui.cli import main


@pytest.fixture(scope="module")
def rows():
    """3rpr, 10 samples per case (accuracy refused the scene before: points solved together)."""
    return {(r["strategy"], r["case"]): r for r in accuracy("3rpr", samples=10).rows}


def test_a_row_for_each_strategy_and_case(rows):
    assert set(rows) == {(s, c) for s in STRATEGIES for c in ("uniform", "near-toggle", "far-1e3")}
    assert all(r["compared"] > 0 and r["samples"] == 10 for r in rows.values())


def test_the_certified_path_agrees_with_the_reference_to_its_digits(rows):
    """algkin.solve at 17 digits against 40: within a unit of the 17th digit, relative."""
    for case in ("uniform", "near-toggle", "far-1e3"):
        row = rows["certified", case]
        assert 0 <= row["max_rel_error"] < 1e-16 and row["missed"] == 0, case


def test_the_floats_are_finite_and_the_eliminants_roots_lose_digits_near_a_toggle(rows):
    for (strategy, case), row in rows.items():
        assert math.isfinite(row["max_abs_error"]), (strategy, case)
    # two roots of the eliminant a relative 1e-6..1e-12 apart in the input: float roots keep half the digits
    assert rows["eliminant-roots", "near-toggle"]["max_rel_error"] > 10 * rows["eliminant-roots", "uniform"]["max_rel_error"]
    assert rows["eliminant-roots", "uniform"]["max_rel_error"] < 1e-10


def test_the_injected_clock_gives_the_times():
    ticks = iter(range(10**6))
    result = group_accuracy("3rpr", samples=10, clock=lambda: float(next(ticks)))
    assert {r["ns_per_sample"] for r in result.rows} == {1e9}
    assert str(DIGITS) in result.to_json()["reference"]


def test_the_cli_prints_rows_and_json_and_plots_them(capsys, tmp_path):
    assert main(["accuracy", "3rpr", "--samples", "10", "--json", "--plot", str(tmp_path / "a.png")]) == 0
    assert (tmp_path / "a.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    document = json.loads(capsys.readouterr().out)
    assert document["point"] == "P1, P2" and len(document["rows"]) == 9
    assert main(["accuracy", "3rpr", "--of", "P1"]) == 2
    assert capsys.readouterr().err.count("\n") == 1
