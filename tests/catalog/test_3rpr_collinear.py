"""The catalog's collinear 3-RPR: base joints on a line, platform joints on a line. Gosselin and
Merlet (1994): every pose has its mirror in the base line, and at most four of the eliminant's
six roots are real. The configurations are checked against the constraints themselves (the
legs' and the side's lengths, P3 the midpoint), at 40 digits, not against the eliminant."""

from decimal import Decimal, localcontext
from fractions import Fraction

import pytest

import algkin

A = {"A1": (0, 0), "A2": (10, 0), "A3": (4, 0)}


def _point(configuration, name):
    return tuple(Decimal(v) for v in configuration.points[name])


def _dist(p, q):
    return ((p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2).sqrt()


def test_four_real_modes_at_equal_legs_each_on_the_constraints_and_in_mirror_pairs():
    found = algkin.solve("3rpr-collinear", at={"r1": 13}, digits=40)
    assert found.complex_count == 6 and len(found.configurations) == 4  # all four real at r1 = 13
    mirrored = set()
    with localcontext() as ctx:
        ctx.prec = 50
        for c in found.configurations:
            p1, p2, p3 = (_point(c, n) for n in ("P1", "P2", "P3"))
            for joint, base, leg in ((p1, "A1", 13), (p2, "A2", 13), (p3, "A3", 13)):
                assert abs(_dist(joint, A[base]) - leg) < Decimal("1e-35")
            assert abs(_dist(p1, p2) - 8) < Decimal("1e-35")
            assert all(abs(p3[k] - (p1[k] + p2[k]) / 2) < Decimal("1e-35") for k in (0, 1))
            mirrored.add(tuple(round(float(v), 9) for v in (p1[0], -p1[1], p2[0], -p2[1])))
    own = {tuple(round(float(v), 9) for v in (*_point(c, "P1"), *_point(c, "P2"))) for c in found.configurations}
    assert own == mirrored  # each pose's mirror in the base line is a configuration too


@pytest.mark.parametrize("r1", [Fraction(19, 2), 11, 12, Fraction(27, 2), 15, Fraction(33, 2)])
def test_never_more_than_four_real(r1):
    found = algkin.solve("3rpr-collinear", at={"r1": str(r1)}, digits=10)
    assert found.complex_count == 6 and len(found.configurations) <= 4 and len(found.configurations) % 2 == 0
