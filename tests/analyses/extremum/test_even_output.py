"""An output whose eliminant holds it in even powers only (a distance: its eliminant is one in its
square): the stationary and meeting conditions from resultants in the square, of half the degree.

On the Stephenson III family with the tracing point's ``u`` symbolic, the stationary resultant in
``dist(P, O)`` had 8,481 terms (17 s); in its square, 2,193 (0.1 s)."""

import mpmath
import pytest
import sympy

from algkin.analyses.extremum import problem_for
from algkin.analyses.extremum.critical import (Problem, critical_points, extreme, in_square, meeting_factors,
                                               stationary_factors)
from algkin.derivation.pipeline import derive
from algkin.derivation.prepared import prepare
from algkin.runtime.budget import Budget
from algkin.system import symbol
from algkin.system.angles import Parametrisation

C, S, T, U = (symbol(n) for n in ("c", "s", "t", "u"))
CIRCLE = Parametrisation((C, S), T)
OUTPUT = "dist(P, O)"
V = mpmath.mpf(1) / 4  # the scene's other frame coordinate


@pytest.fixture(scope="module")
def family():
    """``dist(P, O)`` of the Stephenson III family with ``u`` symbolic: its problem."""
    prepared = prepare("stephenson-iii-family", outputs=[OUTPUT], params=["u"])
    derived = derive(prepared, method="resultant", samples=0)
    return problem_for(derived, OUTPUT, witnesses=prepared.witnesses)


def test_a_polynomial_in_the_square_is_halved_and_another_is_not():
    x, y = sympy.symbols("x y")
    assert in_square([x**6 - y * x**2, x**2 + 1], x) == [x**3 - x * y, x + 1]
    assert in_square([x**2 - y, x**3], x) is None
    assert in_square([y + 1], x) is None  # no power of x at all: nothing to halve


def test_the_same_factors_as_the_resultants_in_the_output_itself():
    """The halved resultants' factors are those of the resultants in ``u`` itself, by sympy: of ``F``
    and ``dF/dtheta`` (stationary), of ``F`` and ``dF/du`` (meeting: ``u = 0`` a double root among them)."""
    eliminant = (U**2 - 5 + 4 * C) * (U**2 - 2 - S)
    problem = Problem(sympy.expand(eliminant), U, U, CIRCLE, ())
    moving, along = problem.half_angle()
    expected = {"stationary": sympy.resultant(moving, along, U), "meeting": sympy.resultant(moving, moving.diff(U), U)}
    found = {"stationary": stationary_factors(problem), "meeting": meeting_factors(problem)}
    for key, resultant in expected.items():
        assert _signless(found[key]) == _signless(f for f, _ in sympy.factor_list(resultant)[1]), key


def _signless(factors):
    """The factors holding ``t``, each with a positive leading coefficient in it."""
    return {sympy.expand(f * sympy.sign(sympy.Poly(f, T).LC())) for f in factors if f.has(T)}


@pytest.mark.slow
def test_the_stationary_resultant_keeps_within_a_term_budget(family):
    """Before, the resultant in ``dist(P, O)`` itself had 8,481 terms (this budget stopped it)."""
    factors = stationary_factors(family, deadline=Budget(terms=4000).start())
    degrees = sorted(sympy.Poly(f, family.t).degree() for f in factors)
    assert degrees == [2, 2, 6, 24, 44]


@pytest.mark.slow
@pytest.mark.parametrize("u", ["1/3", "1/2", "3/4"])
def test_the_family_s_factors_give_each_design_s_extremes(family, u):
    """The minimum and maximum over the crank's turn at ``u`` from the family's stationary and
    meeting factors specialised there, against the scene's geometry at 50 digits (circle
    intersections, a scan every quarter degree refined where the slope is zero)."""
    values = {family.parameters[0]: sympy.Rational(u)}
    stationary = [sympy.expand(f.xreplace(values)) for f in stationary_factors(family)]
    meeting = [sympy.expand(f.xreplace(values)) for f in meeting_factors(family)]
    with mpmath.workdps(40):
        points = critical_points(family.at(values), stationary, 0, 360, meeting)
        found = {"min": extreme(points), "max": extreme(points, largest=True)}
    expected = _extremes(sympy.Rational(u))
    with mpmath.workdps(50):
        for key, (degrees, value) in expected.items():
            assert abs(found[key].value - value) < 1e-25, key
            assert abs(found[key].input_deg - degrees) < 1e-20, key


def _extremes(u):
    """``{"min"/"max": (degrees, dist(P, O))}`` over a turn at the rational ``u``, from the geometry at 50 digits."""
    with mpmath.workdps(50):
        at = lambda degrees: _distance(degrees, mpmath.mpf(u.p) / u.q)  # noqa: E731
        grid = [mpmath.mpf(k) / 4 for k in range(1441)]
        values = [at(x) for x in grid]
        found = {}
        for key, sign in (("min", 1), ("max", -1)):
            start = grid[min(range(len(grid)), key=lambda k: sign * values[k])]
            degrees = mpmath.findroot(lambda x: mpmath.diff(at, x), start) % 360
            found[key] = (degrees, at(degrees))
        return found


def _distance(degrees, u):
    """|PO| at the crank angle ``degrees``: the scene's points built one after the other."""
    angle = mpmath.radians(degrees)
    a = (mpmath.cos(angle), mpmath.sin(angle))
    b = _left(a, (4, 0), 3, mpmath.mpf(7) / 2)
    c = _on_bar(a, b, mpmath.mpf(1) / 2, mpmath.mpf(1) / 2)
    f = _left(c, (-1, 5), 3, 2)
    p = _on_bar(c, f, u, V)
    return mpmath.hypot(*p)


def _left(p, q, to_p, to_q):
    """The point at ``to_p`` from ``p`` and ``to_q`` from ``q``, left of the line from ``p`` to ``q``."""
    dx, dy = q[0] - p[0], q[1] - p[1]
    span = mpmath.hypot(dx, dy)
    along = (to_p**2 - to_q**2 + span**2) / (2 * span)
    across = mpmath.sqrt(to_p**2 - along**2)
    return p[0] + (along * dx - across * dy) / span, p[1] + (along * dy + across * dx) / span


def _on_bar(p, q, along, across):
    """``p + along (q - p) + across rot90(q - p)``."""
    dx, dy = q[0] - p[0], q[1] - p[1]
    return p[0] + along * dx - across * dy, p[1] + along * dy + across * dx


@pytest.mark.parametrize("eliminant", [U**2 - S, (U**2 - S) * (U**2 - S - 1)])
def test_values_meeting_at_zero_are_found(eliminant):
    """``u**2 = s``: its two values meet only at 0 (``s = 0``), where the square's polynomial has no
    discriminant at all; with ``u**2 = s + 1`` as well, the square's discriminant in ``c, s`` is a
    number. Against sympy's resultant of ``F`` and ``dF/du`` in ``u`` itself."""
    problem = Problem(sympy.expand(eliminant), U, U, CIRCLE, ())
    moving, _ = problem.half_angle()
    expected = sympy.resultant(moving, moving.diff(U), U)
    assert _signless(meeting_factors(problem)) == _signless(f for f, _ in sympy.factor_list(expected)[1])
