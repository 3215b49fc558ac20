"""The ``synthesize`` command: its grammar, what it runs (``algkin.synthesis``) and its report.

The kind on the command line (``motion``, ``function``, ``path``) must be the file's. The
scene files (``--out DIR``) and the figure (``--plot F``) are made within the budget and written
by the parent, each whole or not at all. A fault in the file's data that only the mathematics
sees (two equal poses, a pure translation) is said as the file's: ``FILE: poses: ...``.
"""

from __future__ import annotations

import argparse
import os
import pathlib
import re
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from ...errors import SceneError, UsageError
from ...runtime.terminal import one_line
from .reports import Document, render

if TYPE_CHECKING:
    from .commands import Command, File, Outcome
    from .parser import Subcommands

__all__ = ["add_command", "COMMANDS", "report_synthesis"]

KINDS = ("motion", "function", "path")
# the mathematics' arguments -> the file's keys (its errors are the file's)
_DATA = {"poses": "poses", "pairs": "pairs", "points": "points", "ground": "ground", "crank_pivot": "pivots.crank",
         "rocker_pivot": "pivots.rocker"}


def add_command(commands: Subcommands, command: Callable[[Subcommands, str, str], argparse.ArgumentParser],
                json_option: Callable[[argparse.ArgumentParser, str], None]) -> None:
    """Add ``synthesize`` to the subcommands (``command``: how a subcommand is made)."""
    synthesize = command(commands, "synthesize", "four-bars from wanted poses (motion), angle pairs (function) or "
                                                 "path points (path): every solution, certified; scene files written")
    synthesize.add_argument("kind", choices=KINDS, help="what the file asks for")
    synthesize.add_argument("file", help="the synthesis file (.toml): poses, pairs or points, exact; or an example's "
                                         "name (fourbar-poses, fourbar-pairs, three-pairs, straight-line-path, seven-points-path)")
    synthesize.add_argument("--out", metavar="DIR", help="write each mechanism's scene file into DIR")
    synthesize.add_argument("--plot", metavar="FILE",
                            help="draw the solutions with the poses or points (.png/.svg/.pdf)")
    synthesize.add_argument("--digits", type=int, default=30, help="significant digits of each number shown")
    synthesize.add_argument("--bits", type=int, default=128, help="working precision of the certified roots")
    synthesize.add_argument("--min-transmission", dest="min_transmission", type=float, default=30.0,
                            help="degrees: a transmission angle below it (or above 180 minus it) is a defect")
    json_option(synthesize, "the solutions, the mechanisms and their defects")


def _cmd_synthesize(args: argparse.Namespace) -> Outcome:
    from ...synthesis import synthesize
    from ...synthesis.files import read_task

    task = read_task(args.file)
    if task.kind != args.kind:
        raise UsageError("kind", args.kind, f"{args.file} asks for {task.kind} synthesis (kind = \"{task.kind}\")")
    if args.out:
        _never_over_input(args.file, args.out, task.name)
    try:
        found = synthesize(task, bits=args.bits, digits=args.digits, min_transmission=args.min_transmission,
                           budget=args.deadline)
    except UsageError as err:
        if err.argument in _DATA:
            raise SceneError(args.file, _DATA[err.argument], err.message) from None
        raise
    document = found.to_json()
    files: list[File] = []
    if args.out:
        out = pathlib.Path(args.out)
        files += [(out / name, text) for name, text in found.scenes().items()]
        document["written"] = [str(path) for path, _ in files]
    if args.plot:
        files.append(_figure(found, args.plot))
        document["plot"] = args.plot
    return render(args, document, report_synthesis), 0, files


def _never_over_input(file: str, out: str, name: str) -> None:
    """Refuse ``--out`` before the work if the input is there under the name of a scene file it
    writes (``NAME-K.toml``, through any link): it would be replaced by a mechanism."""
    from ...synthesis.fourbar import safe_name

    folder = pathlib.Path(out)
    if not (folder.is_dir() and os.path.isfile(file)):
        return  # a folder still to make, or an example taken by name: nothing of the user's there
    written = re.compile(rf"{re.escape(safe_name(name))}-[0-9]+\.toml")
    for path in folder.iterdir():
        if written.fullmatch(path.name) and path.is_file() and os.path.samefile(path, file):
            raise UsageError("--out", out, f"holds the input {file} as {path.name}, a name of the scene files "
                                           "written there; algkin never writes over what it reads")


def _figure(found: Any, path: str) -> File:
    from ..plot import FORMATS, image
    from ..synthesisdraw import synthesis_figure

    out = pathlib.Path(path)
    if out.suffix.lower() not in FORMATS or out.suffix.lower() in (".gif", ".mp4", ".html"):
        raise UsageError("--plot", path, "unknown figure format; valid: .png, .svg, .pdf")
    return out, image(synthesis_figure(found), out.suffix)


def report_synthesis(d: Document) -> str:
    """``algkin synthesize``'s text: the counts, each real solution, each mechanism and its defects.

    >>> print(report_synthesis({"kind": "motion", "name": "t", "approximate_angles": False, "complex_count": 4,
    ...     "burmester": [{"centre": ["1", "2"], "circle": ["0", "1"]}], "mechanisms": [], "usable": 0,
    ...     "timings": {"solve": 0.1, "check": 0.0}}))
    t: motion synthesis, 4 complex solutions, 1 real
      Burmester pair 1: centre (1, 2), circle point (0, 1)
    no four-bar: fewer than two real pairs
    """
    lines = [f"{d['name']}: {d['kind']} synthesis" + _counts(d)]
    if d.get("approximate_angles"):
        lines.append("  (angles given in degrees taken to 60 digits: solutions are of those angles)")
    if "centre_curve" in d:
        lines += [f"  centre-point curve: {_shown(d['centre_curve'])} = 0",
                  f"  circle-point curve: {_shown(d['circle_curve'])} = 0",
                  "four poses: a one-parameter family of dyads (five poses give the Burmester pairs)"]
        return "\n".join(lines)
    if "size" in d:
        size = d["size"]
        lines.append(f"  system: {size['equations']} equations in {size['unknowns']} unknowns ({size['points']} points); "
                     f"the first five points' eliminant: degree {size['eliminant_degree']} in t1, "
                     f"{size['eliminant_terms']} terms, {size['eliminant_bits']}-bit coefficients, "
                     f"{size['five_point_solutions']} solutions")
    for k, pair in enumerate(d.get("burmester", []), 1):
        lines.append(f"  Burmester pair {k}: centre ({', '.join(pair['centre'])}), "
                     f"circle point ({', '.join(pair['circle'])})")
    for k, solution in enumerate(d.get("solutions", []), 1):
        starts = solution.get("start")
        lines.append(f"  solution {k}: " + ", ".join(f"{n} {v}" for n, v in solution["lengths"].items())
                     + (f"; at the first pair the crank at {starts['input']['degrees']:.6g} deg, the rocker at "
                        f"{starts['output']['degrees']:.6g} deg" if starts else ""))
    if not d["mechanisms"]:
        lines.append("no four-bar: " + ("fewer than two real pairs" if d["kind"] == "motion" else "no real solution"))
    for m in d["mechanisms"]:
        verdict = "usable" if m["usable"] else "not usable: " + "; ".join(f"{x['kind']} defect ({x['why']})"
                                                                         for x in m["defects"]) \
            if m["reached"] else "NOT reached by the scene (largest miss {:.3g})".format(m["deviation"])
        span = m["transmission_range"]
        lines.append(f"  {m['scene']}: {m['grashof'] or 'not a four-bar class'}"
                     + (f", transmission {span[0]:.1f}-{span[1]:.1f} deg" if span else "") + f"; {verdict}")
    lines += [f"  left out: {what}: {reason}" for what, reason in _left_out(d.get("excluded", []))]
    lines += [f"wrote {one_line(path)}" for path in d.get("written", [])]  # under --out: one line
    if d.get("plot"):
        lines.append(f"wrote {d['plot']}")
    return "\n".join(lines)


def _left_out(excluded: list[dict[str, Any]]) -> list[tuple[str, str]]:
    """What was left out and why, a line each: a factor's roots by the factor, the solutions of
    several factors left out for one reason counted together (three lines alike said nothing more)."""
    shown: list[tuple[str, str]] = []
    counts: dict[str, list[int]] = {}
    for left in excluded:
        if "factor" in left:
            shown.append((f"the roots of {_shown(left['factor'])}", left["reason"]))
        elif left["reason"] in counts:
            counts[left["reason"]][0] += left["complex_count"]
            counts[left["reason"]][1] += left["real_count"]
        else:
            counts[left["reason"]] = [left["complex_count"], left["real_count"]]
    return shown + [(f"{complex_count} solution(s), {real_count} real", reason)
                    for reason, (complex_count, real_count) in counts.items()]


def _shown(polynomial: str, room: int = 160) -> str:
    """A polynomial as the report shows it: whole when short, else its start and its length
    (``--json`` has it whole)."""
    return polynomial if len(polynomial) <= room else f"{polynomial[:room]} ... ({len(polynomial)} characters; --json: whole)"


def _counts(d: Document) -> str:
    if "complex_count" not in d:
        return ""
    real = d.get("real_count", len(d.get("burmester", d.get("solutions", []))))
    return f", {d['complex_count']} complex solution{'s' * (d['complex_count'] != 1)}, {real} real"


COMMANDS: dict[str, Command] = {"synthesize": _cmd_synthesize}
