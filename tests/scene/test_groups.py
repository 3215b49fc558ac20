"""Points solved together: the ``unknown = true`` points and ``[constraints]`` table (SPEC section 2,
"Loops solved together, and modes"), loaded, written back, and cut into groups."""

import pytest
import sympy

from algkin.errors import SceneError, UsageError
from algkin.scene import compile_scene, dump_scene, load_scene, load_scene_text
from algkin.scene.groups import compile_groups

# The SPEC's example, as written there.
SPEC_3RPR = '''
name = "3rpr"
description = "3-RPR parallel manipulator: a rigid triangle on three legs."

[inputs]
r1 = { range = [5, 12], unit = "length" }      # the leg A1P1, driven

[parameters]
r2 = 9
r3 = 8

[points]
A1 = { fixed = [0, 0] }
A2 = { fixed = [10, 0] }
A3 = { fixed = [3, 8] }
P1 = { unknown = true }
P2 = { unknown = true }
P3 = { frame = ["P1", "P2"], at = ["1/2", "3/4"] }   # rigid with the platform side P1P2

[constraints]
leg1 = "dist(A1, P1) = r1"
leg2 = "dist(A2, P2) = r2"
leg3 = "dist(A3, P3) = r3"
side = "dist(P1, P2) = 5"

[outputs]
P1 = "P1"
'''


def _scene(points, constraints, extra=""):
    return load_scene_text(f"{extra}\n[points]\n{points}\n[constraints]\n{constraints}\n", "s.toml")


def test_the_spec_example_loads_and_is_one_group_of_four_equations():
    scene = load_scene_text(SPEC_3RPR, "3rpr.toml")
    assert scene.unknown_points == ("P1", "P2")
    assert load_scene_text(dump_scene(scene)) == scene
    (group,) = compile_groups(scene).groups
    assert group.points == ("P1", "P2") and group.unknowns == ("P1_x", "P1_y", "P2_x", "P2_y")
    assert group.constraints == ("leg1", "leg2", "leg3", "side")
    x1, y1, x2, y2, r1 = sympy.symbols("P1_x P1_y P2_x P2_y r1", real=True)
    # P3 = P1 + (P2 - P1)/2 + 3/4 rot90(P2 - P1), at distance 8 from (3, 8), by hand
    p3 = (x1 + (x2 - x1) / 2 - sympy.Rational(3, 4) * (y2 - y1), y1 + (y2 - y1) / 2 + sympy.Rational(3, 4) * (x2 - x1))
    expected = [x1**2 + y1**2 - r1**2, (x2 - 10)**2 + y2**2 - 81, (p3[0] - 3)**2 + (p3[1] - 8)**2 - 64,
                (x1 - x2)**2 + (y1 - y2)**2 - 25]
    assert [sympy.expand(e - f) for e, f in zip(group.equations, expected)] == [0] * 4


def test_a_squared_length_and_a_point_on_a_line():
    scene = _scene('A = { fixed = [0, 0] }\nB = { fixed = [4, 0] }\nP = { unknown = true }',
                   'a = "dist(A, P)**2 = 10"\nb = "on(P, line(A, B))"')
    (group,) = compile_groups(scene).groups
    x, y = sympy.symbols("P_x P_y", real=True)
    assert list(group.equations) == [x**2 + y**2 - 10, 4 * y]
    assert load_scene_text(dump_scene(scene)) == scene


def test_groups_come_in_dependency_order_and_a_cycle_is_one_group():
    """Q hangs on P (a dyad-like pair of constraints); R and S hold each other (a cycle)."""
    scene = _scene('A = { fixed = [0, 0] }\nB = { fixed = [4, 0] }\nQ = { unknown = true }\n'
                   'P = { unknown = true }\nR = { unknown = true }\nS = { unknown = true }',
                   'q1 = "dist(P, Q) = 1"\nq2 = "dist(B, Q) = 2"\np1 = "dist(A, P) = 3"\np2 = "dist(B, P) = 3"\n'
                   'r1 = "dist(A, R) = 2"\nr2 = "dist(R, S) = 2"\ns1 = "dist(B, S) = 2"\ns2 = "on(S, line(A, R))"')
    groups = compile_groups(scene).groups
    assert [set(g.points) for g in groups][:1] == [{"P"}]
    assert {g.points[0]: i for i, g in enumerate(groups)}["P"] < {g.points[0]: i for i, g in enumerate(groups)}["Q"]
    assert sorted(sorted(g.points) for g in groups) == [["P"], ["Q"], ["R", "S"]]


@pytest.mark.parametrize(("points", "constraints", "said"), [
    ('A = { fixed = [0, 0] }\nP = { unknown = true }', 'a = "dist(A, P) = 1"',
     "constraints: the group of P has fewer equations than unknowns: 1 (a) for 2 (P_x, P_y)"),
    ('A = { fixed = [0, 0] }\nB = { fixed = [1, 0] }\nC = { fixed = [0, 1] }\nP = { unknown = true }',
     'a = "dist(A, P) = 1"\nb = "dist(B, P) = 1"\nc = "dist(C, P) = 1"',
     "constraints: the group of P has more equations than unknowns: 3 (a, b, c) for 2 (P_x, P_y)"),
    ('A = { fixed = [0, 0] }\nP = { unknown = true }\nQ = { unknown = true }',
     'a = "dist(A, P) = 1"\nb = "on(P, line(A, Q))"\nc = "dist(P, Q) = 1"',
     "the group of P, Q has fewer equations than unknowns: 3 (a, b, c) for 4"),
])
def test_a_group_whose_counts_differ_names_its_points_and_the_counts(points, constraints, said):
    with pytest.raises(SceneError) as caught:
        compile_groups(_scene(points, constraints))
    assert said in str(caught.value) and "\n" not in str(caught.value)


@pytest.mark.parametrize(("points", "constraints", "said"), [
    ('P = { unknown = false }', '', "points.P.unknown: expected true"),
    ('A = { fixed = [0, 0] }\nP = { unknown = true }', 'a = "dist(A, P) ="', "constraints.a: expected dist(P, Q) = L"),
    ('A = { fixed = [0, 0] }\nP = { unknown = true }', 'a = "dist(A, Z) = 1"', "constraints.a: unknown point 'Z'"),
    ('A = { fixed = [0, 0] }\nP = { unknown = true }', 'a = "dist(A, P) = -1"', "constraints.a: the length must be positive"),
    ('A = { fixed = [0, 0] }\nP = { unknown = true }', 'a = "dist(A, P) = q"', "constraints.a: unknown name 'q'"),
    ('A = { fixed = [0, 0] }\nB = { fixed = [1, 0] }\nP = { unknown = true }', 'a = "dist(A, B) = 1"',
     "constraints.a: holds no point solved together"),
    ('A = { fixed = [0, 0] }\nP = { unknown = true }', 'a = "on(P, line(A, A))"', "constraints.a: line(A, A) has no direction"),
    ('A = { fixed = [0, 0] }\nP = { unknown = true }', 'a = 3', "constraints.a: expected a string"),
])
def test_bad_constraints_are_one_line_naming_the_element(points, constraints, said):
    with pytest.raises(SceneError) as caught:
        _scene(points, constraints)
    assert said in str(caught.value)


def test_a_dyad_beside_points_solved_together_is_a_group_of_its_own_in_order():
    """D is built by a dyad on the fixed A, B: its two circles, a group before P's (P hangs on D);
    E is a dyad on P: a group after it. Their equations are the circles, by hand."""
    scene = _scene('A = { fixed = [0, 0] }\nB = { fixed = [4, 0] }\nP = { unknown = true }\n'
                   'D = { dyad = ["A", "B"], lengths = [3, 3] }\nE = { dyad = ["P", "B"], lengths = [2, 5] }',
                   'a = "dist(A, P) = 3"\nb = "dist(D, P) = 3"')
    compiled = compile_groups(scene)
    assert [(g.points, g.constraints) for g in compiled.groups] == [(("D",), ("D.1", "D.2")), (("P",), ("a", "b")),
                                                                     (("E",), ("E.1", "E.2"))]
    dx, dy, px, py, ex, ey = sympy.symbols("D_x D_y P_x P_y E_x E_y", real=True)
    assert [sympy.expand(e) for e in compiled.groups[0].equations] == [sympy.expand(dx**2 + dy**2 - 9),
                                                                       sympy.expand((dx - 4)**2 + dy**2 - 9)]
    assert [sympy.expand(e) for e in compiled.groups[2].equations] == [
        sympy.expand((ex - px)**2 + (ey - py)**2 - 4), sympy.expand((ex - 4)**2 + ey**2 - 25)]
    # left of P -> B: cross(B - P, E - P) > 0, as the dyad's branch says it
    assert sympy.expand(compiled.sides["E"].expr - ((4 - px) * (ey - py) - (0 - py) * (ex - px))) == 0
    assert (compiled.sides["E"].positive, compiled.sides["E"].negative) == ("left", "right")


def test_a_cycle_through_a_dyad_is_one_group_not_refused():
    """D is a dyad on P and Q, and P, Q (three equations for four unknowns) are held through D:
    they depend on each other, so the three points are one group (a triad), merged, not refused."""
    scene = _scene('A = { fixed = [0, 0] }\nB = { fixed = [4, 0] }\nC = { fixed = [2, 5] }\nP = { unknown = true }\n'
                   'Q = { unknown = true }\nD = { dyad = ["P", "Q"], lengths = [3, 3] }',
                   'a = "dist(A, P) = 2"\nb = "dist(B, Q) = 2"\nd = "dist(P, Q) = 3"\nc = "dist(D, C) = 1"')
    (group,) = compile_groups(scene).groups
    assert set(group.points) == {"P", "Q", "D"} and set(group.constraints) == {"a", "b", "c", "d", "D.1", "D.2"}


def test_a_group_after_a_dyad_with_too_few_equations_is_named_with_its_counts():
    scene = _scene('A = { fixed = [0, 0] }\nB = { fixed = [4, 0] }\nP = { unknown = true }\n'
                   'D = { dyad = ["A", "B"], lengths = [3, 3] }', 'a = "dist(D, P) = 3"')
    with pytest.raises(SceneError) as caught:
        compile_groups(scene)
    said = "constraints: the group of P has fewer equations than unknowns: 1 (a) for 2 (P_x, P_y)"
    assert said in str(caught.value) and "\n" not in str(caught.value)


def test_compile_scene_refuses_them_naming_the_command_that_takes_them():
    said = ("has points solved together \\(P1, P2\\): show, solve, follow, derive, curve, verify, toggles, plot, export, "
            "sweep and accuracy take it, and in Python derive, curve, solve, follow, rates and load_quantities; "
            "extremum and singular do not yet, nor prepare and compile_scene")
    with pytest.raises(UsageError, match=said):
        compile_scene(load_scene_text(SPEC_3RPR, "3rpr.toml"))


@pytest.mark.parametrize(("change", "said"), [
    (("r2 = 9", 'r2 = "1e200"'), "parameters.r2: 1.00E+200 is outside the magnitudes 1e-100 to 1e100"),
    (("r2 = 9", 'r2 = "1e-200"'), "parameters.r2: 1.00E-200 is outside the magnitudes"),
    (("r2 = 9", "r2 = -9"), "constraints.leg2: length must be positive, got -9"),
    (('side = "dist(P1, P2) = 5"', 'side = "dist(P1, P2)**2 = r3 - 8"'),
     "constraints.side: length must be positive, got 0"),
    (('"dist(A1, P1) = r1"', '"dist(A1, P1) = r1 - 6"'),
     "constraints.leg1: length must be positive, got r1 - 6 = -1 at an end of its input's range"),
    (('at = ["1/2", "3/4"]', 'at = ["1e150", "3/4"]'), "points.P3: 1.00E+150 is outside the magnitudes"),
    # an internal TypeError ("not a polynomial: sqrt(2)") in derive and solve
    (('side = "dist(P1, P2) = 5"', 'side = "dist(P1, P2)**2 = sqrt(2)"'), "constraints.side: sqrt(2) makes its equation"),
    (('side = "dist(P1, P2) = 5"', 'side = "dist(P1, P2) = 1 + sqrt(2)"'), "constraints.side: sqrt(2) makes its equation"),
    (("r2 = 9", 'r2 = "1 + sqrt(2)"'), "parameters.r2: 1 + sqrt(2) is not rational"),
])
def test_values_the_dyads_refuse_are_refused_in_a_group_too(change, said):
    """A chain's checks of its values, for a scene of points solved together: the SPEC's 3-RPR
    with one value made bad. ``derive`` failed with an internal OverflowError on a leg of 1e200, and
    a leg of -9 was taken as 9 (squared); a literal -9 was already refused."""
    with pytest.raises(SceneError) as caught:
        compile_groups(load_scene_text(SPEC_3RPR.replace(*change), "3rpr.toml"))
    assert said in str(caught.value) and "\n" not in str(caught.value)


def test_a_group_scene_of_ordinary_values_is_still_taken():
    """The checks refuse by value, not by form: the catalog's groups and the SPEC's example compile."""
    for name in ("3rpr", "3rpr-six-modes", "stephenson-iii-triad", "eightbar-triad-dyad", "fourbar-instant-centre"):
        assert compile_groups(load_scene(name)).groups
    assert compile_groups(load_scene_text(SPEC_3RPR.replace("r2 = 9", 'r2 = "1e-50"'), "3rpr.toml")).groups
    root = SPEC_3RPR.replace('side = "dist(P1, P2) = 5"', 'side = "dist(P1, P2) = sqrt(26)"')  # squared: 26
    assert compile_groups(load_scene_text(root, "3rpr.toml")).groups[0].equations[3].is_polynomial()


def test_a_line_through_two_points_at_one_place_says_so():
    """``on(P, line(A, B))`` with A and B at one place (B's coordinates parameters whose defaults put
    it on A) holds for every P: it was "the group of no point has more equations than unknowns:
    1 (c) for 0 ()", which names neither the constraint nor what is wrong."""
    scene = _scene('A = { fixed = [0, 0] }\nB = { fixed = ["u", "u"] }\nC = { fixed = [3, 0] }\nP = { unknown = true }',
                   'a = "dist(A, P) = 1"\nb = "dist(C, P) = 3"\nc = "on(P, line(A, B))"', extra="[parameters]\nu = 0")
    with pytest.raises(SceneError) as caught:
        compile_groups(scene)
    said = str(caught.value)
    assert "constraints.c: line(A, B) has no direction: A and B are at one place" in said and "\n" not in said
