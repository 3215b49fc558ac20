import importlib
from pathlib import Path

import pytest

BENCHMARKS = Path(__file__).resolve().parents[2] / "benchmarks"  # scripts, not a package: imported from their folder


@pytest.fixture
def benchmark_module(monkeypatch):
    """``benchmark_module("bench_sweep")``: a script of benchmarks/ imported as its own run imports it."""
    monkeypatch.syspath_prepend(str(BENCHMARKS))
    return importlib.import_module
