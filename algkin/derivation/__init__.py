"""Derivations: a scene through branches, witnesses, elimination and verification to a result.

``prepared`` compiles a scene and finds its branches and witnesses once (``prepare``),
``pipeline`` runs the stages (``derive``, ``curve``) on a scene or a prepared one, ``results``
holds what they answer, ``witnesses`` draws the configurations that select factors,
``checking`` sets up the independent check, ``assembles`` finds where a scene assembles and
certifies branch labels, ``curves`` holds what a point's curve needs besides its elimination,
and ``tasks`` names the elimination tasks a derivation needs. This package sits above
``branches``, ``verify`` and ``eliminate`` and below the analyses (``algkin.analyses``), the
bench and the presentation (``algkin.ui``). The facade's ``algkin.prepare``, ``algkin.derive``
and ``algkin.curve`` are this package's functions, loaded on first use.
"""

from .pipeline import curve, derive
from .prepared import Prepared, prepare
from .results import CurveResult, Derivation

__all__ = ["derive", "curve", "prepare", "Prepared", "Derivation", "CurveResult"]
