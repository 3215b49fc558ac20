"""Derivations: a scene through branches, witnesses, elimination and verification to a result.

``pipeline`` runs the stages (``derive``, ``curve``) and ``tasks`` names the elimination
tasks a derivation needs. This package sits above ``branches``, ``verify`` and ``eliminate``
and below the analyses (``algkin.analyses``), the bench and the presentation (``algkin.ui``).
The facade ``algkin.derive`` and ``algkin.curve`` are this package's functions, loaded on
first use.
"""

from .pipeline import curve, derive

__all__ = ["derive", "curve"]
