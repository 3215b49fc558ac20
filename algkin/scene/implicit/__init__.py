"""Implicit points compiled into specs that supply their own closed form, stable floats and toggles."""

from .algebra import reduce_on_circles
from .base import ImplicitSpec, StableEvaluator
from .dyad import DyadSpec
from .slider import SliderSpec

__all__ = ["ImplicitSpec", "StableEvaluator", "DyadSpec", "SliderSpec", "reduce_on_circles"]
