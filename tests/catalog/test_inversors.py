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

from .geometry import ROOT, at_angle, circles, on_circle, rigid, run

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


# -- Hart's crossed mode, named by a configuration and followed across its change point ---------
# By hand (a=4, b=2, r=1): D exists while |A - Z| <= 2, i.e. cos(angle) >= 1/4; at angle 0, A = (2, 0),
# B = (-2, 0), D = (1, -sqrt(3)) (left of A -> W, W = 2Z - A = O) and C is (-1, sqrt(3)) crossed (Q.x =
# -3/2) or B + D - A = (-3, -sqrt(3)) for the parallelogram. At 300 deg D = O and C = 2B: the flat
# configuration where the two modes cross (tan(300/2)**2 = 1/3).
HART_ENDS = (float(mpmath.degrees(mpmath.acos(mpmath.mpf(1) / 4))), 360 - float(mpmath.degrees(mpmath.acos(0.25))))


def hart_scene(tmp_path, c_line):
    text = (ROOT / "algkin" / "catalog" / "hart-inversor.toml").read_text()
    lines = [c_line if line.startswith("C =") else line for line in text.splitlines()]
    path = tmp_path / "hart.toml"
    path.write_text("\n".join(lines) + "\n")
    return str(path)


def named_pieces(document):
    """(from, to, branch) of the named mode's pieces, the branch as derive labels it there."""
    (mode,) = document["modes"]
    return [(p["from_deg"], p["to_deg"], p["branch"]) for p in mode["pieces"] if p["status"] == "mode"]


def on_mode(pieces, theta):
    """The branch label of the piece holding ``theta`` strictly inside, or None."""
    return next((label for lo, hi, label in pieces if lo < theta < hi), None)


@pytest.fixture(scope="module")
def hart_derived():
    return run("derive", "hart-inversor", "--outputs", "Q", "C", "--samples", "0")


def test_hart_named_mode_changes_label_at_the_flat_configuration(hart_derived):
    (mode,) = hart_derived["modes"]
    assert [(round(lo, 9), round(hi, 9), b) for lo, hi, b in named_pieces(hart_derived)] == [
        (0, round(HART_ENDS[0], 9), "D:left C:left"), (round(HART_ENDS[1], 9), 300, "D:left C:right"),
        (300, 360, "D:left C:left")]
    (change,) = mode["change_points"]
    assert (change["input_deg"], change["from"], change["to"]) == (300.0, "right", "left")
    t = sympy.Symbol("t_angle")
    assert sympy.parse_expr(change["polynomial"]).subs(t, sympy.tan(sympy.pi * 150 / 180)).equals(0)


def test_hart_named_crossed_mode_keeps_q_on_its_line_across_the_change_point(hart_derived):
    pieces = named_pieces(hart_derived)
    values = {b["label"]: b["values"] for b in hart_derived["branches"]}
    sampled = 0
    with mpmath.workdps(45):  # 128+ bits
        for theta in [284.5 + k / 2 for k in range(152)] + [k / 2 for k in range(152)]:
            label = on_mode(pieces, theta % 360)
            if label is None:
                continue
            sampled += 1
            q_x = at_angle(values[label]["Q_x"], theta % 360, "angle", digits=45)
            assert abs(q_x + mpmath.mpf(3) / 2) < 1e-30, (theta, label, q_x)
    assert sampled >= 2 * 150  # every half degree where the mode exists: 284.5-360 and 0-75.5


def test_the_old_left_scene_leaves_the_line_between_the_toggle_and_the_fold(tmp_path):
    # the failure this fixes: `branch = "left"` is the parallelogram mode over (284.48, 300)
    path = hart_scene(tmp_path, 'C = { dyad = ["B", "D"], lengths = ["b", "a"], branch = "left" }')
    document = run("derive", path, "--outputs", "Q", "--samples", "0")
    chosen = next(b for b in document["branches"] if b["selected"])
    assert "modes" not in document
    assert abs(at_angle(chosen["values"]["Q_x"], 290, "angle") + mpmath.mpf(3) / 2) > 0.1


def test_the_parallelogram_named_takes_q_off_the_line(tmp_path):
    path = hart_scene(tmp_path, 'C = { dyad = ["B", "D"], lengths = ["b", "a"], mode = { at = 0, near = [-3, -1.7] } }')
    document = run("derive", path, "--outputs", "Q", "C", "--samples", "0")
    pieces = named_pieces(document)
    values = {b["label"]: b["values"] for b in document["branches"]}
    with mpmath.workdps(40):
        for theta in (290, 299, 301, 330, 1, 40, 70):
            label = on_mode(pieces, theta)
            a_, b_, _, d_, _, _ = hart(theta)
            c_ = (b_[0] + d_[0] - a_[0], b_[1] + d_[1] - a_[1])  # the parallelogram ABCD
            got = [at_angle(values[label][u], theta, "angle") for u in ("C_x", "C_y", "Q_x")]
            assert abs(got[0] - c_[0]) < 1e-30 and abs(got[1] - c_[1]) < 1e-30, theta
            assert abs(got[2] + mpmath.mpf(3) / 2) > 1e-3, theta


def test_the_curve_of_q_on_the_named_mode_is_the_line_alone():
    document = run("curve", "hart-inversor", "--point", "Q")
    assert sympy.parse_expr(document["curve"]) in (2 * Q_x + 3, -(2 * Q_x + 3))
    (sextic,) = document["other_modes_dropped"]
    assert sympy.Poly(sympy.parse_expr(sextic), Q_x, Q_y).total_degree() == 6
    assert sextic in document["dropped_factors"] and document["verification"]["passed"]


@pytest.mark.parametrize("c_line, said", [
    ('C = { dyad = ["B", "D"], lengths = ["b", "a"], mode = { at = 0, near = [-2, 0] } }',
     "points.C.mode.near: [-2, 0] is not close to a configuration of C at angle = 0°: the nearest is [-1, 1.73205]"),
    ('C = { dyad = ["B", "D"], lengths = ["b", "a"], branch = "left", mode = { at = 0, near = [-1, 1.7] } }',
     "points.C.mode: give branch or mode, not both"),
    ('C = { dyad = ["B", "D"], lengths = ["b", "a"], mode = { at = 180, near = [-1, 1.7] } }',
     "points.C.mode.at: C does not assemble at angle = 180°"),
    ('C = { dyad = ["B", "D"], lengths = ["b", "a"], mode = { at = 400, near = [-1, 1.7] } }',
     "points.C.mode.at.angle: 400 is outside the input's range [0, 360]"),
    ('C = { dyad = ["B", "D"], lengths = ["b", "a"], mode = { at = 0 } }', "points.C.mode.near: missing"),
])
def test_a_bad_mode_is_refused_in_one_line(tmp_path, capsys, c_line, said):
    assert main(["derive", hart_scene(tmp_path, c_line), "--samples", "0"]) == 2
    error = capsys.readouterr().err.strip()
    assert len(error.splitlines()) == 1 and said in error, error
