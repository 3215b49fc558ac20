"""The independent check of a derivation or a curve, set up: the system and branches with the dimensions at their defaults.

``algkin.verify`` solves the original system numerically and compares; it knows nothing of
elimination, so what it checks is handed to it here, every symbolic dimension replaced by its
default.

>>> from algkin.derivation.prepared import prepare
>>> prepared = prepare("fourbar", outputs=["B"], params=["a"])
>>> setup = check_setup(prepared.compiled, prepared.branches)
>>> setup.system.parameters, [labels["B"] for labels, _, _ in setup.branches], dict(setup.inputs)
((), ['left', 'right'], {'theta': (0.0, 6.283185307179586)})
>>> verify_prepared(prepared, samples=0, seed=0, polynomials={}, factors={}).status.value
'skipped'
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence

import sympy

from ..branches import Branch
from ..runtime.frozen import frozen
from ..scene import Compiled
from ..system import symbol
from ..system.convert import expanded
from ..verify import CheckSetup, Verification, verify_branches
from ..verify.check import Indicator, PolynomialLike
from .prepared import Prepared

__all__ = ["check_setup", "verify_prepared"]


def check_setup(compiled: Compiled, branches: Iterable[Branch], *, keep_dimensions: bool = False) -> CheckSetup:
    """What an independent check of ``branches`` starts from, the dimensions at their defaults
    (the system, its indicators, per branch ``(labels, values, discriminants)``, each input's
    range in radians or its units, and the dimensions' values).

    With ``keep_dimensions`` the symbolic dimensions stay symbols, valued by ``parameter_values``
    as the check runs: the check's compiled programs are then the same whatever the values (a
    sweep's designs of one family share them)."""
    system = compiled.system
    defaults = {} if keep_dimensions else {symbol(n): compiled.parameter_values[n] for n in system.parameters}
    # no dimension to fix (none symbolic, or kept so): the compiled system and forms as they are, their
    # python-flint polynomials (the elimination's) with them
    fixed = system if not defaults else type(system)(
        system.unknowns, (), system.inputs, tuple(expanded(e.xreplace(defaults)) for e in system.equations),
        system.nonnegative)
    inputs = {n: (i.radians(i.lo), i.radians(i.hi))
              for n, i in compiled.scene.inputs.items() if n in system.inputs}
    indicators: list[Indicator] = [(i.point, _fixed(i.expr, defaults), i.positive, i.negative)
                                   for i in compiled.indicators]
    return CheckSetup(
        system=fixed,
        indicators=indicators,
        branches=tuple((b.labels, frozen({u: _fixed(v, defaults) for u, v in b.values.items()}),
                        frozen({p: _fixed(d, defaults) for p, d in b.discriminants.items()})) for b in branches),
        inputs=frozen(inputs), parameters=compiled.parameter_values)


def _fixed(expr: sympy.Expr, defaults: Mapping[sympy.Symbol, object]) -> sympy.Expr:
    """``expr`` with the dimensions at their ``defaults`` (itself where there are none: no walk of its tree)."""
    return expr.xreplace(defaults) if defaults else expr


def verify_prepared(prepared: Prepared, *, samples: int, seed: int, polynomials: Mapping[str, PolynomialLike],
                    factors: Mapping[str, Sequence[PolynomialLike]]) -> Verification:
    """The check of ``prepared``'s branches on ``samples`` inputs (none: skipped), where they may
    assemble; ``polynomials`` (name -> an eliminant) must vanish on every root, and ``factors``
    (name -> its kept factors) lets the check catch a leftover extraneous factor."""
    if not samples:
        return Verification.skipped()
    return verify_branches(check_setup(prepared.compiled, prepared.branches), samples=samples, seed=seed,
                           polynomials=polynomials, factors=factors, where=prepared.where)
