"""The README walk: every ``.venv/bin/algkin ...`` command in README.md's code blocks runs as
written, from a fresh directory holding only what the README's ``mkdir -p`` lines make (the
files it writes land in those, never beside them), and ends as the README says: exit 0, or,
where the next line is a ``# algkin: failed: ...`` comment, exit 1 with that line's opening on
stderr."""

import os
import re
import shlex
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest

# Every README command, a bench and an animation among them: about 25 s, run by CI (make test-slow).
pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parents[1]
README = ROOT / "README.md"
PROGRAM = ".venv/bin/algkin"
# The expected line is quoted up to its message's first words: timings and sizes vary by machine.
_EXPECTED = re.compile(r"^# (algkin: failed: [^:]+:)")


def readme_commands():
    """(arguments, expected stderr opening or None) of each ``algkin`` line in a code block."""
    blocks = re.findall(r"^```[a-z]*\n(.*?)^```", README.read_text(encoding="utf-8"), re.S | re.M)
    commands = []
    for block in blocks:
        lines = block.splitlines()
        for line, following in zip(lines, lines[1:] + [""]):
            if line.startswith(PROGRAM + " "):
                expected = _EXPECTED.match(following)
                commands.append((_quick(shlex.split(line[len(PROGRAM):], comments=True)),
                                 expected.group(1) if expected else None))
    return commands


def _quick(args):
    """``args``, but a ``bench`` gives each row 1 s once: the README's 30 s per row and 3 rounds
    take about two minutes for the same code path (rows over budget are reported, not failed). The
    rows that finish in 2 s finish in 1 (the fourbar-symbolic's three, 3 to 110 ms, each checked
    against the reference): only the six rows over budget wait less, 14 s -> 8 s."""
    if args[0] != "bench":
        return args
    budget = args.index("--budget")
    return [*args[:budget + 1], "1", *args[budget + 2:], "--rounds", "1"]


def readme_directories():
    """The directories the README's code blocks make (``mkdir -p scratch``) for its commands' files."""
    return re.findall(r"^mkdir -p (\S+)$", README.read_text(encoding="utf-8"), re.M)


COMMANDS = readme_commands()
DIRECTORIES = readme_directories()


def test_the_readme_shows_commands():
    assert len(COMMANDS) > 15 and any(expected for _, expected in COMMANDS)


@pytest.fixture(scope="module")
def walked(tmp_path_factory):
    """Every README command run, two at a time, each in its own empty directory."""
    tmp_path_factory.getbasetemp()  # made once here: two threads making it at once would race

    def run(args):
        workdir = tmp_path_factory.mktemp("readme")
        for directory in DIRECTORIES:
            (workdir / directory).mkdir(parents=True)
        start = time.perf_counter()
        result = subprocess.run([sys.executable, "-m", "algkin", *args], cwd=workdir, capture_output=True,
                                text=True, env=dict(os.environ, PYTHONPATH=str(ROOT)), timeout=300)
        return result, time.perf_counter() - start, sorted(os.listdir(workdir))

    with ThreadPoolExecutor(max_workers=2) as pool:
        yield dict(zip(range(len(COMMANDS)), pool.map(run, [args for args, _ in COMMANDS])))


@pytest.mark.parametrize("index", range(len(COMMANDS)), ids=[" ".join(a)[:60] for a, _ in COMMANDS])
def test_readme_command_runs_as_shown(index, walked):
    args, expected = COMMANDS[index]
    result, _seconds, left = walked[index]
    assert left == sorted(DIRECTORIES), (args, left)  # written into the README's scratch directory only
    if expected is None:
        assert result.returncode == 0, (args, result.stderr[-2000:])
    else:
        assert result.returncode == 1, (args, result.returncode, result.stderr[-2000:])
        assert result.stderr.startswith(expected), (expected, result.stderr)


def test_the_readmes_picture_is_what_its_command_draws_now(tmp_path):
    # Issue 35: the committed picture had drifted from its command's drawing; `make images` (run
    # by `make docs`) draws it again: committed after a change to the drawings, it matches.
    from matplotlib.image import imread
    import numpy as np

    command, path = re.search(r"`\.venv/bin/algkin ([^`]*--out (docs/images/\S+\.png)[^`]*)`",
                              README.read_text(encoding="utf-8")).groups()
    args = [str(tmp_path / "drawn.png") if arg == path else arg for arg in shlex.split(command)]
    done = subprocess.run([sys.executable, "-m", "algkin", *args], cwd=tmp_path, capture_output=True, text=True,
                          env=dict(os.environ, PYTHONPATH=str(ROOT)), timeout=300)
    assert done.returncode == 0, done.stderr
    drawn, committed = imread(tmp_path / "drawn.png"), imread(ROOT / path)
    assert drawn.shape == committed.shape, "run `make images` and commit the picture"
    # the same drawing, whatever small antialiasing differences another matplotlib makes
    assert np.mean(np.abs(drawn - committed).max(axis=2) > 0.25) < 0.002, "run `make images` and commit the picture"
