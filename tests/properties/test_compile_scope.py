"""A scene compiles only what the asked-for output needs (what ``show`` says it compiles: docs/cli/show.md).

The expected unknowns, parameters and inputs come from the construction graph, read off by
hand: A is a crank (explicit) on O; B a dyad on A and D (four-bar) or a slider on L and A
(on a fixed line, or the line through L and A); P a frame on A and B; O, D and L are fixed,
D at ``O + g*(u, v)``. An inversor's P hangs on the twin E instead (a kite: P on the bar AE,
so B is not needed and E is an ordinary dyad), or on B and E (a cell: P the rhombus ABPE
closed, the mirror image of A; its lengths are l, so p and q are not needed).
"""

import pytest
from hypothesis import given, settings, strategies as st

from algkin.scene import compile_scene
from algkin.testing import strategies

# output -> (unknowns, four-bar parameters, slider-crank parameters, moves with the input)
NEEDS = {
    "A": ({"A_x", "A_y"}, {"a"}, {"r"}, True),
    "B": ({"B_x", "B_y"}, {"a", "g", "l", "m"}, {"r", "l"}, True),
    "B.x": ({"B_x", "B_y"}, {"a", "g", "l", "m"}, {"r", "l"}, True),
    "P": ({"B_x", "B_y", "P_x", "P_y"}, {"a", "g", "l", "m", "p", "q"}, {"r", "l", "p", "q"}, True),
    "P.y": ({"B_x", "B_y", "P_y"}, {"a", "g", "l", "m", "p", "q"}, {"r", "l", "p", "q"}, True),
    "dist(O, A)": ({"dist_O_A"}, {"a"}, {"r"}, True),
    "dist(A, B)": ({"B_x", "B_y", "dist_A_B"}, {"a", "g", "l", "m"}, {"r", "l"}, True),
    "dist(O, L)": ({"dist_O_L"}, None, set(), False),
    "dist(O, D)": ({"dist_O_D"}, {"g"}, None, False),
}


FOUR_BAR = {"a", "g", "l", "m"}
CELL = {"B_x", "B_y", "E_x", "E_y", "P_x", "P_y"}
INVERSORS = {  # output -> (unknowns, parameters), where they differ from the four-bar's
    "inversor-kite": {"P": ({"E_x", "E_y", "P_x", "P_y"}, FOUR_BAR | {"p", "q"}),
                      "P.y": ({"E_x", "E_y", "P_y"}, FOUR_BAR | {"p", "q"})},
    "inversor-cell": {"P": (CELL, FOUR_BAR), "P.y": (CELL, FOUR_BAR)},
}


@pytest.mark.slow  # one of the largest property runs (10-25 s): the slow set, which CI runs
@settings(max_examples=590)
@given(strategies.scenes(), st.sampled_from(sorted(NEEDS)))
def test_only_what_the_output_needs(scene, output):
    unknowns, four_bar, slider, moves = NEEDS[output]
    if output in INVERSORS.get(scene.name, {}):
        unknowns, four_bar = INVERSORS[scene.name][output]
    parameters = four_bar if "D" in scene.points else slider
    if parameters is None:
        with pytest.raises(ValueError, match="unknown point"):
            compile_scene(scene, [output])
        return
    system = compile_scene(scene, [output], params=sorted(scene.parameters)).system
    assert set(system.unknowns) == unknowns
    assert set(system.parameters) == parameters
    assert set(system.inputs) == ({"theta"} if moves else set())
    used = {str(v) for e in system.equations for v in e.free_symbols}
    assert used == unknowns | parameters | ({"c_theta", "s_theta"} if moves else set())
    assert len(system.equations) == len(unknowns) + moves  # one per unknown, and c**2 + s**2 = 1
