"""Verification independent of the derivation: numeric solutions of the original system."""

from .check import Verification, verify_branches
from .solve import Blocks, solve_all

__all__ = ["Verification", "verify_branches", "Blocks", "solve_all"]
