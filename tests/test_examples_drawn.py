"""A property test draws the same examples whatever ran before it in its process (tests/conftest.py):
serial and pytest-xdist's workers run the same examples."""

import importlib.util
import sys

from hypothesis import given, settings, strategies as st

# Integers no module of algkin holds: hypothesis would draw them once it read a module that does.
DISTINCT = list(range(987_654_000, 987_654_400))


def _draws():
    """The integers a derandomized property test draws, in order."""
    drawn = []

    @settings(max_examples=300, database=None)
    @given(st.integers())
    def draw(n):
        drawn.append(n)

    draw()
    return drawn


def test_a_module_loaded_by_a_test_leaves_the_examples_of_later_tests_alone(tmp_path, monkeypatch):
    # As numba's kernels, which algkin imports from its cache folder: a local module, not a test's.
    before = _draws()
    path = tmp_path / "kernel_of_constants.py"
    path.write_text(f"CONSTANTS = {DISTINCT!r}\n")
    spec = importlib.util.spec_from_file_location(path.stem, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    monkeypatch.setitem(sys.modules, path.stem, module)  # loaded for this test only
    after = _draws()
    assert after == before
    assert not set(after) & set(DISTINCT)
