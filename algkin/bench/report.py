"""The bench report as a table, CSV and JSON (its plot is drawn by ``algkin.ui.plot``).

>>> from algkin.bench.agree import Agreement
>>> from algkin.bench.row import BenchRow
>>> rows = [BenchRow("p", "linear", "flint", 2.5e-3, ratio=1.0, degree=6, terms=29, bits=12,
...                  agrees=Agreement.EQUAL, note="median of 5 runs")]
>>> print(table(rows))  # doctest: +NORMALIZE_WHITESPACE
problem  method  backend  time     vs default  deg  terms  bits  agrees  note
p        linear  flint    2.50 ms  1.00x       6    29     12    equal   median of 5 runs
"""

from __future__ import annotations

import csv
import io
from collections.abc import Callable, Iterable, Sequence
from typing import TYPE_CHECKING

from ..errors import OutputError
from ..runtime.files import write_atomic
from ..runtime.strict_json import json_text
from .row import COLUMNS, BenchRow

if TYPE_CHECKING:
    from . import BenchReport

__all__ = ["table", "to_csv", "write", "seconds_text", "COLUMNS"]

HEADERS = ("problem", "method", "backend", "time", "vs default", "deg", "terms", "bits", "agrees", "note")


def seconds_text(value: float | None) -> str:
    if value is None:
        return "-"
    for unit, scale in (("s", 1.0), ("ms", 1e-3), ("us", 1e-6)):
        if value >= scale:
            return f"{value / scale:.2f} {unit}"
    return f"{value / 1e-9:.0f} ns"


def _cells(row: BenchRow) -> list[str]:
    values = row.to_json()
    text = {"seconds": seconds_text(row.seconds), "ratio": "-" if row.ratio is None else f"{row.ratio:.2f}x"}
    return [text.get(k, "-" if values[k] is None else str(values[k])) for k in COLUMNS]


def table(rows: Iterable[BenchRow]) -> str:
    """Aligned columns, one line per row."""
    cells = [list(HEADERS)] + [_cells(r) for r in rows]
    widths = [max(len(line[i]) for line in cells) for i in range(len(HEADERS) - 1)]
    return "\n".join("  ".join(c.ljust(w) for c, w in zip(line, widths)) + "  " + line[-1]
                     for line in cells)


def to_csv(rows: Iterable[BenchRow]) -> str:
    out = io.StringIO()
    writer = csv.DictWriter(out, fieldnames=COLUMNS, lineterminator="\n")
    writer.writeheader()
    writer.writerows(r.to_json() for r in rows)
    return out.getvalue()


def write(report: BenchReport, directory: str,
          plot: Callable[[Sequence[BenchRow], str], str] | None = None) -> list[str]:
    """bench.json, bench.csv and, given ``plot``, bench.png in ``directory``; the paths written.

    ``plot(rows, path)`` draws the rows' figure to ``path`` and returns the path: presentation
    lives above the bench (``algkin.ui``), so the command line passes it in. Each file replaces
    an earlier one only once complete (``algkin.runtime.files``).
    """
    import os

    try:
        os.makedirs(directory, exist_ok=True)
    except OSError as err:
        raise OutputError(directory, err.strerror or str(err)) from err
    paths = [os.path.join(directory, n) for n in ("bench.json", "bench.csv")]
    write_atomic(paths[0], json_text(report.to_json()))
    write_atomic(paths[1], to_csv(report.rows))
    if plot is not None:
        paths.append(plot(report.rows, os.path.join(directory, "bench.png")))
    return paths
