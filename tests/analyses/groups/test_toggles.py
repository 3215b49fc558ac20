"""``toggles`` on a scene with points solved together: where two modes meet, against the number of
real solutions that Newton's method from many starts finds and proves on either side (no eliminant)."""

from fractions import Fraction

import numpy as np
import pytest

from algkin.analyses.groups.scene import prepare_groups
from algkin.analyses.groups.toggles import toggles_groups
from algkin.verify.groups import real_solutions

STEP = Fraction(1, 100)


def _counts(name, values):
    prepared = prepare_groups(name)
    group, = prepared.compiled.groups
    inputs = {prepared.input.name: prepared.variables}
    samples = [prepared.sample(v).exact() for v in values]
    return [len(found) for found in real_solutions(group.unknowns, group.equations, inputs, samples,
                                                   np.random.default_rng(1), starts=128)]


@pytest.mark.parametrize("name, count", [("3rpr", 2), ("stephenson-iii-triad", 4)])
def test_every_toggle_is_certified_and_two_real_modes_appear_or_vanish_there(name, count):
    found = toggles_groups(name)
    assert len(found.toggles) == count and all(t.certified for t in found.toggles)
    values = [Fraction(t.value).limit_denominator(10**6) for t in found.toggles]
    counts = _counts(name, [v + d for v in values for d in (-STEP, STEP)])
    for before, after in zip(counts[::2], counts[1::2]):
        assert abs(before - after) == 2, counts


def test_the_3rpr_singularity_locus_in_r1():
    """Between its two toggles the 3-RPR does not assemble; outside them it has two real modes."""
    found = toggles_groups("3rpr")
    low, high = (t.value for t in found.toggles)
    assert low == pytest.approx(7.92278018529, abs=1e-9) and high == pytest.approx(11.2064417138, abs=1e-9)
    assert _counts("3rpr", [7, 9, 10, 12]) == [2, 0, 0, 2]
    assert found.to_json()["toggles"][0]["kind"] == "modes meet"
    assert "input_length" in found.to_json()["toggles"][0]


def test_between_the_triads_toggles_it_assembles_only_near_zero_and_between_193_and_231():
    assert _counts("stephenson-iii-triad", [0, 90, 200, 270, 330]) == [2, 0, 2, 0, 2]


@pytest.mark.parametrize("name", ["3rpr", "stephenson-iii-triad"])
def test_each_toggles_factor_is_in_the_variable_its_docs_name_and_vanishes_there(name):
    """The factor of an angle's toggle is in ``t = tan(theta/2)`` (docs/cli/toggles.md; ``t_`` was
    printed), a length's in the length; evaluated there (mpmath, 60 digits) it is 0 to its size."""
    import mpmath
    import sympy

    found = toggles_groups(name)
    for toggle in found.toggles:
        factor = sympy.parse_expr(toggle.factor)
        (variable,) = factor.free_symbols
        angle = found.unit == "deg"
        assert str(variable) == ("t" if angle else found.input)
        with mpmath.workdps(60):
            at = mpmath.tan(mpmath.radians(toggle.value) / 2) if angle else mpmath.mpf(toggle.value)
            value = sympy.lambdify(variable, factor, "mpmath")(at)
            size = sum(abs(c) * abs(at) ** k for (k,), c in sympy.Poly(factor, variable).terms())
            assert abs(value) < 1e-9 * size, (toggle, value)
