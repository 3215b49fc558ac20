"""A sweep's directory: its manifest, one Parquet part file per chunk, and the merged dataset.

``manifest.json`` says what the sweep is (the scene as TOML, the designs, random ones with their
draw scheme, the analyses, the traced point, the chunk size, the budget and algkin's version); a
run into a directory that holds another sweep is refused. Each chunk's rows go to ``parts/part-NNNNNN.parquet``, written
to a temporary name and renamed when whole, so a part file present is a chunk done; when all
are, ``designs.parquet`` is their rows sorted by design id. Parquet is written by pyarrow (the
``sweep`` extra), imported only here.
"""

from __future__ import annotations

import json
import pathlib
import re
from collections.abc import Mapping, Sequence
from typing import Any

from ..errors import UsageError
from ..runtime.files import atomic_output, write_atomic
from .design import TIMING_PREFIX

__all__ = ["MANIFEST", "DATASET", "read_manifest", "open_directory", "done_chunks", "write_part", "merge",
           "read_dataset", "without_timings", "arrow_schema"]

MANIFEST = "manifest.json"
DATASET = "designs.parquet"
PARTS = "parts"
_PART = re.compile(r"part-(\d{6})\.parquet")


def _pyarrow() -> Any:
    try:
        import pyarrow
        import pyarrow.parquet  # noqa: F401 - the submodule, loaded for the callers
    except ImportError:
        raise UsageError("sweep", "pyarrow", "needs the sweep extra: pip install 'algkin[sweep]'") from None
    return pyarrow


def arrow_schema(columns: Mapping[str, str]) -> Any:
    """The Arrow schema of columns ``{name: type}`` (string, float64, int64, bool, list<float64>)."""
    pa = _pyarrow()
    types = {"string": pa.string(), "float64": pa.float64(), "int64": pa.int64(), "bool": pa.bool_(),
             "list<float64>": pa.list_(pa.float64())}
    return pa.schema([(name, types[kind]) for name, kind in columns.items()])


def read_manifest(folder: str | pathlib.Path, *, argument: str = "folder") -> dict[str, Any] | None:
    """The manifest of the sweep in ``folder`` (None if it has none); one that cannot be read is a
    usage error naming ``argument``, the caller's parameter that gave ``folder``."""
    path = pathlib.Path(folder) / MANIFEST
    if not path.is_file():
        return None
    try:
        found = json.loads(path.read_text())
    except (OSError, ValueError) as err:
        raise UsageError(argument, str(folder), f"its {MANIFEST} cannot be read: {err}") from None
    if not _is_manifest(found):
        raise UsageError(argument, str(folder), f"its {MANIFEST} is not a sweep's (edited or damaged: "
                                                "its scene's text and the traced point are missing)")
    return found


def _is_manifest(found: Any) -> bool:
    """Whether ``found`` has what a sweep's manifest must: the scene's TOML and the point, as text."""
    return (isinstance(found, dict) and isinstance(found.get("scene"), dict)
            and isinstance(found["scene"].get("toml"), str) and isinstance(found.get("point"), str))


def open_directory(folder: str | pathlib.Path, manifest: Mapping[str, Any], check_only: bool = False) -> None:
    """Check that ``folder`` is new, empty or holds this same sweep; unless ``check_only``, make it
    and write the manifest. A different sweep there is a usage error naming what differs."""
    from ..runtime.files import check_directory

    folder = pathlib.Path(folder)
    check_directory("out", str(folder))
    found = read_manifest(folder, argument="out")
    if found is None and folder.is_dir() and any(folder.iterdir()):
        raise UsageError("out", str(folder), f"is not empty and holds no sweep ({MANIFEST}); give a new directory")
    if found is not None and found != manifest:
        differs = sorted(k for k in set(found) | set(manifest) if found.get(k) != manifest.get(k))
        raise UsageError("out", str(folder), f"holds a different sweep (its {', '.join(differs)} differ); "
                                               "give the same arguments to resume, or a new directory")
    if check_only:
        return
    (folder / PARTS).mkdir(parents=True, exist_ok=True)
    for stale in (folder / PARTS).glob(".part-*.tmp.parquet"):  # a run killed while writing a part
        stale.unlink(missing_ok=True)
    if found is None:
        write_atomic(folder / MANIFEST, json.dumps(manifest, indent=2, sort_keys=True) + "\n")


def done_chunks(folder: str | pathlib.Path) -> set[int]:
    """The chunks whose part file is written (whole: they appear only by a rename)."""
    parts = pathlib.Path(folder) / PARTS
    if not parts.is_dir():
        return set()
    return {int(m.group(1)) for p in parts.iterdir() if (m := _PART.fullmatch(p.name))}


def write_part(folder: str | pathlib.Path, index: int, rows: Sequence[Mapping[str, Any]],
               columns: Mapping[str, str]) -> None:
    """Write one chunk's rows as its part file, whole or not at all."""
    pa = _pyarrow()
    table = pa.Table.from_pylist([dict(r) for r in rows], schema=arrow_schema(columns))
    with atomic_output(pathlib.Path(folder) / PARTS / f"part-{index:06d}.parquet") as temporary:
        pa.parquet.write_table(table, temporary)


def merge(folder: str | pathlib.Path, columns: Mapping[str, str]) -> pathlib.Path:
    """``designs.parquet``: every part's rows, sorted by design id, written whole."""
    pa = _pyarrow()
    parts = sorted((pathlib.Path(folder) / PARTS).glob("part-*.parquet"))
    schema = arrow_schema(columns)
    table = pa.concat_tables([_table(p, schema=schema) for p in parts]) if parts else schema.empty_table()
    table = table.sort_by("design")
    target = pathlib.Path(folder) / DATASET
    with atomic_output(target) as temporary:
        pa.parquet.write_table(table, temporary)
    return target


def read_dataset(folder: str | pathlib.Path) -> Any:
    """The merged dataset of a finished sweep, as an Arrow table."""
    path = pathlib.Path(folder) / DATASET
    if not path.is_file():
        raise UsageError("folder", str(folder), f"holds no {DATASET}: not a finished sweep")
    table = _table(path)
    missing = [c for c in ("design", "status", "reason") if c not in table.column_names]
    if missing:
        raise UsageError("folder", str(folder), f"its {DATASET} is not a sweep's (no column {', '.join(missing)})")
    return table


def _table(path: pathlib.Path, schema: Any = None) -> Any:
    """The Parquet file at ``path`` (as ``schema``, if given); one that cannot be read (damaged, or
    not one of this sweep's parts) is a usage error naming it."""
    try:
        return _pyarrow().parquet.read_table(path, schema=schema)
    except (OSError, ValueError) as err:  # pyarrow's ArrowInvalid is a ValueError
        raise UsageError("folder", str(path), f"cannot be read as this sweep's: {' '.join(str(err).split())}; "
                                              "delete it to compute it again") from None


def without_timings(table: Any) -> Any:
    """``table`` without its timing columns: what two runs of the same sweep must agree on."""
    return table.drop_columns([n for n in table.column_names if n.startswith(TIMING_PREFIX)])
