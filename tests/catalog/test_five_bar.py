"""The five-bar with two inputs: its end point against hand geometry at both cranks' angles."""

import mpmath
import sympy

from .geometry import branch, circles, on_circle, run, same


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
