"""Angle outputs of random scenes (``phi = "angle(X, Y)"``): every branch's closed forms of
the direction's cosine and sine verified, and equal to the direction of the hand-drawn points."""

import mpmath
import sympy
from hypothesis import given, settings, strategies as st

from algkin.derivation.pipeline import derive
from algkin.testing import strategies

from .hand import trajectory

SAMPLES = 2
ANGLES = range(11, 360, 50)


@settings(max_examples=40, deadline=None)
@given(strategies.scenes().filter(lambda scene: "phi" in scene.outputs), st.integers(0, 2**16))
def test_angle_output_is_the_direction_of_its_points(scene, seed):
    result = derive(scene, ["phi"], samples=SAMPLES, seed=seed, certify=False)
    assert result.verification.passed, result.verification.failures
    assert result.verification.compared > 0
    start, end = scene.outputs["phi"].points
    c, s = (sympy.Symbol(n, real=True) for n in ("c_theta", "s_theta"))
    checked = 0
    with mpmath.workdps(40):
        for branch in result.branches:
            forms = [sympy.lambdify((c, s), branch.values[u], "mpmath") for u in ("cos_phi", "sin_phi")]
            for degrees in ANGLES:
                # angle(O, A) needs no dyad or slider: the branch is "unique", any label draws A
                points = trajectory(scene, degrees, branch.label if branch.labels else "left")
                if points is None or not all(sympy.N(d.subs({c: mpmath.cos(mpmath.radians(degrees)),
                                                             s: mpmath.sin(mpmath.radians(degrees))})) > 1e-20
                                             for d in branch.discriminants.values()):
                    continue
                dx, dy = (points[end][k] - points[start][k] for k in (0, 1))
                length = mpmath.hypot(dx, dy)
                t = mpmath.radians(degrees)
                cos_phi, sin_phi = (form(mpmath.cos(t), mpmath.sin(t)) for form in forms)
                assert abs(cos_phi - dx / length) < 1e-25 and abs(sin_phi - dy / length) < 1e-25, degrees
                checked += 1
    assert checked > 0
