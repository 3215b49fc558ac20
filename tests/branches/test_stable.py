"""The stabilised evaluator agrees with the closed forms at high precision, on every catalog scene."""

from fractions import Fraction

import mpmath
import numpy as np
import pytest
import sympy
from hypothesis import given, settings, strategies as st

from algkin.branches import closed_forms
from algkin.branches.stable import StableBranch
from algkin.branches.constructions.floats import stable_quadratic
from algkin.scene.load import catalog_names
from algkin.evaluate import MPMATH, evaluate
from algkin.scene import compile_scene, load_scene
from algkin.system import symbol

EPS = 2.0**-53
# the arm has no dyad or slider; points solved together have no closed-form branches (yet)
SCENES = [n for n in catalog_names() if n != "arm-string" and not load_scene(n).unknown_points]


def _truth(branch, compiled, angles):
    """Every unknown of the branch at 40 digits from its closed form, nan where it is not real
    (its own dyad, or one it is built on, cannot assemble); and per sample whether some
    discriminant of the branch is negative."""
    defaults = {symbol(n): sympy.Rational(str(v)) for n, v in compiled.parameter_values.items()}
    inputs = list(compiled.system.inputs.values())  # an angle's (c, s), a length's (s,)
    real = lambda v: float(v) if not isinstance(v, mpmath.mpc) else (float(v.real) if v.imag == 0 else np.nan)  # noqa: E731
    with mpmath.workdps(40):
        rows, blocked = [], []
        for sample in zip(*angles):
            values = {}
            for variables, angle in zip(inputs, sample):
                values.update(zip(variables, (mpmath.cos(angle), mpmath.sin(angle)) if len(variables) == 2
                                  else (mpmath.mpf(angle),)))
            rows.append([real(evaluate(v.xreplace(defaults), values, MPMATH)) for v in branch.values.values()])
            # a form may lose its square roots (an inversor's straight line, P_x = 5/2): where some
            # discriminant is negative the branch does not assemble, whatever such a form says
            blocked.append(any(not real(evaluate(d.xreplace(defaults), values, MPMATH)) >= 0
                               for d in branch.discriminants.values()))
    return np.array(rows).T, np.array(blocked)


@pytest.mark.parametrize("name", SCENES)
def test_every_branch_matches_its_closed_form(name):
    compiled = compile_scene(load_scene(name))
    rng = np.random.default_rng(7)
    angles = [rng.uniform(-np.pi, np.pi, 60) if compiled.scene.inputs[n].is_angle
              else rng.uniform(*compiled.scene.inputs[n].span, 60) for n in compiled.system.inputs]
    for branch in closed_forms(compiled):
        truth, blocked = _truth(branch, compiled, angles)
        got = StableBranch(compiled, branch)(*angles)
        for row, unknown in zip(truth, branch.values):
            if unknown not in got:  # an output defined from the points, not a point
                continue
            mismatched = np.isnan(row) != np.isnan(got[unknown])
            assert not np.any(mismatched & ~blocked), (branch.label, unknown)
            ok = ~np.isnan(row) & ~np.isnan(got[unknown])
            scale = 1 + np.abs(row[ok])
            assert np.max(np.abs(got[unknown][ok] - row[ok]) / scale, initial=0) < 1e-11, (branch.label, unknown)


rationals = st.fractions(min_value=-100, max_value=100, max_denominator=1000)


def _exact(a2, a1, a0, t):
    t = Fraction(float(t))
    return a2 * t * t + a1 * t + a0


@settings(max_examples=300)
@given(rationals.filter(lambda v: v != 0), rationals, rationals, st.floats(-1e6, 1e6))
def test_stable_quadratic_is_accurate_to_a_few_ulps_of_its_own_condition(a2, a1, a0, t):
    computed = float(stable_quadratic(a2, a1, a0)(np.array([t]))[0])
    exact = _exact(a2, a1, a0, t)
    disc = a1 * a1 - 4 * a2 * a0
    if disc < 0:  # a sum of two positive terms: relative accuracy everywhere, however small
        bound = 8 * EPS * abs(exact)
    else:  # each root is rounded once: as good as the distance to it allows
        with mpmath.workdps(40):
            roots = [(-a1 + sign * mpmath.sqrt(disc)) / (2 * a2) for sign in (1, -1)]
            bound = 8 * EPS * abs(float(exact)) * (1 + sum(float(abs(r) / abs(t - r)) for r in roots if t != r))
    assert abs(computed - float(exact)) <= bound + 1e-300


def test_a_sum_of_positives_where_the_expanded_form_cancels():
    # 1e-4 t**2 - 2 t + (1e4 + 1e-6): minimum 1e-6 at t = 1e4, terms of size 1e4 cancel there.
    a2, a1, a0 = Fraction(1, 10**4), Fraction(-2), Fraction(10**4) + Fraction(1, 10**6)
    t = np.array([1e4])
    expanded = float(a2) * t * t + float(a1) * t + float(a0)
    stable = stable_quadratic(a2, a1, a0)(t)
    assert abs(stable[0] - 1e-6) <= 4 * EPS * 1e-6
    assert abs(expanded[0] - 1e-6) > 1e3 * abs(stable[0] - 1e-6)  # the naive form loses digits
