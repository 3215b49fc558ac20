"""Strict agreement: only equality (up to a constant, or modulo the side relations) agrees;
the bench never checks algkin against itself, and exits 1 on a disagreeing row."""

import flint
import pytest
import sympy

from algkin.bench import agree, specialise
from algkin.bench.agree import Agreement, agreement, from_sympy
from algkin.bench.problems import build
from algkin.ui.cli import main

CTX = flint.fmpq_mpoly_ctx.get(("x", "y", "b"), "lex")
X, Y, B = CTX.gens()
CIRCLE = X**2 + Y**2 - 1


def test_an_extra_factor_does_not_agree_and_is_named():
    verdict = agreement(CIRCLE * (X - 3 * Y), CIRCLE)
    assert verdict.kind is Agreement.EXTRA_FACTOR and not verdict.agrees
    assert "x - 3*y" in verdict.detail and "degree 1" in verdict.detail


def test_a_missing_factor_does_not_agree():
    verdict = agreement(CIRCLE, CIRCLE * (Y + 2))
    assert verdict.kind is Agreement.MISSING_FACTOR and not verdict.agrees
    assert "y + 2" in verdict.detail


def test_equal_up_to_a_nonzero_constant():
    verdict = agreement(flint.fmpq(-7, 3) * CIRCLE, CIRCLE)
    assert verdict.kind is Agreement.EQUAL and verdict.agrees


def test_equal_modulo_the_circle_relation_and_not_without_it():
    keep = ["x", "c", "s"]
    c, s, x = sympy.symbols("c s x")
    one, other, circle = (from_sympy(e, keep) for e in (x + c**2, x + 1 - s**2, c**2 + s**2 - 1))
    assert agreement(one, other).kind is Agreement.DIFFERENT
    assert agreement(one, other, [circle]).kind is Agreement.EQUAL_MOD_SIDE


def test_content_in_the_parameters_agrees_only_without_a_real_zero():
    assert agreement(CIRCLE * (B**2 + 160000), CIRCLE, parameters=["b"]).kind is Agreement.EQUAL_UP_TO_CONTENT
    # b**2 - 4 vanishes at b = 2: a real mechanism lies on it, so it is a factor, not content
    assert agreement(CIRCLE * (B**2 - 4), CIRCLE, parameters=["b"]).kind is Agreement.EXTRA_FACTOR
    # without b declared a parameter, the same factor is an extra factor
    assert agreement(CIRCLE * (B**2 + 160000), CIRCLE).kind is Agreement.EXTRA_FACTOR


def test_the_arm_eliminant_drops_its_content_and_reports_it():
    """b**2 + 160000 > 0 for every real b: no arm lies on it (it comes from t = -+i)."""
    result = build("arm-extremum").task.run("linear", "flint")
    assert all("AB" in {str(v) for v in f.free_symbols} for f in result.factors), result.factors
    b = next(v for v in result.polynomial.free_symbols if str(v) == "b")
    assert [sympy.expand(d - (b**2 + 160000)) for d in result.dropped] == [0]


@pytest.fixture(scope="module")
def fourbar():
    """The symbolic four-bar, its side relations, and two fresh eliminations at random values."""
    task = build("fourbar-symbolic").task
    found = [specialise.fresh(task, v, 60) for v in specialise.specialisations(task, [], 2, seed=3)]
    return task, found


def test_the_specialised_check_passes_the_true_eliminant(fourbar):
    task, found = fourbar
    result = task.run("linear", "flint")
    verdict = specialise.check(agree.rebuild(agree.portable(result.engine, result.raw), list(task.keep)), found)
    assert verdict.kind is Agreement.EQUAL, verdict


def test_the_specialised_check_catches_one_wrong_coefficient(fourbar):
    task, found = fourbar
    result = task.run("linear", "flint")
    poly = agree.rebuild(agree.portable(result.engine, result.raw), list(task.keep))
    monomial, coefficient = poly.monoms()[len(poly) // 2], poly.coeffs()[len(poly) // 2]
    wrong = poly + poly.context().term(coefficient, monomial)  # that one coefficient doubled
    assert not specialise.check(wrong, found).agrees


def test_the_cli_exits_1_on_a_disagreeing_row(monkeypatch, capsys):
    def extra(poly, reference, side=(), parameters=()):
        return agree.Verdict(Agreement.EXTRA_FACTOR, "extra factor x (degree 1, 1 terms)")

    monkeypatch.setattr("algkin.bench.agreement", extra)
    code = main(["bench", "--problems", "two-circles", "--methods", "linear", "groebner", "--backends", "flint",
                 "--no-peers", "--budget", "20", "--rounds", "1"])
    assert code == 1
    assert "extra factor" in capsys.readouterr().out
