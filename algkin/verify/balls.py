"""Float candidates proved to lie next to exactly one root of the original equations, in balls.

The system is proved block by block, in the order ``solve.Blocks`` solved it: each block's
equations in its unknowns, with the inputs and the earlier blocks' enclosures as ball
parameters. In python-flint ``arb`` at the caller's precision, from a block's float
candidate ``x``: a Newton step, then a Krawczyk test on a small box ``X`` around it,
``K = x - Y F(x) + (I - Y J(X)) (X - x)`` with ``Y`` the inverse of ``J``'s midpoint.
``K`` inside the interior of ``X`` proves that, for every parameter value in their balls,
``X`` holds exactly one root, and that it lies in ``K``: an enclosure about as tight as
the working precision (the test contracts quadratically). Two circles (a ``pencil.Pencil``)
are proved without a box: both roots of the quadratic on their radical axis, in balls,
proved real and distinct by its discriminant. A linear block's root is the
ball solution of its linear system, unique where the matrix is proved invertible. Near a
double root (a toggle) more Newton steps are tried before giving up; a candidate that
cannot be proved is reported as such, never used.

>>> import flint
>>> from algkin.system import symbol
>>> x, y = symbol("x"), symbol("y")
>>> circle_and_line = BlockCertifier(["x", "y"], [x**2 + y**2 - 4, x - y], [])
>>> with flint.ctx.workprec(200):
...     root = circle_and_line([1.4142, 1.4142], [])
>>> root[0].overlaps(flint.arb(2).sqrt()), root[0].rad() < 1e-50
(True, True)
"""

from __future__ import annotations

import enum
import functools
from collections.abc import Callable, Sequence
from typing import Protocol

import numpy as np
import sympy
from flint import arb, arb_mat
from numpy.typing import NDArray

from ..evaluate import ARB
from ..evaluate.program import BallProgram, compile_program
from ..runtime.cache import BoundedCache
from ..system import symbol
from ..system.convert import coefficients
from .pencil import Pencil
from .solve import jacobian

__all__ = ["BlockCertifier", "certifier_of", "certify_parameters"]


class Unset(enum.Enum):
    """No pencil given: the certifier finds its own."""

    UNSET = "unset"


UNSET = Unset.UNSET
BOX = 2.0**-96  # the Krawczyk box's half-width, relative to the root's size
ATTEMPTS = 4  # Newton steps tried before a candidate is given up (a near-double root needs more)


class Block(Protocol):
    """A ``solve.Blocks`` block, as far as its proof needs it."""

    @property
    def names(self) -> Sequence[str]: ...  # its unknowns
    @property
    def equations(self) -> Sequence[sympy.Expr]: ...
    @property
    def arguments(self) -> Sequence[str]: ...  # every variable it uses, its unknowns among them
    @property
    def pencil(self) -> Pencil | None: ...  # its two circles, where it is a pencil


class BlockCertifier:
    """Proves float candidates of one block: ``equations`` in ``names``, given ``parameters``."""

    def __init__(self, names: Sequence[str], equations: Sequence[sympy.Expr], parameters: Sequence[str], *,
                 pencil: Pencil | None | Unset = UNSET) -> None:
        unknowns = self.unknowns = [symbol(n) for n in names]
        self.equations, self.arguments = list(equations), list(names) + list(parameters)
        self.n = len(names)
        self.linear = all(sum(m) <= 1 for eq in equations for m in coefficients(eq, unknowns))
        self.residual: BallProgram = compile_program(self.equations, self.arguments, ARB)
        self.identity = arb_mat([[int(i == j) for j in range(self.n)] for i in range(self.n)])
        self.explicit = _explicit(equations, unknowns, parameters)
        # the solver's, where it found it already (the same block and parameters)
        self.pencil = Pencil.of(equations, unknowns, list(parameters)) if isinstance(pencil, Unset) else pencil

    def __call__(self, candidate: Sequence[float], known: Sequence[arb],
                 inverse: NDArray[np.float64] | Callable[[], NDArray[np.float64]] | None = None) -> list[arb] | None:
        """The root's enclosure (one ball per unknown) next to ``candidate``, or ``None``.

        ``known`` lists the balls of the parameters, in order; ``inverse``, the Jacobian's
        inverse in floats at the candidate (or a function making it, called only where it is
        used), saves the first step its own inversion.
        """
        if self.explicit is not None:  # u = formula: its value in balls is the root's enclosure
            value = arb(self.explicit(*known)[0])  # a constant formula comes back as a Python integer
            return [value] if value.is_finite() else None
        if self.pencil is not None:  # the quadratic on the radical axis, in balls: no box to test
            root = self.pencil.enclose(candidate, known)
            if root is not None:
                return root
        x = [arb(float(v)) for v in candidate]
        if self.linear:
            return self._linear(x, known)
        if callable(inverse):
            inverse = inverse()
        if inverse is not None and not np.isnan(inverse[0, 0]):
            root = self._from_inverse(x, known, arb_mat(inverse.tolist()))
            if root is not None:
                return root
        for _ in range(ATTEMPTS):
            moved = self._newton(x, known)
            if moved is None:
                return None
            x = moved
            root = self._krawczyk(x, known)
            if root is not None:
                return root
        return None

    @functools.cached_property
    def jacobian(self) -> BallProgram:
        """The Jacobian as a program, differentiated when first needed: a block its pencil or its
        formula proves never needs it."""
        return compile_program(jacobian(self.equations, self.unknowns), self.arguments, ARB)

    def _linear(self, x: list[arb], known: Sequence[arb]) -> list[arb] | None:
        """``x - J^-1 F(x)`` in balls: exactly the root, for every parameter in its ball."""
        if self.n == 1:  # one division, no matrix
            slope, = self.jacobian(*x, *known)
            if not (slope > 0 or slope < 0):  # not proved nonzero: the root may not be unique
                return None
            value = x[0] - self.residual(*x, *known)[0] / slope
            return [value] if value.is_finite() else None
        jacobian = arb_mat(self.n, self.n, self.jacobian(*x, *known))
        try:
            step = jacobian.solve(arb_mat(self.n, 1, self.residual(*x, *known)))
        except ZeroDivisionError:  # not proved invertible: the root may not be unique
            return None
        root = [x[i] - step[i, 0] for i in range(self.n)]
        return root if all(r.is_finite() for r in root) else None

    def _from_inverse(self, x: list[arb], known: Sequence[arb], inverse: arb_mat) -> list[arb] | None:
        """A Newton step and the Krawczyk test, both with the float inverse ``Y`` (exact as a
        matrix of floats, good to ~1e-16): enough from a float root, in half the work."""
        step = inverse * arb_mat(self.n, 1, self.residual(*x, *known))
        return self._krawczyk([arb((x[i] - step[i, 0]).mid()) for i in range(self.n)], known, inverse)

    def _newton(self, x: list[arb], known: Sequence[arb]) -> list[arb] | None:
        jacobian = arb_mat(self.n, self.n, self.jacobian(*x, *known))
        residual = arb_mat(self.n, 1, self.residual(*x, *known))
        try:
            step = jacobian.solve(residual)
        except ZeroDivisionError:  # singular to the working precision: a double root
            return None
        return [arb((x[i] - step[i, 0]).mid()) for i in range(self.n)]

    def _krawczyk(self, x: list[arb], known: Sequence[arb], inverse: arb_mat | None = None) -> list[arb] | None:
        size = max(abs(float(v)) for v in x) or 1.0  # relative: a mechanism 1e-20 across is proved as tightly
        radius = arb(0, BOX * size)
        box = [v + radius for v in x]
        over_box = arb_mat(self.n, self.n, self.jacobian(*box, *known))
        if inverse is None:
            try:
                inverse = over_box.mid().inv().mid()
            except ZeroDivisionError:
                return None
        residual = arb_mat(self.n, 1, self.residual(*x, *known))
        spread = arb_mat(self.n, 1, [radius] * self.n)
        k = arb_mat(self.n, 1, x) - inverse * residual + (self.identity - inverse * over_box) * spread
        root = [k[i, 0] for i in range(self.n)]
        return root if all(b.contains_interior(r) for b, r in zip(box, root)) else None


def _explicit(equations: Sequence[sympy.Expr], unknowns: Sequence[sympy.Symbol],
              parameters: Sequence[str]) -> BallProgram | None:
    """``a u + f = 0`` with ``a`` a nonzero number (a point defined by a formula): ``-f / a``
    compiled, else ``None``."""
    if len(unknowns) != 1:
        return None
    terms = coefficients(equations[0], unknowns[:1])
    lead = terms.get((1,))
    if max(terms) != (1,) or lead is None or not lead.is_number:
        return None
    return compile_program([-terms.get((0,), sympy.Integer(0)) / lead], parameters, ARB)


CERTIFIERS: BoundedCache[BlockCertifier] = BoundedCache(256, name="blocks' certifiers")


def certify_parameters(block: Block) -> list[str]:
    """The variables a ``solve.Blocks`` block takes as parameters, in the certifier's order."""
    return [a for a in block.arguments if a not in block.names]


def certifier_of(block: Block) -> BlockCertifier:
    """The ``BlockCertifier`` of a ``solve.Blocks`` block, compiled once and reused by later calls."""
    key = (tuple(block.names), tuple(block.equations), tuple(certify_parameters(block)))
    return CERTIFIERS.get(key, lambda: BlockCertifier(*map(list, key), pencil=block.pencil))
