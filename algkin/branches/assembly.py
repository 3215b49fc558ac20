"""Where a scene's chosen branch can assemble: its discriminants on a grid of inputs."""

from collections.abc import Sequence

import numpy as np
import sympy

from ..errors import SceneError
from ..evaluate.program import numpy_function
from ..scene import Compiled
from ..scene.implicit.base import FloatArray
from ..system import input_values, symbol
from .closed_form import Branch

__all__ = ["check_assembly", "GRID"]

GRID = 721
_FLOAT_BITS = 500  # a product of two rationals of more bits than this may leave a float's range (2**1024)


def _in_float_range(expression: sympy.Expr) -> sympy.Expr:
    """``expression`` times a power of two, its largest rational then within a factor 2**64 of 1."""
    bits = max((r.p.bit_length() - r.q.bit_length() for r in expression.atoms(sympy.Rational) if r), default=0)
    return sympy.expand(expression * sympy.Rational(2) ** -(bits - 64)) if bits > 64 else expression


def check_assembly(compiled: Compiled, branches: Sequence[Branch]) -> None:
    """Raise SceneError naming the dyad or slider whose discriminant is negative on the whole range."""
    chosen = next(b for b in branches if b.selected)
    defaults = {symbol(n): v for n, v in compiled.parameter_values.items()}
    angles: dict[sympy.Symbol, FloatArray] = {}
    for name, variables in compiled.system.inputs.items():
        given = compiled.scene.inputs[name]
        grid = np.linspace(given.radians(given.lo), given.radians(given.hi), GRID)
        angles.update({symbol(v): x for v, x in input_values(variables, grid).items()})
    args = list(angles)
    real = np.ones(GRID, dtype=bool)
    for point, disc in chosen.discriminants.items():
        values = _on_grid(args, disc.xreplace(defaults), angles)
        if not np.any(values >= 0):
            spec = next((d for d in compiled.implicit if d.point == point), None)
            why = getattr(spec, "never_meets", "the two circles never meet")
            raise SceneError(compiled.scene.source, f"points.{point}",
                             f"can never assemble: {why} over the input range")
        real &= values >= 0
    _check_sides(compiled, chosen, defaults, args, angles, real)


def _check_sides(compiled: Compiled, chosen: Branch, defaults: dict[sympy.Symbol, sympy.Expr],
                 args: list[sympy.Symbol], angles: dict[sympy.Symbol, FloatArray], real: np.ndarray) -> None:
    """Raise SceneError for a point without modes of its own that lies on the other side than its
    scene says wherever the chosen branch assembles (an inversor's point named where its twin is)."""
    closed = {symbol(u): v.xreplace(defaults) for u, v in chosen.values.items()}
    for spec in compiled.implicit:
        side = spec.side()
        if side is None or not real.any():
            continue
        expression, why = side
        values = _on_grid(args, expression.xreplace(defaults).xreplace(closed), angles)
        if not np.any(values[real] > 0):
            raise SceneError(compiled.scene.source, f"points.{spec.point}", why)


def _on_grid(args: list[sympy.Symbol], expression: sympy.Expr, angles: dict[sympy.Symbol, FloatArray]) -> FloatArray:
    """``expression`` in floats on the grid, where only its sign is read: nan as -inf."""
    if any(max(r.p.bit_length(), r.q.bit_length()) > _FLOAT_BITS for r in expression.atoms(sympy.Rational)):
        # a dimension of huge numerator and denominator (10**90 + 1)/10**89 makes factors past a
        # float's range (1/10**357 is 0.0): expanded, each coefficient is one exact rational again,
        # and scaled by a power of two (the same sign) to a float's range (lengths of 1e77 make a
        # four-bar's discriminant's coefficients 1e308 and more)
        expression = _in_float_range(sympy.expand(expression))
    with np.errstate(all="ignore"):  # a pole (an input where a base meets a base) or a nan is no real value
        values = numpy_function(args, expression)(*angles.values())
        return np.nan_to_num(np.broadcast_to(np.asarray(values, dtype=np.float64), (GRID,)), nan=-np.inf)
