"""The arm-and-string scene: only what |AB| needs, and |AB| as the seed document writes it."""

import math
import random

import sympy

import algkin
from algkin.scene import compile_scene, load_scene


def test_ab_compiles_without_the_centre_of_gravity():
    compiled = compile_scene(load_scene("arm-string"), ["AB"])
    names = set(compiled.system.variables)
    assert not any(n.startswith("G") for n in names)
    assert "G" not in compiled.coordinates
    assert compiled.system.unknowns == ("AB",)


def test_ab_closed_form_is_the_seed_vector_norm():
    result = algkin.derive("arm-string", outputs=["AB"])
    (branch,) = result.branches
    expr = sympy.parse_expr(str(branch.values["AB"]))
    rng = random.Random(1)
    for _ in range(20):
        theta = rng.uniform(0, math.pi)
        # Seed: r_AB = r_OB - r_OA, r_OB = (400, -80), r_OA = 350 (sin t, -cos t).
        expected = math.hypot(400 - 350 * math.sin(theta), -80 + 350 * math.cos(theta))
        value = float(expr.subs({"c_theta": math.cos(theta), "s_theta": math.sin(theta)}))
        assert abs(value - expected) < 1e-9
    assert result.verification.passed


def test_symbolic_b_stays_a_symbol():
    result = algkin.derive("arm-string", outputs=["AB"], params=["b"])
    assert result.compiled.system.parameters == ("b",)
    assert "b" in str(result.eliminations["AB"].polynomial)
    assert result.verification.passed


def test_frame_point_g_is_on_the_arm():
    compiled = compile_scene(load_scene("arm-string"), ["G"])
    gx, gy = compiled.coordinates["G"]
    # G = (g/r) A = 120 (sin t, -cos t).
    assert sympy.simplify(gx - 120 * sympy.Symbol("s_theta", real=True)) == 0
    assert sympy.simplify(gy + 120 * sympy.Symbol("c_theta", real=True)) == 0
