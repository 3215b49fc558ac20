"""Extremum of |AB| in the arm scene against the hand derivation."""

import json
import math
import re
import subprocess
import sys

import flint
import pytest

from algkin.analyses.extremum import extremum
from algkin.errors import UsageError

from ..ui.cli.in_process import run_main


def run(*args):
    out = subprocess.run([sys.executable, "-m", "algkin", *args], capture_output=True, text=True)
    return out.returncode, out.stdout, out.stderr


def written(*args, cwd):
    """``algkin args...`` in this process (``main``): for what it writes, the process tested by ``run``'s tests."""
    out = run_main(args, cwd)
    return out.returncode, out.stdout, out.stderr


def test_minimum_of_ab_by_hand():
    code, out, err = run("extremum", "arm-string", "--of", "AB", "--range", "0:180", "--json")
    assert code == 0, err
    d = json.loads(out)
    # A = 350 (sin t, -cos t) is closest to B = (400, -80) when it points at B:
    # |AB| = |OB| - 350 at sin t = 400/|OB|, cos t = 80/|OB|.
    ob = math.hypot(400, 80)
    assert abs(d["minimum"]["value"] - (ob - 350)) < 1e-9
    assert abs(d["minimum"]["input_deg"] - math.degrees(math.atan2(400, 80))) < 1e-9
    assert d["minimum"]["kind"] == "minimum"
    # Farthest in range is the endpoint t = 180 deg: A = (0, 350).
    assert abs(d["maximum"]["value"] - math.hypot(400, 350 + 80)) < 1e-9
    assert d["maximum"]["kind"] == "endpoint"
    (point,) = d["critical_points"]
    # The certified enclosure holds the exact minimiser, atan2(400, 80) in degrees.
    with flint.ctx.workprec(200):
        exact = flint.arb(5).atan() * 180 / flint.arb.pi()
        assert flint.arb(point["enclosure_deg"]).overlaps(exact)
        assert flint.arb(point["enclosure_deg"]).rad() < 1e-15


def test_closed_forms_from_the_command_line(tmp_path):
    code, out, err = written("extremum", "arm-string", "--of", "AB", "--param", "b", "--json", cwd=tmp_path)
    assert code == 0, err
    form = json.loads(out)["closed_form"]
    assert form["value"] == "sqrt(b**2 + 160000) - 350"
    assert set(form) >= {"value", "input", "valid_when", "regions"}
    code, out, err = written("extremum", "arm-string", "--of", "AB", "--param", "a", "--param", "b", cwd=tmp_path)
    assert code == 0, err
    assert "value = sqrt(a**2 + b**2) - 350" in out


def test_minimiser_leaving_the_range_is_said(tmp_path):
    code, out, err = written("extremum", "arm-string", "--of", "AB", "--param", "b", "--range", "0:90", cwd=tmp_path)
    assert code == 0, err
    assert "(-oo, 0): the minimiser leaves the range; the minimum is at the end theta = 90 deg" in out


def test_bad_range_is_exit_2():
    code, out, err = run("extremum", "arm-string", "--of", "AB", "--range", "9:1")
    assert code == 2 and len(err.strip().splitlines()) == 1 and out == ""


def test_an_angles_extremes_do_not_follow_the_callers_mpmath_precision():
    # mpmath's precision is process-wide: a caller (or an earlier test) at 50 digits once made
    # the transmission angle's minimum of this four-bar differ in its last bits from a fresh process's.
    import mpmath

    from algkin.analyses.extremum import extremum
    from algkin.scene import load_scene
    from algkin.scene.settings import with_values

    scene = with_values(load_scene("fourbar"), {"a": 3, "l": 3, "d": 4})
    found = {}
    for dps in (15, 50):
        with mpmath.workdps(dps):
            result = extremum(scene, "angle(A, B, D)")
        found[dps] = [float(p.value) for p in result.critical_points]
    assert found[15] == found[50]


@pytest.mark.parametrize("output", ["O.x", "dist(O, D)"])
def test_an_output_of_fixed_points_does_not_depend_on_the_input(output):
    # once "scene='chebyshev-lambda': an extremum needs exactly one input", of a scene with one
    with pytest.raises(UsageError, match=re.escape(f"output={output!r}: the output does not depend on the input")):
        extremum("chebyshev-lambda", output)
