"""Elimination ideas measured one at a time, each against algkin without it.

- early factoring: every intermediate resultant factored and cut to the factors the
  witnesses satisfy (algkin's way), against only made squarefree;
- coordinate multipliers: the ``linear`` method with multipliers allowed to hold kept
  coordinates only in the closing Cramer step (algkin's way), against at every step
  ("without" is then the variant that allows them everywhere);
- interleaved resultants: when no linear step applies, one resultant and back to linear
  steps (algkin's way), against resultants for every unknown left;
- multiplier trial division: the multipliers' factors divided out of the eliminant before
  factoring it (algkin's way), against factoring the eliminant whole;
- irreducibility by specialization: proved on a univariate specialization (algkin's way,
  beyond three variables), against flint's multivariate factoring;
- exact witness coordinates: rational inputs and dimensions substituted exactly before the
  balls (algkin's way), against balls for every coordinate;
- python-flint polynomials in: a task eliminates from its system's python-flint forms,
  converted once (algkin's way), against converting its sympy equations at every elimination;
- no choosing what is proved: an eliminant in the elimination ideal whose last factor is
  proved irreducible keeps it once the other factors are dropped, unevaluated (algkin's
  way), against evaluating every factor at every witness;
- shared quadratic parts: circles' radical axes by subtraction (algkin's way), against the
  fraction-free row reduction on their quadratic monomials;
- one resultant left: one unknown held by two equations eliminated by their resultant
  (algkin's way, unless a multiplier already held a kept variable), against its radical axis;
- inputs in a derivation's multipliers: for ``derive``'s eliminant of Stephenson III's
  P_x, the kept cos and sin of the input allowed in multipliers like dimensions (algkin's
  way), against dimensions only (one round each: without it, the run takes about 20 s).

Each variant is swapped in for its runs only; each time is the least CPU time per
elimination over five rounds that alternate with and without (after a warm-up of each),
and every variant's eliminant is asserted equal to algkin's.

Run: ``python benchmarks/bench_ideas.py [--problems ...]``.
"""

import argparse
import time
from contextlib import contextmanager
from dataclasses import replace

import algkin.eliminate as eliminate
import algkin.eliminate.backends as backends
import algkin.eliminate.linear as linear
import algkin.eliminate.methods as methods
import algkin.eliminate.select as select
from algkin.bench.problems import build
from algkin.eliminate.linear import linear_elimination
from algkin.derivation.prepared import prepare
from algkin.derivation.tasks import EliminationTask, eliminant_tasks

PROBLEMS = ("two-circles", "lambda-coupler", "slider-crank", "fourbar-symbolic", "watt-i", "stephenson-iii")
ROUNDS = 5


def _squarefree_only(backend, poly, witnesses):
    _, factors = poly.factor_squarefree()
    product = factors[0][0]
    for factor, _ in factors[1:]:
        product = product * factor
    return product, []


def _coordinates_always(backend, polys, request):
    # every kept variable counts as a dimension: multipliers may hold coordinates at every step
    kept = tuple(n for n in backend.names if n not in request.eliminate)
    return linear_elimination(backend, polys, replace(request, parameters=kept))


def _resultants_for_the_rest(backend, polys, remaining, request):
    return methods.resultant_chain(backend, polys, replace(request, eliminate=tuple(remaining))), list(remaining)


CHOOSE = eliminate._choose


def _choose_without_proof(engine, factors, proof, in_ideal, request):
    return CHOOSE(engine, factors, None, in_ideal, request)


def _run_from_sympy(task, method, backend, budget=None):
    return replace(task, polynomials=()).run(method, backend, budget) if task.polynomials else \
        RUN(task, method, backend, budget)


RUN = EliminationTask.run

IDEAS = {  # the idea -> how to run without it
    "early factoring": lambda: swapped(methods, "_squarefree_kept", _squarefree_only),
    "coordinate multipliers": lambda: swapped(eliminate, "METHODS", {**eliminate.METHODS,
                                                                      "linear": _coordinates_always}),
    "interleaved resultants": lambda: swapped(linear, "_by_resultants", _resultants_for_the_rest),
    "multiplier trial division": lambda: swapped(eliminate, "factor_with",
                                                 lambda backend, poly, divisors: (backend.factors(poly), None)),
    "irreducibility by specialization": lambda: swapped(backends, "irreducibility_proof", lambda poly: None),
    "exact witness coordinates": lambda: swapped(select, "_exact", lambda point: {}),
    "python-flint polynomials in": lambda: swapped(EliminationTask, "run", _run_from_sympy),
    "no choosing what is proved": lambda: swapped(eliminate, "_choose", _choose_without_proof),
    "shared quadratic parts": lambda: swapped(linear, "_shared_quadratic_part", lambda *args: None),
    "one resultant left": lambda: swapped(linear, "_one_resultant_left", lambda *args: False),
}


@contextmanager
def swapped(module, name, replacement):
    original = getattr(module, name)
    setattr(module, name, replacement)
    try:
        yield
    finally:
        setattr(module, name, original)


def proportional(a, b):
    """Whether two eliminants (python-flint) are equal up to a constant."""
    return a * b.leading_coefficient() == b * a.leading_coefficient()


def cpu_time(run):
    """CPU seconds of one ``run()``, and its result."""
    start = time.process_time()
    result = run()
    return time.process_time() - start, result


def with_and_without(task, without, rounds=ROUNDS):
    """Least CPU time with the idea and without it over ``rounds`` rounds, measured in turn
    (the machine's speed drifts), after a warm-up of each; and the two eliminants."""
    run = lambda: task.run("linear", "flint")  # noqa: E731
    run()
    with without():
        run()
    best_with = best_without = float("inf")
    for _ in range(rounds):
        seconds, reference = cpu_time(run)
        best_with = min(best_with, seconds)
        with without():
            seconds, result = cpu_time(run)
        best_without = min(best_without, seconds)
    return best_with, best_without, reference, result


def derive_inputs_row(scene="stephenson-iii", unknown="P_x"):
    """``derive``'s task for ``unknown`` as algkin builds it, against its inputs kept out of
    the multipliers: one timed run each after a warm-up of algkin's, eliminants compared."""
    prepared = prepare(scene, outputs=[unknown.split("_")[0]])
    compiled = prepared.compiled
    task = eliminant_tasks(compiled, prepared.witnesses)[unknown]
    dimensions = replace(task, parameters=tuple(compiled.system.parameters))
    task.run("linear", "flint")
    with_seconds, reference = cpu_time(lambda: task.run("linear", "flint"))
    without_seconds, result = cpu_time(lambda: dimensions.run("linear", "flint"))
    assert proportional(result.raw, reference.raw), (scene, unknown)
    return f"{scene} {unknown}", with_seconds, without_seconds


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--problems", nargs="+", default=list(PROBLEMS))
    args = parser.parse_args()
    print(f"{'problem':18} {'idea':34} {'with (algkin)':>14} {'without':>12} {'ratio':>8}")
    for name in args.problems:
        task = build(name).task
        for idea, without in IDEAS.items():
            with_seconds, without_seconds, reference, result = with_and_without(task, without)
            assert proportional(result.raw, reference.raw), (name, idea)
            print(f"{name:18} {idea:34} {shown(with_seconds):>14} {shown(without_seconds):>12} "
                  f"{without_seconds / with_seconds:7.1f}x")
    name, with_seconds, without_seconds = derive_inputs_row()
    print(f"{name:18} {'inputs in derive multipliers':34} {shown(with_seconds):>14} "
          f"{shown(without_seconds):>12} {without_seconds / with_seconds:7.1f}x")


def shown(seconds):
    return f"{seconds * 1e6:.0f} us" if seconds < 1e-3 else f"{seconds * 1e3:.1f} ms"


if __name__ == "__main__":
    main()
