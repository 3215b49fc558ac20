import importlib
from pathlib import Path

import pytest

BENCHMARKS = Path(__file__).resolve().parents[2] / "benchmarks"  # scripts, not a package: imported from their folder


@pytest.fixture
def benchmark_module(monkeypatch):
    """``benchmark_module("bench_sweep")``: a script of benchmarks/ imported as its own run imports it."""
    monkeypatch.syspath_prepend(str(BENCHMARKS))
    return importlib.import_module


@pytest.fixture
def other_checkout(tmp_path):
    """A stand-in for ``git archive <commit> | tar -x -C DIR``: an algkin that says where it is."""
    (tmp_path / "algkin").mkdir()
    (tmp_path / "algkin" / "__init__.py").write_text("WHERE = 'the other checkout'\n")
    return tmp_path.resolve()
