"""Exact polynomial systems, and the only sympy <-> python-flint conversion."""

from .core import System, symbol, variables_of

__all__ = ["System", "symbol", "variables_of"]
