import pathlib

import pytest
from hypothesis import settings

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
