"""The interactive page of a scene with points solved together: the input's slider and a mode selector.

No closed form is evaluated in the browser: each mode's path over the input is precomputed
(``GroupMotion.paths``: certified continuation, filled in for drawing) and the page
interpolates between its samples, so the drawn positions are the path's to about 1e-4 of
the drawing (a twentieth of a pixel). Points known from the input alone (ground, cranks) are
a JavaScript function of it (``jscode``), drawn where no mode exists too. Where the mode
chosen does not exist at the input, the page says so, with the span where it does and the
inputs where it meets another mode (marked on its path, which ends there).

>>> from algkin.ui.groupmotion import GroupMotion
>>> data = group_model(GroupMotion("3rpr"), 6)
>>> data["input"]["name"], [p["label"] for p in data["paths"]], data["blocked"]
('r1', ['---', '+++', '-+-', '++-'], ['P1', 'P2'])
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import sympy

from ...errors import UsageError
from . import document, script_json
from .jscode import branch_function

if TYPE_CHECKING:
    from ..groupmotion import GroupMotion

__all__ = ["group_model", "group_page"]

DIGITS = 12  # significant digits of the samples written: far below the interpolation's error


def group_model(motion: GroupMotion, value: float | None = None) -> dict[str, object]:
    """The page's data: the input's slider, the parts to draw, each mode's path."""
    names = list(motion.compiled.coordinates)
    index = names.index
    lo, hi = motion.input.span
    start = float(motion.start() if value is None else value)
    paths = motion.paths
    first = next((k for k, p in enumerate(paths) if p.covers(start)), 0)
    return {
        "scene": motion.scene.name,
        "input": {"name": motion.input.name, "lo": lo, "hi": hi, "value": start, "angle": motion.input.is_angle},
        "points": names,
        "ground": [index(g) for g in motion.ground],
        "bars": [[index(p), index(q)] for p, q in [c.points for c in motion.legs] + list(motion.cranks)],
        "rails": [[index(p) for p in c.points] for c in motion.rails],
        "platforms": [[index(p) for p in base] for base in motion.platforms],
        "traced": [index(p) for p in motion.traced],
        "built": [index(p) for p in motion.built],
        "blocked": [p for g in motion.compiled.groups for p in g.points],
        "start": first,
        "paths": [{"label": p.name, "t": [_short(t) for t in p.inputs],
                   "xy": [[_short(v) for name in names for v in p.points[name][k]] for k in range(len(p.inputs))],
                   "meets": list(p.meets)} for p in paths],
    }


def _short(value: float) -> float:
    return float(f"{value:.{DIGITS}g}")


def _built_function(motion: GroupMotion) -> str:
    """JavaScript of the points known from the input alone (ground, cranks), from its variables."""
    forms = [tuple(sympy.sympify(v) for v in motion.compiled.coordinates[p]) for p in motion.built]
    return branch_function([], forms, list(motion.variables))


def group_page(motion: GroupMotion, value: float | None = None) -> str:
    """The HTML text of the page (one file, nothing fetched)."""
    if not motion.paths:
        lo, hi = motion.input.span
        raise UsageError("scene", motion.scene.name, f"no mode assembles at any start tried over {motion.input.name} "
                         f"in [{lo:g}, {hi:g}]: nothing to move")
    data = f"const MODEL = {script_json(group_model(motion, value))};\nconst BUILT = {_built_function(motion)};\n"
    return document(motion.scene, data, "groups.js")
