"""Same input, same --json, byte for byte: across processes with different hash seeds.

Only the values under ``timings`` (seconds measured) may differ; their keys may not.
"""

import os
import re
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[3]
COMMANDS = {
    "derive": ["derive", "fourbar", "--param", "l", "--outputs", "B", "P", "--samples", "5"],
    "curve": ["curve", "slider-crank", "--point", "M", "--samples", "5"],
}


def run(args, hash_seed):
    env = dict(os.environ, PYTHONPATH=str(ROOT), PYTHONHASHSEED=str(hash_seed))
    result = subprocess.run([sys.executable, "-m", "algkin", *args, "--json"], capture_output=True, env=env)
    assert result.returncode == 0, result.stderr.decode()
    return result.stdout


def without_seconds(document):
    """The document with each number in its ``timings`` block replaced by a mark."""
    timings = re.compile(rb'"timings": \{[^{}]*\}')
    assert len(timings.findall(document)) == 1
    return timings.sub(lambda m: re.sub(rb": [0-9.e+-]+", b": <seconds>", m.group(0)), document)


@pytest.fixture(scope="module")
def documents():
    with ThreadPoolExecutor(max_workers=2) as pool:
        jobs = {(name, seed): pool.submit(run, args, seed) for name, args in COMMANDS.items() for seed in (1, 2)}
        return {key: job.result() for key, job in jobs.items()}


@pytest.mark.parametrize("name", sorted(COMMANDS))
def test_same_json_twice(name, documents):
    first, second = documents[(name, 1)], documents[(name, 2)]
    assert without_seconds(first) == without_seconds(second)
    assert b"<seconds>" in without_seconds(first) and b'"total": <seconds>' in without_seconds(first)
