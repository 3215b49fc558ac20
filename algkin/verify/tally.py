"""What a check counts while it runs: shared by verification (``verify.check``) and the rates check.

A check that compared nothing must fail, saying why, rather than pass vacuously, and an error past
its tolerance is reported once per thing compared, however many samples repeat it:

>>> tally = Tally(samples=3)
>>> tally.require_compared("branch value")
>>> tally.failures
['no branch value compared on 3 samples (0 near a degenerate configuration)']
>>> tally = Tally()
>>> for error in (0.5, 0.25):
...     tally.error(error, scale=2.0, tolerance=1e-9, said="branch B:", detail=f"{error} off")
>>> tally.max_abs_error, tally.max_rel_error, tally.failures
(0.5, 0.25, ['branch B: 0.5 off'])
"""

from __future__ import annotations

from dataclasses import dataclass, field

__all__ = ["Tally"]


@dataclass
class Tally:
    """Counts of one check's run (mutable while it runs; its result is a frozen record made from it)."""

    samples: int = 0
    compared: int = 0
    evaluated: int = 0
    near_degenerate: int = 0
    max_abs_error: float = 0.0
    max_rel_error: float = 0.0
    failures: list[str] = field(default_factory=list)

    def error(self, error: float, *, scale: float, tolerance: float, said: str, detail: str) -> None:
        """Record one error, absolute and relative to ``scale``; past ``tolerance`` (relative), the
        failure ``said detail``, once for each ``said``."""
        self.max_abs_error = max(self.max_abs_error, error)
        self.max_rel_error = max(self.max_rel_error, error / scale)
        if not error <= tolerance * scale and not any(f.startswith(said) for f in self.failures):
            self.failures.append(f"{said} {detail}")

    def require_compared(self, what: str) -> None:
        """Fail, saying why, when nothing was compared."""
        if not self.compared:
            self.failures.append(f"no {what} compared on {self.samples} samples "
                                 f"({self.near_degenerate} near a degenerate configuration)")
