"""Numeric evaluation of closed forms (generic over number types)."""

from . import pickled  # noqa: F401 - makes python-flint's balls and polynomials pickle, as the results holding them must
from .tree import ARB, FLOAT, MPMATH, NUMPY, NumberKind, evaluate

__all__ = ["evaluate", "NumberKind", "ARB", "MPMATH", "FLOAT", "NUMPY"]
