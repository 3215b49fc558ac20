"""benchmarks/checkouts.py: another checkout's algkin run in a subprocess, and the ``--against`` option."""

import argparse
import doctest

import pytest


@pytest.fixture
def checkouts(benchmark_module):
    return benchmark_module("checkouts")


def test_its_examples_hold(checkouts):
    assert doctest.testmod(checkouts).failed == 0


def test_a_run_imports_the_checkouts_algkin_before_the_installed_one(checkouts, other_checkout):
    completed = checkouts.run_python(other_checkout, ["-c", "import algkin; print(algkin.WHERE, algkin.__file__)"])
    assert completed.stdout.split()[:3] == ["the", "other", "checkout"]
    assert completed.stdout.split()[3] == str(other_checkout / "algkin" / "__init__.py")


def test_a_failed_run_says_why(checkouts, other_checkout):
    with pytest.raises(RuntimeError, match="exited 3:\nbroken"):
        checkouts.run_python(other_checkout, ["-c", "import sys; sys.stderr.write('broken'); sys.exit(3)"])


def test_against_is_a_directory_with_algkins_sources(checkouts, other_checkout, tmp_path):
    assert checkouts.checkout(str(other_checkout)) == other_checkout.resolve()
    with pytest.raises(argparse.ArgumentTypeError, match="no algkin/__init__.py"):
        checkouts.checkout(str(tmp_path / "algkin"))


def test_the_other_checkout_runs_first_then_this_one(checkouts, other_checkout):
    assert checkouts.measured(other_checkout) == [other_checkout, checkouts.ROOT]
    assert checkouts.describe(other_checkout) == str(other_checkout)
