"""``compile_scene`` refuses coordinates past what floats can square: a long chain of frames, each
link small, compounds its coefficients (before: an OverflowError from the elimination or export)."""

import pytest
import sympy

from algkin.errors import SceneError
from algkin.scene import compile_scene, load_scene_text

LINKS = 3000


def _chain(links):
    """O at the origin, A on the unit crank, P0 = O + (A - O) + rot90(A - O), then each P_k the frame
    of (A, P_{k-1}) at (1, 1): P_k = A + (P_{k-1} - A) + rot90(P_{k-1} - A)."""
    lines = ['name = "chain"', "[inputs]", 't = { range = [0, 360], unit = "deg" }', "[points]",
             "O = { fixed = [0, 0] }", 'A = { crank = "O", length = 1, input = "t" }',
             'P0 = { frame = ["O", "A"], at = [1, 1] }']
    lines += [f'P{k} = {{ frame = ["A", "P{k - 1}"], at = [1, 1] }}' for k in range(1, links)]
    return "\n".join([*lines, "[outputs]", f'P = "P{links - 1}"']) + "\n"


def _w(k):
    """By hand, in Gaussian integers: with A = c + i s, P0 = (1 + i) A and P_k - A = (1 + i)(P_{k-1} - A),
    so P_k = w_k A with w_k = 1 + i (1 + i)**k: P_k's x is Re(w_k) c - Im(w_k) s. (Re w_k, Im w_k)."""
    re, im = 0, 1  # i (1 + i)**0
    for _ in range(k):
        re, im = re - im, re + im  # times (1 + i)
    return 1 + re, im


def _first_past(bound):
    """The first k at which a coefficient of P_k passes ``bound``."""
    return next(k for k in range(LINKS) if max(map(abs, _w(k))) > bound)


def test_a_chain_of_frames_past_float_range_is_refused_at_the_first_point_past_it():
    k = _first_past(10**100)
    assert 660 < k < 670  # |w_k| is about 2**(k/2), past 1e100 = 2**332.2 near k = 664
    with pytest.raises(SceneError, match=rf"^chain.toml: points.P{k}: .*1e100") as raised:
        compile_scene(load_scene_text(_chain(LINKS), "chain.toml"))
    assert "floating-point" in str(raised.value)


def test_a_chain_just_short_of_it_compiles_to_the_coordinates_by_hand():
    k = _first_past(10**100) - 1
    compiled = compile_scene(load_scene_text(_chain(k + 1), "chain.toml"))
    x, _ = compiled.coordinates[f"P{k}"]
    c, s = sympy.symbols("c_t s_t", real=True)
    assert (x.coeff(c), x.coeff(s)) == (_w(k)[0], -_w(k)[1])


def test_a_requested_output_is_read_without_the_spaces_about_it():
    from algkin.scene import load_scene
    from algkin.scene.compile import resolve_outputs

    scene = load_scene("arm-string")
    assert [(o.name, o.kind, o.points) for o in resolve_outputs(scene, [" AB\n", " A.x "])] == \
        [("AB", "dist", ("A", "B")), ("A.x", "x", ("A",))]


@pytest.mark.parametrize(("arguments", "argument"), [
    ((5,), "outputs"),  # was a TypeError from iterating the number
    (("B",), "outputs"),  # a lone name: its letters would be taken for names
    ((["B"], "al"), "params"),  # "al" read as the dimensions a and l
    ((["B", 7],), "outputs"),
    ((["B"], ["a", "a"]), "params"),
])
def test_compile_scenes_arguments_are_checked_naming_them(arguments, argument):
    from algkin.errors import UsageError
    from algkin.scene import load_scene

    with pytest.raises(UsageError) as raised:
        compile_scene(load_scene("fourbar"), *arguments)
    assert raised.value.argument == argument
