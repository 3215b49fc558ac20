"""Geared inputs and crank phases off the quarter turns, against mpmath's cos and sin of the angles.

The reference angles are computed from the definitions (``k*t + phase`` with the phase from
atan2 of its cos and sin, or twice the arctangent of its half-angle tangent), never from the
polynomials algkin writes.
"""

import mpmath
import pytest
import sympy

import algkin
from algkin.scene import dump_scene, load_scene_text
from algkin.scene.driven import multiple_angle

SAMPLES = [-170, -47.5, 0, 13, 88, 123.25, 271]


@pytest.mark.parametrize("k", [-3, -2, -1, 1, 2, 3, 7])
def test_multiple_angle_is_cos_and_sin_of_k_t(k):
    c, s = sympy.symbols("c s")
    cos, sin = (sympy.lambdify((c, s), e, "mpmath") for e in multiple_angle(k, c, s))
    with mpmath.workdps(50):
        for degrees in SAMPLES:
            t = mpmath.radians(degrees)
            assert abs(cos(mpmath.cos(t), mpmath.sin(t)) - mpmath.cos(k * t)) < mpmath.mpf(10) ** -45
            assert abs(sin(mpmath.cos(t), mpmath.sin(t)) - mpmath.sin(k * t)) < mpmath.mpf(10) ** -45


GEARED = '''
[inputs]
t = { range = [0, 360], unit = "deg" }
g = { driven_by = "t", ratio = "-2" }
h = { driven_by = "g", ratio = "3" }

[points]
O = { fixed = [0, 0] }
Q = { fixed = [5, 1] }
A = { crank = "O", length = 2, input = "g", phase = { cos = "3/5", sin = "4/5" } }
B = { crank = "Q", length = "3/2", input = "h", phase = { tan_half = "1/3" } }
C = { crank = "Q", length = 1, input = "t", phase = 180 }

[outputs]
A = "A"
B = "B"
C = "C"
'''


def _crank(center, length, angle):
    return center[0] + length * mpmath.cos(angle), center[1] + length * mpmath.sin(angle)


def test_cranks_on_geared_inputs_turn_by_their_ratios_and_phases():
    result = algkin.derive(load_scene_text(GEARED, "geared.toml"))
    assert list(result.to_json()["inputs"]) == ["t"]  # the geared inputs bring no variables of their own
    (branch,) = result.branches
    forms = {u: sympy.lambdify(sympy.symbols("c_t s_t"), v, "mpmath") for u, v in branch.values.items()}
    with mpmath.workdps(50):
        phase_a = mpmath.atan2(mpmath.mpf(4) / 5, mpmath.mpf(3) / 5)
        phase_b = 2 * mpmath.atan(mpmath.mpf(1) / 3)
        for degrees in SAMPLES:
            t = mpmath.radians(degrees)
            expected = {"A": _crank((0, 0), 2, -2 * t + phase_a), "B": _crank((5, 1), mpmath.mpf(3) / 2, -6 * t + phase_b),
                        "C": _crank((5, 1), 1, t + mpmath.pi)}
            for point, (x, y) in expected.items():
                got = [forms[f"{point}_{axis}"](mpmath.cos(t), mpmath.sin(t)) for axis in "xy"]
                assert abs(got[0] - x) < mpmath.mpf(10) ** -45 and abs(got[1] - y) < mpmath.mpf(10) ** -45, point


def test_geared_scene_and_its_phases_dump_and_load_back():
    scene = load_scene_text(GEARED, "geared.toml")
    text = dump_scene(scene)
    assert 'g = { driven_by = "t", ratio = "-2" }' in text
    assert 'phase = { cos = "3/5", sin = "4/5" }' in text
    assert load_scene_text(text, "geared.toml") == scene


def test_a_phase_of_parameters_stays_symbolic():
    # cos and sin of the phase as parameters (a symbolic angle): kept with --param, the closed
    # form holds for every point (cp, sp) of the unit circle
    text = GEARED.replace('[inputs]', '[parameters]\ncp = "3/5"\nsp = "4/5"\n\n[inputs]').replace(
        'phase = { cos = "3/5", sin = "4/5" }', 'phase = { cos = "cp", sin = "sp" }')
    result = algkin.derive(load_scene_text(text, "symbolic.toml"), outputs=["A"], params=["cp", "sp"])
    x = result.branches[0].values["A_x"]
    # at the phase (5/13, 12/13) and t = 30 deg: 2 cos(-60 deg + atan2(12, 5))
    at = {"cp": sympy.Rational(5, 13), "sp": sympy.Rational(12, 13), "c_t": sympy.sqrt(3) / 2, "s_t": sympy.Rational(1, 2)}
    value = x.xreplace({v: at[v.name] for v in x.free_symbols})
    with mpmath.workdps(40):
        assert abs(sympy.N(value, 40) - 2 * mpmath.cos(mpmath.radians(-60) + mpmath.atan2(12, 5))) < 1e-35
