"""With two dimensions symbolic, where the closed form holds (the defaults' cell of its events' signs)
holds no design the scene refuses: a length of 0 or less (a mechanism has no rocker of length -1)."""

import pytest
import sympy

from algkin.analyses.extremum import extremum
from algkin.scene import load_scene
from algkin.scene.compile import length_not_positive


@pytest.mark.parametrize("scene, output, params, outside", [
    # the events' signs alone: |a - m| < 2 < a + m and |a - m| < 8 -- (7/2, -1) among them
    ("fourbar-nongrashof", "B.y", ["a", "m"], {"a": sympy.Rational(7, 2), "m": -1}),
    # the events' signs alone: c - r > 0 -- any crank r < 0 among them
    ("inverted-slider-crank", "stroke", ["r", "c"], {"r": -2, "c": 5}),
])
def test_where_it_holds_leaves_out_negative_lengths(scene, output, params, outside):
    negative = next(name for name, value in outside.items() if value < 0)
    value = float(outside[negative])
    assert length_not_positive(load_scene(scene), negative, (value, value)) is not None  # the scene refuses it
    form = extremum(scene, output, params=params).closed_form
    at = {sympy.Symbol(name, real=True): sympy.sympify(value) for name, value in outside.items()}
    assert not all(bool(condition.xreplace(at)) for condition in form.valid_when), form.valid_when_text
    assert f"{negative} > 0" in form.valid_when_text
