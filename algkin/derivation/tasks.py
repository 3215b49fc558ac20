"""The eliminations ``derive`` and ``curve`` perform, as data: what ``bench`` times.

A task is one call of ``eliminate``: its equations, the variables to eliminate and to
keep, the kept variables the ``linear`` method may use in multipliers (the dimensions, and
in a derive task the inputs' cos and sin) and the witness configurations that select
factors. A task made from a compiled system also holds the equations as python-flint
polynomials (``System.polynomials``), which it eliminates from: no sympy on the way.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Union

import flint
import sympy

from ..eliminate import Elimination, eliminate
from ..eliminate.select import WitnessGroups
from ..runtime.budget import Budget, Deadline
from ..scene import Compiled
from ..system import System

__all__ = ["EliminationTask", "Eliminant", "curve_task", "eliminant_tasks", "equations_for"]

Eliminant = Union[Elimination[flint.fmpq_mpoly], Elimination[sympy.Poly]]  # what ``eliminate`` gives (flint's, sympy's)


@dataclass(frozen=True)
class EliminationTask:
    equations: tuple[sympy.Expr, ...]
    eliminate: tuple[str, ...]
    keep: tuple[str, ...]
    parameters: tuple[str, ...]
    witnesses: WitnessGroups
    polynomials: tuple[flint.fmpq_mpoly, ...] = ()  # the equations in python-flint, when the task has them

    def run(self, method: str, backend: str, budget: Budget | Deadline | None = None) -> Eliminant:
        return eliminate(self.polynomials or self.equations, self.eliminate, self.keep, method=method,
                         backend=backend, witnesses=self.witnesses, parameters=self.parameters, budget=budget)


def curve_task(compiled: Compiled, groups: WitnessGroups, point: str) -> EliminationTask:
    """Everything but the point's coordinates eliminated: its implicit curve."""
    system = compiled.system
    variables = (f"{point}_x", f"{point}_y")
    others = [u for u in system.unknowns if u not in variables] + list(system.input_variables)
    return EliminationTask(tuple(system.equations), tuple(others), variables + tuple(system.parameters),
                           tuple(system.parameters), tuple(groups), system.polynomials)


def eliminant_tasks(compiled: Compiled, groups: WitnessGroups) -> dict[str, EliminationTask]:
    """Unknown -> the task giving its eliminant in the inputs' cos and sin (and dimensions).

    The inputs' cos and sin are kept here, and multipliers may hold them as they hold
    dimensions: the radical axis of two circles about a crank then keeps each point's
    unknowns to its own equations (``benchmarks/bench_ideas.py``: Stephenson III's P_x
    takes 19 s otherwise, with a degree-60 resultant).
    """
    system = compiled.system
    keep_always = tuple(system.input_variables) + tuple(system.parameters)
    tasks = {}
    for u in system.unknowns:
        chosen, unknowns = _chosen_for(system, u)
        tasks[u] = EliminationTask(tuple(system.equations[k] for k in chosen), tuple(v for v in unknowns if v != u),
                                   (u,) + keep_always, keep_always, tuple(groups),
                                   tuple(system.polynomials[k] for k in chosen))
    return tasks


def equations_for(system: System, unknown: str) -> tuple[list[sympy.Expr], list[str]]:
    """The equations ``unknown`` depends on, and their unknowns (construction order)."""
    chosen, unknowns = _chosen_for(system, unknown)
    return [system.equations[k] for k in chosen], unknowns


def _chosen_for(system: System, unknown: str) -> tuple[list[int], list[str]]:
    """The indices of the equations ``unknown`` depends on, and their unknowns.

    An equation belongs to the unknowns in it that appeared last (equations come in
    construction order); ``unknown``
    needs its own equations and, recursively, those of every unknown they mention, never
    those of later points built on it.
    """
    known = set(system.unknowns)
    names = [[str(v) for v in e.free_symbols if str(v) in known] for e in system.equations]
    introduced: dict[str, int] = {}  # unknown -> index of the first equation that mentions it
    for k, n in enumerate(names):
        for v in n:
            introduced.setdefault(v, k)
    owners = [{v for v in n if introduced[v] == max(introduced[w] for w in n)} if n else set() for n in names]
    needed, stack = set(), [unknown]
    while stack:
        current = stack.pop()
        if current in needed:
            continue
        needed.add(current)
        for n, owner in zip(names, owners):
            if current in owner:
                stack.extend(n)
    chosen = [k for k, n in enumerate(names) if n and set(n) <= needed]
    return chosen, [u for u in system.unknowns if u in needed]
