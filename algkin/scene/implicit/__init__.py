"""Implicit points compiled into specs that supply their own closed form, stable floats and toggles."""

from .algebra import reduce_on_circles
from .base import ImplicitSpec, StableEvaluator
from .dyad import DyadSpec
from .mirror import MirrorSpec
from .slider import SliderSpec

__all__ = ["ImplicitSpec", "StableEvaluator", "DyadSpec", "MirrorSpec", "SliderSpec", "reduce_on_circles"]
