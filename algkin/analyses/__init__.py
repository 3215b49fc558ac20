"""Analyses built on derivations: extrema of an output over the input (``extremum``).

They sit above the derivation layer (``algkin.pipeline``) and below presentation
(``algkin.cli``, ``algkin.plot``): they import the first and never the second.
"""
