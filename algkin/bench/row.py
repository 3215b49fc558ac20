"""One row of ``algkin bench``: a method (or peer, or the default path) on one problem.

>>> from algkin.bench.agree import Agreement
>>> row = BenchRow("two-circles", "linear", "flint", 9.6e-4, degree=4, terms=17, bits=3, agrees=Agreement.EQUAL)
>>> row.passes, row.to_json()["agrees"]
(True, 'equal')
>>> BenchRow("two-circles", "resultant", "sympy", None, note="over budget").passes  # nothing to compare
True
>>> BenchRow("lambda-coupler", "resultant", "flint", 1e-3, agrees=Agreement.EXTRA_FACTOR).passes  # algkin's: wrong
False
>>> BenchRow("lambda-coupler", "PARI/GP resultant", "peer", 1e-4, agrees=Agreement.EXTRA_FACTOR).passes  # a verdict
True
>>> BenchRow("lambda-coupler", "Singular eliminate", "peer", 1e-4, agrees=Agreement.MISSING_FACTOR).passes
False
"""

from __future__ import annotations

from dataclasses import dataclass, field

from .agree import PASSING, Agreement, PortableForm

__all__ = ["BenchRow", "COLUMNS", "EXACT_PEERS"]

# The peers whose answer is exact (an elimination ideal, or every real solution of a zero-dimensional
# system): they and algkin must agree. The others (resultant chains, the roots of one) carry
# extraneous factors or roots by nature: their verdict is shown in their row, never a failure.
EXACT_PEERS = frozenset({"Singular eliminate", "Macaulay2 eliminate", "msolve eliminate", "msolve real solutions",
                         "Singular real solutions"})
COLUMNS = ("problem", "method", "backend", "seconds", "ratio", "degree", "terms", "bits", "agrees", "note")


@dataclass
class BenchRow:
    """What was measured: seconds (median, best of the rounds; ``None`` if it did not finish),
    the eliminant's figures, its verdict against the reference and the time over the default's."""

    problem: str
    method: str
    backend: str  # a backend of ``algkin.eliminate``, or ``peer``
    seconds: float | None
    degree: int | None = None
    terms: int | None = None
    bits: int | None = None
    note: str | None = None
    agrees: Agreement | None = None  # None: it did not finish, nothing to compare
    ratio: float | None = None  # seconds over the default method's on the same problem
    form: PortableForm | None = field(default=None, repr=False)  # the eliminant until compared

    @property
    def passes(self) -> bool:
        """Whether ``algkin bench`` may exit 0 for this row: unless it disagrees with its reference.
        It agrees, is the reference, did not finish, or finished with no reference to compare it
        with (``not compared``, said in its row: no verdict either way); a peer that is not exact
        (``EXACT_PEERS``) always passes, whatever its verdict says."""
        if self.backend == "peer" and self.method not in EXACT_PEERS:
            return True
        return self.agrees is None or self.agrees in PASSING or self.agrees is Agreement.NOT_COMPARED

    def to_json(self) -> dict[str, object]:
        """The row under the keys of the bench's JSON and CSV, its verdict as a string."""
        values = {key: getattr(self, key) for key in COLUMNS}
        values["agrees"] = None if self.agrees is None else str(self.agrees)
        return values
