"""Each eliminant comes from the equations its unknown depends on, not from later points."""

from algkin.derivation.tasks import equations_for
from algkin.scene import compile_scene, load_scene
from algkin.system import symbol


def test_a_dyad_eliminant_ignores_the_points_built_on_it():
    system = compile_scene(load_scene("stephenson-iii"), ["B", "F", "P"]).system
    equations, unknowns = equations_for(system, "B_y")
    assert sorted(unknowns) == ["B_x", "B_y"]
    assert all(not (e.free_symbols & {symbol(n) for n in ("F_x", "F_y", "P_x", "P_y")}) for e in equations)
    assert len(equations) == 2  # B is a four-bar's connector: its two circles, nothing more
    _, later = equations_for(system, "P_x")
    assert {"B_x", "B_y", "F_x", "F_y", "P_x"} <= set(later)
