"""Watt I and Stephenson III six-bars: configurations by hand geometry (two triangles closed
by the law of cosines), and the degree and circularity of their coupler curves from the
literature: Primrose, Freudenstein & Roth, "Six-bar motion" I-III (Arch. Rational Mech. Anal.
24, 1967): a Watt I coupler curve has degree 14 and circularity 7, a Stephenson III coupler
curve degree 18 and circularity 9."""

import mpmath
import pytest

from algkin.branches import closed_forms
from algkin.scene import compile_scene, load_scene

from .geometry import at_angle, circles, curve_at, on_circle, rigid, run, run_process

H = mpmath.mpf(1) / 2


def watt_i(theta, side_b=1, side_f=1):
    """Crank 1 about O with E rigid on it at (1, -1); B closes A-B-D (3, 7/2, D = (4, 0));
    C at (1/2, 1/2) on AB; F closes E-F-C (2, 3/2); P at (1/2, 1/4) on EF."""
    a = on_circle((0, 0), 1, theta)
    e = rigid((0, 0), a, 1, -1)
    b = circles(a, 3, (4, 0), mpmath.mpf(7) / 2, side_b)
    c = rigid(a, b, H, H)
    f = circles(e, 2, c, mpmath.mpf(3) / 2, side_f)
    return None if f is None else (b, f, rigid(e, f, H, H / 2))


def stephenson_iii(theta, side_b=1, side_f=1):
    """The same four-bar and coupler point C; F closes C-F-E (3, 2, E = (-1, 5)); P at (1/2, 1/4) on CF."""
    a = on_circle((0, 0), 1, theta)
    b = circles(a, 3, (4, 0), mpmath.mpf(7) / 2, side_b)
    c = rigid(a, b, H, H)
    f = circles(c, 3, (-1, 5), 2, side_f)
    return None if f is None else (b, f, rigid(c, f, H, H / 2))


CASES = {"watt-i": (watt_i, 14, 7), "stephenson-iii": (stephenson_iii, 18, 9)}


@pytest.mark.parametrize("name", sorted(CASES))
def test_configurations_by_hand(name):
    # The closed forms only (no elimination): the curve test below runs the verification.
    hand = CASES[name][0]
    branches = {b.label: b for b in closed_forms(compile_scene(load_scene(name), ["B", "F"]))}
    assert set(branches) == {"B:left F:left", "B:left F:right", "B:right F:left", "B:right F:right"}
    with mpmath.workdps(40):
        for label, sides in (("B:left F:left", (1, 1)), ("B:left F:right", (1, -1))):
            values = {k: str(v) for k, v in branches[label].values.items()}
            for theta in range(0, 360, 45):
                b, f, _ = hand(theta, *sides)
                for point, (x, y) in (("B", b), ("F", f)):
                    assert abs(at_angle(values[f"{point}_x"], theta) - x) < 1e-30
                    assert abs(at_angle(values[f"{point}_y"], theta) - y) < 1e-30


# the first as a user runs it (its own process), the other's document by main in this process
@pytest.mark.parametrize("name, apart", [(name, k == 0) for k, name in enumerate(sorted(CASES))], ids=sorted(CASES))
def test_coupler_curve_degree_and_circularity(name, apart):
    hand, degree, circularity = CASES[name]
    document = (run_process if apart else run)("curve", name, "--point", "P", "--samples", "6")
    assert (document["degree"], document["circularity"]) == (degree, circularity)
    assert document["irreducible"] and document["verification"]["passed"]
    with mpmath.workdps(40):
        checked = 0
        for theta in range(5, 360, 30):
            for side_f in (1, -1):
                found = hand(theta, 1, side_f)
                if found is not None:
                    assert abs(curve_at(document, found[2])) < 1e-30
                    checked += 1
    assert checked >= 12
