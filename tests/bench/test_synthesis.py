"""Synthesis problems in the bench: named with the others, algkin's row counting what the
synthesis tests found independently (the Burmester set's four real pairs, checked there against
Newton's method on the dyad equations; the five pairs' three four-bars and three rank drops;
Problem 7's 33 and 15, Morgan and Wampler's counts as PHCpack's documentation gives them)."""

from algkin.bench import bench
from algkin.bench.problems import problem_names


def test_the_synthesis_problems_are_bench_problems():
    assert {"burmester-five-poses-real", "freudenstein-five-pairs-real", "path-five-points-real"} <= set(problem_names())


def test_algkin_rows_without_peers():
    report = bench(["burmester-five-poses-real", "freudenstein-five-pairs-real"], None, None, 60.0, False, 1)
    rows = {row.problem: row for row in report.rows}
    assert rows["burmester-five-poses-real"].degree == 4 and "4 real" in rows["burmester-five-poses-real"].note
    assert rows["freudenstein-five-pairs-real"].degree == 6 and "6 real" in rows["freudenstein-five-pairs-real"].note


def test_the_path_problem_is_solved_by_algkins_own_chain():
    report = bench(["path-five-points-real"], None, None, 120.0, False, 1)
    (row,) = report.rows
    assert row.method == "algkin's own solver" and row.degree == 33 and "15 real" in row.note
