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

A scene with points solved together is derived group by group, as ``algkin derive`` does it:

>>> [mode.label for mode in algkin.derive("3rpr", samples=0).groups[0].modes]
['---', '+++']
"""

from __future__ import annotations

import importlib
import warnings
from typing import TYPE_CHECKING, Any

__version__ = "0.1.0"

__all__ = [
    "load_quantities",
    "load_scene",
    "compile_scene",
    "prepare",
    "Prepared",
    "derive",
    "curve",
    "extremum",
    "rates",
    "singular",
    "solve",
    "follow",
    "synthesize",
    "catalog_names",
    "interact",
    "AlgkinError",
    "SceneBuilder",
    # what the functions above return
    "Derivation",
    "CurveResult",
    "GroupDerivation",
    "GroupCurve",
    "Verification",
    "Branch",
    "Extremum",
    "Rates",
    "Singularities",
    "Solution",
    "Followed",
    "Synthesis",
    "Mechanism",
    "Quantity",
    # what bounds them
    "Budget",
]

from .errors import AlgkinError

if TYPE_CHECKING:  # the lazy names' own types, for a type checker (__getattr__ loads them at run time)
    from .analyses.extremum import Extremum, extremum
    from .analyses.follow import Followed, follow
    from .analyses.quantities import Mechanism, Quantity, load_quantities
    from .analyses.rates import Rates, rates
    from .analyses.singular import Singularities, singular
    from .analyses.solve import Solution, solve
    from .synthesis import Synthesis, synthesize
    from .branches import Branch
    from .analyses.dispatch import curve, derive
    from .analyses.groups.curve import GroupCurve
    from .analyses.groups.derive import GroupDerivation
    from .derivation.prepared import Prepared, prepare
    from .derivation.results import CurveResult, Derivation
    from .runtime.budget import Budget
    from .scene import SceneBuilder, catalog_names, compile_scene, load_scene
    from .ui.widgets import interact
    from .verify import Verification

    load = load_quantities  # deprecated: see __getattr__

# Each lazy name -> the module defining it, imported on first use: the scene layer imports sympy
# (0.4 s), not before the command line has its signal handlers; the pipeline pulls in the
# elimination and verification layers; interact needs ipywidgets only when called. derive and curve
# are the pipeline's on a scene of constructions, the groups' on points solved together.
_LAZY = {
    **dict.fromkeys(("SceneBuilder", "catalog_names", "compile_scene", "load_scene"), ".scene"),
    **dict.fromkeys(("derive", "curve"), ".analyses.dispatch"),
    **dict.fromkeys(("prepare", "Prepared"), ".derivation.prepared"),  # what derive, curve and the analyses share
    **dict.fromkeys(("Derivation", "CurveResult"), ".derivation.results"),
    "GroupDerivation": ".analyses.groups.derive",
    "GroupCurve": ".analyses.groups.curve",
    "Verification": ".verify",
    "Branch": ".branches",
    **dict.fromkeys(("extremum", "Extremum"), ".analyses.extremum"),
    **dict.fromkeys(("rates", "Rates"), ".analyses.rates"),
    **dict.fromkeys(("singular", "Singularities"), ".analyses.singular"),
    **dict.fromkeys(("solve", "Solution"), ".analyses.solve"),
    **dict.fromkeys(("synthesize", "Synthesis"), ".synthesis"),
    **dict.fromkeys(("follow", "Followed"), ".analyses.follow"),
    **dict.fromkeys(("load_quantities", "Mechanism", "Quantity"), ".analyses.quantities"),
    "interact": ".ui.widgets",
    "Budget": ".runtime.budget",  # its module loads multiprocessing: only when asked for
}


def __getattr__(name: str) -> Any:
    if name in _LAZY:
        return getattr(importlib.import_module(_LAZY[name], __name__), name)
    if name == "scene":  # ``algkin.scene.dump_scene`` after ``import algkin``, as when it was imported here
        return importlib.import_module(".scene", __name__)
    if name == "load":  # its old name, beside load_scene it read as the wrong one
        warnings.warn("algkin.load is deprecated and goes in the next release: call algkin.load_quantities",
                      DeprecationWarning, stacklevel=2)
        return __getattr__("load_quantities")
    raise AttributeError(f"module 'algkin' has no attribute {name!r}")
