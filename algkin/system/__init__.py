"""Exact polynomial systems, and the only sympy <-> python-flint conversion."""

from .core import System, input_values, inputs_json, symbol, variables_of

__all__ = ["System", "symbol", "variables_of", "input_values", "inputs_json"]
