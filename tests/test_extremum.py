"""Extremum of |AB| in the arm scene against the hand derivation."""

import json
import math
import subprocess
import sys


def run(*args):
    out = subprocess.run([sys.executable, "-m", "algkin", *args], capture_output=True, text=True)
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
    assert "+/-" in point["enclosure_deg"]


def test_bad_range_is_exit_2():
    code, out, err = run("extremum", "arm-string", "--of", "AB", "--range", "9:1")
    assert code == 2 and len(err.strip().splitlines()) == 1 and out == ""
