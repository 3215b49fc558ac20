"""Numeric evaluation of closed forms (generic over number types)."""

from .tree import ARB, FLOAT, MPMATH, NUMPY, NumberKind, evaluate

__all__ = ["evaluate", "NumberKind", "ARB", "MPMATH", "FLOAT", "NUMPY"]
