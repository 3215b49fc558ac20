"""algkin: closed forms of planar mechanisms by elimination.

>>> import algkin
>>> result = algkin.derive("chebyshev-lambda", outputs=["B"])
>>> [branch.label for branch in result.branches]
['left', 'right']
>>> result.verification.passed
True

A scene asked several questions is prepared once (compiled, its branches and witnesses found):

>>> prepared = algkin.prepare("chebyshev-lambda", outputs=["P"])
>>> algkin.curve(prepared, "P", samples=0).degree, algkin.derive(prepared, samples=0).branches == prepared.branches
(6, True)
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

__version__ = "0.1.0"

__all__ = [
    "load",
    "load_scene",
    "compile_scene",
    "prepare",
    "Prepared",
    "derive",
    "curve",
    "extremum",
    "rates",
    "singular",
    "catalog_names",
    "interact",
    "AlgkinError",
    "SceneBuilder",
]

from .errors import AlgkinError

if TYPE_CHECKING:  # the lazy names' own types, for a type checker (__getattr__ loads them at run time)
    from .analyses.extremum import extremum
    from .analyses.quantities import load
    from .analyses.rates import rates
    from .analyses.singular import singular
    from .derivation.pipeline import curve, derive
    from .derivation.prepared import Prepared, prepare
    from .scene import SceneBuilder, catalog_names, compile_scene, load_scene
    from .ui.widgets import interact


def __getattr__(name: str) -> Any:
    # The scene layer imports sympy (0.4 s): not before the command line has its signal handlers.
    if name in ("SceneBuilder", "catalog_names", "compile_scene", "load_scene"):
        from . import scene

        return getattr(scene, name)
    if name == "scene":  # ``algkin.scene.dump_scene`` after ``import algkin``, as when it was imported here
        return importlib.import_module(".scene", __name__)
    # The pipeline pulls in the elimination and verification layers: load on first use.
    if name in ("derive", "curve"):
        from .derivation import pipeline

        return getattr(pipeline, name)
    if name in ("prepare", "Prepared"):  # what derive, curve and the analyses share of a scene
        from .derivation import prepared

        return getattr(prepared, name)
    if name == "extremum":
        from .analyses.extremum import extremum

        return extremum
    if name == "rates":
        from .analyses.rates import rates

        return rates
    if name == "singular":
        from .analyses.singular import singular

        return singular
    if name == "interact":  # ipywidgets only when called
        from .ui.widgets import interact

        return interact
    if name == "load":
        from .analyses.quantities import load

        return load
    raise AttributeError(f"module 'algkin' has no attribute {name!r}")
