"""Verification must catch wrong closed forms, swapped labels and missing branches."""

from importlib.resources import files

import attrs
import pytest
import sympy

import algkin
from algkin.branches import closed_forms
from algkin.errors import UsageError
from algkin.derivation.assembles import where_assembled
from algkin.derivation.checking import check_setup
from algkin.derivation.prepared import prepare
from algkin.scene import compile_scene, load_scene, load_scene_text
from algkin.verify import CheckSetup, verify_branches


def check(compiled, branches, samples, polynomials, factors=None):
    """The pipeline's independent check of ``branches`` (seed 1): ``verify_branches`` on what
    ``check_setup`` gives, the samples where some branch may assemble."""
    return verify_branches(check_setup(compiled, branches), samples=samples, seed=1, polynomials=polynomials, factors=factors,
                           where=where_assembled(compiled, branches))


def lambda_setup():
    compiled = compile_scene(load_scene("chebyshev-lambda"), ["B"])
    return compiled, closed_forms(compiled)


def test_true_closed_forms_pass():
    compiled, branches = lambda_setup()
    report = check(compiled, branches, 20, {})
    assert report.passed and report.compared == 40
    assert report.max_abs_error < 1e-40


def test_swapped_labels_fail():
    compiled, branches = lambda_setup()
    left, right = branches
    swapped = [type(left)(left.label, left.labels, right.values, left.discriminants, True),
               type(right)(right.label, right.labels, left.values, right.discriminants, False)]
    report = check(compiled, swapped, 10, {})
    assert not report.passed
    assert report.max_abs_error > 0.1


def test_slightly_wrong_closed_form_fails():
    compiled, branches = lambda_setup()
    left = branches[0]
    nudged = dict(left.values, B_x=left.values["B_x"] + sympy.Rational(1, 10**12))
    wrong = [type(left)(left.label, left.labels, nudged, left.discriminants, True), branches[1]]
    report = check(compiled, wrong, 5, {})
    assert not report.passed
    assert 1e-13 < report.max_abs_error < 1e-11


def test_missing_branch_fails():
    compiled, branches = lambda_setup()
    report = check(compiled, branches[:1], 5, {})
    assert not report.passed
    assert any("no real closed-form branch" in f for f in report.failures)


def test_wrong_eliminant_fails():
    compiled, branches = lambda_setup()
    x = sympy.Symbol("B_x", real=True)
    report = check(compiled, branches, 5, {"B_x": x**2 - 1})
    assert not report.passed


def test_seed_is_deterministic():
    a = algkin.derive("chebyshev-lambda", ["B"], samples=5, seed=11).verification
    b = algkin.derive("chebyshev-lambda", ["B"], samples=5, seed=11).verification
    assert a.to_json() == b.to_json()


# A check that compared nothing never says "passed": with no sample it is "skipped".

def test_zero_samples_is_skipped_not_passed():
    result = algkin.derive("chebyshev-lambda", outputs=["B"], samples=0, certify=False)
    assert result.verification.status == "skipped"
    assert not result.verification.passed
    assert result.to_json()["verification"]["status"] == "skipped"


def test_negative_samples_are_bad_input():
    with pytest.raises(UsageError, match="samples=-1"):
        algkin.derive("chebyshev-lambda", outputs=["B"], samples=-1)


def test_nothing_to_compare_fails():
    compiled, _ = lambda_setup()
    report = check(compiled, [], 3, {})
    assert report.status == "failed" and not report.passed
    assert any("nothing to compare" in f for f in report.failures)


@pytest.mark.parametrize("k", ["1e-20", "1e50"])
def test_a_lambda_of_any_size_is_compared_as_at_scale_one(k):
    # The check is scale-free: roots found from the pencil of the two circles, proved in boxes
    # sized relative to the root, labels and discriminants decided by sign, errors relative to
    # the configuration. (The mpmath check judged every sample at 1e-20 near a degenerate
    # configuration and compared nothing.)
    text = (LAMBDA_TEXT.replace('D = { fixed = [2, 0] }', 'D = { fixed = ["2*k", 0] }')
            .replace('length = 1,', 'length = "k",').replace('["5/2", "5/2"]', '["5/2*k", "5/2*k"]'))
    scene = load_scene_text(text.replace("[inputs]", f'[parameters]\nk = "{k}"\n\n[inputs]'), "scaled.toml")
    verification = algkin.derive(scene, outputs=["B"], samples=5, certify=False).verification
    assert verification.passed, verification.failures
    assert verification.compared == 10
    assert verification.max_rel_error < 1e-40
    assert verification.max_abs_error < 1e-40 * 3 * float(k)  # coordinates up to about 3k


def test_a_four_bar_of_crank_1_and_bars_near_1e15_is_compared():
    # Mixed scales: the coupler point's equation, 2 P_x - B_x + B_y - c - s = 0 with B near 5e14, has a
    # leading coefficient 1e-15 of its constant's. It was taken for zero beside it: P had no numeric
    # solution and the check, comparing nothing, failed.
    derived = algkin.derive("fourbar", samples=5, certify=False, set={"l": "10**15+1/7", "m": "10**15"})
    verification = derived.verification
    assert verification.passed, verification.failures
    assert verification.compared == 10  # both branches at each of the 5 samples
    assert verification.max_rel_error < 1e-40


def test_a_four_bar_of_lengths_near_1e77_is_compared():
    # Its dyad's discriminant has coefficients past a float's range (a quartic in lengths of 1e77): its
    # sign on the assembly check's grid once overflowed (a traceback, OverflowError)
    derived = algkin.derive("fourbar", samples=5, certify=False, set={"a": "1e77", "d": "4e77", "l": "3e77", "m": "3.5e77"})
    assert derived.verification.passed, derived.verification.failures
    assert derived.verification.compared == 10 and derived.verification.max_rel_error < 1e-40


def test_the_outputs_of_fixed_points_are_checked_on_their_one_configuration():
    # no input and no parameter: nothing varies, so one sample (the scene file puts D at (2, 0)); once a
    # StopIteration where the numeric solution looked for the samples' count among no known values
    derived = algkin.derive("chebyshev-lambda", ["D"], samples=5, certify=False)
    assert [str(v) for v in derived.branches[0].values.values()] == ["2", "0"]
    assert derived.verification.passed and (derived.verification.samples, derived.verification.compared) == (1, 1)


def test_narrow_assembly_range_is_still_compared():
    # Crank 41/8, ground 5, bars 1/2 and 5/2: B assembles on about 6% of the turn, so
    # uniform samples mostly land where nothing can be compared; more are drawn there.
    text = (LAMBDA_TEXT.replace('D = { fixed = [2, 0] }', 'D = { fixed = [5, 0] }')
            .replace('length = 1,', 'length = "41/8",').replace('["5/2", "5/2"]', '["1/2", "5/2"]'))
    verification = algkin.derive(load_scene_text(text, "narrow.toml"), outputs=["B"], samples=3,
                                 certify=False).verification
    assert verification.passed, verification.failures
    assert verification.compared >= 3


def test_wrong_sign_in_a_closed_form_is_caught():
    compiled, branches = lambda_setup()
    left = branches[0]
    flipped = dict(left.values, B_y=-left.values["B_y"])
    report = check(compiled, [type(left)(left.label, left.labels, flipped, left.discriminants, True),
                              branches[1]], 5, {})
    assert not report.passed


LAMBDA_TEXT = (files("algkin.catalog") / "chebyshev-lambda.toml").read_text(encoding="utf-8")


# Minimality: vanishing on the true configurations is not enough, a product with a leftover
# extraneous factor vanishes there too (the issue "Accuracy and agreement claims an outsider
# would accept"). Each kept factor must vanish by itself, and the curve must be squarefree.

@pytest.fixture(scope="module")
def lambda_curve():
    """The coupler curve of P with its kept factors, and the branches it is checked against."""
    result = algkin.curve("chebyshev-lambda", "P", samples=0)
    prepared = prepare("chebyshev-lambda", outputs=["P"])
    return prepared.compiled, prepared.branches, result.elimination.factors


def curve_check(lambda_curve, factors):
    compiled, branches, _ = lambda_curve
    return check(compiled, branches, 4, {"curve": sympy.Mul(*factors)}, {"curve": factors})


def test_true_curve_is_minimal(lambda_curve):
    report = curve_check(lambda_curve, lambda_curve[2])
    assert report.passed, report.failures
    assert report.smallest_factor_residual["curve"][0] < 1e-40


@pytest.mark.parametrize("extra", ["P_x**2 + P_y**2 + 1", "P_x - 100"])
def test_leftover_extraneous_factor_fails(lambda_curve, extra):
    factor = sympy.sympify(extra, locals={n: sympy.Symbol(n, real=True) for n in ("P_x", "P_y")})
    report = curve_check(lambda_curve, lambda_curve[2] + [factor])
    # The product still vanishes on every true position: the old check passed it.
    assert report.max_polynomial_residual["curve"] < 1e-40
    assert not report.passed
    assert len(report.failures) == 1, report.failures
    assert report.failures[0].startswith(f"factor {factor} of curve vanishes on none")


def test_squared_factor_fails(lambda_curve):
    true, = lambda_curve[2]
    report = curve_check(lambda_curve, [true, true])
    assert report.max_polynomial_residual["curve"] < 1e-40
    assert not report.passed
    assert report.failures == (f"curve is not squarefree: ({sympy.expand(true)})**2 divides it",)


def test_factors_must_multiply_to_the_polynomial(lambda_curve):
    compiled, branches, (true,) = lambda_curve
    x = sympy.Symbol("P_x", real=True)
    report = check(compiled, branches, 4, {"curve": true * (x - 100)}, {"curve": [true]})
    assert not report.passed
    assert any("do not multiply" in f for f in report.failures)


def test_extraneous_factor_in_a_derived_eliminant_fails():
    compiled, branches = lambda_setup()
    derived = algkin.derive("chebyshev-lambda", ["B"], samples=0, certify=False).eliminations["B_x"]
    c = sympy.Symbol(next(iter(compiled.system.inputs.values()))[0], real=True)
    factors = derived.factors + [c - 2]  # the input's cosine is never 2
    report = check(compiled, branches, 4, {"B_x": sympy.Mul(*factors)}, {"B_x": factors})
    assert not report.passed
    assert any(f.startswith(f"factor {c - 2} of B_x vanishes on none") for f in report.failures)


def test_curve_and_derive_check_their_kept_factors():
    curve = algkin.curve("chebyshev-lambda", "P", samples=2).verification
    derived = algkin.derive("chebyshev-lambda", ["B"], samples=2, certify=False).verification
    assert [len(v) for v in curve.smallest_factor_residual.values()] == [1]
    assert set(derived.smallest_factor_residual) == {"B_x", "B_y"}
    assert curve.passed and derived.passed


def test_the_check_setup_is_a_frozen_hashable_value_and_the_rest_is_keyword_only():
    compiled, branches = lambda_setup()
    setup = check_setup(compiled, branches)
    again = CheckSetup(system=setup.system, indicators=list(setup.indicators), branches=list(setup.branches),
                       inputs=dict(setup.inputs), parameters=dict(compiled.parameter_values))
    assert setup == again and hash(setup) == hash(again)
    with pytest.raises(attrs.exceptions.FrozenInstanceError):
        setup.inputs = {}
    with pytest.raises(TypeError):
        setup.branches[0][1]["B_x"] = 0  # its mappings are read-only too
    with pytest.raises(TypeError):
        verify_branches(setup, 5)  # samples by name only


def test_a_derivation_with_dimensions_of_sixty_digits_verifies():
    """The discriminants' integer coefficients pass a float's range: the samples where a branch is
    real are then decided in balls (floats' pre-selection raised OverflowError)."""
    from tests.analyses.extremum.test_long_dimensions import LONG

    result = algkin.derive("fourbar", outputs=["B"], set=LONG)
    assert result.verification.passed and result.verification.compared >= 40
