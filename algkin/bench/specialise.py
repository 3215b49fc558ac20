"""An independent check of an eliminant where no full reference finished: a fresh elimination
at random rational values of the dimensions.

The original system with random rationals put for the parameters and for every kept
variable but the first (a point of a circle for the two of a side relation
``c**2 + s**2 - 1``, so that it still holds) is eliminated by the Gröbner basis over
python-flint, keeping the first variable only: a small zero-dimensional problem, even where
the symbolic one runs past the budget. For values off a proper algebraic subset (random
rationals are, almost surely) the roots of that univariate eliminant are the first
variable's values on the curve at those values of the others, so it must equal the row's
eliminant specialised the same way, up to a constant: a wrong coefficient, a missing or an
extra factor shows. The Gröbner elimination shares no code with the ``linear`` method or
the resultant chains it checks.
"""

import random
from collections.abc import Sequence
from fractions import Fraction

import flint
import sympy

from ..errors import AlgkinError
from ..derivation.tasks import EliminationTask
from ..runtime.budget import Budget
from ..system import symbol
from .agree import Agreement, Verdict, agreement, from_sympy

__all__ = ["Specialisation", "specialisations", "fresh", "check"]

HEIGHT = 10**4  # numerators and denominators of the random values, at most
METHOD = ("groebner", "flint")


class Specialisation(dict[str, Fraction]):
    """name -> Fraction, and the univariate eliminant of the system there (or why none)."""

    eliminant: flint.fmpq_mpoly | None = None
    failure: str | None = None


def specialisations(task: EliminationTask, side: Sequence[sympy.Expr], count: int,
                    seed: int) -> list[Specialisation]:
    """``count`` random assignments of the parameters and the kept variables but the first."""
    rng = random.Random(seed)
    names = [n for n in task.keep[1:]]
    circles = _circles(side)
    found = []
    for _ in range(count):
        values = Specialisation()
        for c, s in circles:
            t = _rational(rng)
            values[c], values[s] = (1 - t**2) / (1 + t**2), 2 * t / (1 + t**2)
        for name in names:
            values.setdefault(name, _rational(rng))
        found.append(values)
    return found


def _rational(rng: random.Random) -> Fraction:
    return Fraction(rng.randint(-HEIGHT, HEIGHT) or 1, rng.randint(1, HEIGHT))


def _circles(side: Sequence[sympy.Expr]) -> list[tuple[str, str]]:
    """Pairs ``(c, s)`` of the side relations that read ``c**2 + s**2 - 1``."""
    pairs = []
    for relation in side:
        names = sorted(relation.free_symbols, key=str)
        if len(names) == 2 and sympy.expand(relation - (names[0]**2 + names[1]**2 - 1)) == 0:
            pairs.append((str(names[0]), str(names[1])))
    return pairs


def fresh(task: EliminationTask, values: Specialisation, budget: float) -> Specialisation:
    """Fill ``values.eliminant`` (flint, over ``task.keep[:1]``) by the Gröbner elimination of
    the specialised system, or ``values.failure`` when it fails or runs past ``budget`` s."""
    from ..eliminate import eliminate

    exact = {symbol(n): sympy.Rational(v.numerator, v.denominator) for n, v in values.items()}
    equations = [sympy.expand(e.xreplace(exact)) for e in task.equations]
    equations = [e for e in equations if e != 0]
    method, backend = METHOD
    try:
        result = eliminate(equations, task.eliminate, task.keep[:1], method=method, backend=backend,
                           budget=Budget(seconds=budget))
    except AlgkinError as error:
        values.failure = f"{type(error).__name__}: {str(error)[:100]}"
        return values
    values.eliminant = from_sympy(result.polynomial, list(task.keep[:1]))
    return values


def check(poly: flint.fmpq_mpoly, found: Sequence[Specialisation]) -> Verdict:
    """The ``Verdict`` of the flint polynomial ``poly`` (over the task's kept variables) at
    each specialisation in ``found``: the first that disagrees, else equal; ``not compared``
    when no fresh elimination finished."""
    done = [(values, values.eliminant) for values in found if values.eliminant is not None]
    if not done:
        return Verdict(Agreement.NOT_COMPARED, "; ".join(v.failure or "" for v in found))
    for values, eliminant in done:
        at = poly.subs({n: _fmpq(v) for n, v in values.items()})
        verdict = agreement(_onto(at, eliminant.context()), eliminant)
        if not verdict.agrees:
            return verdict
    return Verdict(Agreement.EQUAL, f"at {len(done)} random rational specialisations, "
                                    f"against {METHOD[0]} / {METHOD[1]}")


def _fmpq(value: Fraction) -> flint.fmpq:
    return flint.fmpq(value.numerator, value.denominator)


def _onto(poly: flint.fmpq_mpoly, target: flint.fmpq_mpoly_ctx) -> flint.fmpq_mpoly:
    """``poly`` (every variable but the first fixed) as a polynomial of ``target``'s one variable."""
    return target.from_dict({(m[0],): c for m, c in zip(poly.monoms(), poly.coeffs())})
