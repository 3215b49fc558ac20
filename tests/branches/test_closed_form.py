"""Closed forms of random four-bars against hand geometry (law of cosines), by label."""

import math

import pytest
import sympy

from hypothesis import given, settings, strategies as st

from algkin.branches import closed_forms
from algkin.evaluate import FLOAT, evaluate
from algkin.scene import compile_scene, load_scene, load_scene_text

FOUR_BAR = """
[inputs]
t = {{ range = [0, 360] }}
[points]
O = {{ fixed = [0, 0] }}
D = {{ fixed = ["{ground}", 0] }}
A = {{ crank = "O", length = "{crank}", input = "t" }}
B = {{ dyad = ["A", "D"], lengths = ["{coupler}", "{rocker}"], branch = "left" }}
[outputs]
B = "B"
"""

lengths = st.fractions(min_value=1, max_value=20, max_denominator=16).map(str)


def by_cosines(crank, ground, coupler, rocker, theta, side):
    """B from the triangle A, B, D: angle at A by the law of cosines, turned toward `side`."""
    ax, ay = crank * math.cos(theta), crank * math.sin(theta)
    dx, dy = ground - ax, -ay
    dist = math.hypot(dx, dy)
    if dist < 1e-6:
        return None
    cos_a = (coupler**2 + dist**2 - rocker**2) / (2 * coupler * dist)
    if not -1 < cos_a < 1:
        return None
    angle = math.atan2(dy, dx) + (1 if side == "left" else -1) * math.acos(cos_a)
    return ax + coupler * math.cos(angle), ay + coupler * math.sin(angle)


@settings(max_examples=60)
@given(lengths, lengths, lengths, lengths, st.floats(0, 2 * math.pi))
def test_branches_match_the_law_of_cosines(crank, ground, coupler, rocker, theta):
    text = FOUR_BAR.format(crank=crank, ground=ground, coupler=coupler, rocker=rocker)
    compiled = compile_scene(load_scene_text(text, "four-bar.toml"))
    values = {"c_t": math.cos(theta), "s_t": math.sin(theta)}
    dims = [float(eval_fraction(v)) for v in (crank, ground, coupler, rocker)]
    for branch in closed_forms(compiled):
        expected = by_cosines(*dims, theta, branch.label)
        disc = evaluate(branch.discriminants["B"], values, FLOAT)
        if expected is None or abs(disc) < 1e-6:
            continue
        x = evaluate(branch.values["B_x"], values, FLOAT)
        y = evaluate(branch.values["B_y"], values, FLOAT)
        scale = sum(dims)
        assert abs(x - expected[0]) < 1e-7 * scale and abs(y - expected[1]) < 1e-7 * scale


def eval_fraction(text):
    from fractions import Fraction

    return Fraction(text)


def _factors(expr):
    """The sums that stand as factors (inside a product or a power), where a number belongs in front."""
    return [arg for node in sympy.preorder_traversal(expr) if isinstance(node, (sympy.Mul, sympy.Pow))
            for arg in node.args if isinstance(arg, sympy.Add)]


@pytest.mark.parametrize("scene", ["fourbar-nongrashof", "fourbar-near-toggle", "slider-crank", "fourbar"])
def test_closed_forms_keep_integer_coefficients_inside_their_factors(scene):
    # Tidy forms: 5*(23 - 16*c)*(80*c + 53)/16, not 5*(23/4 - 4*c)*(20*c + 53/4); a positive
    # number is no part of a condition (c + 5 >= 0, not 4*(c + 5) >= 0).
    compiled = compile_scene(load_scene(scene))
    for branch in closed_forms(compiled):
        for expr in [*branch.values.values(), *branch.discriminants.values()]:
            for add in _factors(expr):
                numbers = [term.as_coeff_Mul()[0] for term in add.args]
                assert all(n.is_Integer for n in numbers), (scene, add)
        assert "/" not in branch.valid_when and not branch.valid_when.startswith("(4*")


def test_branches_share_the_algebra_before_their_labels_differ(monkeypatch):
    """A six-bar's two dyads on four branches: the first dyad's algebra once, the second's once per
    label of the first (3 dyads' algebras, not 8), the modes built from them."""
    from algkin.branches.constructions import dyad

    reductions = []
    modes = dyad.DyadAlgebra.modes
    monkeypatch.setattr(dyad.DyadAlgebra, "modes",
                        lambda self, *args, **kwargs: reductions.append(1) or modes(self, *args, **kwargs))
    branches = closed_forms(compile_scene(load_scene("stephenson-iii"), ["P"]))
    assert [b.label for b in branches] == ["B:left F:left", "B:left F:right", "B:right F:left", "B:right F:right"]
    assert len(reductions) == 3
    left, right = branches[0].values, branches[1].values
    assert left["B_x"] == right["B_x"] and left["F_x"] != right["F_x"]


def test_each_dyads_modes_built_once_for_the_branches_they_are_in():
    # Stephenson III: B's two modes on the crank, F's on each of B's: three square roots in all the
    # closed forms, one per dyad algebra (B once, F once per label of B), not one per branch and point
    from algkin.branches.tower import roots_in

    branches = closed_forms(compile_scene(load_scene("stephenson-iii"), ["P"]))
    assert len(branches) == 4 and len(roots_in([v for b in branches for v in b.values.values()])) == 3


def _meet(p, q, l1, l2, side):
    """The point at ``l1`` from ``p`` and ``l2`` from ``q``, on ``side`` of p -> q (mpmath), None where none."""
    import mpmath

    dx, dy = q[0] - p[0], q[1] - p[1]
    d2 = dx * dx + dy * dy
    along = (l1 * l1 - l2 * l2 + d2) / (2 * d2)
    h2 = l1 * l1 / d2 - along * along
    if h2 < 0:
        return None
    across = mpmath.sqrt(h2) * (1 if side == "left" else -1)
    return p[0] + along * dx - across * dy, p[1] + along * dy + across * dx


def test_a_direction_on_points_with_nested_roots_is_the_geometrys():
    """Hart's inversor's direction of Q from O, its closed forms made in a tower (sympy's expansion of
    the whole took seconds, 125,000 characters a form), against mpmath from the scene's geometry:
    A = 2 (cos, sin), B = -A, D at 2 from A and from W = (2, 0) - A on D's side, C at 2 from B and 4
    from D on C's side, Q = (B + C)/2; cos, sin = Q / |Q|."""
    import mpmath

    from algkin import derive

    mpmath.mp.dps = 40
    derived = derive("hart-inversor", outputs=["angle(O, Q)"], samples=0)  # checked here, not by its own sampling
    compared = 0
    symbols = [sympy.Symbol("c_angle", real=True), sympy.Symbol("s_angle", real=True)]
    for branch in derived.branches:
        sides = dict(part.split(":") for part in branch.label.split())
        forms = {name: sympy.lambdify(symbols, sympy.sympify(branch.values[name]), "mpmath")
                 for name in ("cos_angle_O_Q", "sin_angle_O_Q")}
        for degrees in (10, 40, 70, 290, 310, 350):
            theta = mpmath.radians(degrees)
            a = (2 * mpmath.cos(theta), 2 * mpmath.sin(theta))
            b = (-a[0], -a[1])
            d = _meet(a, (2 - a[0], -a[1]), 2, 2, sides["D"])
            c = None if d is None else _meet(b, d, 2, 4, sides["C"])
            if c is None:
                continue
            q = ((b[0] + c[0]) / 2, (b[1] + c[1]) / 2)
            length = mpmath.hypot(*q)
            for name, expected in (("cos_angle_O_Q", q[0] / length), ("sin_angle_O_Q", q[1] / length)):
                value = forms[name](mpmath.cos(theta), mpmath.sin(theta))
                assert abs(complex(value) - float(expected)) < 1e-12, (branch.label, degrees, name)
                compared += 1
    assert compared >= 24  # each branch where it assembles
