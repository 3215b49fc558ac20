"""What a point's curve needs besides its elimination: its figures, a still point refused, the family heuristic.

>>> from algkin.scene import compile_scene, load_scene
>>> from algkin.branches import closed_forms
>>> compiled = compile_scene(load_scene("fourbar"), ["A"])
>>> still_at(compiled, closed_forms(compiled)[0], "A") is None   # the crank's tip moves
True
"""

from __future__ import annotations

from collections.abc import Sequence

import flint
import sympy

from ..branches import Branch
from ..eliminate import DEFAULT_METHOD
from ..errors import UsageError
from ..scene import Compiled
from ..system import symbol
from .tasks import EliminationTask

__all__ = ["curve_figures", "still_at", "refuse_still", "family_method", "FAMILY_UNKNOWNS"]

FAMILY_UNKNOWNS = 4  # eliminated unknowns up to which a family stays with the linear method


def curve_figures(curve: flint.fmpq_mpoly, variables: Sequence[str]) -> tuple[int, int]:
    """Degree in the point's coordinates, and circularity: how many times ``x**2 + y**2``
    divides the top-degree form (in python-flint, on the exact eliminant, no conversion).

    >>> ctx = flint.fmpq_mpoly_ctx.get(("x", "y"), "lex")
    >>> x, y = ctx.gens()
    >>> curve_figures((x**2 + y**2)**2 - 2*(x**2 - y**2), ("x", "y"))   # the lemniscate
    (4, 2)
    """
    ctx = curve.context()
    names = [str(n) for n in ctx.names()]
    ix, iy = (names.index(v) for v in variables)
    terms = curve.to_dict()
    degree = max(int(m[ix]) + int(m[iy]) for m in terms)
    top = ctx.from_dict({m: c for m, c in terms.items() if int(m[ix]) + int(m[iy]) == degree})
    x, y = ctx.gens()[ix], ctx.gens()[iy]
    circle, count = x * x + y * y, 0
    while 2 * (count + 1) <= degree:
        top, remainder = divmod(top, circle)
        if not remainder.is_zero():
            break
        count += 1
    return degree, count


def still_at(compiled: Compiled, branch: Branch, point: str) -> tuple[sympy.Expr, sympy.Expr] | None:
    """Where ``point`` stays on ``branch`` if its closed form involves no input, else ``None``.

    A fixed point, or one built only from fixed points (a frame on two pivots), does not move:
    its "trajectory" is a point, and eliminating towards a curve would find no polynomial.
    """
    coordinates = [sympy.sympify(v) for v in compiled.coordinates[point]]
    values = {symbol(u): v for u, v in branch.values.items()}
    # read from the symbols the closed forms hold: substituting them first costs milliseconds of sympy
    held = set().union(*(values[v].free_symbols if v in values else {v} for c in coordinates for v in c.free_symbols))
    if held & {symbol(n) for pair in compiled.system.inputs.values() for n in pair}:
        return None
    x, y = (c.xreplace(values) for c in coordinates)
    return x, y


def refuse_still(compiled: Compiled, branches: Sequence[Branch], point: str) -> None:
    """A usage error naming where ``point`` stays, if it stays put on every branch."""
    places = [still_at(compiled, b, point) for b in branches]
    if all(p is not None for p in places):
        x, y = places[next(k for k, b in enumerate(branches) if b.selected)] or (None, None)
        raise UsageError("point", point, f"is fixed at ({x}, {y}): its trajectory is a point, not a curve")


def family_method(task: EliminationTask, method: str) -> str:
    """``interpolate`` for the default method when the curve's parameters enter only the
    traced point's own equations (a symbolic tracing point: every specialisation is a fixed
    curve, cheap to eliminate, while the linear method would carry them through every
    resultant), and more than a four-bar's four unknowns are eliminated (a four-bar's
    family takes the linear method milliseconds); ``method`` otherwise."""
    coordinates = {symbol(v) for v in task.keep[:2]}
    held = [e for e in task.equations if e.free_symbols & {symbol(p) for p in task.parameters}]
    if method != DEFAULT_METHOD or len(task.eliminate) <= FAMILY_UNKNOWNS or not held \
            or any(not e.free_symbols & coordinates for e in held):
        return method
    return "interpolate"
