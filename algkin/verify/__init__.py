"""Verification independent of the derivation: numeric solutions of the original system, proved in balls."""

from .balls import BlockCertifier
from .check import Verification, verify_branches
from .solve import Blocks, solve_floats

__all__ = ["Verification", "verify_branches", "Blocks", "solve_floats", "BlockCertifier"]
