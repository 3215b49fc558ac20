"""One function per command: its whole output (text or JSON) and exit code, and the files it
makes, computed inside the command's budget (``algkin.ui.cli.main`` runs it and writes): the
command passes its deadline, ``args.deadline``, to the work that keeps to it."""

from __future__ import annotations

import argparse
import math
import os
import pathlib
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING, Any, Union

from ...runtime import suggest
from ...errors import UsageError, renamed
from ...runtime.strict_json import json_text
from ...runtime.terminal import one_line
from ...runtime.validation import real
from .groups import group_curve, group_derive, group_toggles, group_verify
from .sweep import COMMANDS as SWEEP_COMMANDS
from .synthesis import COMMANDS as SYNTHESIS_COMMANDS
from .reports import (Document, Form, extremum_forms, latex_lines, render, report_accuracy, report_curve,
                      report_derive, report_extremum, report_follow, report_show, report_singular, report_solve, report_toggles, verification_line)

if TYPE_CHECKING:
    from ...bench.row import BenchRow
    from ...derivation.pipeline import Derivation
    from ...scene import Scene
    from ...analyses.rates.check import RatesCheck
    from ...verify import Verification

__all__ = ["COMMANDS", "Command", "Outcome", "File"]

File = tuple[pathlib.Path, Union[str, bytes]]  # a file a command made, for the parent to write
# What a command returns: its output (text or JSON) and exit code, and the files it made
Outcome = Union[tuple[str, int], tuple[str, int, list[File]]]
Command = Callable[[argparse.Namespace], Outcome]


def _bench_plot() -> Callable[[Sequence[BenchRow], str], str] | None:
    """What draws bench.png (``bench.report.write``), or None when the plotting module cannot load."""
    try:
        from ..plot import bench_figure, save
    except ImportError:
        return None
    return lambda rows, path: save(bench_figure(rows), path)


def _cmd_bench(args: argparse.Namespace) -> Outcome:
    from ...bench import bench, problem_names
    from ...bench.report import table, write
    from ...eliminate import backend_names, method_names
    from .parser import BENCH_FULL, BENCH_QUICK

    for option, given, valid in (("--problems", args.problems, problem_names()),
                                 ("--methods", args.methods, method_names()),
                                 ("--backends", args.backends, backend_names())):
        for name in given or ():
            if name not in valid:
                raise UsageError(option, name, "unknown" + suggest.known(name, valid, plural="valid"))
    budget, rounds = BENCH_FULL if args.full else BENCH_QUICK
    budget = budget if args.budget is None else args.budget
    rounds = rounds if args.rounds is None else args.rounds
    report = bench(args.problems, args.methods, args.backends, budget, not args.no_peers, rounds)
    written = write(report, args.out, plot=_bench_plot()) if args.out else []
    if args.json:
        text = json_text(report.to_json())
    else:
        text = "\n".join([table(report.rows), "machine: " + ", ".join(f"{k} {v}" for k, v in report.machine.items()),
                          *(f"wrote {one_line(str(path))}" for path in written)]) + "\n"
    # exit 1 only where one of algkin's rows or a peer's exact elimination disagrees with its
    # reference (``BenchRow.passes``); a resultant chain's extra factor is its row's verdict
    agree = all(row.passes for row in report.rows)
    return text, 0 if agree else 1


def _scene_of(args: argparse.Namespace, params: Sequence[str] | None = None) -> str | Scene:
    """The command's scene: the name or path given (loaded by the command, as from Python), or with
    ``--set``, the scene loaded with those dimensions set (``params``, by default ``--param``, are
    kept symbolic and cannot be set)."""
    if not args.set:
        return args.scene
    from ...scene import load_scene
    from ...scene.settings import parse_settings, with_values

    symbolic = getattr(args, "param", ()) if params is None else params
    return with_values(load_scene(args.scene), parse_settings(args.set), symbolic)


def _method(args: argparse.Namespace) -> str:
    """The method asked for, else the default (imported here: ``algkin list`` loads no algebra)."""
    from ...eliminate import DEFAULT_METHOD

    return DEFAULT_METHOD if args.method is None else args.method


def _range(text: str) -> tuple[float, float]:
    try:
        lo, hi = (real(v) for v in text.split(":"))
    except ValueError:
        raise UsageError("--range", text, "expected lo:hi, e.g. 0:180") from None
    if not all(math.isfinite(v) for v in (lo, hi)):
        raise UsageError("--range", text, "lo and hi must be finite numbers")
    if not lo < hi:
        raise UsageError("--range", text, "lo must be below hi")
    return lo, hi


def _cmd_extremum(args: argparse.Namespace) -> Outcome:
    from ...analyses.extremum import extremum

    _check_latex(args)
    angles = _range(args.range) if args.range else None
    found = extremum(_scene_of(args), args.of, angles, params=args.param, budget=args.deadline)
    if args.latex:
        return latex_lines(extremum_forms(found)), 0
    return render(args, found.to_json(), report_extremum), 0


def _cmd_toggles(args: argparse.Namespace) -> Outcome:
    from ...analyses.limits import limits
    from ...analyses.toggles import toggles

    together = _solved_together(args)
    if together is not None:
        return group_toggles(args, together)
    scene = _scene_of(args)
    document = toggles(scene, budget=args.deadline).to_json()
    if document["unit"] == "deg":  # a turning input's: the output's limit positions and time ratio
        document.update(limits(scene, budget=args.deadline).to_json())
    return render(args, document, report_toggles), 0


def _cmd_singular(args: argparse.Namespace) -> Outcome:
    from ...analyses.singular import singular

    found = singular(_scene_of(args, ()), args.point, samples=args.samples, seed=args.seed, budget=args.deadline)
    document = found.to_json()
    return render(args, document, report_singular), _verdict_of(document["curve_verification"])


def _verdict_of(verification: Document) -> int:
    """``_verdict`` of a verification's JSON document."""
    return 0 if verification["status"] in ("passed", "skipped") else 1


def _cmd_accuracy(args: argparse.Namespace) -> Outcome:
    from ...bench.accuracy import accuracy

    if args.samples < 10:
        raise UsageError("--samples", args.samples, "needs at least 10 samples per case")
    out = _figure_path("--plot", args.plot) if args.plot is not None else None
    result = accuracy(_scene_of(args), args.samples, args.seed, of=args.of, budget=args.deadline)
    text = render(args, result.to_json(), report_accuracy)
    if out is None:
        return text, 0
    from ..plot import accuracy_figure, image

    # Drawn here, within the budget; written by the parent, where an interrupt can still clean up.
    return text, 0, [(out, image(accuracy_figure(result), out.suffix))]


def _figure_path(option: str, text: str) -> pathlib.Path:
    """The figure's path, of a format it can be drawn in (``paths.check_paths`` checked that it can be written)."""
    from ..plot import FORMATS

    out = pathlib.Path(text)
    if out.suffix.lower() not in FORMATS:
        raise UsageError(option, text, f"unknown figure format; valid: {', '.join(FORMATS)}")
    return out


def _cmd_plot(args: argparse.Namespace) -> Outcome:
    """The drawing made within the budget, as bytes; the parent writes it (a stop at the deadline
    leaves no file begun)."""
    if args.of is None:
        from ..draw import mechanism_file

        for option in ("range", "derivative", "against"):
            if getattr(args, option):
                raise UsageError(f"--{option}", getattr(args, option), "goes with --of OUTPUT")
        # plot's --param names the page's sliders, which start at the values set: no clash
        data = mechanism_file(_scene_of(args, ()), args.out, args.input, args.branch, args.modes, args.param,
                              args.range_of, budget=args.deadline)
        return _drawn(args, pathlib.Path(args.out), data)
    for option in ("input", "branch", "modes", "param", "range_of"):
        if getattr(args, option):
            value = getattr(args, option)
            raise UsageError(f"--{option.replace('_', '-')}", " ".join(value) if isinstance(value, list) else value,
                             "draws the mechanism; leave out --of")
    out = _figure_path("--out", args.out)
    if args.against and args.derivative:
        raise UsageError("--against", args.against, "draws the minimum; leave out --derivative")
    against = _against(args.against) if args.against else None
    from ...analyses.quantities import load_quantities
    from ...scene.compile import refuse_lengths_not_positive
    from ...scene.load import as_scene
    from ..plot import image, minimum_figure, quantity_figure

    params = [against[0]] if against else []
    with renamed("params", to="--against"):  # --against's dimension, made symbolic
        scene = as_scene(_scene_of(args, params))
        if against:
            refuse_lengths_not_positive(scene, against[0], against[1:], argument="--against")
        quantity = load_quantities(scene, params, budget=args.deadline).output(args.of)
    with renamed("outputs", to="of"):
        found = quantity.extremum(_range(args.range) if args.range else None)
    figure = minimum_figure(quantity, found, *against) if against else \
        quantity_figure(quantity, found, derivative=args.derivative)
    return _drawn(args, out, image(figure, out.suffix))


def _drawn(args: argparse.Namespace, out: pathlib.Path, data: bytes) -> Outcome:
    """``plot``'s outcome: what it says, and its drawing for the parent to write to ``out``."""
    return render(args, _written(args, out), lambda d: d["out"]), 0, [(out, data)]


def _written(args: argparse.Namespace, out: str | os.PathLike[str]) -> dict[str, object]:
    """``plot``'s JSON document: the file written and what it shows."""
    return {"scene": args.scene, "out": str(out), "format": pathlib.Path(str(out)).suffix.lower().lstrip("."),
            "of": args.of}


def _against(text: str) -> tuple[str, float, float]:
    """``--against p=lo:hi``: the dimension and its span."""
    from ..draw import parse_ranges

    ((name, (lo, hi)),) = parse_ranges([text], "--against").items()
    return name, lo, hi


def _cmd_list(args: argparse.Namespace) -> Outcome:
    from ...catalog import catalog_entries  # the files read, not loaded: no algebra imported

    document = {"scenes": [{"name": name, "description": description} for name, description in catalog_entries()]}
    return render(args, document, lambda d: "\n".join(f"{s['name']:24} {s['description']}" for s in d["scenes"])), 0


def _cmd_show(args: argparse.Namespace) -> Outcome:
    from ...scene import compile_scene
    from ...scene.load import as_scene
    from ...system import inputs_json

    args.deadline.note(f"loading {args.scene}")
    scene = as_scene(_scene_of(args))
    args.deadline.note(f"compiling {scene.name}")
    if scene.unknown_points:
        return render(args, _shown_groups(scene, args), report_show), 0
    compiled = compile_scene(scene, args.outputs, args.param)
    document = {
        "scene": scene.name,
        "description": scene.description,
        "length_unit": scene.unit,  # the scene's ``unit`` of length, "" when it says none
        "points": {n: type(c).__name__.lower() for n, c in scene.points.items()},
        "outputs": {n: list(v) for n, v in compiled.outputs.items()},
        "inputs": inputs_json(compiled.system.inputs),
        "system": compiled.system.to_json(),
        # point -> why it never assembles: dyads on two fixed bases, decided exactly
        "never_assembles": dict(compiled.never_assembles),
    }
    if scene.driven:  # inputs turned by others through gears: no variables of their own
        document["geared"] = {n: {"driven_by": d.driver, "ratio": str(d.ratio)} for n, d in scene.driven.items()}
    return render(args, document, report_show), 0


def _shown_groups(scene: Scene, args: argparse.Namespace) -> dict[str, object]:
    """``show``'s document for a scene with points solved together: each group's points,
    unknowns, constraints and equations (every parameter at its default, as solve takes them)."""
    from ...scene.groups import compile_groups
    from ...system import inputs_json

    for option in ("outputs", "param"):
        if getattr(args, option):
            raise UsageError(f"--{option}", " ".join(getattr(args, option)),
                             "not with points solved together: show gives every group at the defaults")
    compiled = compile_groups(scene)
    equations = [str(eq) for group in compiled.groups for eq in group.equations]
    return {
        "scene": scene.name,
        "description": scene.description,
        "length_unit": scene.unit,
        "points": {n: type(c).__name__.lower() for n, c in scene.points.items()},
        "outputs": {n: [o.text] for n, o in scene.outputs.items()},
        "inputs": inputs_json(compiled.inputs),
        "system": {"unknowns": [u for group in compiled.groups for u in group.unknowns], "parameters": [],
                   "equations": equations},
        "groups": [{"points": list(g.points), "unknowns": list(g.unknowns), "constraints": list(g.constraints),
                    "equations": [str(eq) for eq in g.equations]} for g in compiled.groups],
    }


def _cmd_derive(args: argparse.Namespace) -> Outcome:
    from ...derivation.pipeline import derive

    out = _full_forms_target(args)
    together = _solved_together(args)
    if together is not None:
        return _finish(args, out, *group_derive(args, together))
    result = derive(_scene_of(args), args.outputs, **_engine(args))
    # the sympy forms only for LaTeX: reduced again and made readable, they cost seconds on a six-bar
    forms = _derive_forms(result) if args.latex else []
    document: Document = result.to_json()
    code = _verdict(result.verification)
    if args.rates:
        document, rate_forms, rate_code = _rates(result, document, args)
        forms, code = forms + rate_forms, max(code, rate_code)
    return _finish(args, out, document, report_derive, forms, code)


def _derive_forms(result: Derivation) -> list[Form]:
    """derive's LaTeX forms: each eliminant reduced on the circles, each branch's closed forms."""
    from ...branches import readable

    forms = [(f"eliminant of {u}, reduced on c^2 + s^2 = 1", p, "= 0") for u, p in result.eliminants_reduced.items()]
    return forms + [(f"{u}, branch {b.label}", readable(v), "") for b in result.branches for u, v in b.values.items()]


def _rates(result: Derivation, document: Document, args: argparse.Namespace) -> tuple[Document, list[Form], int]:
    """``derive --rates``: ``document`` with the rates' keys and timings, their LaTeX forms, the exit code."""
    from ...analyses.rates import rates_of

    try:
        found = rates_of(result, args.samples, args.seed)
    except UsageError as err:  # the scene cannot have rates: asked for by --rates
        raise UsageError("--rates", err.value, err.message) from None
    document = dict(document, **found.to_json())
    timings = dict(document["timings"], **found.timings)
    timings["total"] = timings.pop("total") + sum(found.timings.values())  # still last, and still the whole
    document["timings"] = timings
    forms = [(f"{kind} of {u} per {found.input}, branch {b.label}", expr, "")
             for b in found.branches for kind, rates in (("velocity", b.velocity), ("acceleration", b.acceleration))
             for u, expr in rates.items()]
    return document, forms, _verdict(found.verification)


def _check_latex(args: argparse.Namespace) -> None:
    """--latex replaces the text report; --json has the strings (in sympy syntax): one or the other."""
    if args.latex and args.json:
        raise UsageError("--latex", True, "prints LaTeX instead of the text report; leave out --json or --latex")


def _full_forms_target(args: argparse.Namespace) -> pathlib.Path | None:
    """``--out``'s path (``paths.check_paths`` checked it before the work); ``--latex`` and ``--json``
    refused together."""
    _check_latex(args)
    return None if args.out is None else pathlib.Path(args.out)


def _finish(args: argparse.Namespace, out: pathlib.Path | None, document: Document,
            report: Callable[[Document], str], forms: Sequence[Form], code: int) -> Outcome:
    """What derive and curve return: the JSON, the LaTeX of ``forms`` or the text report, and with
    ``--out`` the whole JSON document as a file for the parent to write."""
    text = latex_lines(forms) if args.latex else render(args, document, report)
    if out is None:
        return text, code
    if not args.json:
        text += f"wrote the full JSON document to {one_line(str(out))}\n"  # the path typed: one line
    return text, code, [(out, json_text(document))]


def _engine(args: argparse.Namespace) -> dict[str, Any]:
    """The options derive, curve and verify share, by name: method, backend, symbolic dimensions, sampling,
    and the command's deadline."""
    return dict(method=_method(args), backend=args.backend, params=args.param, samples=args.samples, seed=args.seed,
                budget=args.deadline)


def _verdict(verification: Verification | RatesCheck) -> int:
    """Exit code: 0 when the check passed or was skipped on request, 1 when it failed."""
    return 0 if verification.status in ("passed", "skipped") else 1


def _cmd_curve(args: argparse.Namespace) -> Outcome:
    from ...derivation.pipeline import curve

    out = _full_forms_target(args)
    together = _solved_together(args)
    if together is not None:
        return _finish(args, out, *group_curve(args, together))
    result = curve(_scene_of(args), args.point, **_engine(args))
    # the sympy form only for LaTeX: on a family's curve it costs seconds
    forms = [(f"curve of {result.point}", result.elimination.polynomial, "= 0")] if args.latex else []
    return _finish(args, out, result.to_json(), report_curve, forms, _verdict(result.verification))


def _cmd_verify(args: argparse.Namespace) -> Outcome:
    from ...derivation.pipeline import derive

    if args.samples == 0:
        raise UsageError("--samples", 0, "verify needs at least one sample (derive and curve take 0 to skip it)")
    together = _solved_together(args)
    if together is not None:
        return group_verify(args, together)
    result = derive(_scene_of(args), args.outputs, certify=False, **_engine(args))
    document = {"scene": result.compiled.scene.name, "verification": result.verification.to_json(),
                "branches": [b.label for b in result.branches], "timings": dict(result.timings)}
    text = render(args, document, lambda d: f"scene {d['scene']}, branches {', '.join(d['branches'])}\n"
                                            + verification_line(d["verification"]))
    return text, _verdict(result.verification)


def _solved_together(args: argparse.Namespace) -> Scene | None:
    """The command's scene when it has points solved together (``unknown = true``), else None."""
    from ...scene.load import as_scene

    scene = as_scene(_scene_of(args))
    return scene if scene.unknown_points else None


def _cmd_export(args: argparse.Namespace) -> Outcome:
    from ..export import export

    code = export(_scene_of(args), args.outputs, args.to, args.param)
    document = {"scene": args.scene, "to": args.to, "outputs": args.outputs, "out": args.out}
    if args.out is None:
        return render(args, dict(document, code=code), lambda d: d["code"].rstrip("\n")), 0
    text = render(args, document, lambda d: f"wrote {d['to']} to {d['out']}")
    return text, 0, [(pathlib.Path(args.out), code)]


def _cmd_solve(args: argparse.Namespace) -> Outcome:
    from ...analyses.solve import solve

    found = solve(_scene_of(args), _at(args.at), mode=args.mode, digits=args.digits)
    return render(args, found.to_json(), report_solve), 0


def _cmd_follow(args: argparse.Namespace) -> Outcome:
    from ...analyses.follow import follow

    start = _at([args.start], "--from")
    found = follow(_scene_of(args), mode=args.mode, start=start, stop=args.stop, at=_at(args.at),
                   digits=args.digits, max_step=args.max_step, deadline=args.deadline)
    return render(args, found.to_json(), report_follow), 0


def _at(texts: Sequence[str], flag: str = "--at") -> dict[str, str]:
    """``NAME=VALUE``s (of ``flag``) as ``{name: value}``, each input once."""
    at: dict[str, str] = {}
    for text in texts:
        name, equals, value = text.partition("=")
        if not (equals and name.strip() and value.strip()):
            raise UsageError(flag, text, "expected INPUT=VALUE, e.g. theta=30")
        if name.strip() in at:
            raise UsageError(flag, text, f"{name.strip()} given twice")
        at[name.strip()] = value.strip()
    return at


COMMANDS: dict[str, Command] = {"list": _cmd_list, "show": _cmd_show, "derive": _cmd_derive, "curve": _cmd_curve,
            "verify": _cmd_verify, "extremum": _cmd_extremum, "plot": _cmd_plot,
            "toggles": _cmd_toggles, "singular": _cmd_singular, "accuracy": _cmd_accuracy, "bench": _cmd_bench,
            "export": _cmd_export, "solve": _cmd_solve, "follow": _cmd_follow, **SWEEP_COMMANDS,
            **SYNTHESIS_COMMANDS}
