"""A family's eliminant by evaluation and interpolation in its parameters.

When symbolic parameters enter only where they cost most (a tracing point's frame
coordinates ``u, v`` on a six-bar, carried through every resultant), eliminating them along
with everything else is out of reach, while each specialisation (the parameters set to
numbers) is an ordinary fixed curve, eliminated in milliseconds. The ``interpolate`` method
rebuilds the family's eliminant from such images:

- images modulo word-size primes (``ModularBackend``), the parameters set to residues; each
  image prepared and eliminated by the ``linear`` method on its own (the family's equations
  come unprepared: ``interpolation``), factored, and cut to the factors of the
  *signature*: their degrees in the kept variables, read once from an exact elimination at
  the first witness's parameters and its ball check (the factors the motion lies on); the
  intermediate factors that elimination dropped are dropped from images too, told by their
  *shape* (degrees and number of terms), once an image dropping them has been found to keep
  factors of one dropping none (all of those of the signature's degrees, where they are the
  signature's alone);
- the *cluster*: where other factors share the signature's degrees in images, each image is
  the product of all of them, and the interpolated product is factored over QQ at the end and
  cut to the factors that, at the first witness's parameters (the *anchor*), divide the
  eliminant the witness chose there (``("told-apart-at-the-witness", k)``); in any case the
  result specialised at the anchor must be that eliminant, or the method fails (once
  interpolated again dropping no shape, if it dropped some);
- each image made monic (lex-leading coefficient 1): the eliminant is defined up to a factor
  in the parameters, and this fixes it when the leading coefficient is a number (on the
  catalog's tracing-point families it is); when it is not, the line test below finds no
  polynomial, and the method declines: the ``linear`` method runs instead, and the log says
  ``("interpolation-declined", ...)``;
- the total degree in the parameters found first, on a random line through them (Newton
  interpolation in one variable until two further images are predicted exactly); then dense
  Newton interpolation on a triangular grid (``(D + 1)(D + 2)/2`` images for two parameters
  of total degree ``D``), recursively, one parameter at a time;
- unlucky points (the image's factors of the signature's degrees not the cluster's: a
  degree drop or an extra split) skipped, another residue drawn;
- images under several primes joined by the Chinese remainder theorem; the denominators
  found by rational reconstruction, the numerators lifted as integers; primes added until
  the check passes;
- the check: at ``CHECKS`` random rational parameter values beyond the interpolation's
  needs, the interpolated eliminant specialised must equal, exactly, the product of some of
  the factors of the eliminant computed directly at that point (both primitive), over QQ and
  with no factor dropped (the shapes dropped leave some out); the two processes
  each do one beside their images. It is recorded in the log as ``("checked-at", k)``.

The algebra that rebuilds a polynomial from images (Newton interpolation, Chinese
remaindering, rational reconstruction) is ``algkin.eliminate.reconstruct``; the second
process is forked by ``algkin.runtime.child``; the exact elimination the signature is read
from runs on a ``Recording`` of the backend, which keeps the factors it met.

>>> import sympy
>>> from algkin.eliminate import eliminate
>>> x, y, r = sympy.symbols("x y r")
>>> circles = [x**2 + y**2 - r**2, (x - 3)**2 + y**2 - 4]   # y of the crossing, radius r symbolic
>>> result = eliminate(circles, ["x"], ["y", "r"], method="interpolate", parameters=["r"])
>>> sympy.factor(result.polynomial)
r**4 - 26*r**2 + 36*y**2 + 25
>>> [entry for entry in result.log if entry[0] in ("interpolated", "checked-at")]  # degree 4 in r: 5 images, two primes
[('interpolated', 10), ('checked-at', 2)]
"""

import functools
import math
import operator
import random
from collections import Counter
from collections.abc import Callable, Sequence

from typing import Any, TypeVar, cast

import attrs
import flint

from ..errors import ComputationError
from .backends import FlintBackend
from .linear import linear_elimination
from .methods import prepare
from .modular import PRIMES, ModularBackend, Shape, shape
from .protocol import Backend, P
from .reconstruct import (MAX_DEGREE, RETRIES, Image, NotPolynomial, Residues, Unlucky, crt, line_degree, newton,
                          rational)
from .recording import Recording
from .request import EliminationRequest, LogEntry, MethodOutcome
from .select import select_factors

__all__ = ["interpolation", "MAX_DEGREE", "CHECKS"]

CHECKS = 2  # exact checks at random rational parameters, beyond the interpolation's needs
SPARE_BITS = 6  # a reconstructed fraction is trusted for its denominator with this many bits to spare

_T = TypeVar("_T")


def interpolation(backend: Backend[P], polys: list[P], request: EliminationRequest) -> MethodOutcome[P]:
    """The eliminant of ``polys`` (unprepared: see below) with ``request.parameters`` symbolic,
    by interpolating specialisations; ``linear`` itself when no parameter is held or the
    backend is not flint.

    The equations come unprepared, and each specialisation is prepared on its own: a
    variable that a family's equation defines linearly with a numeric slope only because
    another dimension is fixed (on the Stephenson III with ``u`` symbolic and ``v = 1/4``,
    ``F_x`` from ``P_y``'s equation) would, substituted in the family, take from every image
    the better substitutions its specialisation allows (``B_x`` and ``B_y`` from both of
    ``P``'s): an eliminant of degree 152 in ``P_x``, ``P_y`` instead of 72 by 48."""
    held = set().union(*(backend.variables(p) for p in polys)) if polys else set()
    parameters = [n for n in backend.names if n in request.parameters and n in held]
    if not parameters or backend.name != "flint":
        return _linear(backend, polys, request)
    family = _Family(cast(FlintBackend, backend), cast(list[flint.fmpq_mpoly], polys), request, parameters)
    try:
        return MethodOutcome([cast(P, family.solve())], log=family.log)
    except NotPolynomial:  # the leading coefficient holds a parameter: no monic normalisation
        return MethodOutcome(polys, log=[("interpolation-declined", "leading coefficient")]).then(
            _linear(backend, polys, request))


def _linear(backend: Backend[P], polys: list[P], request: EliminationRequest) -> MethodOutcome[P]:
    """The ``linear`` method on ``polys`` prepared."""
    prepared = prepare(backend, polys, request.eliminate)
    return prepared.then(linear_elimination(backend, prepared.left, request))


Degrees = tuple[int, ...]
"""A factor's degree in each kept variable (the parameters' and the eliminated ones' left out)."""


@attrs.frozen
class _Anchor:
    """The first witness's parameters and the eliminant there over QQ, cut to the factors the
    witness lies on (primitive): the one place where the motion's factors are known, so where
    the family, specialised, must give them."""

    values: dict[str, flint.fmpq]
    eliminant: flint.fmpq_mpoly


class _Family:
    """One interpolation: the equations, the parameters, the signature, and what was done."""

    def __init__(self, backend: FlintBackend, polys: list[flint.fmpq_mpoly], request: EliminationRequest,
                 parameters: list[str]) -> None:
        self.backend, self.polys, self.request, self.parameters = backend, polys, request, parameters
        self.kept = [n for n in backend.names if n not in request.eliminate and n not in parameters]
        self.random = random.Random(0x5EED)
        self.log: list[LogEntry] = []
        self.signature, drop, self.anchor = self._learn()
        self.modular = ModularBackend(backend.names, PRIMES[0])  # reads the degrees of the factors of an image
        self.drop = self._trusted(drop)
        self.cluster = self._cluster()

    @property
    def total(self) -> Degrees:
        """The kept variables' degrees of an image: the product of the cluster's factors."""
        return tuple(map(sum, zip(*self.cluster)))

    # -- exact images, over QQ --------------------------------------------------------------

    def _exact(self, values: dict[str, flint.fmpq]) -> list[flint.fmpq_mpoly]:
        """The factors of the eliminant at the parameters ``values``, over QQ."""
        backend = self.backend
        polys = [backend.specialize(p, values) for p in self.polys]
        return _eliminant_factors(backend, polys, self.request)

    def _learn(self) -> tuple[list[Degrees], frozenset[Shape], _Anchor | None]:
        """At the first witness's parameters, over QQ with the witness choosing factors: the
        signature (the kept variables' degrees of each final factor the motion lies on), the
        shapes (degrees and number of terms) of the factors it dropped (and no kept one
        shares): images drop those too, early, and stay as small as the fixed curve's
        elimination (on the Stephenson III family, a factor of the same degrees as the kept
        one, halving the degree of the last resultant); and the anchor (None without a
        witness: then every factor is kept, and the anchor has nothing to choose)."""
        point = next((w for group in self.request.witnesses for w in group), None)
        exact = getattr(point, "exact", {}) if point is not None else {}
        if point is None or not all(n in exact for n in self.parameters):  # no witness: keep every factor
            return sorted(self._degrees(f) for f in self._exact(self._rational_point())), frozenset(), None
        values = {n: exact[n] for n in self.parameters}
        recording = Recording(self.backend)
        polys = [recording.specialize(p, values) for p in self.polys]
        request = EliminationRequest(self.request.eliminate, [[point]], (), self.request.deadline)
        prepared = prepare(recording, polys, request.eliminate)
        outcome = linear_elimination(recording, prepared.left, request)
        final = _eliminant_factors(recording, outcome.left, EliminationRequest((), (), (), request.deadline))
        kept, _ = select_factors(recording, final, [[point]], check=False)
        dropped = {shape(f) for f in outcome.dropped}
        others = {shape(f) for f in recording.seen if not any(f == g for g in outcome.dropped)}
        anchor = _Anchor(values, self.backend.primitive(_product(kept))) if kept else None
        return sorted(self._degrees(f) for f in kept), frozenset(dropped - others), anchor

    def _degrees(self, poly: flint.fmpq_mpoly) -> Degrees:
        return tuple(self.backend.degree(poly, n) for n in self.kept)

    def _rational_point(self, rng: random.Random | None = None) -> dict[str, flint.fmpq]:
        rng = rng or self.random
        return {n: flint.fmpq(rng.randrange(-999, 1000), rng.randrange(1, 1000)) for n in self.parameters}

    def _candidates(self, backend: Backend[P], factors: Sequence[P]) -> list[P]:
        """The factors of the signature's degrees: the motion's, and any of the same degrees."""
        return [f for f in factors if self._degrees_in(backend, f) in self.signature]

    def _pick(self, backend: Backend[P], factors: Sequence[P]) -> P | None:
        """The primitive (mod a prime: monic) product of the factors of the signature's
        degrees; None (an unlucky point) unless their degrees are exactly the cluster's."""
        chosen = self._candidates(backend, factors)
        if sorted(self._degrees_in(backend, f) for f in chosen) != self.cluster:
            return None
        return backend.primitive(_product(chosen))

    def _degrees_in(self, backend: Backend[P], poly: P) -> Degrees:
        return tuple(backend.degree(poly, n) for n in self.kept)

    # -- modular images -----------------------------------------------------------------------

    def _modular(self, prime: int, drop: frozenset[Shape]) -> tuple[ModularBackend, Image]:
        """The backend mod ``prime`` dropping the shapes ``drop``, and ``residues -> the eliminant
        there``, unselected (None where it is a number, or where a resultant or a leading
        coefficient vanishes: not generic there)."""
        modular = ModularBackend(self.backend.names, prime, drop)
        reduced = [modular.reduce(p) for p in self.polys]

        def eliminant(point: dict[str, int]) -> flint.nmod_mpoly | None:
            polys = [p.subs(cast("dict[str | int, int]", point)) for p in reduced]
            try:
                return _eliminant(modular, polys, self.request)
            except (ComputationError, ZeroDivisionError):
                return None

        return modular, eliminant

    def _factors_at(self, drop: frozenset[Shape]) -> Callable[[dict[str, int]], list[flint.nmod_mpoly] | None]:
        """``residues -> the irreducible factors`` of the image mod the first prime dropping ``drop``."""
        modular, eliminant = self._modular(PRIMES[0], drop)

        def factors(point: dict[str, int]) -> list[flint.nmod_mpoly] | None:
            found = eliminant(point)
            return None if found is None else [modular.primitive(f) for f in modular.irreducible(found)]

        return factors

    def _images(self, prime: int) -> Image:
        """``residues -> the monic image mod prime`` (None at an unlucky point), the factors of
        the trusted shapes dropped on the way."""
        modular, eliminant = self._modular(prime, self.drop)

        def image(point: dict[str, int]) -> flint.nmod_mpoly | None:
            found = eliminant(point)
            if found is None:
                return None
            if self._degrees_in(modular, found) == self.total:  # the cluster's degrees already:
                return modular.primitive(found)  # G here, up to a number (its factors, if it splits)
            return self._pick(modular, modular.irreducible(found))

        return image

    def _random_residues(self, rng: random.Random) -> dict[str, int]:
        return {n: rng.randrange(PRIMES[0]) for n in self.parameters}

    def _trusted(self, drop: frozenset[Shape]) -> frozenset[Shape]:
        """``drop`` if, at a random point mod the first prime, the image dropping those shapes
        keeps the signature's degrees, in factors all of the image dropping none: there, the
        same factors where those degrees are the signature's alone, or some of them where
        other factors share them (the Stephenson III family with a bad elimination order:
        four of the curve's degrees), the anchor telling at the end whether they are the
        motion's; else none (the witness's parameters were special: a factor's shape there
        is not its generic one)."""
        if not drop:
            return drop
        rng = random.Random(PRIMES[0] ^ 0x5EED)
        full_at, dropped_at = self._factors_at(frozenset()), self._factors_at(drop)
        for _ in range(RETRIES):
            point = self._random_residues(rng)
            full = full_at(point)
            if full is None:
                continue
            everyone = self._candidates(self.modular, full)
            dropping = self._candidates(self.modular, dropped_at(point) or [])
            kept = _submultiset(self.signature, sorted(self._degrees_in(self.modular, f) for f in dropping))
            return drop if kept and all(any(f == g for g in everyone) for f in dropping) else frozenset()
        return frozenset()

    def _cluster(self) -> list[Degrees]:
        """The degrees of the factors of the signature's degrees in an image at a random point
        mod the first prime (the trusted shapes dropped): the signature's where they tell the
        motion's factors by their degrees; more where other factors share them, and the
        images are then the product of all of those, which the anchor cuts at the end."""
        rng = random.Random(PRIMES[0] ^ 0xC1A5)
        factors_at = self._factors_at(self.drop)
        for _ in range(RETRIES):
            factors = factors_at(self._random_residues(rng))
            if factors is None:
                continue
            found = sorted(self._degrees_in(self.modular, f) for f in self._candidates(self.modular, factors))
            if not _submultiset(self.signature, found):
                continue
            if found != self.signature:
                self.log.append(("shared-degrees", len(found) - len(self.signature)))
            return found
        return self.signature

    def solve(self) -> flint.fmpq_mpoly:
        """The interpolated eliminant over QQ, checked, cut to the motion's factors at the
        anchor; interpolated again without dropping any shape if the trusted ones turn out, at
        the anchor, to have dropped the motion's factors."""
        candidate = self._interpolated_and_checked()
        chosen = self._cut(candidate)
        if self.anchor is None or self._specialized(chosen, self.anchor.values) == self.anchor.eliminant:
            return chosen
        if self.drop:
            self.log.append(("distrusted-drop", len(self.drop)))
            self.drop = frozenset()
            self.cluster = self._cluster()
            return self.solve()
        raise ComputationError(f"interpolating in {', '.join(self.parameters)}: the family found is not the "
                               "motion's at the witness's parameters")

    def _cut(self, candidate: flint.fmpq_mpoly) -> flint.fmpq_mpoly:
        """``candidate``, or where other factors share the signature's degrees (the cluster is
        larger), its factors over QQ that divide the anchor's eliminant once specialised there."""
        if self.cluster == self.signature or self.anchor is None:
            return candidate
        backend, anchor = self.backend, self.anchor
        chosen = [f for f in backend.factors(candidate) if self._degrees(f) in self.signature
                  and backend.quotient(anchor.eliminant, self._specialized(f, anchor.values)) is not None]
        self.log.append(("told-apart-at-the-witness", len(chosen)))
        return backend.primitive(_product(chosen)) if chosen else candidate

    def _specialized(self, poly: flint.fmpq_mpoly, values: dict[str, flint.fmpq]) -> flint.fmpq_mpoly:
        return self.backend.primitive(self.backend.specialize(poly, values))

    def _interpolated_and_checked(self) -> flint.fmpq_mpoly:
        """The product of the images' factors (the cluster's) over QQ, checked: primes two at a
        time, the second's images in a forked child (the two cores of a small machine); in the
        first round, each process also eliminates directly at one of the checks' points (they
        do not depend on the images)."""
        residues: Residues = {}
        modulus, count = 1, 0
        degree = line_degree(self._images(PRIMES[0]), self.parameters, PRIMES[0], self.random)
        self.log.append(("parameter-degree", degree))
        checks: list[tuple[dict[str, flint.fmpq], list[flint.fmpq_mpoly]]] = []
        for first, second in zip(PRIMES[::2], PRIMES[1::2]):
            here, there = (0, 0) if checks else (CHECKS - CHECKS // 2, CHECKS // 2)  # direct eliminations each
            rounds = _both(self._round, (first, degree, here), (second, degree, there))
            for prime, (found, direct) in zip((first, second), rounds):
                checks += [(values, [self._ring().from_dict(terms) for terms in factors]) for values, factors in direct]
                if found is None:  # unlucky throughout: the next prime
                    continue
                values, used = found
                count += used
                residues, modulus = crt(residues, modulus, values, prime)
            candidate = self._lift(residues, modulus) if residues else None
            if candidate is not None and self._check(candidate, checks):
                self.log += [("interpolated", count), ("checked-at", len(checks))]
                return candidate
        raise ComputationError(f"interpolating the family in {', '.join(self.parameters)}: "
                               f"no check passed after {len(PRIMES)} primes")

    def _round(self, prime: int, degree: int, directs: int
               ) -> tuple[tuple[Residues, int] | None, list[tuple[dict[str, flint.fmpq], list[Any]]]]:
        """``_interpolated``, then ``directs`` direct eliminations at random rational points
        (drawn from a generator of the prime's own: a forked child's copy of ``self.random``
        would draw the parent's points), each as ``(point, its factors' terms)``: a process
        boundary passes no polynomial."""
        found = self._interpolated(prime, degree)
        rng = random.Random(prime ^ 0xC4EC)
        direct = [self._direct(rng) for _ in range(directs)]
        return found, [(values, [f.to_dict() for f in factors]) for values, factors in direct]

    def _direct(self, rng: random.Random) -> tuple[dict[str, flint.fmpq], list[flint.fmpq_mpoly]]:
        """A random rational point and the factors of the signature's degrees of the eliminant
        computed directly there, over QQ, none dropped (primitive): points where they do not
        hold the signature's degrees are passed over."""
        for _ in range(RETRIES):
            values = self._rational_point(rng)
            direct = [self.backend.primitive(f) for f in self._candidates(self.backend, self._exact(values))]
            if _submultiset(self.signature, sorted(map(self._degrees, direct))):
                return values, direct
        raise ComputationError(f"interpolating in {', '.join(self.parameters)}: no check point of the signature")

    def _interpolated(self, prime: int, degree: int) -> tuple[Residues, int] | None:
        """The family mod ``prime`` (monomial -> residue) and the images it took; None if unlucky."""
        try:
            poly, used = newton(self._images(prime), self.parameters, degree, prime, random.Random(prime))
        except Unlucky:
            return None
        return {m: int(c) for m, c in zip(poly.monoms(), poly.coeffs())}, used

    def _lift(self, residues: Residues, modulus: int) -> flint.fmpq_mpoly | None:
        """The rational polynomial the residues stand for: the denominators found by rational
        reconstruction where it succeeds with bits to spare, then every coefficient times their lcm lifted as an
        integer (symmetric range): half the bits rational reconstruction needs, so fewer primes
        (the check decides). None if no coefficient reconstructs."""
        # denominators are small (they divide the integer eliminant's leading coefficient), numerators
        # not: reconstructions allowed a quarter of the bits for the denominator
        reconstructed = functools.partial(rational, modulus=modulus, denominator_bits=modulus.bit_length() // 4)
        found = [value for value in map(reconstructed, residues.values()) if value is not None]
        # a false reconstruction fills the bound (numerator times denominator near the modulus);
        # a true one, of a small coefficient, leaves bits to spare
        room = modulus.bit_length() - SPARE_BITS
        denominators = {int(v.q) for v in found if int(v.p).bit_length() + int(v.q).bit_length() < room}
        if not denominators:
            return None
        common = math.lcm(*denominators)
        terms = {}
        for monomial, residue in residues.items():
            lifted = residue * common % modulus
            lifted = lifted - modulus if 2 * lifted > modulus else lifted
            if abs(lifted).bit_length() >= room:  # a numerator filling the modulus: the lcm is short of a factor
                return None
            terms[monomial] = flint.fmpq(lifted, common)
        return self._ring().from_dict(terms)

    def _ring(self) -> flint.fmpq_mpoly_ctx:
        """The backend's polynomial ring, where polynomials are rebuilt from their terms."""
        ring: flint.fmpq_mpoly_ctx = self.backend.ctx
        return ring

    def _check(self, candidate: flint.fmpq_mpoly,
               checks: Sequence[tuple[dict[str, flint.fmpq], list[flint.fmpq_mpoly]]]) -> bool:
        """Whether ``candidate`` specialised at each point of ``checks`` is the product of some of
        the factors found directly there (all of them but those the trusted shapes dropped),
        holding the signature's degrees."""
        for values, direct in checks:
            specialized = self._specialized(candidate, values)
            dividing = [f for f in direct if self.backend.quotient(specialized, f) is not None]
            if not _submultiset(self.signature, sorted(map(self._degrees, dividing))) \
                    or self.backend.primitive(_product(dividing)) != specialized:
                return False
        return True


def _product(factors: Sequence[_T]) -> _T:
    """The product of ``factors`` (not empty)."""
    return functools.reduce(operator.mul, factors)


def _submultiset(smaller: Sequence[Degrees], larger: Sequence[Degrees]) -> bool:
    """Whether every entry of ``smaller`` is in ``larger`` at least as often."""
    return not Counter(smaller) - Counter(larger)


def _eliminant(backend: Backend[P], polys: list[P], request: EliminationRequest) -> P | None:
    """The eliminant of ``polys`` by the linear method, unselected (None: a number)."""
    bare = EliminationRequest(request.eliminate, (), (), request.deadline)
    prepared = prepare(backend, polys, bare.eliminate)
    left = [p for p in linear_elimination(backend, prepared.left, bare).left if not backend.is_zero(p)]
    if not left:
        raise ComputationError("nothing left after eliminating")
    eliminant = left[0]
    for poly in left[1:]:
        eliminant = backend.gcd(eliminant, poly)
    return None if backend.is_constant(eliminant) else eliminant


def _eliminant_factors(backend: Backend[P], polys: list[P], request: EliminationRequest) -> list[P]:
    """The irreducible factors of the eliminant of ``polys`` by the linear method, unselected: on a
    backend over QQ, whose ``factors`` are irreducible (an image mod a prime is cut by
    ``ModularBackend.irreducible``)."""
    eliminant = _eliminant(backend, polys, request)
    return [] if eliminant is None else backend.factors(eliminant)


def _both(work: Callable[..., _T], here: tuple[Any, ...], there: tuple[Any, ...]) -> tuple[_T, _T]:
    """``(work(*here), work(*there))``, the second in a forked child while the first runs here;
    both here where this process cannot fork (a daemonic one, such as a bench measurement's
    or a budget's). The child's error is raised here; the child is always reaped."""
    from ..runtime.child import can_fork, forked  # here: multiprocessing's imports are no small command's

    if not can_fork():
        return work(*here), work(*there)
    with forked(lambda tell: work(*there)) as child:
        mine = work(*here)
        return mine, child.answer()
