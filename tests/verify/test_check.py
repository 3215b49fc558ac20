"""Verification must catch wrong closed forms, swapped labels and missing branches."""

import sympy

import algkin
from algkin.branches import closed_forms
from algkin.pipeline import _verify
from algkin.scene import compile_scene, load_scene


def lambda_setup():
    compiled = compile_scene(load_scene("chebyshev-lambda"), ["B"])
    return compiled, closed_forms(compiled)


def test_true_closed_forms_pass():
    compiled, branches = lambda_setup()
    report = _verify(compiled, branches, 20, 1, {})
    assert report.passed and report.compared == 40
    assert report.max_abs_error < 1e-40


def test_swapped_labels_fail():
    compiled, branches = lambda_setup()
    left, right = branches
    swapped = [type(left)(left.label, left.labels, right.values, left.discriminants, True),
               type(right)(right.label, right.labels, left.values, right.discriminants, False)]
    report = _verify(compiled, swapped, 10, 1, {})
    assert not report.passed
    assert report.max_abs_error > 0.1


def test_slightly_wrong_closed_form_fails():
    compiled, branches = lambda_setup()
    left = branches[0]
    nudged = dict(left.values, B_x=left.values["B_x"] + sympy.Rational(1, 10**12))
    wrong = [type(left)(left.label, left.labels, nudged, left.discriminants, True), branches[1]]
    report = _verify(compiled, wrong, 5, 1, {})
    assert not report.passed
    assert 1e-13 < report.max_abs_error < 1e-11


def test_missing_branch_fails():
    compiled, branches = lambda_setup()
    report = _verify(compiled, branches[:1], 5, 1, {})
    assert not report.passed
    assert any("no real closed-form branch" in f for f in report.failures)


def test_wrong_eliminant_fails():
    compiled, branches = lambda_setup()
    x = sympy.Symbol("B_x", real=True)
    report = _verify(compiled, branches, 5, 1, {"B_x": x**2 - 1})
    assert not report.passed


def test_seed_is_deterministic():
    a = algkin.derive("chebyshev-lambda", ["B"], samples=5, seed=11).verification
    b = algkin.derive("chebyshev-lambda", ["B"], samples=5, seed=11).verification
    assert a.to_json() == b.to_json()
