"""Toggles of four-bars against the law of cosines, and the Grashof class against the rule."""

import math
from fractions import Fraction
from importlib.resources import files

import pytest
import sympy
from hypothesis import assume, example, given, settings, strategies as st

from algkin.derivation.prepared import prepare
from algkin.scene import compile_scene, load_scene_text
from algkin.analyses.toggles import discriminant_factors, grashof, toggles

from ..derivation.work import counting


def four_bar(crank, ground, coupler, rocker):
    return load_scene_text(f"""
name = "four-bar"
[inputs]
angle = {{ range = [0, 360], unit = "deg" }}
[points]
O = {{ fixed = [0, 0] }}
D = {{ fixed = ["{ground}", 0] }}
A = {{ crank = "O", length = "{crank}", input = "angle" }}
B = {{ dyad = ["A", "D"], lengths = ["{coupler}", "{rocker}"], branch = "left" }}
[outputs]
B = "B"
""")


def law_of_cosines(crank, ground, coupler, rocker):
    """Crank angles where |AD| = coupler + rocker (extended) or |coupler - rocker| (folded)."""
    found = []
    for kind, span in (("extended", coupler + rocker), ("folded", abs(coupler - rocker))):
        cosine = (crank**2 + ground**2 - span**2) / (2 * crank * ground)
        if -1 < cosine < 1:
            angle = math.degrees(math.acos(cosine))
            found += [(angle, kind), (360 - angle, kind)]
    return sorted(found)


def test_non_grashof_dead_centres_by_hand():
    result = toggles(four_bar(3, 4, 2, "5/2"))
    assert result.grashof["class"] == "non-grashof (triple rocker)"
    expected = law_of_cosines(3, 4, 2, 2.5)
    assert [(round(t.input_deg, 12), t.kind) for t in result.toggles] == [(round(a, 12), k) for a, k in expected]
    for toggle, (angle, _) in zip(result.toggles, expected):
        assert toggle.enclosure.contains(angle) or abs(toggle.enclosure.mid() - angle) < 1e-12
        assert toggle.enclosure.rad() < 1e-15


def test_chebyshev_lambda_has_none_and_is_a_crank_rocker():
    result = toggles("chebyshev-lambda")
    assert result.toggles == ()
    assert result.grashof["class"] == "crank-rocker"  # 1 + 5/2 < 2 + 5/2, crank shortest
    # disc(B_y) has the factor c - 2 (equal y, different points), which is not a toggle.
    assert any(a["factor"] == "c_angle - 2" for a in result.artefacts)


def grashof_by_rule(crank, ground, coupler, rocker):
    bars = sorted([crank, ground, coupler, rocker])
    margin = bars[1] + bars[2] - bars[0] - bars[3]
    if margin < 0:
        return "non-grashof (triple rocker)"
    if margin == 0:
        return "change point"
    return {crank: "crank-rocker", ground: "double crank", coupler: "double rocker"}.get(bars[0], "rocker-crank")


lengths = st.fractions(min_value=Fraction(1, 2), max_value=8, max_denominator=12)


@settings(max_examples=20)
@given(lengths, lengths, lengths, lengths)
def test_random_four_bars_match_the_law_of_cosines(crank, ground, coupler, rocker):
    bars = sorted([crank, ground, coupler, rocker])
    assume(bars[3] < bars[0] + bars[1] + bars[2])  # it closes somewhere
    assume(len(set(bars)) == 4 and bars[1] + bars[2] != bars[0] + bars[3])  # no change point
    expected = law_of_cosines(*(float(v) for v in (crank, ground, coupler, rocker)))
    assume(all(min(abs(a), abs(a - 180), abs(a - 360)) > 1e-6 for a, _ in expected))
    # The longest bar is shorter than the other three together: a quadrilateral exists, so
    # some crank angle assembles it and "can never assemble" would be a bug, not a pass.
    result = toggles(four_bar(crank, ground, coupler, rocker))
    assert [t.kind for t in result.toggles] == [k for _, k in expected]
    assert [t.input_deg for t in result.toggles] == pytest.approx([a for a, _ in expected], abs=1e-9)
    assert result.grashof["class"] == grashof_by_rule(crank, ground, coupler, rocker)


def test_grashof_class_of_a_tilted_change_point_stays_exact():
    # Found by the strategies: ground 1649/132 along (-4/5, 3/5) from O = (1, 0). By hand,
    # 1/2 + 1649/132 = 1715/132 = 87/11 + 61/12: a change point. nsimplify once turned the
    # pivot's coordinate 1 - 4*g/5 = -1319/165 into a product of radicals, so "non-grashof".
    scene = load_scene_text("""
[parameters]
g = "1649/132"
[inputs]
angle = { range = [0, 360], unit = "deg" }
[points]
O = { fixed = [1, 0] }
D = { fixed = ["1 - 4*g/5", "3*g/5"] }
A = { crank = "O", length = "1/2", input = "angle" }
B = { dyad = ["A", "D"], lengths = ["87/11", "61/12"], branch = "left" }
[outputs]
B = "B"
""")
    found = grashof(compile_scene(scene, ["B"]))
    assert found["class"] == "change point" and found["margin"] == "0"
    assert found["bars"]["ground"] == "1649/132"


def slider_crank(crank, rod, offset):
    return load_scene_text(f"""
name = "slider-crank"
[inputs]
theta = {{ range = [0, 360], unit = "deg" }}
[points]
O = {{ fixed = [0, 0] }}
L = {{ fixed = [0, "{offset}"] }}
A = {{ crank = "O", length = "{crank}", input = "theta" }}
B = {{ slider = {{ through = "L", direction = [1, 0] }}, distance = {{ to = "A", length = "{rod}" }}, branch = "ahead" }}
[outputs]
B = "B"
""")


def tangent_angles(crank, rod, offset):
    """By hand: the rod reaches the line y = offset only while |crank*sin(theta) - offset| <= rod;
    the circle about A is tangent to the line where crank*sin(theta) = offset +- rod."""
    found = []
    for height in (offset + rod, offset - rod):
        if -1 < height / crank < 1:
            angle = math.degrees(math.asin(height / crank)) % 360
            found += [angle, (180 - angle) % 360]
    return sorted(found + [360.0] * found.count(0.0))  # the range [0, 360] holds 0 deg twice


def test_slider_tangent_toggles_by_hand():
    # crank 3, rod 1, line y = 1/2: sin(theta) = 1/2 (30, 150 deg) or -1/6 (189.59, 350.41 deg).
    result = toggles(slider_crank(3, 1, "1/2"))
    assert [t.kind for t in result.toggles] == ["tangent"] * 4 and {t.point for t in result.toggles} == {"B"}
    assert [t.input_deg for t in result.toggles] == pytest.approx(
        [30, 150, 180 + math.degrees(math.asin(1 / 6)), 360 - math.degrees(math.asin(1 / 6))], abs=1e-12)
    assert result.toggles[0].enclosure.contains(30) and result.toggles[1].enclosure.contains(150)
    assert result.grashof is None


def test_catalog_slider_crank_turns_without_toggles():
    # rod 3 > crank 1 + offset 1/2: the rod always reaches the line, twice.
    assert toggles("slider-crank").toggles == ()


@settings(max_examples=15)
@given(lengths, lengths, st.fractions(min_value=-4, max_value=4, max_denominator=6))
@example(Fraction(1, 2), Fraction(1, 2), Fraction(-4))  # 4 - 1/2 > 1/2: never reaches the line
def test_random_slider_cranks_match_the_arcsine(crank, rod, offset):
    # crank*sin(theta) = offset +- rod exactly at +-crank would be a double root: left out
    expected = tangent_angles(*(float(v) for v in (crank, rod, offset)))
    assume(all(abs(abs(float(offset) + sign * float(rod)) - float(crank)) > 1e-9 for sign in (1, -1)))
    if abs(offset) - crank > rod:  # the rod never reaches the line: refused, and only then
        with pytest.raises(ValueError, match="can never assemble"):
            toggles(slider_crank(crank, rod, offset))
        return
    found = toggles(slider_crank(crank, rod, offset)).toggles
    assert [t.input_deg for t in found] == pytest.approx(expected, abs=1e-9)


def test_toggles_compile_and_branch_the_scene_once_with_its_artefacts(monkeypatch):
    # The artefacts' eliminants (B_x and B_y of the four-bar's one dyad) reuse the scene the
    # toggles compiled and branched: one compilation, one set of branches.
    work = counting(monkeypatch)
    _, done = work(lambda: toggles("fourbar"))
    assert done == {"compile_scene": 1, "closed_forms": 1, "eliminate": 2}
    prepared = prepare("fourbar", outputs=["B"])
    found, done = work(lambda: toggles(prepared))
    assert done == {"compile_scene": 0, "closed_forms": 0, "eliminate": 2}
    assert found.to_json() == toggles("fourbar").to_json()


def test_a_scene_file_given_as_a_path_object(tmp_path):
    # as the other analyses take it: a catalog name, a path (text or pathlib.Path) or a Scene
    path = tmp_path / "lambda.toml"
    path.write_text(files("algkin.catalog").joinpath("chebyshev-lambda.toml").read_text(encoding="utf-8"))
    found = toggles(path, artefacts=False)
    assert (found.toggles, found.grashof["class"]) == ((), "crank-rocker")  # as the module's example says


U, C, S, K = (sympy.Symbol(n) for n in ("u", "c_t", "s_t", "k"))
TERMS = st.lists(st.tuples(st.integers(-6, 6), st.integers(0, 3), st.integers(0, 2), st.integers(0, 2), st.integers(0, 1)),
                 min_size=2, max_size=7)


@settings(max_examples=60, deadline=None)
@given(TERMS, st.fractions(-3, 3, max_denominator=4))
def test_discriminant_factors_are_sympys_factor_list_in_its_order(terms, k):
    # eliminant-like polynomials in u over the input's c, s and a dimension k given a value
    polynomial = sympy.Add(*[a * U**e * C**i * S**j * K**m for a, e, i, j, m in terms])
    assume(sympy.degree(polynomial, U) >= 2)
    values = {K: sympy.Rational(k.numerator, k.denominator)}
    expected = sympy.factor_list(sympy.expand(sympy.discriminant(polynomial, U).xreplace(values)))[1]
    assert [str(f) for f in discriminant_factors(polynomial, U, values)] == [str(f) for f, _ in expected]


def test_a_toggle_where_an_earlier_dyad_cannot_assemble_is_none():
    # Hart's inversor (a = 4, b = 2, r = 1): D is on A = 2 (cos, sin) and W = 2Z - A, Z = (1, 0), at b = 2
    # and 2r = 2, so |AW|**2 = 4 |Z - A|**2 = 20 - 16 cos: D closes where cos >= 1/4 (extended at
    # cos = 1/4). C, built on D, "folded" at 120 and 240 degrees by its eliminated condition, where
    # |AW|**2 = 28 > 16: no real mechanism there, so no toggle (it was listed, certified).
    found = toggles("hart-inversor", artefacts=False)
    d = sorted(t.input_deg for t in found.toggles if t.point == "D")
    assert d == pytest.approx([math.degrees(math.acos(1 / 4)), 360 - math.degrees(math.acos(1 / 4))], abs=1e-12)
    for t in found.toggles:
        assert math.cos(math.radians(t.input_deg)) >= 1 / 4 - 1e-12, t  # where D assembles
    assert not any(abs(t.input_deg - deg) < 1e-6 for t in found.toggles for deg in (120, 240))
