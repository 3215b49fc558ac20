"""What an elimination method is asked, and what it answers.

A method is ``method(backend, polys, request) -> MethodOutcome``: the request says which
unknowns to eliminate and what guides and bounds the work; the outcome carries everything
the method found, so nothing is passed in to be filled. The steps inside a method answer
outcomes too, chained with ``MethodOutcome.then``.
"""

from dataclasses import dataclass, field
from typing import Generic, Protocol

from ..runtime.budget import Deadline, started
from .protocol import Backend, P
from .select import WitnessGroups

__all__ = ["LogEntry", "EliminationRequest", "MethodOutcome", "Method"]

LogEntry = tuple[str, str | int]
"""A step taken: its kind (``substituted``, ``resultant``, ...) and its unknown or count."""


@dataclass(frozen=True)
class EliminationRequest:
    """The unknowns to eliminate; the witness groups that choose factors; the ``parameters``
    (kept variables a ``linear`` multiplier may hold); the deadline the work keeps to (by default, none)."""

    eliminate: tuple[str, ...]
    witnesses: WitnessGroups = ()
    parameters: tuple[str, ...] = ()
    deadline: Deadline = field(default_factory=started)


@dataclass(frozen=True)
class MethodOutcome(Generic[P]):
    """The equations ``left`` (free of the eliminated unknowns), the factors ``dropped`` on the
    way, the ``log`` of steps, and the ``multipliers`` equations were multiplied by (the
    eliminant's extraneous factors can only be theirs)."""

    left: list[P]
    dropped: list[P] = field(default_factory=list)
    log: list[LogEntry] = field(default_factory=list)
    multipliers: list[P] = field(default_factory=list)

    def then(self, step: "MethodOutcome[P]") -> "MethodOutcome[P]":
        """This outcome followed by ``step``, which started from its equations."""
        return MethodOutcome(step.left, self.dropped + step.dropped, self.log + step.log,
                             self.multipliers + step.multipliers)


class Method(Protocol):
    """An elimination method, on any backend: ``METHODS`` maps names to these."""

    def __call__(self, backend: Backend[P], polys: list[P], request: EliminationRequest, /) -> MethodOutcome[P]: ...
