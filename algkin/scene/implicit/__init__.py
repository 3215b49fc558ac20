"""Implicit points compiled into specs that describe their geometry (their branch algebra: ``algkin.branches.constructions``)."""

from .base import ImplicitSpec
from .dyad import DyadSpec
from .mirror import MirrorSpec
from .slider import SliderSpec

__all__ = ["ImplicitSpec", "DyadSpec", "MirrorSpec", "SliderSpec"]
