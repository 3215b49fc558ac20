"""The certified reference against values found here by other means: a four-bar's circles met
by hand and mpmath's own Newton on the scene's equations, both far past float64."""

import mpmath
import numpy as np
import pytest
import sympy
from flint import ctx
from hypothesis import assume, given, settings, strategies as st

from algkin.branches import closed_forms
from algkin.bench.reference import BITS, NotCertified, Reference
from algkin.scene import compile_scene, load_scene
from algkin.system import symbol

AGREE = 1e-30  # relative: 100 bits, twice float64's
# fourbar-nongrashof: crank 2, ground 5, coupler 3, rocker 7/2, branch left; it assembles while
# cos(theta) >= -53/80, so it toggles at +-acos(-53/80) = +-131.49 deg.
BARS = (2, 5, 3, mpmath.mpf(7) / 2)
TOGGLE = float(mpmath.acos(mpmath.mpf(-53) / 80))


def _reference(scene, of):
    compiled = compile_scene(scene, [of])
    branch = next(b for b in closed_forms(compiled) if b.selected)
    (outputs,) = compiled.outputs.values()
    return compiled, Reference(compiled, branch, outputs)


@pytest.fixture(scope="module")
def four_bar():
    return _reference(load_scene("fourbar-nongrashof"), "B")[1]


def _by_hand(theta, crank, ground, coupler, rocker):
    """B left of A -> D (A = crank (cos, sin), D = (ground, 0)), the circles met at 60 digits;
    None where they miss."""
    with mpmath.workdps(60):
        t = mpmath.mpf(theta)  # a float64 exactly
        ax, ay = crank * mpmath.cos(t), crank * mpmath.sin(t)
        dx, dy = ground - ax, -ay
        d2 = dx * dx + dy * dy
        along = (d2 + coupler**2 - rocker**2) / (2 * d2)
        chord = coupler**2 / d2 - along * along
        if chord < 0:
            return None
        h = mpmath.sqrt(chord)  # cross(D - A, B - A) = h |AD|**2 > 0: left
        return ax + along * dx - h * dy, ay + along * dy + h * dx


def _midpoints(ball_row):
    with mpmath.workdps(60):
        return [mpmath.mpf(b.mid().str(60, radius=False)) for b in ball_row]


def _assert_agrees(found, exact):
    with mpmath.workdps(60):
        size = mpmath.sqrt(sum(v * v for v in exact))
        assert max(abs(f - e) for f, e in zip(found, exact)) <= AGREE * size, (found, exact)


def test_four_bar_equals_its_circles_met_by_hand(four_bar):
    inside = [TOGGLE * (1 - offset) for offset in (1e-6, 1e-10, 1e-14)]
    theta = np.array([-2.0, -0.3, 0.0, 1.0, 2.2] + inside + [-v for v in inside])
    certified = four_bar.certify(theta)
    assert certified.ok.all()
    for k, angle in enumerate(theta):
        exact = _by_hand(angle, *BARS)
        _assert_agrees(_midpoints(certified.roots[k]), exact)
        assert certified.points[:, k].tolist() == [float(v) for v in exact]  # correctly rounded


@pytest.mark.parametrize("name, of", [("chebyshev-lambda", "P"), ("watt-i", "P"), ("arm-string", "AB"),
                                      ("whitworth-quick-return", "D"), ("inverted-slider-crank", "H"),
                                      ("peaucellier-lipkin", "P")])
def test_equals_mpmath_newton_on_the_whole_system(name, of):
    # A frame point on a dyad (chebyshev-lambda), a dyad on a dyad (watt-i), a distance with no
    # dyad (arm-string), sliders on a moving line (whitworth, inverted slider-crank), an inversor's
    # mirrored points (peaucellier): mpmath's findroot polishes the reference's float root to 60
    # digits, from the scene's own equations taken all at once.
    compiled, reference = _reference(load_scene(name), of)
    # the inversor assembles within +-120 deg only
    theta = np.array([0.1, 1.0, 2.0, 4.5, 6.0] if name == "peaucellier-lipkin" else [0.1, 1.0, 2.5, 4.0, 6.0])
    certified = reference.certify(theta)
    assert certified.ok.all()
    defaults = {symbol(n): sympy.Rational(str(v)) for n, v in compiled.parameter_values.items()}
    (c, s), = compiled.system.inputs.values()
    unknowns = [symbol(u) for u in compiled.system.unknowns]
    equations = [e.xreplace(defaults) for e in compiled.system.equations
                 if not e.free_symbols <= {symbol(c), symbol(s)}]
    system = sympy.lambdify(unknowns + [symbol(c), symbol(s)], equations, "mpmath")
    for k, angle in enumerate(theta):
        with mpmath.workdps(60):
            cs = mpmath.cos(mpmath.mpf(angle)), mpmath.sin(mpmath.mpf(angle))
            start = [float(b.mid()) for b in certified.roots[k]]  # 53 bits: it picks the root
            exact = mpmath.findroot(lambda *x, cs=cs: system(*x, *cs), start, tol=mpmath.mpf(10) ** -100)
        _assert_agrees(_midpoints(certified.roots[k]), list(exact))


def test_condition_number_is_the_slope_of_the_root(four_bar):
    theta = np.array([0.5, TOGGLE * (1 - 1e-8)])
    kappas = four_bar.certify(theta).kappas
    for angle, kappa in zip(theta, kappas):
        with mpmath.workdps(60):
            step = mpmath.mpf(10) ** -20
            ahead, behind, here = (_by_hand(mpmath.mpf(angle) + d, *BARS) for d in (step, -step, 0))
            slope = mpmath.sqrt(sum(((p - q) / (2 * step)) ** 2 for p, q in zip(ahead, behind)))
            expected = abs(angle) * slope / mpmath.sqrt(sum(v * v for v in here)) + 1
        assert abs(kappa / float(expected) - 1) < 1e-6


def test_refuses_where_the_branch_does_not_assemble(four_bar):
    theta = np.array([1.0, TOGGLE * (1 + 1e-10), 2.5, np.pi, np.nan])
    certified = four_bar.certify(theta)
    assert certified.ok.tolist() == [True, False, False, False, False]
    assert np.isnan(certified.points[:, 1:]).all() and np.isnan(certified.kappas[1:]).all()
    with pytest.raises(NotCertified, match="2.29"):  # the first angle refused, named
        four_bar(theta)


def test_no_samples():
    _, reference = _reference(load_scene("fourbar"), "B")
    certified = reference.certify(np.zeros(0))
    assert certified.points.shape == (2, 0) and not certified.ok.size


def test_leaves_the_working_precision_as_it_found_it(four_bar):
    before = ctx.prec
    four_bar.certify(np.array([0.3]))
    assert ctx.prec == before != BITS


@settings(max_examples=40, deadline=None)
@given(st.floats(min_value=-np.pi, max_value=np.pi))
def test_certified_exactly_where_the_circles_meet(four_bar, angle):
    # away from the toggles, where float64 cannot tell a hair's breadth on either side
    assume(abs(abs(angle) - TOGGLE) > 1e-12)
    certified = four_bar.certify(np.array([angle]))
    exact = _by_hand(angle, *BARS)
    assert bool(certified.ok[0]) == (exact is not None)
    if exact is not None:
        _assert_agrees(_midpoints(certified.roots[0]), exact)
