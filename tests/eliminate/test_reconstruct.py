"""The interpolation algebra of the interpolate method: Newton interpolation mod a prime with
unlucky points skipped, the Chinese remainder theorem, rational reconstruction; on values
worked out by hand."""

import random

import flint
import pytest

from algkin.eliminate.modular import PRIMES, ModularBackend
from algkin.eliminate.reconstruct import crt, newton, rational


def test_unlucky_points_are_skipped():
    prime = PRIMES[0]
    backend = ModularBackend(("x", "u", "v"), prime)
    gx, gu, gv = backend.ctx.gens()
    family = gx**2 + (3 * gu**2 - gv) * gx + gu * gv**3 + 5
    refused = []

    def image(point):
        if point["u"] % 3 == 0 or (point["u"] + point["v"]) % 5 == 0:  # a third and a fifth unlucky
            refused.append(point)
            return None
        return family.subs(point)

    found, used = newton(image, ["u", "v"], 4, prime, random.Random(3))
    assert found == family
    assert used == 15  # (4 + 1)(4 + 2)/2 grid points, the refused ones not counted
    assert refused


@pytest.mark.parametrize("numerator,denominator", [(3, 7), (-123456, 7919), (0, 1), (5, 1)])
def test_rational_reconstruction(numerator, denominator):
    modulus = PRIMES[0] * PRIMES[1]
    residue = numerator * pow(denominator, -1, modulus) % modulus
    assert rational(residue, modulus) == flint.fmpq(numerator, denominator)


def test_residues_joined_under_two_primes():
    # 100 = 2 mod 7 = 1 mod 11, and -3 = 4 mod 7 = 8 mod 11: mod 77, 100 is 23 and -3 is 74
    joined, modulus = crt({(1,): 2, (0,): 4}, 7, {(1,): 1, (0,): 8}, 11)
    assert (joined, modulus) == ({(1,): 23, (0,): 74}, 77)
