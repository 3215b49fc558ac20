"""Verification independent of the derivation: numeric solutions of the original system, proved in balls."""

from .balls import BlockCertifier
from .check import CheckSetup, Verification, verify_branches
from .solve import Blocks, solve_floats

__all__ = ["Verification", "CheckSetup", "verify_branches", "Blocks", "solve_floats", "BlockCertifier"]
