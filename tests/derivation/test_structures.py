"""A design that assembles at one input only is a structure, said so; one that assembles on a short
stretch only is verified with its samples in that stretch. Ends by the law of cosines, by hand."""

import math

import pytest

import algkin.verify.check as check
from algkin.derivation.assembles import STRUCTURE
from algkin.derivation.pipeline import curve
from algkin.errors import SceneError
from algkin.ui.cli import main

# The catalog four-bar: O = (0, 0), D = (d, 0), A on the crank of length a at angle theta, B on
# circles of radii l = 3 about A and m = 7/2 about D. B exists while |AD| <= l + m = 13/2, and
# |AD|^2 = a^2 + d^2 - 2 a d cos(theta) >= (d - a)^2, equal at theta = 0 only.
# With a = 5/6, d = 22/3: d - a = 44/6 - 5/6 = 39/6 = 13/2 = l + m (a + l = d - m: 23/6 both):
# B exists at theta = 0 only, the coupler and rocker stretched in one line: a structure.
STILL = {"a": "5/6", "d": "22/3"}


def test_a_four_bar_that_reaches_across_at_one_angle_only_is_a_structure():
    with pytest.raises(SceneError, match=STRUCTURE) as raised:
        curve("fourbar", "P", set=STILL)
    assert "points.B: assembles only at theta = 0° (with a=5/6, d=22/3, l=3, m=7/2)" in str(raised.value)


def test_the_command_prints_no_curve_for_it(capsys):
    # bad input, as a design that never assembles (d a little larger) is: exit 2, one line, no curve
    assert main(["curve", "fourbar", "--point", "P", "--set", "a=5/6", "--set", "d=22/3"]) == 2
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1
    assert err.endswith("assembles only at theta = 0° (with a=5/6, d=22/3, l=3, m=7/2): a structure, not a motion\n")


def test_a_short_stretch_of_motion_is_sampled_where_it_assembles(monkeypatch):
    # a = 1, d = 7499/1000: |AD| <= 13/2 while cos(theta) >= (1 + d^2 - (13/2)^2) / (2 d),
    # theta within 2.39 degrees of 0: a stretch of 4.8 degrees of the turn
    d = 7499 / 1000
    end = math.acos((1 + d * d - 6.5 ** 2) / (2 * d))
    assert 2.38 < math.degrees(end) < 2.40
    drawn = []
    solve = check._check_batch

    def spy(report, plan, angles, *, rng, worst):
        drawn.extend(angles["theta"].tolist())
        return solve(report, plan, angles, rng=rng, worst=worst)

    monkeypatch.setattr(check, "_check_batch", spy)
    found = curve("fourbar", "P", set={"d": "7499/1000"})
    assert found.verification.passed and found.verification.samples == 40
    # both modes compared on every sample: each sample within the stretch
    assert found.verification.compared == 80
    assert drawn and all(min(t, 2 * math.pi - t) <= end + 1e-9 for t in drawn)
    # the coupler curve of a four-bar: the tricircular sextic, its extraneous factor dropped
    assert (found.degree, found.circularity) == (6, 3)


def test_an_irreducible_curve_says_why_even_when_its_factor_was_chosen_at_the_witnesses():
    # Peaucellier's P: the line 2 r x = L^2 - s^2, kept among the eliminant's factors at the
    # witnesses (no cheaper proof): a degree-1 factor is irreducible, and the JSON says why
    # instead of irreducibility: null beside irreducible: true (issue 35 item 7)
    document = curve("peaucellier-lipkin", "P", samples=0).to_json()
    assert document["degree"] == 1 and document["irreducible"] is True
    assert document["irreducibility"].startswith("irreducible over QQ: the one factor")


def test_a_structure_of_exact_dimensions_says_so_without_an_empty_list():
    # The four-bar above with its lengths written in the file, no parameter: 'with ' named none
    text = """name = "still"
[inputs]
theta = { range = [0, 360], unit = "deg" }
[points]
O = { fixed = [0, 0] }
D = { fixed = ["22/3", 0] }
A = { crank = "O", length = "5/6", input = "theta" }
B = { dyad = ["A", "D"], lengths = [3, "7/2"], branch = "left" }
[outputs]
B = "B"
"""
    from algkin.scene import load_scene_text

    with pytest.raises(SceneError, match=STRUCTURE) as raised:
        curve(load_scene_text(text, "still.toml"), "B")
    assert str(raised.value) == "still.toml: points.B: assembles only at theta = 0°: a structure, not a motion"
