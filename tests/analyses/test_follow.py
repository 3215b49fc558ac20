"""``algkin.follow``: a mode followed by certified continuation on the scene's original equations,
against what is computed apart: each branch's closed form (``algkin.branches``) evaluated in balls
at the same input, and for the 3-RPR the discriminant of its forward kinematics' sextic (by hand, in sympy)."""

from fractions import Fraction

import flint
import pytest
import sympy

import algkin
from algkin.analyses.follow import follow
from algkin.branches import closed_forms
from algkin.errors import BudgetExceeded, UsageError
from algkin.evaluate import ARB, evaluate
from algkin.runtime.budget import Budget
from algkin.scene import compile_scene, load_scene
from tests.clocks import Clock


def _branches(name):
    scene = load_scene(name)
    compiled = compile_scene(scene, list(scene.points))
    (variables,) = [v for v in compiled.system.inputs.values()]
    return {b.label: b for b in closed_forms(compiled)}, variables


def _closed_form(branch, variables, degrees, unknown):
    """The branch's closed form of ``unknown`` at ``degrees`` (exact), in balls."""
    radians = flint.arb.pi() * flint.fmpq(degrees.numerator, degrees.denominator) / 180
    values = dict(zip(variables, (radians.cos(), radians.sin())))
    return evaluate(branch.values[unknown], values, ARB)


def _on_its_own_branch(followed, name):
    """Each sample's unknowns inside its branch's closed form at the same input, and off every other branch."""
    branches, variables = _branches(name)
    with flint.ctx.workprec(128):
        for sample in followed.samples:
            degrees = Fraction(sample.at)
            for label, branch in branches.items():
                on = all(ball.overlaps(_closed_form(branch, variables, degrees, u)) for u, ball in sample.values.items())
                assert on == (label == followed.mode), (label, sample.at)


@pytest.mark.parametrize("name, mode", [("chebyshev-lambda", "left"), ("chebyshev-lambda", "right"),
                                        ("fourbar", "left"), ("stephenson-iii", "B:left F:right")])
def test_a_mode_followed_through_a_full_turn_of_a_crank_rocker_is_its_labelled_branch(name, mode):
    followed = follow(name, mode=mode, start={next(iter(load_scene(name).inputs)): 0}, stop=360, digits=12)
    assert followed.ended == "reached" and followed.meeting is None
    assert followed.samples[0].at == "0" and followed.samples[-1].at == "360" and followed.steps >= 8
    assert followed.samples[0].points == followed.samples[-1].points  # a full turn closes
    _on_its_own_branch(followed, name)


@pytest.mark.parametrize("mode", ["left", "right"])
def test_a_dyad_next_to_its_fold_followed_with_a_huge_first_step_stays_on_its_mode(mode):
    """fourbar-near-toggle: 1/1000 from the change point, its two modes nearly meet at 180 degrees."""
    followed = follow("fourbar-near-toggle", mode=mode, start={"theta": 0}, stop=360, max_step=360)
    assert followed.ended == "reached" and "180" in [s.at for s in followed.samples]
    _on_its_own_branch(followed, "fourbar-near-toggle")


def _3rpr_discriminant_roots():
    """The real leg lengths r1 in [4, 13] where two of the 3-RPR's assembly modes meet, computed apart:
    P1 = (x, y), P2 = P1 + 5 (c, s), P3 = P1 + 5/2 (c, s) + 15/4 (-s, c) (catalog 3rpr); legs 2 and 3
    minus leg 1 are linear in (x, y); their solution put into leg 1 and c, s by the half-angle u, a
    sextic in u (Gosselin, Sefrioui and Richard); where its discriminant in u vanishes."""
    x, y, c, s, u, r = sympy.symbols("x y c s u r", real=True)
    a, b = 5 * c / 2 - sympy.Rational(15, 4) * s - 3, 5 * s / 2 + sympy.Rational(15, 4) * c - 8
    legs = [2 * x * (5 * c - 10) + (5 * c - 10) ** 2 + 10 * y * s + 25 * s ** 2 - (81 - r ** 2),
            2 * x * a + a ** 2 + 2 * y * b + b ** 2 - (64 - r ** 2)]
    corner = sympy.solve(legs, [x, y], dict=True)[0]
    closing = sympy.numer(sympy.together(corner[x] ** 2 + corner[y] ** 2 - r ** 2))
    in_u = sympy.numer(sympy.together(closing.subs({c: (1 - u ** 2) / (1 + u ** 2), s: 2 * u / (1 + u ** 2)})))
    sextic = next(f for f, _ in sympy.factor_list(sympy.expand(in_u))[1] if sympy.degree(f, u) == 6)
    roots = []
    for factor, _ in sympy.factor_list(sympy.discriminant(sympy.Poly(sextic, u), u))[1]:
        poly = sympy.Poly(factor, r)
        roots += [(Fraction(str(lo)), Fraction(str(hi))) for (lo, hi), _ in poly.intervals(eps=sympy.Rational(1, 10**40))
                  if 4 <= lo and hi <= 13]
    return roots


@pytest.fixture(scope="module")
def meetings():
    return _3rpr_discriminant_roots()


def test_3rpr_modes_followed_along_a_leg_meet_where_the_discriminant_vanishes(meetings):
    """From r1 = 6 (two real modes) up: both meet, in one interval holding a root of the discriminant."""
    ends = []
    for configuration in algkin.solve("3rpr", at={"r1": 6}).configurations:
        followed = follow("3rpr", mode=configuration.mode, start={"r1": 6}, stop=12)
        assert followed.ended == "meets" and followed.meeting["holds_zero"] and followed.meeting["proved"]
        lo, hi = Fraction(followed.meeting["from"]), Fraction(followed.meeting["to"])
        assert hi - lo < Fraction(1, 10**6)
        assert [root for root in meetings if lo <= root[0] and root[1] <= hi], (lo, hi, meetings)
        ends.append((lo, hi))
    assert len(ends) == 2 and max(lo for lo, _ in ends) <= min(hi for _, hi in ends)  # they meet each other


def test_inputs_near_a_meeting_are_written_apart_from_their_neighbours():
    """Steps near a meeting are short: each input still reads apart from the next, whatever ``digits``."""
    followed = follow("3rpr", mode="---", start={"r1": 6}, stop=12, digits=6)
    inputs = [sample.at for sample in followed.samples]
    assert len(set(inputs)) == len(inputs) and inputs[0] == "6"
    assert all(len(sample.points["P1"][0].replace(".", "").lstrip("0")) <= 6 for sample in followed.samples)


def test_3rpr_a_mode_followed_where_the_discriminant_has_no_root_reaches_its_end(meetings):
    assert not [root for root in meetings if root[1] >= 5 and root[0] <= 6]
    for configuration in algkin.solve("3rpr", at={"r1": 6}).configurations:
        followed = follow("3rpr", mode=configuration.mode, start={"r1": 6}, stop=5)
        assert followed.ended == "reached" and followed.samples[-1].at == "5"
        assert followed.mode == configuration.mode


def test_the_json_gives_how_it_ended_the_steps_and_each_sample():
    document = follow("fourbar-nongrashof", mode="left", start={"theta": 0}, stop=180, digits=8).to_json()
    assert set(document) >= {"scene", "mode", "input", "from", "to", "ended", "steps", "meeting", "samples"}
    assert document["ended"] == "meets" and document["steps"] == len(document["samples"]) - 1
    # the dead centre of a crank 2, ground 5, coupler 3, rocker 7/2: cos = (4 + 25 - 169/4) / 20
    dead_centre = sympy.deg(sympy.acos(sympy.Rational(4 + 25, 20) - sympy.Rational(169, 80)))
    assert Fraction(document["meeting"]["from"]) <= dead_centre.evalf(30) <= Fraction(document["meeting"]["to"])


@pytest.mark.parametrize("started", [True, False], ids=["deadline", "budget"])
def test_the_deadline_is_kept(started):
    """A budget not yet started is started by ``follow`` (as ``prepare`` does): it was an AttributeError."""
    budget = Budget(seconds=5, clock=Clock())
    with pytest.raises(BudgetExceeded, match="max_seconds=5: stopped after"):
        follow("chebyshev-lambda", mode="left", start={"angle": 0}, stop=360,
               deadline=budget.start() if started else budget)


@pytest.mark.parametrize("kwargs, said", [
    (dict(mode="up"), "mode='up': not a mode of chebyshev-lambda (modes: left, right)"),
    (dict(start={"theta": 0}), "start='theta': not an input of chebyshev-lambda (inputs: angle)"),
    (dict(stop=400), "stop='angle=400': expected a number of degrees in [0, 360]"),
    (dict(start={"angle": -1}), "start='angle=-1': expected a number of degrees in [0, 360]"),
    (dict(start={}), "start={}: expected one input and its value"),
    (dict(max_step=0), "max_step=0: expected a positive number"),
    # once taken: 3.6e302 steps, never ending (without a budget) and a sample kept at each
    (dict(max_step="1e-300"), "max_step='1e-300': would take over 100000 steps from 0 to 360; give at least "
                              "0.0036"),
    # 1e-100000 was read, then failed printing its denominator; 1e-1000000000 never came back from Fraction
    (dict(start={"angle": "1e-100000"}), "start='angle=1e-100000': decimal exponent out of range"),
    (dict(stop="1e-1000000000"), "stop='angle=1e-1000000000': decimal exponent out of range"),
    (dict(max_step="1e-1000000000"), "max_step='1e-1000000000': decimal exponent out of range"),
    (dict(at={"angle": 3}), "at='angle': is the input followed: give its value as the start only"),
    (dict(digits=0), "digits=0: expected a whole number of digits"),
    # these three went on: None followed solve's first branch; a list and a string failed inside (a TypeError,
    # an AttributeError at the first step)
    (dict(mode=None), "mode=None: expected a mode's label"),
    (dict(at=[("angle", 3)]), "at=[('angle', 3)]: expected a mapping"),
    (dict(deadline="10"), "deadline='10': expected an algkin.Budget"),
    # Python writes no integer of more than 4300 digits: the message itself was a ValueError
    (dict(stop=10**5000), "stop='angle=<an int of 16610 bits>': number too large"),
    (dict(max_step=10**5000), "max_step=<an int of 16610 bits>: "),
])
def test_bad_input_names_the_argument(kwargs, said):
    with pytest.raises(UsageError) as caught:
        follow("chebyshev-lambda", **{**dict(mode="left", start={"angle": 0}, stop=360), **kwargs})
    assert str(caught.value).startswith(said)


def test_a_mode_that_does_not_assemble_at_the_start_is_refused():
    with pytest.raises(UsageError, match="mode='left': does not assemble at theta = 150"):
        follow("fourbar-nongrashof", mode="left", start={"theta": 150}, stop=0)


def test_a_triad_mode_is_followed_from_an_angle_with_irrational_cos():
    """Once refused: points solved together took only multiples of 90 degrees."""
    followed = follow("stephenson-iii-triad", mode="+++", start={"theta": 10}, stop=30)
    assert (followed.samples[0].at, followed.samples[-1].at) == ("10", "30")


def test_the_facade_exports_it():
    followed = algkin.follow("chebyshev-lambda", mode="right", start={"angle": 0}, stop=90)
    assert type(followed) is algkin.Followed and followed.mode == "right" and followed.samples[-1].at == "90"


def test_the_result_is_a_frozen_value_its_balls_kept_out_of_equality():
    first, second = (follow("chebyshev-lambda", mode="left", start={"angle": 0}, stop=90, digits=10) for _ in range(2))
    assert first == second and hash(first) == hash(second)
    assert all(isinstance(ball, flint.arb) for ball in first.samples[-1].values.values())
    with pytest.raises(AttributeError):
        first.steps = 0
