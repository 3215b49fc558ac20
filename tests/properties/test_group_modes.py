"""Drawn scenes with points solved together: every real solution of the original equations, found by
the independent numeric solver, matches one mode of ``algkin.solve``; none missing, none extra."""

from fractions import Fraction

import flint
import numpy as np
from hypothesis import given, settings, strategies as st

import algkin
from algkin.scene.groups import compile_groups
from algkin.testing import strategies
from algkin.verify.groups import BITS, STARTS, real_solutions

MORE_STARTS = 4 * STARTS  # Newton from random starts may miss a root: no sample may hinge on it


def _exact(scene, name, value):
    """The input's variables at ``value`` exactly: a length, or an angle's cos and sin at a quarter turn."""
    if not scene.inputs[name].is_angle:
        return {f"{name}": flint.fmpq(value.numerator, value.denominator)}
    c, s = {90: (0, 1), 180: (-1, 0), 270: (0, -1)}[int(value)]
    return {f"c_{name}": flint.fmpq(c), f"s_{name}": flint.fmpq(s)}


def _matches(root, configuration, unknowns):
    """The proved root and the configuration's decimals (30 digits) agree to 1e-25."""
    points = configuration.points
    with flint.ctx.workprec(BITS):  # the decimals read at the proofs' precision, not 53 bits
            return all(abs(float((root[u] - flint.arb(points[u[:-2]]["_xy".index(u[-1]) - 1])).mid())) < 1e-25
                   for u in unknowns)


@settings(max_examples=6, deadline=None)
@given(strategies.group_scenes(), st.integers(0, 2**16))
def test_every_numeric_solution_matches_one_mode(scene, seed):
    name, value = strategies.design_input(scene)
    solution = algkin.solve(scene, {name: value})
    assert solution.configurations  # the design assembles there
    compiled = compile_groups(scene)
    (group,) = compiled.groups
    roots, = real_solutions(group.unknowns, group.equations, {name: compiled.inputs[name]},
                            [_exact(scene, name, Fraction(value))], np.random.default_rng(seed), starts=MORE_STARTS)
    matched = [sum(_matches(r, c, group.unknowns) for r in roots) for c in solution.configurations]
    owners = [sum(_matches(r, c, group.unknowns) for c in solution.configurations) for r in roots]
    assert matched == [1] * len(solution.configurations), "a mode missing, or matched twice"
    assert owners == [1] * len(roots), "a numeric solution that is no mode (extra)"
