"""Where a scene's chosen branch can assemble: its discriminants on a grid of inputs."""

from collections.abc import Sequence

import numpy as np
import sympy

from ..errors import SceneError
from ..scene import Compiled
from ..scene.implicit.floats import FloatArray
from ..system import symbol
from .closed_form import Branch

__all__ = ["check_assembly", "GRID"]

GRID = 721


def check_assembly(compiled: Compiled, branches: Sequence[Branch]) -> None:
    """Raise SceneError naming the dyad or slider whose discriminant is negative on the whole range."""
    chosen = next(b for b in branches if b.selected)
    defaults = {symbol(n): v for n, v in compiled.parameter_values.items()}
    angles: dict[sympy.Symbol, FloatArray] = {}
    for name, (c, s) in compiled.system.inputs.items():
        given = compiled.scene.inputs[name]
        grid = np.linspace(float(given.to_radians(given.lo)), float(given.to_radians(given.hi)), GRID)
        angles[symbol(c)], angles[symbol(s)] = np.cos(grid), np.sin(grid)
    args = list(angles)
    for point, disc in chosen.discriminants.items():
        with np.errstate(all="ignore"):  # a discriminant's pole (an input where a base meets a base) is no real root
            values = sympy.lambdify(args, disc.xreplace(defaults), "numpy")(*angles.values())
            if not np.any(np.broadcast_to(values, (GRID,)) >= 0):
                spec = next((d for d in compiled.implicit if d.point == point), None)
                why = getattr(spec, "never_meets", "the two circles never meet")
                raise SceneError(compiled.scene.source, f"points.{point}",
                                 f"can never assemble: {why} over the input range")
