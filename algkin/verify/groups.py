"""Every real solution of a group of equations solved together, found without its eliminant.

At each sample of the inputs, the group's original equations are solved by Newton's method from
many random starts (``solve.solve_floats``, numpy, all samples at once), and each end point is
refined and proved in balls on the same equations (``balls.BlockCertifier``: a Krawczyk test, at
the working precision): a proved ball holds exactly one root. Balls that overlap are one root.
Nothing here knows the group's eliminant: this is what it is checked against.

>>> import numpy as np, flint
>>> from algkin.system import symbol
>>> x, y, r = symbol("x"), symbol("y"), symbol("r")
>>> found = real_solutions(("x", "y"), (x**2 + y**2 - r, x - 2*y), {"r": ("r",)},
...                        [{"r": flint.fmpq(5)}], np.random.default_rng(0))
>>> sorted(round(float(s["x"].mid()), 9) for s in found[0])
[-2.0, 2.0]
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import flint
import numpy as np
import sympy

from ..system import System
from .balls import BlockCertifier, certifier_of, certify_parameters
from .solve import Blocks, solve_floats

__all__ = ["real_solutions", "STARTS", "BITS"]

STARTS = 64
"""Random Newton starts per sample."""
BITS = 192
"""Working precision of the proofs."""


def real_solutions(unknowns: Sequence[str], equations: Sequence[sympy.Expr], inputs: Mapping[str, tuple[str, ...]],
                   samples: Sequence[Mapping[str, flint.fmpq]], rng: np.random.Generator, *,
                   starts: int = STARTS) -> list[list[dict[str, flint.arb]]]:
    """Per sample (every input variable's exact value), the real solutions of ``equations`` in ``unknowns``
    found from ``starts`` random starts, each proved in balls (``BITS``), distinct."""
    if not samples:
        return []
    system = System(tuple(unknowns), (), inputs, tuple(equations))
    blocks = Blocks(system)
    names = [v for pair in inputs.values() for v in pair]
    known = {n: np.array([float(s[n]) for s in samples]) for n in names}
    candidates = solve_floats(blocks, known, rng, starts=starts)
    found: list[list[dict[str, flint.arb]]] = [[] for _ in samples]
    certifiers = [certifier_of(b) for b in blocks.blocks]
    with flint.ctx.workprec(BITS):
        for k, owner in enumerate(candidates.owner):
            balls = {n: flint.arb(v) for n, v in samples[owner].items()}  # at BITS: a wider ball spoils the proof
            root = _proved(blocks, certifiers, candidates.values, k, balls)
            if root is not None and not any(_same(root, other) for other in found[owner]):
                found[owner].append(root)
    return found


def _proved(blocks: Blocks, certifiers: Sequence[BlockCertifier], values: Mapping[str, np.ndarray], k: int,
            sample: Mapping[str, flint.arb]) -> dict[str, flint.arb] | None:
    """Candidate ``k`` proved block by block, or None."""
    known = dict(sample)
    for block, certifier in zip(blocks.blocks, certifiers):
        parameters = [known[a] for a in certify_parameters(block)]
        candidate = [float(values[n][k]) for n in block.names]
        if not all(np.isfinite(candidate)):
            return None
        root = certifier(candidate, parameters)
        if root is None:
            return None
        known.update(zip(block.names, root))
    return {n: v for n, v in known.items() if n not in sample}


def _same(first: Mapping[str, flint.arb], second: Mapping[str, flint.arb]) -> bool:
    return all(first[n].overlaps(second[n]) for n in first)
