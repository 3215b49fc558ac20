import importlib
import pathlib
import pkgutil

import pytest
from hypothesis import settings

import algkin


def _load_every_algkin_module():
    """Now and then hypothesis draws a constant of the project's modules loaded so far (its "local
    constants": of every module outside site-packages and the standard library, tests aside): the
    pool read once all of algkin is loaded holds the constants of all the code under test."""
    for found in pkgutil.walk_packages(algkin.__path__, "algkin."):
        if found.name != "algkin.__main__":  # importing it runs the command line
            importlib.import_module(found.name)


def _freeze_hypothesis_local_constants():
    """Keep the pool of local constants read now, the same in one process and in each pytest-xdist
    worker: hypothesis would add those of each local module loaded later (numba's kernels, which
    algkin imports from its cache folder, a script of benchmarks/, a module a test writes), and what
    a test draws would depend on which tests ran before it in its process."""
    from hypothesis.internal.conjecture import providers

    read = getattr(providers, "_get_local_constants", None)
    if read is None:  # a hypothesis that draws no local constants
        return
    constants = read()
    providers._get_local_constants = lambda: constants


@pytest.hookimpl(trylast=True)  # after hypothesis's own: reading the constants now is no side effect of a plugin
def pytest_sessionstart(session):
    _load_every_algkin_module()
    _freeze_hypothesis_local_constants()


# Property tests run algebra of varying cost: no per-example deadline, reproducible blobs.
# "ci" (the default) draws the same examples on every run; `pytest --hypothesis-profile=explore`
# draws new ones each time and remembers failures in the example database.
settings.register_profile("ci", deadline=None, print_blob=True, derandomize=True)
settings.register_profile("explore", deadline=None, print_blob=True)
settings.load_profile("ci")


@pytest.fixture
def interrupted_writes(monkeypatch):
    """Every ``Path.write_bytes`` (how algkin writes a finished file) writes a few bytes and is
    then interrupted, as by Ctrl-C."""

    def interrupted(path, data):
        with open(path, "wb") as handle:
            handle.write(data[:10])
        raise KeyboardInterrupt

    monkeypatch.setattr(pathlib.Path, "write_bytes", interrupted)
