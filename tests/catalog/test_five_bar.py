"""The five-bar with two inputs: its end point against hand geometry at both cranks' angles."""

import os
import subprocess
import sys

import mpmath
import sympy

from .geometry import ROOT, branch, circles, on_circle, run, same


def test_end_point_with_both_cranks_up_exactly():
    # t1 = t2 = 90 deg: A1 = (0, 2), A2 = (2, 2); P is the apex of the isosceles triangle with
    # base 2 and sides 3: P = (1, 2 + sqrt(9 - 1)) = (1, 2 + 2*sqrt(2)).
    document = run("derive", "five-bar", "--samples", "12")
    assert document["inputs"] == {"t1": {"cos": "c_t1", "sin": "s_t1"}, "t2": {"cos": "c_t2", "sin": "s_t2"}}
    assert document["verification"]["passed"] and document["verification"]["compared"] > 0
    values = branch(document, "left")["values"]
    at = {sympy.Symbol(n): v for n, v in (("c_t1", 0), ("s_t1", 1), ("c_t2", 0), ("s_t2", 1))}
    assert same(sympy.parse_expr(values["P_x"]).subs(at), 1)
    assert same(sympy.parse_expr(values["P_y"]).subs(at), 2 + 2 * sympy.sqrt(2))


def test_end_point_over_both_inputs():
    document = run("derive", "five-bar", "--samples", "0")
    mpmath.mp.dps = 40
    for label, side in (("left", 1), ("right", -1)):
        expr = {k: sympy.parse_expr(v) for k, v in branch(document, label)["values"].items()}
        for t1 in range(0, 181, 30):
            for t2 in range(0, 181, 30):
                a1, a2 = on_circle((0, 0), 2, t1), on_circle((2, 0), 2, t2)
                if mpmath.hypot(a2[0] - a1[0], a2[1] - a1[1]) < 1e-9:
                    continue  # A1 = A2 (t1 = 60, t2 = 120): no base line, no side
                p = circles(a1, 3, a2, 3, side)
                if p is None:
                    continue
                at = {sympy.Symbol("c_t1"): a1[0] / 2, sympy.Symbol("s_t1"): a1[1] / 2,
                      sympy.Symbol("c_t2"): (a2[0] - 2) / 2, sympy.Symbol("s_t2"): a2[1] / 2}
                assert abs(sympy.N(expr["P_x"].subs(at), 40) - p[0]) < 1e-30
                assert abs(sympy.N(expr["P_y"].subs(at), 40) - p[1]) < 1e-30
    mpmath.mp.dps = 15


def test_curve_of_a_two_input_point_is_refused(tmp_path):
    # P moves with t1 and t2: it sweeps a region, there is no implicit curve F(P_x, P_y) = 0.
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    result = subprocess.run([sys.executable, "-m", "algkin", "curve", "five-bar", "--point", "P"],
                            capture_output=True, text=True, env=env, cwd=tmp_path)
    assert result.returncode == 2 and result.stdout == ""
    assert result.stderr.count("\n") == 1
    for words in ("--point='P'", "2 inputs (t1, t2)", "region, not a curve"):
        assert words in result.stderr
    assert os.listdir(tmp_path) == []


def test_curve_of_a_one_input_point_of_the_five_bar_is_a_circle():
    # A1 depends on t1 only: its curve is the crank circle x**2 + y**2 = 4, by hand.
    document = run("curve", "five-bar", "--point", "A1", "--samples", "4")
    x, y = sympy.symbols("A1_x A1_y")
    assert sympy.simplify(sympy.parse_expr(document["curve"]) - (x**2 + y**2 - 4)) == 0
