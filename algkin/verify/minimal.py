"""Is an eliminant no larger than the motion it describes?

Vanishing on every true configuration does not make an eliminant right: a product with a
leftover extraneous factor (one the elimination brought in and the factor selection kept)
vanishes there too, and so does a square of a true factor. So each kept factor must vanish
*by itself* on some true configuration (the numeric solutions of the original system,
found without the eliminant), the kept factors must multiply to the reported polynomial,
and that polynomial must be squarefree. Everything here is sympy and mpmath: nothing from
the elimination is reused.
"""

import mpmath
import sympy

from ..evaluate import MPMATH, evaluate

__all__ = ["FactorCheck", "relative_residual", "structure_failures"]


def relative_residual(terms, solution):
    """|sum of the terms| / sum of |terms| at ``solution``: scale-free, ~0 only where the sum
    cancels to the working precision."""
    total, magnitude = mpmath.mpf(0), mpmath.mpf(0)
    for term in terms:
        value = evaluate(term, solution, MPMATH)
        total += value
        magnitude += abs(value)
    return abs(total) / magnitude if magnitude else abs(total)


class FactorCheck:
    """The smallest residual of each kept factor over the numeric solutions seen so far.

    A factor of the true motion vanishes on the configurations of its component; one that
    vanishes on none of them was brought in by the elimination and should have been dropped.
    """

    def __init__(self, factors):
        self.factors = {name: [(f, list(sympy.expand(f).as_ordered_terms())) for f in fs]
                        for name, fs in (factors or {}).items()}
        self.smallest = {name: [mpmath.inf] * len(fs) for name, fs in self.factors.items()}

    def see(self, solution):
        """Take one numeric solution into account."""
        for name, pairs in self.factors.items():
            best = self.smallest[name]
            for k, (_, terms) in enumerate(pairs):
                best[k] = min(best[k], relative_residual(terms, solution))

    def failures(self, tolerance, evaluated):
        """One message per kept factor that vanished on no numeric solution."""
        return [f"factor {factor} of {name} vanishes on none of the {evaluated} numeric solutions "
                f"(smallest relative residual {mpmath.nstr(best, 3)}): extraneous"
                for name, pairs in self.factors.items()
                for (factor, _), best in zip(pairs, self.smallest[name]) if not best <= tolerance]

    def to_json(self):
        """Per polynomial, each kept factor's smallest residual (0 up to working precision if true)."""
        return {name: [float(v) for v in values] for name, values in self.smallest.items()}


def structure_failures(polynomials, factors):
    """Messages for every polynomial that is not squarefree, or is not the product of its
    kept factors (when they are given)."""
    failures = [_not_squarefree(name, p) for name, p in polynomials.items()]
    failures += [_not_product(name, polynomials[name], fs) for name, fs in (factors or {}).items()
                 if name in polynomials]
    return [f for f in failures if f]


def _not_squarefree(name, polynomial):
    """A repeated factor names itself: it adds degree and no points (Yun's algorithm, gcd with
    the derivatives, in sympy)."""
    gens = sorted(sympy.sympify(polynomial).free_symbols, key=str)
    if not gens:
        return None
    repeated = [(f.as_expr(), m) for f, m in sympy.Poly(polynomial, *gens).sqf_list()[1] if m > 1]
    if not repeated:
        return None
    return f"{name} is not squarefree: " + ", ".join(f"({f})**{m}" for f, m in repeated) + " divides it"


def _not_product(name, polynomial, factors):
    """The factors checked one by one must be the polynomial reported, up to a constant."""
    ratio = sympy.cancel(sympy.sympify(polynomial) / sympy.Mul(*factors))
    if ratio.free_symbols or ratio == 0:
        return f"the kept factors of {name} do not multiply to it (quotient {ratio})"
    return None
