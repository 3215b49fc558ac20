"""Running a checkout's algkin in a subprocess: the benches' ``--against DIR``, a change's before and after in one run.

``DIR`` holds another checkout's sources (``git archive <commit> | tar -x -C DIR``). A bench given
it runs each measurement from ``DIR`` and from this checkout in turn, in the same rounds, so that
the load of a shared machine falls on both alike and their ratio comes from one run. Each run is
a fresh ``python`` with its checkout first on ``sys.path`` (``PYTHONPATH``, which Dask's worker
processes inherit too; an editable install's finder comes after it), run from that checkout.

>>> measured(None) == [ROOT]
True
>>> describe(ROOT)
'this checkout'
"""

import argparse
import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]  # this checkout: its algkin is the one measured by default


def checkout(text):
    """``--against``'s value: a directory holding algkin's sources, resolved (argparse reports the error)."""
    path = Path(text).resolve()
    if not (path / "algkin" / "__init__.py").is_file():
        raise argparse.ArgumentTypeError(f"{text} holds no algkin/__init__.py (make it with "
                                         "`git archive <commit> | tar -x -C DIR`)")
    return path


def add_against(parser):
    """The ``--against DIR`` option, the same in every bench that has it."""
    parser.add_argument("--against", type=checkout, metavar="DIR",
                        help="another checkout's sources, measured in the same rounds (before)")


def measured(against):
    """The checkouts measured, in the order each round runs them: ``against`` (before) first, then this one."""
    return [ROOT] if against is None else [against, ROOT]


def describe(root):
    """How a table names the checkout it measured."""
    return "this checkout" if root == ROOT else str(root)


def environment(root):
    """The environment of a python run from ``root``'s sources: that checkout first on ``sys.path``."""
    return dict(os.environ, PYTHONPATH=str(root))


def run_python(root, arguments):
    """``python <arguments>`` from ``root``'s sources, its output captured; its stderr raised with the failure."""
    completed = subprocess.run([sys.executable, *map(str, arguments)], capture_output=True, text=True,
                               env=environment(root), cwd=root)
    if completed.returncode:
        raise RuntimeError(f"python {' '.join(map(str, arguments))} from {root} exited "
                           f"{completed.returncode}:\n{completed.stderr}")
    return completed
