"""Where a point is at a limit position: x, y, its angle about its path's centre or its place
along its line (exact where it has radicals), and whether the coupler is extended or folded.

>>> import sympy
>>> from .condition import Path
>>> x, y = sympy.symbols("x y")
>>> circle = Path(x**2 + y**2 - 4, (sympy.Integer(0), sympy.Integer(0)), None)
>>> place = position(circle, (flint.arb(0), flint.arb(2)), None, "O")
>>> place["about"], round(place["angle_deg"], 9)
('O', 90.0)
"""

from __future__ import annotations

from collections.abc import Mapping

import flint
import sympy

from ...evaluate import ARB, evaluate
from ...scene import Compiled
from ...scene.constructions import Crank, Fixed
from ...scene.model import Scene
from .condition import Path
from .exact import tidy
from .results import Json

__all__ = ["kind", "position", "centre_name", "middle"]


def kind(scene: Scene, compiled: Compiled, point: str, values: Mapping[str, flint.arb]) -> str:
    """extended / folded when the point hangs on a crank tip P about a ground pivot O (the sign of
    ``(X - P) . (P - O)``: the coupler along the crank or back over it), else stationary."""
    cranks = {}
    for reference in scene.points[point].references:
        crank = scene.points[reference]
        if isinstance(crank, Crank) and isinstance(scene.points[crank.center], Fixed):
            cranks[reference] = crank.center
    if len(cranks) != 1:
        return "stationary"
    (tip, pivot), = cranks.items()
    (x, y), (px, py), (ox, oy) = (compiled.coordinates[p] for p in (point, tip, pivot))
    along = evaluate((x - px) * (px - ox) + (y - py) * (py - oy), values, ARB)
    return "extended" if along > 0 else "folded" if along < 0 else "stationary"


def middle(ball: flint.arb) -> float:
    """The ball's midpoint as a float."""
    return float(ball.mid())


def position(path: Path, xy: tuple[flint.arb, flint.arb], exact: tuple[sympy.Expr, sympy.Expr] | None,
             centre: str | None) -> Json:
    """Where the point is: x, y and its angle about its path's centre (named ``centre`` if a
    point of the scene is there) or its place along its line."""
    x, y = xy
    place: Json = {"x": middle(x), "y": middle(y)}
    exact_place: Json = {}
    if exact is not None:
        exact_place = {"x": str(exact[0]), "y": str(exact[1])}
        place.update(x=float(exact[0]), y=float(exact[1]))  # 0, not the middle of a ball around it
    if path.centre is not None:
        qx, qy = (flint.arb(str(sympy.N(v, 60))) for v in path.centre)
        place["angle_deg"] = middle(flint.arb.atan2(y - qy, x - qx) * 180 / flint.arb.pi())
        place["about"] = centre or f"({path.centre[0]}, {path.centre[1]})"
        if exact is not None:
            exact_place["angle_deg"] = str(tidy(180 * sympy.atan2(exact[1] - path.centre[1],
                                                                  exact[0] - path.centre[0]) / sympy.pi))
    else:
        assert path.direction is not None
        dx, dy = path.direction
        norm = sympy.sqrt(dx**2 + dy**2)
        ux, uy = (flint.arb(str(sympy.N(v / norm, 60))) for v in (dx, dy))
        place["along"] = middle(x * ux + y * uy)
        place["direction"] = [str(dx / norm), str(dy / norm)]
        if exact is not None:
            exact_place["along"] = str(tidy((exact[0] * dx + exact[1] * dy) / norm))
    if exact is not None:
        place["exact"] = exact_place
    return place


def centre_name(scene: Scene, compiled: Compiled, path: Path) -> str | None:
    """The fixed point of the scene at the centre of a circular path, if one is there."""
    if path.centre is None:
        return None
    return next((n for n, (x, y) in compiled.coordinates.items()
                 if isinstance(scene.points[n], Fixed) and (x, y) == path.centre), None)
