"""Inversors: two points from the same pair of circles kept apart, checked against hand geometry.

Peaucellier-Lipkin: B and D are the two intersections of the circles of radius L about O and
s about A, and P the second intersection (after A) of the circles of radius s about B and D.
By hand, P is the inverse of A in the circle about O of power L**2 - s**2 (|OA| |OP| = L**2 - s**2,
P on the ray OA); A runs on the circle of radius r through O, so P runs on the straight line
x = (L**2 - s**2) / (2 r). Hart's inversor (a crossed four-bar ABCD pivoted at the midpoint O of
AB): the midpoints P of AD and Q of BC stay collinear with O, on a line parallel to the
diagonals, with OP OQ = -(a**2 - b**2) / 4, so Q runs on x = -(a**2 - b**2) / (8 r).
"""

import mpmath
import pytest
import sympy

from algkin.ui.cli import main

from .geometry import at_angle, circles, on_circle, rigid, run

P_x, P_y, Q_x, Q_y, L, s, r, a, b = sympy.symbols("P_x P_y Q_x Q_y L s r a b")


def peaucellier(theta, r=1, L=3, s=2):
    """The cell by the law of cosines: B left of O -> A, D right of it, P across BD from A."""
    a_ = on_circle((r, 0), r, theta)
    b_, d_ = (circles((0, 0), L, a_, s, side) for side in (1, -1))
    return a_, b_, d_, (b_[0] + d_[0] - a_[0], b_[1] + d_[1] - a_[1])  # the rhombus ABPD closed


def hart(theta, a=4, b=2, r=1):
    """The crossed four-bar by hand: D from DA = b and the midpoint of AD on the circle about (r, 0)."""
    a_, b_ = on_circle((0, 0), mpmath.mpf(a) / 2, theta), on_circle((0, 0), mpmath.mpf(a) / 2, theta + 180)
    d_ = circles(a_, b, (2 * r - a_[0], -a_[1]), 2 * r, 1)
    c_ = circles(b_, b, d_, a, 1)
    return a_, b_, c_, d_, rigid(a_, d_, mpmath.mpf(1) / 2, 0), rigid(b_, c_, mpmath.mpf(1) / 2, 0)


def test_peaucellier_traces_the_straight_line_of_its_dimensions():
    document = run("curve", "peaucellier-lipkin", "--point", "P", "--param", "L", "--param", "s", "--param", "r")
    assert sympy.simplify(sympy.parse_expr(document["curve"]) / (2 * r * P_x - (L**2 - s**2))).is_number
    assert document["verification"]["passed"]


@pytest.mark.parametrize("theta", [-100, -45, 0, 30, 75, 115])
def test_peaucellier_point_is_the_inverse_of_the_crank_point(theta):
    document = run("derive", "peaucellier-lipkin", "--outputs", "P", "B", "D", "--samples", "0")
    chosen = next(b for b in document["branches"] if b["selected"])
    with mpmath.workdps(40):
        a_, b_, d_, p_ = peaucellier(theta)
        got = {u: at_angle(v, theta, "angle") for u, v in chosen["values"].items()}
        assert abs(got["P_x"] - p_[0]) < 1e-30 and abs(got["P_y"] - p_[1]) < 1e-30
        assert abs(got["B_x"] - b_[0]) < 1e-30 and abs(got["D_y"] - d_[1]) < 1e-30
        # the inversion, from A alone: |OA| |OP| = L**2 - s**2 = 5, and P on the ray OA
        assert abs(mpmath.hypot(*a_) * mpmath.hypot(got["P_x"], got["P_y"]) - 5) < 1e-30
        assert abs(a_[0] * got["P_y"] - a_[1] * got["P_x"]) < 1e-30


def test_hart_crossed_four_bar_traces_its_line():
    document = run("curve", "hart-inversor", "--point", "Q", "--param", "a", "--param", "b", "--param", "r")
    factors = sympy.factor_list(sympy.parse_expr(document["curve"]))[1]
    assert any(sympy.simplify(f / (8 * r * Q_x + a**2 - b**2)).is_number for f, _ in factors)
    assert document["verification"]["passed"]


@pytest.mark.parametrize("theta", [5, 20, 45, 70])
def test_hart_midpoints_stay_collinear_with_a_constant_product(theta):
    document = run("derive", "hart-inversor", "--outputs", "P", "Q", "C", "--samples", "0")
    chosen = next(b for b in document["branches"] if b["selected"])
    with mpmath.workdps(40):
        a_, b_, c_, d_, p_, q_ = hart(theta)
        got = {u: at_angle(v, theta, "angle") for u, v in chosen["values"].items()}
        assert abs(got["Q_x"] - q_[0]) < 1e-30 and abs(got["Q_y"] - q_[1]) < 1e-30
        assert abs(got["Q_x"] + mpmath.mpf(3) / 2) < 1e-30  # the line x = -(16 - 4) / 8
        assert abs(p_[0] * got["Q_y"] - p_[1] * got["Q_x"]) < 1e-30  # O, P, Q collinear...
        assert abs(p_[0] * got["Q_x"] + p_[1] * got["Q_y"] + 3) < 1e-30  # ...O between them, OP OQ = 3
        # crossed: the diagonals AC and BD are parallel
        assert abs((c_[0] - a_[0]) * (d_[1] - b_[1]) - (c_[1] - a_[1]) * (d_[0] - b_[0])) < 1e-30


@pytest.mark.parametrize("scene", ["peaucellier-lipkin", "hart-inversor"])
@pytest.mark.parametrize("command", [["verify"], ["toggles"], ["derive"]])
def test_every_command_runs_on_the_inversors(scene, command):
    document = run(*command, scene)
    if command != ["toggles"]:
        verification = document.get("verification", document)
        assert verification["passed"] and verification["compared"] > 0


@pytest.mark.parametrize("scene", ["peaucellier-lipkin", "hart-inversor"])
def test_the_inversors_draw(scene, tmp_path):
    out = tmp_path / f"{scene}.png"
    assert main(["plot", scene, "--out", str(out)]) == 0 and out.stat().st_size > 1000


CELL = """
name = "cell"
[inputs]
angle = {{ range = [-120, 120], unit = "deg" }}
[points]
O = {{ fixed = [0, 0] }}
Q = {{ fixed = [1, 0] }}
A = {{ crank = "Q", length = 1, input = "angle" }}
B = {{ dyad = ["O", "A"], lengths = [3, 2], branch = "left" }}
D = {{ dyad = {d_bases}, lengths = {d_lengths}, branch = "{d_branch}" }}
P = {{ dyad = ["B", "D"], lengths = [2, 2], branch = "{p_branch}" }}
{extra}
[outputs]
P = "P"
"""


def cell(tmp_path, d_bases='["O", "A"]', d_lengths="[3, 2]", d_branch="right", p_branch="left", extra=""):
    path = tmp_path / "cell.toml"
    path.write_text(CELL.format(d_bases=d_bases, d_lengths=d_lengths, d_branch=d_branch, p_branch=p_branch,
                                extra=extra))
    return str(path)


def test_the_twin_on_reversed_bases_is_the_same_cell(tmp_path):
    # left of A -> O is right of O -> A: the same D
    document = run("curve", cell(tmp_path, '["A", "O"]', "[2, 3]", "left"), "--point", "P")
    assert sympy.parse_expr(document["curve"]) * 1 in (2 * P_x - 5, -(2 * P_x - 5))


@pytest.mark.parametrize("change, said", [
    (dict(d_branch="left"), "points.D: the left intersection of its circles is B itself"),
    (dict(p_branch="right"), "points.P: the right intersection of its circles is A itself"),
    (dict(extra='E = { dyad = ["O", "A"], lengths = [3, 2], branch = "left" }\n'),
     "points.E: its two circles meet only at B and D, both built already"),
])
def test_a_point_named_where_its_twin_is_is_bad_input(tmp_path, capsys, change, said):
    path = cell(tmp_path, **change)
    outputs = ["--outputs", "P", "E"] if "extra" in change else []  # only the points the outputs need are built
    assert main(["derive", path, *outputs]) == 2
    error = capsys.readouterr().err.strip()
    assert len(error.splitlines()) == 1 and said in error, error
