"""The interpolate method: hand-derived families, exact agreement with direct specialisation,
unlucky points skipped, and the cases it declines."""

import random

import pytest
import sympy

from algkin.eliminate import eliminate
from algkin.eliminate.modular import PRIMES, ModularBackend

x, y, r, s, d = sympy.symbols("x y r s d", real=True)  # algkin's symbols are real


def _same_up_to_constant(a, b):
    ratio = sympy.cancel(sympy.expand(a) / sympy.expand(b))
    return ratio.is_number and ratio != 0


def test_two_circles_with_symbolic_radii_by_hand():
    # circles about (0, 0) and (3, 0) with radii r and s: subtracting, 6x = r**2 - s**2 + 9,
    # and 36 y**2 = 36 r**2 - (r**2 - s**2 + 9)**2
    circles = [x**2 + y**2 - r**2, (x - 3)**2 + y**2 - s**2]
    result = eliminate(circles, ["x"], ["y", "r", "s"], method="interpolate", parameters=["r", "s"])
    assert _same_up_to_constant(result.polynomial, 36 * y**2 + (r**2 - s**2 + 9)**2 - 36 * r**2)
    assert dict(result.log)["parameter-degree"] == 4
    assert ("checked-at", 2) in result.log


def test_a_leading_coefficient_in_the_parameters_declines_to_linear():
    # centres 0 and d apart: 4 d**2 y**2 = 4 d**2 r**2 - (r**2 - 4 + d**2)**2, the y**2 term holds d
    circles = [x**2 + y**2 - r**2, (x - d)**2 + y**2 - 4]
    result = eliminate(circles, ["x"], ["y", "r", "d"], method="interpolate", parameters=["r", "d"])
    assert ("interpolation-declined", "leading coefficient") in result.log
    assert _same_up_to_constant(result.polynomial, 4 * d**2 * y**2 + (r**2 - 4 + d**2)**2 - 4 * d**2 * r**2)


def test_a_daemonic_process_interpolates_without_a_child():
    from algkin.bench.measure import measure

    circles = [x**2 + y**2 - r**2, (x - 3)**2 + y**2 - s**2]
    seconds, log, note = measure(lambda: eliminate(circles, ["x"], ["y", "r", "s"], method="interpolate",
                                                   parameters=["r", "s"]), lambda e: e.log, 60)
    assert seconds is not None, note  # a bench measurement runs in a daemonic child
    assert ("checked-at", 2) in log


def test_factors_sharing_the_motions_degrees_are_told_apart_at_the_witness():
    # x = +-1 and y = (r + 1) x: the eliminant (y - r - 1)(y + r + 1), two factors of degree 1 in y
    # at every r; the witness (x, y) = (1, 3/2) at r = 1/2 lies on the first only
    import flint

    from algkin.eliminate.select import Witness

    exact = {"x": flint.fmpq(1), "y": flint.fmpq(3, 2), "r": flint.fmpq(1, 2)}
    witness = Witness({n: flint.arb(v) for n, v in exact.items()}, exact)
    result = eliminate([x**2 - 1, y - (r + 1) * x], ["x"], ["y", "r"], method="interpolate", parameters=["r"],
                       witnesses=[[witness]])
    assert _same_up_to_constant(result.polynomial, y - r - 1)
    assert ("told-apart-at-the-witness", 1) in result.log


def test_no_parameter_is_the_linear_method():
    circles = [x**2 + y**2 - 1, (x - 1)**2 + y**2 - 1]
    result = eliminate(circles, ["x"], ["y"], method="interpolate")
    assert _same_up_to_constant(result.polynomial, 4 * y**2 - 3)  # x = 1/2


def test_a_dropped_shape_tells_factors_of_equal_degrees_apart():
    backend = ModularBackend(("x", "y"), PRIMES[0], frozenset({((1, 2), 4)}))
    gx, gy = backend.ctx.gens()
    kept, dropped = gx + gy**2 + 1, gx + 2 * gy**2 + 3 * gy + 1  # degrees (1, 2) both; 3 terms and 4
    assert backend.factors(kept * dropped) == [kept]
    assert backend.factors(dropped * (gx + 5)) == [gx + 5]
    assert backend.factors(dropped) == [dropped]  # dropping every factor drops none


def test_where_no_dropped_shape_can_divide_the_squarefree_parts_are_kept_unfactored():
    backend = ModularBackend(("x", "y"), PRIMES[0], frozenset({((3, 0), 2)}))
    gx, gy = backend.ctx.gens()
    poly = (gx + gy + 1) * (gx + 2 * gy + 3)  # degree 2 in x: no factor of degree 3 in x divides it
    assert backend.factors(poly) == [poly]
    assert len(backend.irreducible(poly)) == 2
    linear_in_x = ModularBackend(("x", "y"), PRIMES[0], frozenset({((1, 0), 2)}))  # a factor x + c
    # it fits in the degrees, but at y = 2 and y = 5 the values (x + 3)(x + 7) and (x + 6)(x + 13) share none
    assert linear_in_x.factors(poly) == [poly]
    assert linear_in_x.factors((gx + 4) * (gx + gy + 1)) == [gx + gy + 1]  # x + 4 divides: found and dropped


def test_the_learned_drop_is_trusted_and_one_dropping_the_motions_factor_is_not():
    from algkin.eliminate.backends import FlintBackend
    from algkin.eliminate.interpolate import _Family
    from algkin.eliminate.methods import prepare
    from algkin.eliminate.request import EliminationRequest

    task = _curve_task("stephenson-iii-family", ["u", "v"])
    backend = FlintBackend(task.eliminate + task.keep)
    polys = prepare(backend, [backend.from_sympy(e) for e in task.equations], task.eliminate).left
    family = _Family(backend, polys, EliminationRequest(task.eliminate, task.witnesses, task.parameters), ["u", "v"])
    # the resultant in s_theta splits in two factors of degree 6 in F_x, F_y, P_x, P_y: one spurious
    # (its cos and sin of a mismatched sign), told from the other by its terms
    split = (0, 0, 6, 6, 0, 0, 6, 6, 0, 0)
    spurious = [terms for degrees, terms in family.drop if degrees == split]
    assert len(spurious) == 1
    assert family._trusted(family.drop) == family.drop
    wrong = frozenset((split, terms) for terms in range(1, 1000) if terms != spurious[0])  # the other one
    assert family._trusted(wrong) == frozenset()


def _curve_task(scene, params):
    from algkin.derivation.prepared import prepare
    from algkin.derivation.tasks import curve_task

    prepared = prepare(scene, outputs=["P"], params=params)
    return curve_task(prepared.compiled, prepared.witnesses, "P")


def _direct(task, values):
    """The irreducible factors of the eliminant of the equations specialised at ``values``
    (no witnesses: they hold other values of the parameters)."""
    from algkin.system import symbol

    replace = {symbol(n): v for n, v in values.items()}
    equations = [sympy.expand(e.xreplace(replace)) for e in task.equations]
    return eliminate(equations, task.eliminate, task.keep[:2]).factors


def _among(poly, factors):
    return any(_same_up_to_constant(poly, f) for f in factors)


def _at(poly, values):
    return sympy.expand(poly.xreplace({sympy.Symbol(n, real=True): v for n, v in values.items()}))


def test_fourbar_coupler_point_family_equals_direct_specialisation():
    # P's frame coordinates p, q symbolic: every rational (p, q) gives the fixed four-bar's curve
    task = _curve_task("fourbar", ["p", "q"])
    family = task.run("interpolate", "flint")
    assert family.method == "interpolate" and ("checked-at", 2) in family.log
    rng = random.Random(11)
    for _ in range(3):
        values = {n: sympy.Rational(rng.randrange(-50, 50), rng.randrange(1, 30)) for n in ("p", "q")}
        assert _among(_at(family.polynomial, values), _direct(task, values))


@pytest.mark.slow
def test_stephenson_iii_family_equals_the_fixed_point_curves():
    from algkin.derivation.pipeline import curve

    family = curve("stephenson-iii-family", "P", params=["u", "v"], samples=8)
    assert family.elimination.method == "interpolate" and family.verification.passed
    fixed = curve("stephenson-iii", "P", samples=0).elimination.polynomial  # the catalog's (1/2, 1/4)
    assert _same_up_to_constant(_at(family.elimination.polynomial, {"u": sympy.Rational(1, 2),
                                                                    "v": sympy.Rational(1, 4)}), fixed)
    task = _curve_task("stephenson-iii-family", ["u", "v"])
    rng = random.Random(5)
    for _ in range(2):
        values = {n: sympy.Rational(rng.randrange(-40, 40), rng.randrange(1, 20)) for n in ("u", "v")}
        assert _among(_at(family.elimination.polynomial, values), _direct(task, values))


def test_curve_interpolates_a_symbolic_tracing_point_beyond_a_four_bar():
    from algkin.derivation.curves import family_method

    family = _curve_task("stephenson-iii-family", ["u", "v"])
    assert family_method(family, "linear") == "interpolate"
    assert family_method(family, "resultant") == "resultant"  # a method asked for by name is kept
    assert family_method(_curve_task("stephenson-iii-family", []), "linear") == "linear"  # nothing symbolic
    assert family_method(_curve_task("fourbar", ["p", "q"]), "linear") == "linear"  # four unknowns: linear is fast
    assert family_method(_curve_task("fourbar", ["a", "d", "l", "m", "p", "q"]), "linear") == "linear"


def _stephenson_iii_family_point(theta, u, modes):
    """P of the catalog's stephenson-iii-family at crank angle ``theta`` (radians), v = 1/4, in
    the assembly ``modes`` (the two dyads' signs), from the scene's geometry in mpmath; None
    where a dyad does not assemble."""
    import mpmath

    def dyad(p, q, near, far, sign):
        dx, dy = q[0] - p[0], q[1] - p[1]
        d = mpmath.sqrt(dx**2 + dy**2)
        along = (near**2 - far**2 + d**2) / (2 * d)
        if near**2 < along**2:
            return None
        h = sign * mpmath.sqrt(near**2 - along**2)
        return p[0] + (along * dx - h * dy) / d, p[1] + (along * dy + h * dx) / d

    def frame(p, q, a, b):  # p + a (q - p) + b rot90(q - p)
        dx, dy = q[0] - p[0], q[1] - p[1]
        return p[0] + a * dx - b * dy, p[1] + a * dy + b * dx

    half = mpmath.mpf(1) / 2
    a = (mpmath.cos(theta), mpmath.sin(theta))
    b = dyad(a, (4, 0), 3, mpmath.mpf(7) / 2, modes[0])
    if b is None:
        return None
    c = frame(a, b, half, half)
    f = dyad(c, (-1, 5), 3, 2, modes[1])
    return None if f is None else frame(c, f, u, mpmath.mpf(1) / 4)


@pytest.mark.slow
def test_stephenson_iii_family_in_u_alone_holds_the_mechanisms_points():
    # v fixed at 1/4 gives F_x a numeric slope in P_y's equation: substituted in the family it
    # left every image an eliminant of degree 152 whose four factors of the curve's degrees the
    # signature could not tell apart ("every image unlucky")
    import mpmath

    from algkin.derivation.pipeline import curve

    family = curve("stephenson-iii-family", "P", params=["u"], samples=8)
    assert family.elimination.method == "interpolate" and family.verification.passed
    poly = family.elimination.polynomial
    px, py, u = (sympy.Symbol(n, real=True) for n in ("P_x", "P_y", "u"))
    terms = [sympy.lambdify((px, py, u), t, "mpmath") for t in sympy.Add.make_args(sympy.expand(poly))]
    mpmath.mp.dps = 50
    try:
        checked = 0
        for u_value in (mpmath.mpf(-3) / 7, mpmath.mpf(5) / 3, mpmath.e):
            for degrees in range(0, 360, 40):
                for modes in ((1, 1), (1, -1), (-1, 1), (-1, -1)):
                    point = _stephenson_iii_family_point(mpmath.radians(degrees), u_value, modes)
                    if point is None:
                        continue
                    values = [t(*point, u_value) for t in terms]
                    assert abs(mpmath.fsum(values)) < mpmath.mpf(10) ** -40 * mpmath.fsum(map(abs, values))
                    checked += 1
        assert checked > 50
    finally:
        mpmath.mp.dps = 15
