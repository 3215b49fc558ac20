"""Function generation (Freudenstein), checked against independent computations.

Expected values never come from the code under test:
- three pairs: four-bars built by hand (rational lengths, positions of rational cos and sin
  found from the loop equation by exact arithmetic in ``fractions``), recovered exactly;
- four and five pairs: every solution closes the ORIGINAL loop (crank, coupler, rocker,
  ground as vectors) at each pair, at 50 digits (mpmath); the complex count is that of
  independent numeric solutions of the un-eliminated equations in R1, R2, R3 and the cos and
  sin of the starts (Newton from many random complex starts, polished by mpmath's findroot);
  data built from a known four-bar, which must be among the solutions.
"""

from __future__ import annotations

import random
from fractions import Fraction

import flint
import mpmath
import numpy as np
import pytest
import sympy

from algkin.eliminate.group import solve_group
from algkin.errors import UsageError
from algkin.synthesis.data import Angle, AnglePair
from algkin.synthesis.function import FreudensteinSolution, FunctionSynthesis, freudenstein, system

DIGITS = 50


def half(t) -> Angle:
    return Angle.of_tan_half(flint.fmpq(Fraction(t).numerator, Fraction(t).denominator))


def pair(t_in, t_out) -> AnglePair:
    return AnglePair(half(t_in), half(t_out))


def fraction(value: flint.fmpq) -> Fraction:
    return Fraction(int(value.p), int(value.q))


def mp(value) -> mpmath.mpf:
    """A value as an mpmath number (at the caller's precision: every check runs in ``mpmath.workdps``)."""
    if isinstance(value, flint.fmpq):
        return mpmath.mpf(int(value.p)) / int(value.q)
    return mpmath.mpf(value.mid().str(DIGITS + 10, radius=False))


# --- three pairs: hand solutions -------------------------------------------------------------

# Found by hand: crank 2 about (0, 0), rocker 5 about (6, 0); crank and rocker at angles of
# half-angle tangents t_in, t_out; the coupler's end points are sqrt(41) apart at each pair
# (|A - B|**2 = 41 computed below in fractions, not by algkin).
HAND = dict(crank=2, rocker=5, ground=6, coupler_squared=41,
            pairs=[("-5/2", "-3/2"), ("-7/4", "-4/3"), ("-5/6", -1)])
# and crank 1, rocker 3, ground 3, coupler exactly 1
UNIT = dict(crank=1, rocker=3, ground=3, coupler_squared=1, pairs=[(-2, "-9/2"), ("-3/2", "-11/3"), (-1, -3)])


def loop_gap(crank, rocker, ground, t_in, t_out) -> Fraction:
    """|A - B|**2 for the crank's end A and the rocker's end B, exactly (the loop equation's coupler squared)."""
    t, u = Fraction(t_in), Fraction(t_out)
    cos_in, sin_in = (1 - t * t) / (1 + t * t), 2 * t / (1 + t * t)
    cos_out, sin_out = (1 - u * u) / (1 + u * u), 2 * u / (1 + u * u)
    ax, ay = crank * cos_in, crank * sin_in
    bx, by = ground + rocker * cos_out, rocker * sin_out
    return (ax - bx) ** 2 + (ay - by) ** 2


@pytest.mark.parametrize("linkage", [HAND, UNIT], ids=["sqrt41", "unit"])
def test_three_pairs_give_back_the_hand_four_bar_exactly(linkage):
    assert all(loop_gap(linkage["crank"], linkage["rocker"], linkage["ground"], *p) == linkage["coupler_squared"]
               for p in linkage["pairs"])  # the data are positions of that four-bar
    found = freudenstein([pair(*p) for p in linkage["pairs"]], ground=flint.fmpq(linkage["ground"]))
    solution, = found.solutions
    assert (solution.crank, solution.rocker, solution.ground, solution.coupler_squared) == \
        tuple(flint.fmpq(linkage[k]) for k in ("crank", "rocker", "ground", "coupler_squared"))
    first = half(linkage["pairs"][0][0]), half(linkage["pairs"][0][1])
    assert solution.start_input == (first[0].cos, first[0].sin)
    assert solution.start_output == (first[1].cos, first[1].sin)
    a, c, d, b2 = (Fraction(linkage[k]) for k in ("crank", "rocker", "ground", "coupler_squared"))
    assert tuple(map(fraction, solution.ratios)) == (d / a, d / c, (a * a - b2 + c * c + d * d) / (2 * a * c))
    assert (found.complex_count, found.real_count, found.excluded) == (1, 1, ())


def test_three_pairs_exact_coupler_where_it_is_rational_and_a_ball_where_not():
    unit, = freudenstein([pair(*p) for p in UNIT["pairs"]], ground=flint.fmpq(3)).solutions
    assert unit.coupler == flint.fmpq(1)
    root41, = freudenstein([pair(*p) for p in HAND["pairs"]], ground=flint.fmpq(6)).solutions
    assert isinstance(root41.coupler, flint.arb) and root41.coupler.overlaps(flint.arb(41).sqrt())
    assert root41.coupler.rad() < 1e-35


def test_a_crank_found_negative_is_turned_to_a_positive_length():
    """The same four-bar, its input angles measured along the crank's other end: the crank
    points the other way (R1 < 0); the solution turns it back, so its start is the hand four-bar's."""
    turned = [(-1 / Fraction(t_in), t_out) for t_in, t_out in HAND["pairs"]]   # t -> -1/t: the angle + 180
    solution, = freudenstein([pair(*p) for p in turned], ground=flint.fmpq(6)).solutions
    assert (solution.crank, solution.rocker, solution.coupler_squared) == (2, 5, 41)
    start = half(HAND["pairs"][0][0])
    assert solution.start_input == (start.cos, start.sin)
    assert solution.ratios[0] > 0


def test_three_pairs_of_an_infinitely_long_crank_are_an_answer_not_an_error():
    """psi = 2 phi + 180 at every pair: R1 = 0, R2 = 1, R3 = 0 solve every equation
    (-cos phi = cos(phi - psi) = cos(180 - phi)), and Cramer's determinant, in fractions, is not zero."""
    data = [0, "1/2", 2]
    rows = []
    for t in data:
        t = Fraction(t)
        ci, si = (1 - t * t) / (1 + t * t), 2 * t / (1 + t * t)
        co, so = -(ci * ci - si * si), -(2 * ci * si)
        rows.append([co, -ci, Fraction(1), ci * co + si * so])
        assert -ci == ci * co + si * so
    assert sympy.Matrix([r[:3] for r in rows]).det() != 0
    pairs = [AnglePair(half(t), Angle(flint.fmpq(*row[0].as_integer_ratio()), -2 * half(t).cos * half(t).sin))
             for t, row in zip(data, rows)]
    found = freudenstein(pairs)
    assert found.solutions == () and (found.complex_count, found.real_count) == (1, 1)
    exclusion, = found.excluded
    assert exclusion.reason.startswith("R1 = 0") and "crank" in exclusion.reason


@pytest.mark.parametrize("pairs, unknown_start, says", [
    ([(0, 0), (1, 1)], False, "takes 3 pairs (absolute pairs), not 2"),
    ([(0, 0), (1, 1), (2, 2), (3, 3)], False, "takes 3 pairs"),
    ([(0, 0), (1, 1), (2, 2)], True, "takes 4 or 5 pairs (offsets from unknown starts), not 3"),
    ([(0, 0), (1, 1), (2, 2), (3, 3), (4, 4), (5, 5)], True, "not 6"),
    ([(0, 0), (1, 1), (0, 0)], False, "pairs 1 and 3 are equal"),
    ([(0, 0), (1, 1), (2, 0), (3, 3), (2, 0)], True, "pairs 3 and 5 are equal"),
    ([(0, 0), (1, 0), (2, 0)], False, "singular"),   # every output 0: cos output the constant column
])
def test_bad_pairs_are_one_line_usage_errors(pairs, unknown_start, says):
    with pytest.raises(UsageError) as raised:
        freudenstein([pair(*p) for p in pairs], unknown_start=unknown_start)
    assert raised.value.argument == "pairs" and says in str(raised.value) and "\n" not in str(raised.value)


def test_a_ground_not_positive_is_a_usage_error():
    with pytest.raises(UsageError, match="ground"):
        freudenstein([pair(*p) for p in HAND["pairs"]], ground=flint.fmpq(0))


# --- unknown starts: a known four-bar, and the original loop ---------------------------------

KNOWN = dict(crank=Fraction(2, 5), coupler=Fraction(6, 5), rocker=Fraction(4, 5), ground=Fraction(1))


def known(name: str) -> mpmath.mpf:
    """A length of the known four-bar, at the caller's precision."""
    return mpmath.mpf(KNOWN[name].numerator) / KNOWN[name].denominator
INPUT_OFFSETS = [0, "1/5", "2/5", "3/5", "4/5"]   # half-angle tangents: 0 to 77 degrees


def rocker_angle(crank, coupler, rocker, ground, phi):
    """The rocker's angle with the crank at ``phi``: B on the circle about (ground, 0) of radius
    ``rocker`` and on the circle about A of radius ``coupler``, the intersection left of A -> (ground, 0)."""
    ax, ay = crank * mpmath.cos(phi), crank * mpmath.sin(phi)
    dx, dy = ground - ax, -ay
    distance = mpmath.sqrt(dx * dx + dy * dy)
    along = (coupler**2 - rocker**2 + distance**2) / (2 * distance)
    across = mpmath.sqrt(coupler**2 - along**2)
    bx = ax + (along * dx - across * dy) / distance
    by = ay + (along * dy + across * dx) / distance
    return mpmath.atan2(by, bx - ground)


def rational_half(angle) -> Angle:
    """The angle of a 40-digit rational half-angle tangent next to ``angle`` (radians): the
    known four-bar is then a solution to about 1e-38."""
    t = mpmath.tan(angle / 2)
    scale = 10**40
    return Angle.of_tan_half(flint.fmpq(int(mpmath.nint(t * scale)), scale))


def known_pairs(count: int) -> tuple[list[AnglePair], mpmath.mpf, mpmath.mpf]:
    """The known four-bar's pairs, with its start angles: exact input offsets from the crank's
    start (0.3 radians; four pairs: the angle of half-angle tangent 1/3, the inputs then
    absolute and exact), output offsets to 40 digits."""
    with mpmath.workdps(80):
        offsets = [half(t) for t in INPUT_OFFSETS[:count]]
        start_input = mpmath.mpf("0.3") if count == 5 else 2 * mpmath.atan(mpmath.mpf(1) / 3)
        phis = [start_input + mpmath.atan2(mp(o.sin), mp(o.cos)) for o in offsets]
        psis = [rocker_angle(known("crank"), known("coupler"), known("rocker"), known("ground"), p) for p in phis]
        outputs = [rational_half(psi - psis[0]) for psi in psis]
        if count == 4:   # the inputs absolute: the start's cos and sin rational (tan(start/2) = 1/3)
            start = half("1/3")
            inputs = [Angle(start.cos * o.cos - start.sin * o.sin, start.sin * o.cos + start.cos * o.sin) for o in offsets]
        else:
            inputs = offsets
        return [AnglePair(i, o) for i, o in zip(inputs, outputs)], phis[0], psis[0]


def angle_of(cos_sin) -> mpmath.mpf:
    return mpmath.atan2(mp(cos_sin[1]), mp(cos_sin[0]))


def closes_the_loop(solution: FreudensteinSolution, pairs: list[AnglePair]) -> mpmath.mpf:
    """The largest gap | |A - B| - coupler | over the pairs, A the crank's end and B the rocker's
    at the pair's angles (the solution's starts plus the offsets from the first pair), at 50 digits."""
    with mpmath.workdps(DIGITS):
        a, b, c, d = (mp(x) for x in (solution.crank, solution.coupler, solution.rocker, solution.ground))
        phi0, psi0 = angle_of(solution.start_input), angle_of(solution.start_output)
        first_in, first_out = angle_of((pairs[0].input.cos, pairs[0].input.sin)), \
            angle_of((pairs[0].output.cos, pairs[0].output.sin))
        worst = mpmath.mpf(0)
        for p in pairs:
            phi = phi0 + angle_of((p.input.cos, p.input.sin)) - first_in
            psi = psi0 + angle_of((p.output.cos, p.output.sin)) - first_out
            ax, ay = a * mpmath.cos(phi), a * mpmath.sin(phi)
            bx, by = d + c * mpmath.cos(psi), c * mpmath.sin(psi)
            worst = max(worst, abs(mpmath.sqrt((ax - bx) ** 2 + (ay - by) ** 2) - b))
        return worst


# --- unknown starts: independent numeric solutions of the un-eliminated equations ----------


def numeric_solutions(pairs: list[AnglePair], *, seed: int = 7, starts: int = 120):
    """Every complex solution of R1 cos psi_i - R2 cos phi_i + R3 = cos(phi_i - psi_i) with the
    cos and sin of the unknown starts on the unit circle (R1, R2, R3, [ci, si,] co, so), by
    Newton from random complex points (numpy), each polished to 50 digits by mpmath.findroot."""
    r1, r2, r3, ci, si, co, so = sympy.symbols("R1 R2 R3 ci si co so")
    first = pairs[0]
    equations = [co**2 + so**2 - 1]
    if len(pairs) == 5:
        equations.append(ci**2 + si**2 - 1)
        unknowns = [r1, r2, r3, ci, si, co, so]
    else:
        unknowns = [r1, r2, r3, co, so]
    def cos_sin(angle) -> tuple[sympy.Float, sympy.Float]:   # the offset's, by mpmath, to 60 digits
        with mpmath.workdps(60):
            return tuple(sympy.Float(mpmath.nstr(f(angle), 60), 60) for f in (mpmath.cos, mpmath.sin))

    for p in pairs:
        with mpmath.workdps(60):
            din = angle_of((p.input.cos, p.input.sin)) - angle_of((first.input.cos, first.input.sin))
            dout = angle_of((p.output.cos, p.output.sin)) - angle_of((first.output.cos, first.output.sin))
        (cd, sd), (co_d, so_d) = cos_sin(din), cos_sin(dout)
        if len(pairs) == 5:
            cos_in, sin_in = ci * cd - si * sd, si * cd + ci * sd
        else:
            cos_in, sin_in = cos_sin(angle_of((p.input.cos, p.input.sin)))
        cos_out, sin_out = co * co_d - so * so_d, so * co_d + co * so_d
        equations.append(r1 * cos_out - r2 * cos_in + r3 - (cos_in * cos_out + sin_in * sin_out))
    jacobian = sympy.Matrix(equations).jacobian(unknowns)
    f_np = sympy.lambdify([unknowns], equations, "numpy")
    j_np = sympy.lambdify([unknowns], jacobian, "numpy")
    f_mp = sympy.lambdify([unknowns], equations, "mpmath")
    j_mp = sympy.lambdify([unknowns], jacobian, "mpmath")
    rng = np.random.default_rng(seed)
    approximate: list[np.ndarray] = []
    for _ in range(starts):
        x = rng.normal(size=len(unknowns)) + 1j * rng.normal(size=len(unknowns))
        for _ in range(60):
            try:
                step = np.linalg.solve(np.array(j_np(x), dtype=complex), np.array(f_np(x), dtype=complex))
            except np.linalg.LinAlgError:
                break
            x = x - step
            if np.linalg.norm(step) < 1e-13 * (1 + np.linalg.norm(x)):
                break
        if np.all(np.isfinite(x)) and np.linalg.norm(np.array(f_np(x), dtype=complex)) < 1e-9 and \
                all(np.linalg.norm(x - other) > 1e-6 for other in approximate):
            approximate.append(x)
    found = []
    with mpmath.workdps(DIGITS):
        for x in approximate:
            polished = mpmath.findroot(lambda *v: f_mp(list(v)), [mpmath.mpc(v) for v in x],
                                       J=lambda *v: j_mp(list(v)), tol=mpmath.mpf(10) ** (-2 * DIGITS + 10))
            values = [polished[k] for k in range(len(unknowns))]
            assert max(abs(e) for e in f_mp(values)) < mpmath.mpf(10) ** (-DIGITS + 5)
            assert all(max(abs(u - v) for u, v in zip(values, other)) > 1e-30 for other in found)
            found.append(values)
    return found, [str(u) for u in unknowns]


def classes(found, names):
    """The numeric solutions up to turning a link by 180 degrees (the same four-bar): their
    cos and sin of twice each start."""
    keys = []
    for values in found:
        v = dict(zip(names, values))
        key = [v["co"] ** 2 - v["so"] ** 2, 2 * v["co"] * v["so"]]
        if "ci" in v:
            key = [v["ci"] ** 2 - v["si"] ** 2, 2 * v["ci"] * v["si"]] + key
        if all(max(abs(a - b) for a, b in zip(key, other)) > 1e-30 for other in keys):
            keys.append(key)
    return keys


def twice(cos_sin) -> tuple[mpmath.mpf, mpmath.mpf]:
    c, s = mp(cos_sin[0]), mp(cos_sin[1])
    return c * c - s * s, 2 * c * s


def check_counts_against_numeric(found: FunctionSynthesis, pairs: list[AnglePair]) -> None:
    with mpmath.workdps(DIGITS):
        _check_counts(found, pairs)


def _check_counts(found: FunctionSynthesis, pairs: list[AnglePair]) -> None:
    numeric, names = numeric_solutions(pairs)
    keys = classes(numeric, names)
    turns = 4 if len(pairs) == 5 else 2   # the crank's and the rocker's 180-degree turns
    assert len(numeric) == turns * len(keys)
    assert len(keys) == found.complex_count
    real = [k for k in keys if all(abs(mpmath.im(x)) < 1e-30 for x in k)]
    assert len(real) == found.real_count
    assembled = []
    for solution in found.solutions:
        mine = (twice(solution.start_input) if len(pairs) == 5 else ()) + twice(solution.start_output)
        assembled.append(sum(1 for k in real if max(abs(mpmath.re(a) - b) for a, b in zip(k, mine)) < 1e-30))
    assert assembled == [1] * len(found.solutions)
    unassembled = sum(e.real_count for e in found.excluded if e.solutions)
    assert len(found.solutions) + unassembled == found.real_count


FIVE_OTHER = [(0, 0), ("1/3", "1/5"), ("2/3", "1/2"), (1, "3/4"), ("4/3", 1)]
FOUR_OTHER = [("1/7", 0), ("1/2", "1/4"), (1, "2/3"), (2, "3/2")]


def test_five_pairs_from_a_known_four_bar_find_it_and_every_solution_closes_the_loop():
    pairs, phi0, psi0 = known_pairs(5)
    found = freudenstein(pairs, unknown_start=True, bits=256)
    for solution in found.solutions:
        assert closes_the_loop(solution, pairs) < mpmath.mpf(10) ** -40
    with mpmath.workdps(DIGITS):
        solution, = [s for s in found.solutions if abs(mp(s.crank) - known("crank")) < 1e-30]
        assert abs(mp(solution.coupler) - known("coupler")) < 1e-30 and abs(mp(solution.rocker) - known("rocker")) < 1e-30
        assert abs(angle_of(solution.start_input) - phi0) < 1e-30 and abs(angle_of(solution.start_output) - psi0) < 1e-30
    check_counts_against_numeric(found, pairs)


def test_five_other_pairs_every_solution_closes_the_loop_and_the_count_is_the_numeric_one():
    pairs = [pair(*p) for p in FIVE_OTHER]
    found = freudenstein(pairs, unknown_start=True, bits=256)
    assert found.solutions
    for solution in found.solutions:
        assert closes_the_loop(solution, pairs) < mpmath.mpf(10) ** -40
    check_counts_against_numeric(found, pairs)


def test_four_pairs_from_a_known_four_bar_find_it_and_every_solution_closes_the_loop():
    pairs, phi0, psi0 = known_pairs(4)
    found = freudenstein(pairs, unknown_start=True, bits=256)
    for solution in found.solutions:
        assert closes_the_loop(solution, pairs) < mpmath.mpf(10) ** -40
        assert solution.start_input in ((pairs[0].input.cos, pairs[0].input.sin),
                                        (-pairs[0].input.cos, -pairs[0].input.sin))  # exact: the first input
    with mpmath.workdps(DIGITS):
        solution, = [s for s in found.solutions if abs(mp(s.crank) - known("crank")) < 1e-30]
        assert abs(mp(solution.coupler) - known("coupler")) < 1e-30 and abs(mp(solution.rocker) - known("rocker")) < 1e-30
        assert abs(angle_of(solution.start_output) - psi0) < 1e-30
    check_counts_against_numeric(found, pairs)


def test_four_other_pairs_every_solution_closes_the_loop_and_the_count_is_the_numeric_one():
    pairs = [pair(*p) for p in FOUR_OTHER]
    found = freudenstein(pairs, unknown_start=True, bits=256)
    for solution in found.solutions:
        assert closes_the_loop(solution, pairs) < mpmath.mpf(10) ** -40
    check_counts_against_numeric(found, pairs)


def test_the_extraneous_factors_of_five_pairs_are_reported_not_counted():
    found = freudenstein([pair(*p) for p in FIVE_OTHER], unknown_start=True)
    extraneous = [e for e in found.excluded if e.reason.startswith("extraneous")]
    assert extraneous and not any(e.solutions for e in extraneous)
    assert found.group is not None
    assert found.group.complex_count == found.complex_count + sum(e.complex_count for e in extraneous)


@pytest.mark.parametrize("data", [FIVE_OTHER, FOUR_OTHER], ids=["five", "four"])
def test_the_system_for_other_solvers_has_the_synthesis_count(data):
    pairs = [pair(*p) for p in data]
    equations, unknowns = system(pairs, unknown_start=True)
    assert len(equations) == len(unknowns)
    assert solve_group(equations, unknowns).complex_count == freudenstein(pairs, unknown_start=True).complex_count


def test_solutions_compare_by_their_exact_identity():
    pairs = [pair(*p) for p in FIVE_OTHER]
    first, second = freudenstein(pairs, unknown_start=True), freudenstein(pairs, unknown_start=True, bits=300)
    assert first.solutions == second.solutions and hash(first.solutions) == hash(second.solutions)
    assert len(set(first.solutions)) == len(first.solutions)


def test_random_five_pair_sets_close_the_loop():
    rng = random.Random(3)
    for _ in range(3):
        data = [(0, 0)] + [(Fraction(rng.randint(-9, 9), rng.randint(1, 9)), Fraction(rng.randint(-9, 9), rng.randint(1, 9)))
                           for _ in range(4)]
        pairs = [pair(*p) for p in data]
        found = freudenstein(pairs, unknown_start=True)
        for solution in found.solutions:
            assert closes_the_loop(solution, pairs) < mpmath.mpf(10) ** -30
        assert found.complex_count <= 3


def test_four_pairs_three_at_one_crank_angle_have_no_solution_an_answer_not_an_error():
    """Pairs 1, 2, 4 put the crank at -90 degrees with three different rocker angles: a
    four-bar has at most two rocker positions at one crank angle, so none passes."""
    found = freudenstein([pair(*p) for p in [(-1, "1/2"), (-1, -1), (0, 3), (-1, 2)]], unknown_start=True)
    assert (found.solutions, found.complex_count, found.real_count) == ((), 0, 0)


def test_four_pairs_that_every_start_satisfies_are_a_usage_error():
    """Three pairs with the crank at 0 degrees: R1 = 1 (the crank as long as the ground, its end
    on the rocker's pivot) with R3 = R2 solves them at any rocker angle, so the four pairs leave
    a family: they determine no four-bar."""
    with pytest.raises(UsageError, match="every start satisfies these pairs"):
        freudenstein([pair(*p) for p in [(0, 1), (0, "-1/3"), (0, 3), ("-1/3", 2)]], unknown_start=True)
