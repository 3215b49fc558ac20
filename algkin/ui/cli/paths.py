"""The files a command reads and writes, checked in one place before any work: every output can
be written, and none is an input of the same command (or inside a directory it reads).

>>> import argparse, os, tempfile
>>> sweep = tempfile.mkdtemp()
>>> check_paths(argparse.Namespace(command="atlas", dir=sweep, out=os.path.join(sweep, "designs.parquet")))
Traceback (most recent call last):
...
algkin.errors.UsageError: --out='...designs.parquet': is inside the input directory ...; write it elsewhere
>>> os.rmdir(sweep)
"""

import argparse
import os

from ...errors import UsageError

__all__ = ["check_paths"]

# Each command's outputs: (attribute, flag, a file or a directory). A flag left out is None.
OUTPUTS = {
    "derive": (("out", "--out", "file"),),
    "curve": (("out", "--out", "file"),),
    "plot": (("out", "--out", "file"),),
    "export": (("out", "--out", "file"),),
    "accuracy": (("plot", "--plot", "file"),),
    "atlas": (("out", "--out", "file"),),
    "bench": (("out", "--out", "directory"),),
    "sweep": (("out", "--out", "directory"),),
    "synthesize": (("out", "--out", "directory"), ("plot", "--plot", "file")),
}
INPUTS = ("scene", "dir", "file")  # the attributes naming what a command reads (a catalog name is no file)


def check_paths(args: argparse.Namespace) -> None:
    """Raise ``UsageError`` naming the flag of the first output of ``args.command`` that cannot be
    written or that is, or is inside, one of its inputs."""
    from ...runtime.files import check_directory, check_output

    inputs = [path for path in (getattr(args, name, None) for name in INPUTS) if path and os.path.exists(path)]
    for name, flag, kind in OUTPUTS.get(args.command, ()):
        path = getattr(args, name, None)
        if path is None:
            continue
        for given in inputs:
            _not_over(flag, path, given)
        (check_output if kind == "file" else check_directory)(flag, path)


def _not_over(flag: str, path: str, given: str) -> None:
    """Refuse ``path`` if it is the input ``given`` (the same file, through any link) or inside it."""
    target, source = os.path.realpath(path), os.path.realpath(given)
    if target == source or _same_file(target, source):
        raise UsageError(flag, path, f"is the input {given}; algkin never writes over what it reads")
    if os.path.isdir(source) and os.path.commonpath([target, source]) == source:
        raise UsageError(flag, path, f"is inside the input directory {given}; write it elsewhere")


def _same_file(one: str, other: str) -> bool:
    """Whether two existing paths are one file (a hard link too)."""
    try:
        return os.path.samefile(one, other)
    except OSError:  # one of them does not exist (or cannot be looked up: check_output says why)
        return False
