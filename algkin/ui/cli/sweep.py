"""The ``sweep`` and ``atlas`` commands: their grammar and what they run (``algkin.sweep``, ``algkin.ui.atlas``)."""

from __future__ import annotations

import argparse
from collections.abc import Callable
from typing import TYPE_CHECKING

from ...runtime.strict_json import json_text
from ...runtime.terminal import one_line

if TYPE_CHECKING:
    from ...scene import Scene
    from .commands import Command, Outcome
    from .parser import Subcommands

__all__ = ["add_commands", "COMMANDS"]


def add_commands(commands: Subcommands, command: Callable[[Subcommands, str, str], argparse.ArgumentParser],
                 json_option: Callable[[argparse.ArgumentParser, str], None], *,
                 scene_arguments: Callable[[argparse.ArgumentParser], None]) -> None:
    """Add ``sweep`` and ``atlas`` to the subcommands (``command``: how a subcommand is made;
    ``scene_arguments``: the scene and ``--set``, as every command that takes a scene has them)."""
    sweep = command(commands, "sweep", "named analyses over a grid (or random draws) of a scene's dimensions, "
                                       "one Parquet row per design; resumable, on Dask or in this process")
    scene_arguments(sweep)
    sweep.add_argument("--grid", nargs="+", action="extend", default=[], required=True, metavar="NAME=LO:HI:COUNT",
                       help="COUNT exact values of dimension NAME from LO to HI (repeatable: their product); "
                            "with --random, NAME=LO:HI")
    sweep.add_argument("--random", type=_positive, metavar="N", help="N designs drawn in the --grid ranges")
    sweep.add_argument("--seed", type=int, default=0, help="random seed of the --random draws")
    sweep.add_argument("--analyses", default="curve", metavar="A,B,...",
                       help="comma-separated: curve, grashof, toggles, limits, transmission, singular; "
                            "for points solved together: modes, toggles")
    sweep.add_argument("--point", help="the point whose coupler curve is found and drawn (default: the scene's last)")
    sweep.add_argument("--out", required=True, metavar="DIR", help="the sweep's directory (resumed if it holds it)")
    sweep.add_argument("--executor", default="dask", help="dask (a LocalCluster, or --scheduler) or serial")
    sweep.add_argument("--workers", type=_positive, help="worker processes of the LocalCluster (default: one per core)")
    sweep.add_argument("--scheduler", metavar="ADDRESS", help="an existing Dask scheduler, e.g. tcp://host:8786")
    sweep.add_argument("--budget", type=float, metavar="SECONDS", help="seconds per design; past it, the design fails")
    sweep.add_argument("--chunk", type=_positive, default=8, help="designs per part file and per Dask task")
    sweep.add_argument("--yes", action="store_true",
                       help="start even a run projected to take longer than a day (it is refused otherwise)")
    json_option(sweep, "the counts and the dataset written")
    atlas = command(commands, "atlas", "a self-contained page browsing a sweep's coupler curves, with filters")
    atlas.add_argument("dir", metavar="DIR", help="a finished sweep's directory (algkin sweep --out DIR)")
    atlas.add_argument("--out", required=True, help="the .html page to write")
    atlas.add_argument("--samples", type=_positive, default=181,
                       help="inputs sampled per curve for its thumbnail (at most 3601, every tenth of a degree)")
    json_option(atlas, "what was written")


def _positive(text: str) -> int:
    if not (text.isascii() and text.strip().isdigit()) or int(text) < 1:
        raise argparse.ArgumentTypeError(f"expected a whole number from 1, got {text!r}")
    return int(text)


def _cmd_sweep(args: argparse.Namespace) -> Outcome:
    from ...sweep import sweep

    done = sweep(_scene_set(args), args.out, grid=args.grid, random=args.random, seed=args.seed,
                 analyses=[a for a in args.analyses.split(",")], point=args.point, executor=args.executor,
                 workers=args.workers, scheduler=args.scheduler, budget=args.budget, chunk=args.chunk,
                 yes=args.yes)
    document = done.to_json()
    if args.json:
        return json_text(document), 0
    counts = ", ".join(f"{k} {v}" for k, v in document["status"].items())
    return (f"{document['designs']} designs ({document['computed']} computed now): {counts}\n"
            f"wrote {one_line(document['dataset'])}\n"), 0  # under --out: one line


def _scene_set(args: argparse.Namespace) -> str | Scene:
    """The scene named, or with ``--set``, loaded with those dimensions set: any but a swept one."""
    if not args.set:
        return str(args.scene)
    from ...errors import UsageError
    from ...scene import load_scene
    from ...scene.settings import parse_settings, with_values

    settings = parse_settings(args.set)
    swept = {axis.split("=", 1)[0].strip() for axis in args.grid}
    for name in settings.keys() & swept:
        raise UsageError("set", f"{name}={settings[name]}", f"{name} is swept by --grid; set it or sweep it, not both")
    scene = load_scene(args.scene)
    valued = with_values(scene, settings)
    _refuse_a_set_no_design_takes(scene, valued, tuple(n for n in swept if n in scene.parameters), args.set)
    return valued


def _refuse_a_set_no_design_takes(scene: Scene, valued: Scene, swept: tuple[str, ...], given: list[str]) -> None:
    """UsageError where the values ``--set`` gives make the scene refuse to compile, the swept dimensions
    kept symbolic, though the file's own values compile: every design would fail for the same reason
    (``--set l=-1``). Where the file's values fail too, each design says why, as without ``--set``."""
    from ...errors import SceneError, UsageError
    from ...scene import compile_scene

    if scene.unknown_points:
        return  # its groups' values are checked as the sweep is planned
    try:
        compile_scene(valued, list(valued.points), swept)
    except SceneError as refused:
        try:
            compile_scene(scene, list(scene.points), swept)
        except SceneError:
            return
        raise UsageError("set", " ".join(given), str(refused)) from None


def _cmd_atlas(args: argparse.Namespace) -> Outcome:
    from ..atlas import write_atlas

    written = write_atlas(args.dir, args.out, samples=args.samples)
    document = {"out": str(args.out), "designs": written["designs"], "drawn": written["drawn"]}
    if args.json:
        return json_text(document), 0
    return f"wrote {one_line(args.out)}: {document['drawn']} of {document['designs']} designs drawn\n", 0


COMMANDS: dict[str, Command] = {"sweep": _cmd_sweep, "atlas": _cmd_atlas}
