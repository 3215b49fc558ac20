"""A polynomial in parameters rebuilt from its images modulo primes: the interpolation algebra
of the ``interpolate`` method (``algkin.eliminate.interpolate``), with no elimination in it.

- ``line_degree``: the total degree in the parameters, by Newton interpolation along a random
  line through them until two further images are predicted exactly;
- ``newton``: dense Newton interpolation on a triangular grid (``(D + 1)(D + 2)/2`` images
  for two parameters of total degree ``D``), recursively, one parameter at a time, unlucky
  points (an image of None) skipped;
- ``crt``: residues under several primes joined (the Chinese remainder theorem);
- ``rational``: the small fraction a residue stands for (rational reconstruction).

An image is a function ``{parameter: residue} -> polynomial mod the prime`` (None where the
point is unlucky). Here the family ``x + u**2 v``, rebuilt mod 101 from its values:

>>> import random
>>> import flint
>>> ctx = flint.nmod_mpoly_ctx.get(("x", "u", "v"), modulus=101)
>>> x, u, v = ctx.gens()
>>> family = x + u**2 * v
>>> image = lambda point: family.subs(point)
>>> line_degree(image, ["u", "v"], 101, random.Random(1))
3
>>> found, used = newton(image, ["u", "v"], 3, 101, random.Random(2))
>>> found == family, used
(True, 10)
>>> rational(3 * pow(7, -1, 101 * 103) % (101 * 103), 101 * 103)
3/7
"""

import math
import random
from collections.abc import Callable, Sequence
from typing import cast

import flint

from ..errors import ComputationError

__all__ = ["Image", "Residues", "Unlucky", "NotPolynomial", "line_degree", "newton", "crt", "rational", "MAX_DEGREE", "RETRIES"]

MAX_DEGREE = 80  # the largest total degree in the parameters looked for
RETRIES = 20  # unlucky points skipped in a row before giving up

Image = Callable[[dict[str, int]], "flint.nmod_mpoly | None"]
"""``{parameter: residue} -> the image mod the prime`` there, None at an unlucky point."""

Residues = dict[tuple[int, ...], int]
"""A polynomial mod a modulus: monomial (exponents) -> residue."""


class Unlucky(Exception):
    """Too many unlucky points in a row."""


class NotPolynomial(Exception):
    """The images are not a polynomial of degree up to ``MAX_DEGREE`` in the parameters."""


def line_degree(image: Image, parameters: Sequence[str], prime: int, rng: random.Random) -> int:
    """The total degree in the parameters: Newton interpolation along a random line through
    them until the next two images are predicted exactly."""
    start = {n: rng.randrange(prime) for n in parameters}
    slope = {n: rng.randrange(1, prime) for n in parameters}
    ts: list[int] = []
    table: list[flint.nmod_mpoly] = []  # Newton coefficients
    hits, misses = 0, 0
    while len(ts) <= MAX_DEGREE + 2:
        t = rng.randrange(prime)
        value = image({n: (start[n] + slope[n] * t) % prime for n in parameters})
        if value is None or t in ts:
            misses += 1
            if misses > RETRIES:
                raise ComputationError(f"interpolating in {', '.join(parameters)}: every image unlucky ({RETRIES + 1} "
                                       "random values in a row gave no eliminant of the expected factors' degrees)")
            continue
        misses = 0
        if table and value == _newton_value(table, ts, t, prime):
            hits += 1
            if hits == 2:
                return len(table) - 1
            continue
        hits = 0
        table.append(_divided(value, table, ts, t, prime))
        ts.append(t)
    raise NotPolynomial


def _newton_value(table: Sequence[flint.nmod_mpoly], ts: Sequence[int], t: int, prime: int) -> flint.nmod_mpoly:
    """The Newton form ``table`` (not empty) on nodes ``ts`` at ``t`` (Horner)."""
    total = table[-1]
    for k in range(len(table) - 2, -1, -1):
        total = total * ((t - ts[k]) % prime) + table[k]
    return total


def _divided(value: flint.nmod_mpoly, table: Sequence[flint.nmod_mpoly], ts: Sequence[int], t: int,
             prime: int) -> flint.nmod_mpoly:
    """The next Newton coefficient, for the node ``t`` with ``value``."""
    residual = value - _newton_value(table, ts, t, prime) if table else value
    weight = 1
    for node in ts:
        weight = weight * (t - node) % prime
    return residual * pow(weight, -1, prime)


def newton(image: Image, parameters: Sequence[str], degree: int, prime: int, rng: random.Random
           ) -> tuple[flint.nmod_mpoly, int]:
    """The polynomial of total degree ``degree`` in ``parameters`` whose values ``image`` gives,
    by Newton interpolation on a triangular grid; and how many images it took. Unlucky if
    ``RETRIES`` points in a row were."""
    if not parameters:
        value = image({})
        if value is None:
            raise Unlucky
        return value, 1
    first, rest = parameters[0], parameters[1:]
    nodes: list[int] = []
    parts: list[flint.nmod_mpoly] = []  # h_i: G = sum_i prod_{k<i} (first - nodes[k]) h_i(rest)
    used = 0
    for i in range(degree + 1):
        for _ in range(RETRIES):
            node = rng.randrange(prime)
            if node in nodes:
                continue
            try:
                part, count = newton(_peeled(image, first, node, nodes, parts, prime), rest, degree - i, prime, rng)
            except Unlucky:
                continue
            used += count
            nodes.append(node)
            parts.append(part)
            break
        else:
            raise Unlucky
    gen = parts[0].context().gens()[parts[0].context().names().index(first)]
    total, basis = parts[0] * 0, parts[0] * 0 + 1
    for node, part in zip(nodes, parts):
        total = total + basis * part
        basis = basis * (gen - node)
    return total, used


def _peeled(image: Image, first: str, node: int, nodes: Sequence[int], parts: Sequence[flint.nmod_mpoly],
            prime: int) -> Image:
    """Images of the next Newton part at ``first = node``: the known parts subtracted, divided
    by their basis there."""
    def peeled(point: dict[str, int]) -> flint.nmod_mpoly | None:
        value = image({first: node, **point})
        if value is None:
            return None
        weight = 1
        for k, part in enumerate(parts):
            value = value - (part.subs(cast("dict[str | int, int]", point)) if point else part) * weight
            weight = weight * (node - nodes[k]) % prime
        return value * pow(weight, -1, prime)

    return peeled


def crt(residues: Residues, modulus: int, new: Residues, prime: int) -> tuple[Residues, int]:
    """The residues mod ``modulus`` joined with ``new``'s mod ``prime``: residues mod their product.

    >>> crt({(1,): 2}, 5, {(1,): 3, (0,): 1}, 7) == ({(1,): 17, (0,): 15}, 35)
    True
    """
    inverse = pow(modulus, -1, prime)
    joined = {}
    for monomial in set(residues) | set(new):
        old = residues.get(monomial, 0)
        joined[monomial] = old + modulus * ((new.get(monomial, 0) - old) * inverse % prime)
    return joined, modulus * prime


def rational(residue: int, modulus: int, denominator_bits: int | None = None) -> flint.fmpq | None:
    """The fraction ``n/d`` congruent to ``residue`` with ``d`` below ``2**denominator_bits``
    and ``|n| d < modulus/2`` (by default ``|n|, d < sqrt(modulus/2)``), or None."""
    if denominator_bits is None:
        numerator_bound = denominator_bound = math.isqrt(modulus // 2)
    else:
        denominator_bound = 1 << denominator_bits
        numerator_bound = modulus // (2 * denominator_bound)
    r0, r1, s0, s1 = modulus, residue % modulus, 0, 1
    while r1 >= numerator_bound:
        q = r0 // r1
        r0, r1, s0, s1 = r1, r0 - q * r1, s1, s0 - q * s1
    if s1 == 0 or abs(s1) >= denominator_bound:
        return None
    return flint.fmpq(r1, s1) if s1 > 0 else flint.fmpq(-r1, -s1)
