"""The branch algebra of each implicit point's construction: what branches and analyses ask of a
compiled spec (``algkin.scene.implicit``, which describes geometry only).

One module per construction (``dyad``, ``slider``, ``mirror``, ``meet``), each a ``BranchAlgebra``:
the point's closed form on a mode, the conditions where its two modes meet, and a float64
evaluator free of cancellation. ``algebra_of`` picks it by the spec's type; a new
construction is one more spec in the scene layer and one more case here.

>>> from algkin.scene import compile_scene, load_scene
>>> [type(algebra_of(spec)).__name__ for spec in compile_scene(load_scene("peaucellier-lipkin")).implicit]
['DyadAlgebra', 'MirrorAlgebra', 'MirrorAlgebra']
"""

from ...scene.implicit import DyadSpec, ImplicitSpec, MeetSpec, MirrorSpec, SliderSpec
from .base import BranchAlgebra, Fix, HalfAngle, Mode, StableEvaluator, Substitution
from .dyad import DyadAlgebra
from .meet import MeetAlgebra
from .mirror import MirrorAlgebra
from .slider import SliderAlgebra

__all__ = ["algebra_of", "BranchAlgebra", "DyadAlgebra", "MeetAlgebra", "MirrorAlgebra", "SliderAlgebra", "StableEvaluator",
           "Substitution", "Mode", "Fix", "HalfAngle"]


def algebra_of(spec: ImplicitSpec) -> BranchAlgebra:
    """The branch algebra of the compiled implicit point ``spec``; TypeError for a spec without one."""
    match spec:
        case DyadSpec():
            return DyadAlgebra(spec)
        case SliderSpec():
            return SliderAlgebra(spec)
        case MirrorSpec():
            return MirrorAlgebra(spec)
        case MeetSpec():
            return MeetAlgebra(spec)
    raise TypeError(f"no branch algebra for {type(spec).__name__}: add its case to algkin.branches.constructions")
