"""The compiled evaluator is the stabilised numpy form, fused: same values on every accuracy case,
NaN where a branch cannot assemble, numpy again where numba is absent or does not pay."""

import os
import sys

import numpy as np
import pytest

from algkin.bench.accuracy import sample_cases, Subject
from algkin.errors import UsageError
from algkin.branches import closed_forms
from algkin.branches.stable import StableBranch
from algkin.evaluate import fused
from algkin.evaluate.fused import COLD_SAMPLES, Kernel, numba_available
from algkin.evaluate.trace import trace
from algkin.scene import compile_scene, load_scene

needs_numba = pytest.mark.skipif(not numba_available(), reason="numba (the fast extra) is not installed")
ULPS = 4  # the compiled and numpy forms round the same operations; libm's and numpy's sqrt are exact


def _ulps(a, b):
    """|a - b| in units of the last place of the larger, NaN where either is NaN."""
    return np.abs(a - b) / np.spacing(np.maximum(np.abs(a), np.abs(b)))


# Each an accuracy run's subject (scene, output): a crank-rocker, a near-change-point four-bar (its
# near-fold case), a non-Grashof one (toggles to 1e-14), a slider-crank (tangent toggles), an explicit
# distance.
SUBJECTS = [("chebyshev-lambda", "P"), ("fourbar-near-toggle", "B"), ("fourbar-nongrashof", "B"),
            ("slider-crank", None), ("arm-string", "dist(A, B)")]


@pytest.fixture(scope="module", params=SUBJECTS, ids=[s for s, _ in SUBJECTS])
def subject_cases(request):
    name, of = request.param
    scene = load_scene(name)
    of = of or next(iter(scene.outputs))
    subject = Subject(scene, of)
    return subject, sample_cases(subject, 100, np.random.default_rng(3))


@needs_numba
def test_compiled_equals_the_stabilised_numpy_form_on_every_accuracy_case(subject_cases):
    subject, cases = subject_cases
    for case, theta in cases.items():
        numpy_values = subject.stable(theta)
        compiled = subject.stable(theta, engine="compiled")
        assert (np.isnan(numpy_values) == np.isnan(compiled)).all(), case
        both = ~np.isnan(numpy_values)
        assert _ulps(numpy_values[both], compiled[both]).max(initial=0) <= ULPS, case


@needs_numba
def test_compiled_is_within_the_stabilised_error_of_the_certified_truth(subject_cases):
    subject, cases = subject_cases
    theta = np.concatenate(list(cases.values()))
    certified = subject.reference.certify(theta)
    theta, truth = theta[certified.ok], certified.points[:, certified.ok]
    size = np.abs(truth).max(axis=0)
    numpy_error = np.abs(subject.stable(theta) - truth).max(axis=0) / size
    compiled_error = np.abs(subject.stable(theta, engine="compiled") - truth).max(axis=0) / size
    assert (compiled_error <= numpy_error + ULPS * 2.0**-52).all()


@needs_numba
def test_a_branch_that_cannot_assemble_is_nan_never_the_other_branch():
    # fourbar-nongrashof's rocker cannot turn through a full circle: the inputs past its toggles are NaN
    compiled = compile_scene(load_scene("fourbar-nongrashof"), ["B"])
    left, right = (StableBranch(compiled, b).kernel() for b in closed_forms(compiled))
    theta = np.linspace(0, 2 * np.pi, 3601)
    bx_left, by_left = left(theta, engine="compiled")
    bx_right, by_right = right(theta, engine="compiled")
    blocked = np.isnan(bx_left)
    assert 0 < blocked.sum() < theta.size
    assert (np.isnan(bx_right) == blocked).all()
    # where both assemble they are mirror images across the base line: never the same point
    assemble = ~blocked & (np.hypot(bx_left - bx_right, by_left - by_right) > 0)
    assert assemble.sum() > theta.size / 4


def test_without_numba_the_fallback_gives_the_numpy_values(monkeypatch):
    compiled = compile_scene(load_scene("chebyshev-lambda"), ["B"])
    kernel = StableBranch(compiled, closed_forms(compiled)[0]).kernel()
    theta = np.random.default_rng(1).uniform(-10, 10, 5000)
    expected = kernel(theta, engine="numpy")
    monkeypatch.setitem(sys.modules, "numba", None)  # import numba now raises ImportError
    assert not numba_available()
    assert kernel.engine(10**9, "compiled") == "numpy"
    for got, want in zip(kernel(theta, engine="compiled"), expected):
        np.testing.assert_array_equal(got, want)


def test_auto_leaves_a_few_hundred_samples_to_numpy(tmp_path, monkeypatch):
    monkeypatch.setenv("ALGKIN_CACHE_DIR", str(tmp_path))
    kernel = Kernel(trace(lambda t: [t * 3.0 + 1.0], ["t"]), lambda t: [t * 3.0 + 1.0])
    assert kernel.engine(200) == "numpy"
    assert kernel.engine(COLD_SAMPLES - 1) == "numpy"
    assert kernel.engine(200, "numpy") == "numpy"
    with pytest.raises(Exception, match="engine"):
        kernel.engine(200, "fortran")


@needs_numba
def test_the_kernel_is_cached_on_disk_and_loaded_by_its_hash(tmp_path, monkeypatch):
    monkeypatch.setenv("ALGKIN_CACHE_DIR", str(tmp_path))
    program = trace(lambda t: [np.sqrt((1 - t) * (1 + t)), np.where(t > 0, t, -t)], ["t"])
    kernel = Kernel(program, None)
    t = np.linspace(-2, 2, 40_001)  # three blocks and a bit: every block boundary crossed
    root, size = kernel(t, engine="compiled", threads=2)
    with np.errstate(invalid="ignore"):
        np.testing.assert_array_equal(root, np.sqrt((1 - t) * (1 + t)))
    np.testing.assert_array_equal(size, np.abs(t))
    assert kernel.path.parent == tmp_path and kernel.path.read_text() == kernel.source
    assert kernel.loaded and kernel.engine(1) == "compiled"
    monkeypatch.setitem(fused._loaded, kernel.key, fused._loaded[kernel.key])
    again = Kernel(program, None)  # the same source: the same file, the module already loaded
    assert again.key == kernel.key and again.loaded


@needs_numba
@pytest.mark.parametrize("name", ["peaucellier-lipkin", "stephenson-iii", "five-bar", "whitworth-quick-return"])
def test_every_point_of_inversors_six_bars_and_two_inputs_compiles_to_the_numpy_values(name):
    compiled = compile_scene(load_scene(name), list(load_scene(name).points))
    kernel = StableBranch(compiled, next(b for b in closed_forms(compiled) if b.selected)).kernel()
    rng = np.random.default_rng(7)
    angles = [rng.uniform(-7, 7, 20_000) for _ in compiled.circles]
    for want, got in zip(kernel(*angles, engine="numpy"), kernel(*angles, engine="compiled")):
        assert (np.isnan(want) == np.isnan(got)).all() and (~np.isnan(want)).any()
        assert _ulps(want[~np.isnan(want)], got[~np.isnan(want)]).max() <= ULPS


@needs_numba
def test_from_half_angle_tangents_the_values_are_those_from_the_angles():
    compiled = compile_scene(load_scene("fourbar"), ["B", "P"])
    stable = StableBranch(compiled, next(b for b in closed_forms(compiled) if b.selected))
    theta = np.random.default_rng(4).uniform(-np.pi, np.pi, 30_000)
    tangents = stable.kernel(tangents=True)
    assert not any(op == "tan" for _, op, _ in tangents.program.lines)
    for engine in ("numpy", "compiled"):  # numpy's tan is the one both take: the same values, bit for bit
        for got, want in zip(tangents(np.tan(0.5 * theta), engine=engine), stable.kernel()(theta, engine="numpy")):
            np.testing.assert_array_equal(got, want)


@needs_numba
def test_a_length_input_enters_the_kernel_as_it_is():
    # hydraulic-boom: a boom lifted by a cylinder of length s (a dyad on two ground pivots), s in [4/5, 12/5]
    compiled = compile_scene(load_scene("hydraulic-boom"))
    stable = StableBranch(compiled, next(b for b in closed_forms(compiled) if b.selected))
    kernel = stable.kernel()
    assert not any(op == "tan" for _, op, _ in kernel.program.lines)
    s = np.linspace(0.8, 2.4, 20_001)
    for want, got in zip(kernel(s, engine="numpy"), kernel(s, engine="compiled")):
        assert np.isfinite(want).all()
        np.testing.assert_array_equal(got, want)


def _fresh_kernel(monkeypatch):
    """A kernel that no test has loaded in this process (its module is made again)."""
    monkeypatch.setattr(fused, "_loaded", {})
    return Kernel(trace(lambda t: [t * 5.25 + 0.5], ["t"]), lambda t: [t * 5.25 + 0.5])


@needs_numba
@pytest.mark.parametrize("where", ["a-file", "/proc/algkin-cache"])
def test_a_cache_that_cannot_be_written_is_not_used(tmp_path, monkeypatch, where):
    # a file where the directory should be (anyone), or a directory no one makes files in (root included)
    if where == "a-file":
        where = tmp_path / "cache"
        where.write_text("not a directory")
    elif not os.path.isdir("/proc/self"):
        pytest.skip("needs /proc")
    monkeypatch.delenv("ALGKIN_CACHE_DIR", raising=False)
    monkeypatch.setenv("XDG_CACHE_HOME", str(where))
    kernel = _fresh_kernel(monkeypatch)
    t = np.linspace(-1, 1, 101)
    assert kernel.engine(len(t), "auto") == "numpy" and kernel.engine(len(t), "compiled") == "compiled"
    (got,) = kernel(t, engine="compiled")
    np.testing.assert_array_equal(got, t * 5.25 + 0.5)
    assert kernel.loaded and not kernel.path.exists()


@needs_numba
@pytest.mark.parametrize("value", ["0", "-1", "two"])
def test_a_bad_numba_num_threads_is_a_usage_error_naming_it(monkeypatch, value):
    monkeypatch.setenv("NUMBA_NUM_THREADS", value)
    kernel = _fresh_kernel(monkeypatch)
    with pytest.raises(UsageError, match=f"NUMBA_NUM_THREADS='{value}': must be a whole number"):
        kernel(np.linspace(-1, 1, 11), engine="compiled")
