"""Implicit points compiled into specs that describe their geometry (their branch algebra: ``algkin.branches.constructions``)."""

from .base import ImplicitSpec
from .dyad import DyadSpec
from .meet import MeetSpec
from .mirror import MirrorSpec
from .slider import SliderSpec

__all__ = ["ImplicitSpec", "DyadSpec", "MeetSpec", "MirrorSpec", "SliderSpec"]
