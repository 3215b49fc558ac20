"""The atlas: one self-contained page to browse a sweep's coupler curves, with filters.

Each design that assembles gets a thumbnail: its traced point's path on every assembly
mode (the scene's own drawn darker), sampled here from the closed forms derived once with
the dimensions symbolic (``algkin.analyses.motion``) and embedded as SVG path data. The page
(inline CSS and JavaScript, no network) filters the thumbnails by Grashof class, curve
degree, number of singular points (when the sweep has that column) and the transmission
angle's range; the filters also start from the URL's query (``atlas.html?class=crank-rocker&tmin=40``),
and the page writes what it shows to ``<output id="state" data-shown data-total data-drawn>``.

>>> import math
>>> _paths([(float("nan"), 0.0), (0.0, 0.0), (1.0, 1.0), (float("nan"), 1.0), (2.0, 2.0), (3.0, 3.0)],
...        (0.0, 0.0, 3.0))
'M5,95L35,65 M65,35L95,5'
"""

from __future__ import annotations

import math
import pathlib
from fractions import Fraction
from importlib import resources
from typing import TYPE_CHECKING, Any

import numpy as np

from ..errors import UsageError
from ..runtime.files import check_output, write_atomic
from .html import fill, markup, script_json

if TYPE_CHECKING:
    from ..scene import Scene

__all__ = ["write_atlas", "atlas_data", "atlas_page", "BOX", "FILTERS", "MAX_SAMPLES"]

MAX_SAMPLES = 3601  # inputs per thumbnail at most: a tenth of a degree apart, finer than its 100 units show
BOX = 100  # each thumbnail's SVG view box is BOX x BOX, the curve inside a margin of MARGIN
MARGIN = 5
FILTERS = {"class": "grashof_class", "degree": "curve_degree", "singular": "singular_count"}


def _paths(points: list[tuple[float, float]], frame: tuple[float, float, float]) -> str:
    """SVG path data of a sampled path (nan where it cannot assemble: a gap), in the frame (x0, y0, size)."""
    x0, y0, size = frame
    scale = (BOX - 2 * MARGIN) / size if size > 0 else 0.0
    runs: list[str] = []
    run: list[str] = []
    for x, y in points + [(math.nan, math.nan)]:
        if math.isfinite(x) and math.isfinite(y):
            run.append(f"{_short(MARGIN + (x - x0) * scale)},{_short(BOX - MARGIN - (y - y0) * scale)}")
        elif run:
            runs.append("M" + "L".join(run) if len(run) > 1 else f"M{run[0]}L{run[0]}")
            run = []
    return " ".join(runs)


def _short(value: float) -> str:
    return f"{value:.1f}".rstrip("0").rstrip(".")


def _frame(tracks: list[list[tuple[float, float]]]) -> tuple[float, float, float] | None:
    """(x0, y0, size): the square around every finite point of the tracks, centred; None if there are none."""
    finite = np.array([p for track in tracks for p in track if math.isfinite(p[0]) and math.isfinite(p[1])])
    if not len(finite):
        return None
    lo, hi = finite.min(axis=0), finite.max(axis=0)
    size = float(max(hi - lo))
    centre = (lo + hi) / 2
    return float(centre[0] - size / 2), float(centre[1] - size / 2), size


class _Tracer:
    """The traced point's path per assembly mode for any design: one Motion with the swept dimensions
    symbolic, or (when one of them cannot stay symbolic) a Motion per design."""

    def __init__(self, scene: Scene, point: str, swept: list[str], samples: int) -> None:
        from ..analyses.motion import Motion

        self.scene, self.point, self.samples = scene, point, samples
        shared = Motion(scene)
        self.shared = shared if set(swept) <= set(shared.params) else None

    def valid(self, values: dict[str, str]) -> bool:
        """Whether the scene takes ``values`` (a failed design's may be refused by its compilation, a
        length not positive: the symbolic closed forms would still draw it)."""
        from ..errors import SceneError
        from ..scene import compile_scene
        from ..scene.settings import with_values

        try:
            compile_scene(with_values(self.scene, values), [self.point])
        except SceneError:
            return False
        return True

    def tracks(self, values: dict[str, str]) -> list[tuple[bool, list[tuple[float, float]]]]:
        from ..analyses.motion import Motion
        from ..scene.settings import with_values

        motion = self.shared or Motion(with_values(self.scene, values))
        numbers = {n: float(Fraction(v)) for n, v in values.items() if n in motion.params}
        found: list[tuple[bool, list[tuple[float, float]]]] = []
        for branch in motion.branches:
            _, points = motion.sweep(numbers, branch=branch.label, samples=self.samples)
            xs, ys = points[self.point]
            found.append((bool(branch.selected), list(zip(map(float, xs), map(float, ys)))))
        return found


def atlas_data(folder: str | pathlib.Path, samples: int = 181) -> dict[str, Any]:
    """The page's data: one entry per design (values, status, the filtered columns, thumbnail paths)."""
    from ..scene.load import load_scene_text
    from ..sweep import read_dataset, read_manifest

    manifest = read_manifest(folder)
    if manifest is None:
        raise UsageError("DIR", str(folder), "holds no sweep (manifest.json)")
    rows = read_dataset(folder).to_pylist()
    scene = load_scene_text(manifest["scene"]["toml"], f"{folder}/manifest.json")
    if manifest["point"] not in scene.points:
        raise UsageError("DIR", str(folder), f"its manifest's point {manifest['point']!r} is not a point of its scene")
    swept = [c[len("param_"):] for c in (rows[0] if rows else {}) if c.startswith("param_") and not c.endswith("_float")]
    tracer = _Tracer(scene, manifest["point"], swept, samples)
    designs = [_entry(row, swept, tracer) for row in rows]
    return {"scene": scene.name, "point": manifest["point"], "params": swept, "designs": designs,
            "filters": {key: column in (rows[0] if rows else {}) for key, column in FILTERS.items()},
            "transmission": bool(rows) and "transmission_min_deg" in rows[0]}


def _entry(row: dict[str, Any], swept: list[str], tracer: _Tracer) -> dict[str, Any]:
    values = {n: row[f"param_{n}"] for n in swept}
    entry = {"id": row["design"], "values": values, "status": row["status"], "reason": row["reason"],
             "class": row.get("grashof_class"), "degree": row.get("curve_degree"),
             "circularity": row.get("curve_circularity"), "singular": row.get("singular_count"),
             "tmin": row.get("transmission_min_deg"), "tmax": row.get("transmission_max_deg"), "paths": []}
    if row["status"] in ("does-not-assemble", "structure"):  # no motion: nothing to draw
        return entry
    if row["status"] == "failed" and not tracer.valid(values):  # no mechanism: nothing to draw
        return entry
    tracks = tracer.tracks(values)
    frame = _frame([t for _, t in tracks])
    if frame is not None:
        entry["paths"] = [{"selected": selected, "d": _paths(track, frame)} for selected, track in tracks]
    return entry


def atlas_page(data: dict[str, Any]) -> str:
    """The HTML text of the atlas for ``data`` (``atlas_data``)."""
    template = resources.files("algkin.ui.html").joinpath("atlas.html").read_text(encoding="utf-8")
    return fill(template, {"title": markup(f"algkin atlas: {data['scene']}", line=True),
                           "data": script_json(data)})


def write_atlas(folder: str | pathlib.Path, out: str | pathlib.Path, samples: int = 181) -> dict[str, int]:
    """Write the atlas of the sweep in ``folder`` to ``out``; how many designs it holds and how many it draws."""
    if not 1 <= samples <= MAX_SAMPLES:
        raise UsageError("--samples", samples, f"expected a number of inputs per thumbnail from 1 to {MAX_SAMPLES}")
    check_output("--out", str(out))
    if pathlib.Path(out).suffix.lower() not in (".html", ".htm"):  # as plot refuses a suffix it does not write
        raise UsageError("--out", str(out), "the atlas is an HTML page: give a name ending in .html")
    data = atlas_data(folder, samples)
    write_atomic(out, atlas_page(data))
    return {"designs": len(data["designs"]), "drawn": sum(1 for d in data["designs"] if d["paths"])}
