"""Odd values through the real command (SPEC §3, §7): each is either computed or refused in one
line with exit 2 (bad input), never a traceback."""

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[3]
FIVE_BAR = (ROOT / "algkin" / "catalog" / "five-bar.toml").read_text()


def algkin(*args, cwd, timeout=300):
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    return subprocess.run([sys.executable, "-m", "algkin", *args], cwd=cwd, env=env, capture_output=True,
                          text=True, timeout=timeout)


def refused(done, *words):
    """``done`` exited 2 with one line on stderr holding ``words``, and said nothing on stdout."""
    assert done.returncode == 2, (done.returncode, done.stderr[-2000:])
    assert "Traceback" not in done.stderr and done.stdout == ""
    lines = done.stderr.splitlines()
    assert len(lines) == 1, done.stderr[-2000:]
    for word in words:
        assert word in lines[0], (word, lines[0][:500])
    return lines[0]


def test_a_five_bar_whose_second_input_turns_about_a_half_turn(tmp_path):
    """Its witnesses were indexed by the first input's count of samples: those of an input
    around 180 degrees (half-angle tangents near infinity) were all dropped."""
    text = FIVE_BAR.replace('t2 = { range = [0, 180]', 't2 = { range = [179, 181]')
    assert text != FIVE_BAR
    (tmp_path / "five.toml").write_text(text)
    done = algkin("derive", "five.toml", "--json", cwd=tmp_path)
    assert done.returncode == 0, done.stderr[-2000:]
    document = json.loads(done.stdout)
    assert document["verification"]["passed"] and document["verification"]["samples"] > 0


def huge_over_huge(value, digits=90):
    """``value + 10**-digits`` written as the quotient of two integers of about ``digits`` digits."""
    return f"{value * 10**digits + 1}/{10**digits}"


def test_a_dimension_of_huge_numerator_and_denominator_gives_the_curve(tmp_path):
    """d = 4.000...1: the curve's integer coefficients pass a float's range (they overflowed in
    the verification's float magnitudes); its residuals are scaled by a power of two."""
    done = algkin("curve", "fourbar", "--point", "P", "--set", f"d={huge_over_huge(4)}", "--json", cwd=tmp_path)
    assert done.returncode == 0, done.stderr[-2000:]
    document = json.loads(done.stdout)
    assert document["verification"]["passed"] and document["verification"]["evaluated"] > 0
    assert document["degree"] == 6 and document["circularity"] == 3  # a four-bar's coupler curve


def test_a_dimension_just_past_reach_written_huge_is_refused_as_its_round_value_is(tmp_path):
    """d = 10.000...1 (as d = 10): |AD| >= 9 > l + m = 13/2, so B never assembles; a factor 1/10**357
    of its discriminant was 0.0 in floats, and the check took it for assembling."""
    refused(algkin("curve", "fourbar", "--point", "P", "--set", "d=10", cwd=tmp_path), "points.B", "never assemble")
    refused(algkin("curve", "fourbar", "--point", "P", "--set", f"d={huge_over_huge(10, 89)}", cwd=tmp_path),
            "points.B", "never assemble")
