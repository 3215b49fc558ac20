"""A family's design equals the extremum derived afresh for it, and the four-bar's by hand."""

import math
from fractions import Fraction

import pytest
import sympy

from algkin.analyses.extremum import extremum
from algkin.analyses.extremum.family import extremum_family
from algkin.errors import AlgkinError, UsageError
from algkin.scene.load import load_scene
from algkin.scene.settings import with_values

OUTPUT = "angle(A, B, D)"  # the transmission angle, at the coupler-rocker joint B

# (a, d, l, m): crank, ground, coupler, rocker
CRANK_ROCKERS = [(1, 4, 3, "7/2"), (1, 4, 3, 3), ("1/2", 3, "5/2", "7/2"), ("3/2", "9/2", 4, "7/2")]
DOUBLE_CRANKS = [(3, 1, "7/2", 4), ("5/2", "3/4", 3, "5/2")]
NON_GRASHOF = [(2, 5, 3, "7/2"), ("3/2", "7/2", 1, "7/2"), ("3/2", 4, 3, "7/3"), (3, 4, "3/2", 2)]
NEAR_CHANGE_POINT = [(1, 4, 3, "2001/1000"), (1, 4, 3, "1999/1000"), (3, 2, "5/2", "7/2"), (1, 4, 2, 3)]
GRID = [(a, d, 3, m) for a in ("1/2", "5/4", 2) for d in (3, 4) for m in ("5/2", "7/2")]


def _values(design):
    return dict(zip("adlm", design))


@pytest.fixture(scope="module")
def family():
    return extremum_family("fourbar", OUTPUT, ["a", "d", "l", "m"])


def _same(found, expected):
    assert len(found.critical_points) == len(expected.critical_points)
    for got, want in zip(found.critical_points, expected.critical_points):
        assert got.kind == want.kind
        assert float(got.input_deg) == pytest.approx(float(want.input_deg), abs=1e-12)
        assert (got.value != got.value and want.value != want.value) or \
            float(got.value) == pytest.approx(float(want.value), abs=1e-12)
    for key in ("minimum", "maximum"):
        assert [str(e) for e in found.exact[key]] == [str(e) for e in expected.exact[key]]
    assert found.stationary == expected.stationary
    assert (found.scene, found.input, found.range, dict(found.parameters)) == \
        (expected.scene, expected.input, expected.range, dict(expected.parameters))


@pytest.mark.parametrize("design", CRANK_ROCKERS + DOUBLE_CRANKS + NON_GRASHOF + NEAR_CHANGE_POINT + GRID)
def test_design_equals_the_extremum_derived_afresh(family, design):
    expected = extremum(with_values(load_scene("fourbar"), _values(design)), OUTPUT)
    found = family.at(_values(design))
    _same(found, expected)
    assert family.fell_back == 0


@pytest.mark.parametrize("design", CRANK_ROCKERS + DOUBLE_CRANKS)
def test_turning_crank_extremes_by_hand(family, design):
    # cos(mu) = (l^2 + m^2 - a^2 - d^2 + 2 a d cos(theta)) / (2 l m), |AD|^2 = a^2 + d^2 - 2 a d cos(theta):
    # with the crank turning fully it is extreme where cos(theta) is, at 0 (least angle) and 180 degrees
    a, d, l, m = (Fraction(str(x)) for x in design)
    at_0 = (l**2 + m**2 - (d - a) ** 2) / (2 * l * m)
    at_180 = (l**2 + m**2 - (d + a) ** 2) / (2 * l * m)
    found = family.at(_values(design))
    assert (float(found.minimum.input_deg), float(found.maximum.input_deg)) == (0.0, 180.0)
    assert float(found.minimum.value) == pytest.approx(math.degrees(math.acos(at_0)), abs=1e-12)
    assert float(found.maximum.value) == pytest.approx(math.degrees(math.acos(at_180)), abs=1e-12)
    for key, cos in (("minimum", at_0), ("maximum", at_180)):  # sympy writes acos(1/2) as pi/3
        via = sympy.Rational(cos.numerator, cos.denominator)
        assert [str(e) for e in found.exact[key]] == [str(180 * sympy.acos(via) / sympy.pi), str(via)]


def test_non_grashof_extreme_at_its_dead_centre(family):
    # a = 2, d = 5, l = 3, m = 7/2: the crank stops where |AD| = l + m, cos(theta) = (4 + 25 - 169/4)/20 = -53/80;
    # there coupler and rocker are stretched out, the transmission angle 180 degrees
    found = family.at({"a": 2, "d": 5, "l": 3, "m": "7/2"})
    assert found.maximum.kind == "dead centre"
    assert float(found.maximum.input_deg) == pytest.approx(math.degrees(math.acos(-53 / 80)), abs=1e-12)
    assert [str(e) for e in found.exact["maximum"]] == ["180", "-1"]


def test_design_that_does_not_assemble_fails_as_extremum_does(family):
    design = {"a": 1, "d": 10, "l": 1, "m": 1}  # |AD| >= 9 > l + m: never assembles
    with pytest.raises(AlgkinError) as afresh:
        extremum(with_values(load_scene("fourbar"), design), OUTPUT)
    fell_back = family.fell_back
    with pytest.raises(type(afresh.value)):
        family.at(design)
    assert family.fell_back == fell_back + 1


def test_values_not_given_keep_the_scene_defaults(family):
    assert family.at({"m": "7/2"}) == family.at({"a": 1, "d": 4, "l": 3, "m": Fraction(7, 2)})


@pytest.mark.parametrize("values", [{"p": 1}, {"a": "one"}, {"a": 1.5j}])
def test_bad_values_are_refused_in_one_line(family, values):
    with pytest.raises(UsageError, match="values"):
        family.at(values)
