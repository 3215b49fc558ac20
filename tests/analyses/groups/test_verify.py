"""``verify`` on a scene with points solved together: the eliminant's modes against proved numeric
solutions of the original equations, none missing, none extra."""

import attrs
import pytest

from algkin.analyses.groups.scene import GroupScene
from algkin.analyses.groups.verify import verify_groups
from algkin.scene import load_scene_text


@pytest.mark.parametrize("name", ["stephenson-iii-triad", "3rpr", "3rpr-six-modes"])
def test_every_mode_matches_one_proved_solution(name):
    found = verify_groups(name, samples=6)
    v = found.verification
    assert v["passed"] and v["compared"] > 0 and v["max_abs_error"] < 1e-30, v["failures"]


def test_a_solution_the_eliminant_lost_matches_no_mode(monkeypatch):
    real = GroupScene.modes

    def fewer(self, sample, *, bits=128):
        return [group[1:] for group in real(self, sample, bits=bits)]

    monkeypatch.setattr(GroupScene, "modes", fewer)
    v = verify_groups("3rpr", samples=4).verification
    assert not v["passed"] and any("matches no mode" in f for f in v["failures"])


def test_a_mode_no_proved_solution_holds_is_missing(monkeypatch):
    real = GroupScene.modes

    def moved(self, sample, *, bits=128):
        return [tuple(attrs.evolve(m, values={u: b + 1 for u, b in m.values.items()}) for m in group)
                for group in real(self, sample, bits=bits)]

    monkeypatch.setattr(GroupScene, "modes", moved)
    v = verify_groups("3rpr", samples=4).verification
    assert not v["passed"] and any("(missing)" in f for f in v["failures"])


def test_nothing_compared_is_no_pass():
    scene = load_scene_text('''
[inputs]
r = { range = [1, 2], unit = "length" }
[points]
A = { fixed = [0, 0] }
B = { fixed = [10, 0] }
P = { unknown = true }
[constraints]
a = "dist(A, P) = r"
b = "dist(B, P) = 3"
''', "apart.toml")
    v = verify_groups(scene, samples=3).verification
    assert not v["passed"] and v["compared"] == 0 and "nothing compared" in v["failures"][-1]
