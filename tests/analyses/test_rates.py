"""Velocities and accelerations (``algkin.rates``): against hand derivations, against the implicit
function theorem at numeric roots, and their check against central differences, which must
pass on the seed's lambda and a six-bar and catch a wrong derivative."""

import math

import mpmath
import numpy as np
import pytest
import sympy
from hypothesis import given, settings, strategies as st

import algkin
from algkin.analyses.rates import Rate, check_forms, rates_of
from algkin.analyses.rates.check import check_rates
from algkin.analyses.rates.forms import Derivative
from algkin.analyses.rates.text import quick
from algkin.derivation.pipeline import derive
from algkin.derivation.checking import check_setup
from algkin.errors import UsageError
from algkin.evaluate import MPMATH, evaluate
from algkin.scene import load_scene_text
from algkin.system import symbol
from algkin.testing import strategies
from algkin.verify import solve_floats
from algkin.verify.solve import blocks_of

CRANK = """
name = "crank"
[parameters]
r = 3
[inputs]
t = { range = [0, 360], unit = "deg" }
[points]
O = { fixed = [0, 0] }
A = { crank = "O", length = "r", input = "t" }
[outputs]
A = "A"
"""

c_t, s_t, r = symbol("c_t"), symbol("s_t"), symbol("r")


def test_a_crank_point_moves_along_its_circle_and_accelerates_towards_the_pivot():
    # by hand: A = (r cos t, r sin t), A' = (-r sin t, r cos t), A'' = -A
    found = algkin.rates(load_scene_text(CRANK), params=["r"], samples=4)
    (branch,) = found.branches
    assert branch.velocity == {"A_x": -r * s_t, "A_y": r * c_t}
    assert branch.acceleration == {"A_x": -r * c_t, "A_y": -r * s_t}
    assert found.verification.passed and found.verification.compared == 4


def _on_circle(k):
    """An exact point (c, s) on the unit circle: rational tangent half-angles."""
    t = sympy.Rational(k, 7) - 3
    return (1 - t**2) / (1 + t**2), 2 * t / (1 + t**2)


def test_the_arm_string_length_has_the_hand_derived_rates():
    # |AB|**2 = (a - r s)**2 + (r c - b)**2 with A = r (sin, -cos), B = (a, -b), r = 350, so
    # |AB|' = r (b s - a c) / |AB| and |AB|'' = r (a s + b c) / |AB| - (r (b s - a c))**2 / |AB|**3
    found = algkin.rates("arm-string", outputs=["AB"], params=["a", "b"], samples=6)
    a, b, c, s = symbol("a"), symbol("b"), symbol("c_theta"), symbol("s_theta")
    ab = sympy.sqrt((a - 350 * s) ** 2 + (350 * c - b) ** 2)
    velocity = 350 * (b * s - a * c) / ab
    acceleration = 350 * (a * s + b * c) / ab - (350 * (b * s - a * c)) ** 2 / ab**3
    (branch,) = found.branches
    for k in range(12):
        point = {**dict(zip((c, s), _on_circle(k))), a: sympy.Rational(400 + 37 * k, 3), b: 80 - 11 * k}
        for form, hand in ((branch.velocity["AB"], velocity), (branch.acceleration["AB"], acceleration)):
            assert abs(sympy.N((form - hand).xreplace(point), 60)) < 1e-50
    assert found.verification.passed


@pytest.fixture(scope="module")
def lambda_rates():
    return rates_of(derive("chebyshev-lambda", outputs=["B", "P"], samples=4), samples=12, seed=3)


def test_the_lambda_rates_of_b_and_p_pass_their_check(lambda_rates):
    check = lambda_rates.verification
    assert [b.label for b in lambda_rates.branches] == ["left", "right"]
    assert set(lambda_rates.branches[0].velocity) == {"B_x", "B_y", "P_x", "P_y"}
    assert check.passed and check.status == "passed" and not check.failures
    assert check.compared >= 12 and check.max_rel_error < 1e-30


def _wrong(forms, unknown, velocity_sign=1, acceleration_sign=1):
    return [dict(f, **{unknown: Rate(velocity_sign * f[unknown].velocity, acceleration_sign * f[unknown].acceleration)})
            for f in forms]


def _forms(found):
    return [{u: Rate(b.velocity[u], b.acceleration[u]) for u in b.velocity} for b in found.branches]


@pytest.mark.parametrize("unknown, signs", [("P_x", (-1, 1)), ("B_y", (1, -1))])
def test_a_sign_flipped_lambda_rate_is_caught(lambda_rates, unknown, signs):
    check = check_forms(lambda_rates.derivation, _wrong(_forms(lambda_rates), unknown, *signs), samples=6)
    what = "velocity" if signs[0] < 0 else "acceleration"
    assert not check.passed and check.status == "failed" and check.max_rel_error > 1e-3
    assert any(f"the {what} of {unknown}" in f for f in check.failures), check.failures


def test_a_velocity_in_place_of_an_acceleration_is_caught(lambda_rates):
    forms = [{u: Rate(r.velocity, r.velocity) for u, r in f.items()} for f in _forms(lambda_rates)]
    assert not check_forms(lambda_rates.derivation, forms, samples=4).passed


@pytest.fixture(scope="module", params=["watt-i", "stephenson-iii"])
def six_bar_rates(request):
    return rates_of(derive(request.param, samples=2), samples=5, seed=1)


def test_a_six_bar_coupler_point_has_checked_rates_and_a_flipped_one_is_caught(six_bar_rates):
    check = six_bar_rates.verification
    assert len(six_bar_rates.branches) == 4 and set(six_bar_rates.branches[0].velocity) == {"P_x", "P_y"}
    assert check.passed and check.compared >= 5 and check.max_rel_error < 1e-30
    wrong = check_forms(six_bar_rates.derivation, _wrong(_forms(six_bar_rates), "P_y", 1, -1), samples=3)
    assert not wrong.passed and any("the acceleration of P_y" in f for f in wrong.failures)


def test_the_forms_read_back_from_their_text_to_the_same_values(six_bar_rates, lambda_rates):
    # every lambda form; a six-bar's first branch's P_y (the text of its acceleration is ~190,000 characters)
    for found, wanted in ((lambda_rates, None), (six_bar_rates, "P_y")):
        c, s = found.derivation.compiled.system.inputs[found.input]
        with mpmath.workdps(40):
            point = {c: mpmath.cos(mpmath.mpf("0.7")), s: mpmath.sin(mpmath.mpf("0.7"))}
            for branch, texts in list(zip(found.branches, found.to_json()["rates"].values()))[:1 if wanted else None]:
                for u in [wanted] if wanted else branch.velocity:
                    for form, text in ((branch.velocity[u], texts[u]["velocity"]),
                                       (branch.acceleration[u], texts[u]["acceleration"])):
                        exact, back = evaluate(form, point, MPMATH), evaluate(sympy.parse_expr(text), point, MPMATH)
                        assert abs(exact - back) <= 1e-30 * (1 + abs(exact))


def test_the_memoised_chain_rule_agrees_with_sympy_diff():
    c, s = symbol("c_angle"), symbol("s_angle")
    (left, _) = derive("chebyshev-lambda", outputs=["P"], samples=0).branches
    d = Derivative((c, s))
    for form in left.values.values():
        by_sympy = -s * sympy.diff(form, c) + c * sympy.diff(form, s)
        for k in range(5):
            point = dict(zip((c, s), _on_circle(k + 20)))
            assert abs(sympy.N((d(form) - by_sympy).xreplace(point), 50)) < 1e-40


def test_quick_text_parses_back_exactly():
    x, y = sympy.symbols("x y")
    for e in (-3 * x / (2 * y), (x + 1) ** sympy.Rational(-3, 2) * y - sympy.Rational(2, 3),
              sympy.Mul(-2, x + y, 1 / (x - y), evaluate=False), 1 / sympy.sqrt(x) - x**-2, sympy.Abs(y) * x**3):
        assert sympy.simplify(sympy.parse_expr(quick(e)) - e) == 0, quick(e)


def test_zero_samples_skip_the_check_and_two_inputs_are_refused():
    assert algkin.rates("chebyshev-lambda", outputs=["B"], samples=0).verification.status == "skipped"
    assert not algkin.rates("chebyshev-lambda", outputs=["B"], samples=0).verification.passed
    with pytest.raises(UsageError, match="^scene='five-bar': rates need .*2 \\(t1, t2\\)"):
        algkin.rates("five-bar")


def test_a_check_with_nothing_to_compare_fails():
    found = algkin.rates("chebyshev-lambda", outputs=["B"], samples=0)
    setup = check_setup(found.derivation.compiled, found.derivation.branches)
    system, indicators, branches = setup.system, setup.indicators, setup.branches
    nothing = check_rates(system, indicators, [(labels, {}, d) for labels, _, d in branches], (0.0, 6.0), 4)
    assert not nothing.passed and nothing.compared == 0 and "no branch rate compared" in nothing.failures[0]


# -- a second method: the implicit function theorem at a numeric root, -J^-1 dF/dtheta ---------------


def _numeric_root(system, indicators, label, theta):
    """The root of ``label`` at ``theta``: float Newton from random starts (no closed form),
    polished by mpmath at 40 digits."""
    (c, s), = system.inputs.values()
    found = solve_floats(blocks_of(system), {c: np.array([math.cos(theta)]), s: np.array([math.sin(theta)])},
                         np.random.default_rng(0))
    names = list(system.unknowns)
    at = {symbol(c): mpmath.cos(theta), symbol(s): mpmath.sin(theta)}
    equations = [sympy.lambdify([symbol(u) for u in names], e.xreplace(at), "mpmath") for e in system.equations
                 if e.free_symbols & {symbol(u) for u in names}]
    for k in range(len(found.owner)):
        start = [mpmath.mpf(found.values[u][k]) for u in names]
        root = mpmath.findroot(lambda *x: [f(*x) for f in equations], start)
        values = {**dict(zip(map(symbol, names), root)), **at}
        if all((sympy.N(e.xreplace(values)) > 0) == (label[p] == positive)
               for p, e, positive, _ in indicators):
            return dict(zip(names, root))
    return None


def _implicit_velocity(system, root, theta):
    names = list(system.unknowns)
    (c, s), = system.inputs.values()
    unknowns = [symbol(u) for u in names]
    equations = [e for e in system.equations if e.free_symbols & set(unknowns)]
    at = {**dict(zip(unknowns, (root[u] for u in names))), symbol(c): mpmath.cos(theta), symbol(s): mpmath.sin(theta)}
    jacobian = mpmath.matrix([[sympy.N(sympy.diff(e, u).xreplace(at), 40) for u in unknowns] for e in equations])
    along = mpmath.matrix([sympy.N((-symbol(s) * sympy.diff(e, symbol(c)) + symbol(c) * sympy.diff(e, symbol(s)))
                                   .xreplace(at), 40) for e in equations])
    return dict(zip(names, -(mpmath.lu_solve(jacobian, along))))


@settings(max_examples=8, deadline=None)
@given(strategies.four_bars("crank-rocker"), st.floats(0, 2 * math.pi))
def test_four_bar_velocity_matches_the_implicit_function_theorem(scene, theta):
    with mpmath.workdps(40):
        found = algkin.rates(scene, outputs=["B"], samples=0)
        compiled = found.derivation.compiled
        setup = check_setup(compiled, found.derivation.branches)
        system, indicators, branches = setup.system, setup.indicators, setup.branches
        (c, s), = system.inputs.values()
        point = {symbol(c): sympy.Float(mpmath.cos(theta), 40), symbol(s): sympy.Float(mpmath.sin(theta), 40)}
        for branch, (labels, _, discriminants) in zip(found.branches, branches):
            if not all(sympy.N(d.xreplace(point)) > 1e-6 for d in discriminants.values()):
                continue  # not assembled here, or too near a toggle for a float start
            root = _numeric_root(system, indicators, labels, theta)
            assert root is not None, (branch.label, theta)
            expected = _implicit_velocity(system, root, theta)
            defaults = {symbol(n): v for n, v in compiled.parameter_values.items()}
            for u, form in branch.velocity.items():
                value = sympy.N(form.xreplace(defaults).xreplace(point), 40)
                assert abs(value - sympy.Float(expected[u], 40)) <= 1e-25 * (1 + abs(value)), (u, branch.label)

