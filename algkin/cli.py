"""The ``algkin`` command line (SPEC §3): readable reports, or one JSON document with --json.

Exit codes: 0 done, 1 a computation failed, a check did not hold or the budget ran out,
2 bad input, 128 + N stopped by signal N (130 Ctrl-C, 143 SIGTERM, 129 SIGHUP), 141 stdout
closed early. Whatever the outcome, stderr holds at most one line, and with --json stdout
holds one JSON document (``{"error": ...}`` when there is no result).

A command computes its whole output, text or JSON, inside its budget (``--max-seconds``),
in a forked child when there is a time budget; the parent only starts it, waits, and writes.
"""

import argparse
import contextlib
import functools
import json
import math
import os
import pathlib
import re
import signal
import sys
import threading

from .errors import AlgkinError, BudgetExceeded, SceneError, UsageError

__all__ = ["main", "usage", "terminal_safe"]

# What a stopping signal says on stderr; the exit code is 128 + its number, as a shell's.
_STOPS = {signal.SIGINT: "interrupted", signal.SIGTERM: "terminated (SIGTERM)", signal.SIGHUP: "hung up (SIGHUP)"}
# The reader of stdout went away (``algkin list | head -1``): 128 + SIGPIPE, what a shell reports
# for a program the closed pipe ended; 1 would say that the computation failed.
_STDOUT_CLOSED = 128 + signal.SIGPIPE
_ERROR_KINDS = ((UsageError, "usage"), (SceneError, "scene"), (BudgetExceeded, "budget"))


class _Parser(argparse.ArgumentParser):
    """argparse with a one-line error and exit code 2."""

    def error(self, message):
        raise UsageError("arguments", " ".join(sys.argv[1:]), message)


def _common(parser, method=True):
    parser.add_argument("scene", help="catalog name or path of a scene file")
    parser.add_argument("--json", action="store_true", help="one JSON document on stdout")
    if method:
        parser.add_argument("--method", default=None,
                            help="elimination method: linear (the default), resultant, groebner")
        parser.add_argument("--backend", default="flint", help="polynomial backend: flint, sympy")
        parser.add_argument("--param", action="append", default=[], help="keep this parameter symbolic")
        parser.add_argument("--samples", type=int, default=40, help="verification samples")
        parser.add_argument("--seed", type=int, default=0, help="verification seed")
        _budget_options(parser)


def _budget_options(parser, terms=True):
    parser.add_argument("--max-seconds", type=_seconds,
                        help="stop (exit 1) past this many seconds of the whole command, loading included")
    if terms:
        parser.add_argument("--max-terms", type=_terms,
                            help="stop (exit 1) when an eliminant passes this many terms")


def _seconds(text):
    try:
        value = float(text)
    except ValueError:
        value = None
    if value is None or not 0 < value < float("inf"):
        raise argparse.ArgumentTypeError(f"expected a positive number of seconds, got {text!r}")
    return value


def _terms(text):
    if not text.strip().isdigit() or int(text) < 1:
        raise argparse.ArgumentTypeError(f"expected a positive whole number of terms, got {text!r}")
    return int(text)


def build_parser():
    parser = _Parser(prog="algkin", description="Closed forms of planar mechanisms by elimination.")
    commands = parser.add_subparsers(dest="command", required=True, parser_class=_Parser)
    listing = commands.add_parser("list", help="the catalog")
    listing.add_argument("--json", action="store_true")
    show = commands.add_parser("show", help="the scene and the system it compiles to")
    _common(show, method=False)
    show.add_argument("--outputs", nargs="+", help="outputs (names, points, dist(P, Q), P.x)")
    show.add_argument("--param", action="append", default=[])
    _budget_options(show, terms=False)
    derive = commands.add_parser("derive", help="eliminants, closed-form branches, verification")
    _common(derive)
    derive.add_argument("--outputs", nargs="+")
    curve = commands.add_parser("curve", help="implicit trajectory curve of a point")
    _common(curve)
    curve.add_argument("--point", required=True)
    verify = commands.add_parser("verify", help="closed forms against independent numeric solutions")
    _common(verify)
    verify.add_argument("--outputs", nargs="+")
    extremum = commands.add_parser("extremum", help="stationary points of an output over the input")
    extremum.add_argument("scene")
    extremum.add_argument("--of", required=True, help="a scalar output: distance or coordinate")
    extremum.add_argument("--range", help="lo:hi in the input's unit")
    extremum.add_argument("--param", action="append", default=[],
                          help="keep this dimension symbolic: the minimum as a closed form in it")
    extremum.add_argument("--json", action="store_true")
    _budget_options(extremum)
    toggles = commands.add_parser("toggles", help="input angles where assembly modes meet, certified")
    toggles.add_argument("scene")
    toggles.add_argument("--json", action="store_true")
    _budget_options(toggles)
    accuracy = commands.add_parser("accuracy", help="speed against error of each evaluation strategy")
    accuracy.add_argument("scene")
    accuracy.add_argument("--samples", type=int, default=2000, help="samples per case")
    accuracy.add_argument("--seed", type=int, default=0)
    accuracy.add_argument("--plot", help="also draw time against error (log-log) to this .png/.svg/.pdf")
    accuracy.add_argument("--json", action="store_true")
    _budget_options(accuracy)
    plot = commands.add_parser("plot", help="the mechanism with its trajectories and implicit curves "
                                            "(.png/.svg/.pdf), animated (.gif/.mp4), an interactive page "
                                            "(.html); with --of a quantity against the input")
    plot.add_argument("scene")
    plot.add_argument("--out", required=True, help="the file to write: .png, .svg, .pdf, .gif, .mp4 or .html")
    plot.add_argument("--json", action="store_true", help="one JSON document on stdout: what was written")
    plot.add_argument("--input", action="append", default=[],
                      help="the input angle drawn, in degrees: VALUE, or NAME=VALUE for each input")
    plot.add_argument("--branch", help="the assembly mode drawn (default: the scene's)")
    plot.add_argument("--modes", action="store_true", help="every assembly mode side by side")
    plot.add_argument("--param", action="append",
                      help="a dimension with a slider in the .html page (default: every dimension)")
    plot.add_argument("--range-of", action="append", default=[], metavar="NAME=LO:HI",
                      help="the range of dimension NAME's slider in the .html page (repeatable), e.g. a=0.5:2")
    plot.add_argument("--of", help="a scalar output: draw it against the input instead")
    plot.add_argument("--range", help="with --of: lo:hi of the input, in its unit")
    plot.add_argument("--derivative", action="store_true", help="with --of: the slope, with its zero marked")
    plot.add_argument("--against", help="with --of: p=lo:hi, the minimum against the dimension p")
    bench = commands.add_parser("bench", help="elimination methods compared on a problem set, peers beside")
    bench.add_argument("--problems", nargs="+", help="problem names (default: the whole suite)")
    bench.add_argument("--methods", nargs="+", help="elimination methods (default: all)")
    bench.add_argument("--backends", nargs="+", help="polynomial backends (default: all)")
    bench.add_argument("--budget", type=float, default=60.0, help="seconds per row before it is stopped")
    bench.add_argument("--no-peers", action="store_true", help="skip Singular, PARI/GP, Macaulay2, msolve")
    bench.add_argument("--rounds", type=int, default=3,
                       help="rows under 2 s are measured this many times in turn, each keeping its best")
    bench.add_argument("--out", help="directory for bench.json, bench.csv and bench.png")
    bench.add_argument("--json", action="store_true")
    return parser


def usage(command):
    """The ``--help`` text of one command (the docs print it)."""
    commands = next(a for a in build_parser()._actions if isinstance(a, argparse._SubParsersAction))
    return commands.choices[command].format_help()


def _cmd_bench(args):
    from .bench import bench, problem_names
    from .bench.report import table, write
    from .eliminate import backend_names, method_names

    for option, given, valid in (("--problems", args.problems, problem_names()),
                                 ("--methods", args.methods, method_names()),
                                 ("--backends", args.backends, backend_names())):
        for name in given or ():
            if name not in valid:
                raise UsageError(option, name, f"unknown; valid: {', '.join(valid)}")
    if not 0 < args.budget < math.inf:  # nan too
        raise UsageError("--budget", args.budget, "must be a positive number of seconds")
    if args.rounds < 1:
        raise UsageError("--rounds", args.rounds, "must be at least 1")
    if args.out:
        from .files import check_directory

        check_directory("--out", args.out)
    progress = _progress if sys.stderr.isatty() else None  # a terminal watches; a log or a pipe does not
    report = bench(args.problems, args.methods, args.backends, args.budget, not args.no_peers, progress,
                   args.rounds)
    if progress:
        print(file=sys.stderr)
    written = write(report, args.out) if args.out else []
    if args.json:
        text = json.dumps(report.to_json(), indent=2) + "\n"
    else:
        text = "\n".join([table(report.rows), "machine: " + ", ".join(f"{k} {v}" for k, v in report.machine.items()),
                          *(f"wrote {path}" for path in written)]) + "\n"
    agree = all(r["agrees"] in (None, "reference") or r["agrees"].startswith("yes") for r in report.rows)
    return text, 0 if agree else 1


def _progress(message):
    """One status line, rewritten in place."""
    print(f"\r\033[Kalgkin bench: {message}", end="", file=sys.stderr, flush=True)


def _method(args):
    """The method asked for, else the default (imported here: ``algkin list`` loads no algebra)."""
    from .eliminate import DEFAULT_METHOD

    return args.method or DEFAULT_METHOD


def _range(text):
    try:
        lo, hi = (float(v) for v in text.split(":"))
    except ValueError:
        raise UsageError("--range", text, "expected lo:hi, e.g. 0:180") from None
    if not all(math.isfinite(v) for v in (lo, hi)):
        raise UsageError("--range", text, "lo and hi must be finite numbers")
    if not lo < hi:
        raise UsageError("--range", text, "lo must be below hi")
    return lo, hi


def _cmd_extremum(args):
    from .analyses.extremum import extremum

    angles = _range(args.range) if args.range else None
    return _render(args, extremum(args.scene, args.of, angles, params=args.param).to_json(), _report_extremum), 0


def _report_extremum(d):
    dims = ", ".join(f"{n} = {v}" for n, v in d["parameters"].items())
    lines = [f"{d['of']} of {d['scene']} over {d['input']} in [{d['range'][0]:g}, {d['range'][1]:g}] deg"
             + (f" (at {dims})" if dims else "") + ":"]
    lines += [f"  {p['kind']:10} {p['value']:.12g} at {p['enclosure_deg']} deg" for p in d["critical_points"]]
    lines += [f"  {'end':10} {p['value']:.12g} at {p['input_deg']:g} deg" for p in d["endpoints"]]
    for key in ("minimum", "maximum"):
        p = d[key]
        lines.append(f"{key}: {p['value']:.12g} at {p['input_deg']:.12g} deg ({p['kind']})")
    if "closed_form" in d:
        lines += _report_closed_form(d["closed_form"], d["input"])
    return "\n".join(lines)


def _report_closed_form(form, name):
    lines = ["minimum as a closed form:",
             f"  value = {form['value']}",
             f"  {name} = {form['input']} deg" + ("  (a range end)" if form["at"] == "endpoint" else ""),
             "  holds for " + " or ".join(form["valid_when"]) if form["regions"]
             else "  holds where " + " and ".join(form["valid_when"]) + " (the defaults' cell)"]
    if len(form["regions"]) > 1:
        lines.append("  elsewhere:")
        for region in form["regions"]:
            where = _interval(region)
            if region["at"] == "nowhere":
                lines.append(f"    {where}: the output is not real anywhere on the range (no assembly)")
                continue
            what = {"endpoint": "the minimiser leaves the range; the minimum is at the end",
                    "dead centre": "at the dead centre (where the branch stops assembling)"}.get(region["at"],
                                                                                              "stationary")
            lines.append(f"    {where}: {what} {name} = {region['input']} deg, value {region['value']}")
    return lines


def _interval(region):
    lo, hi = region["from"], region["to"]
    return f"({'-oo' if lo is None else f'{lo:.12g}'}, {'oo' if hi is None else f'{hi:.12g}'})"


def _cmd_toggles(args):
    from .toggles import toggles

    return _render(args, toggles(args.scene).to_json(), _report_toggles), 0


def _report_toggles(d):
    lo, hi = d["range"]
    lines = [f"toggles of {d['scene']} over {d['input']} in [{lo:g}, {hi:g}] deg:"]
    lines += [f"  {g['kind']:9} {g['point']} at {g['enclosure_deg']} deg (certified)" for g in d["toggles"]]
    if not d["toggles"]:
        lines.append("  none: every dyad and slider assembles, in both modes apart, over the whole range")
    if d["grashof"]:
        g = d["grashof"]
        bars = ", ".join(f"{k} {v}" for k, v in g["bars"].items())
        lines.append(f"four-bar ({bars}): {g['class']} ({g['rule']}: margin {g['margin']})")
    for artefact in d["artefacts"]:
        lines.append(f"dropped from disc({artefact['eliminant']}): {artefact['factor']}: {artefact['why']}")
    return "\n".join(lines)


def _cmd_accuracy(args):
    from .accuracy import accuracy

    if args.samples < 10:
        raise UsageError("--samples", args.samples, "needs at least 10 samples per case")
    out = _figure_path("--plot", args.plot) if args.plot else None
    result = accuracy(args.scene, args.samples, args.seed)
    text = _render(args, result.to_json(), _report_accuracy)
    if out is None:
        return text, 0
    from .plot import accuracy_figure, image

    # Drawn here, within the budget; written by the parent, where an interrupt can still clean up.
    return text, 0, [(out, image(accuracy_figure(result), out.suffix))]


def _report_accuracy(d):
    lines = [f"accuracy of {d['point']} in {d['scene']}; truth: {d['reference']}",
             f"  {'strategy':12} {'case':13} {'samples':>7} {'ns/sample':>10} {'max rel err':>11} "
             f"{'condition':>9} {'err/(k eps)':>11}"]
    lines += [f"  {r['strategy']:12} {r['case']:13} {r['samples']:7} {r['ns_per_sample']:10.1f} "
              f"{r['max_rel_error']:11.2e} {r['condition']:9.2e} {r['error_over_kappa_eps']:11.2e}"
              for r in d["rows"]]
    return "\n".join(lines)


def _figure_path(option, text):
    import pathlib

    from .files import check_output
    from .plot import FORMATS

    out = pathlib.Path(text)
    if out.suffix.lower() not in FORMATS:
        raise UsageError(option, text, f"unknown figure format; valid: {', '.join(FORMATS)}")
    check_output(option, text)
    return out


def _cmd_plot(args):
    if args.of is None:
        from .draw import plot_mechanism

        for option in ("range", "derivative", "against"):
            if getattr(args, option):
                raise UsageError(f"--{option}", getattr(args, option), "goes with --of OUTPUT")
        written = plot_mechanism(args.scene, args.out, args.input, args.branch, args.modes, args.param,
                                 args.range_of)
        return _render(args, _written(args, written), lambda d: d["out"]), 0
    for option in ("input", "branch", "modes", "param", "range_of"):
        if getattr(args, option):
            value = getattr(args, option)
            raise UsageError(f"--{option.replace('_', '-')}", " ".join(value) if isinstance(value, list) else value,
                             "draws the mechanism; leave out --of")
    out = _figure_path("--out", args.out)
    if args.against and args.derivative:
        raise UsageError("--against", args.against, "draws the minimum; leave out --derivative")
    against = _against(args.against) if args.against else None
    from .mechanism import load
    from .plot import minimum_figure, quantity_figure, save

    quantity = load(args.scene, [against[0]] if against else []).output(args.of)
    found = quantity.extremum(_range(args.range) if args.range else None)
    figure = minimum_figure(quantity, found, *against) if against else \
        quantity_figure(quantity, found, derivative=args.derivative)
    return _render(args, _written(args, save(figure, out)), lambda d: d["out"]), 0


def _written(args, out):
    """``plot``'s JSON document: the file written and what it shows."""
    return {"scene": args.scene, "out": str(out), "format": pathlib.Path(str(out)).suffix.lower().lstrip("."),
            "of": args.of}


def _against(text):
    name, _, span = text.partition("=")
    try:
        lo, hi = _range(span)
    except UsageError:
        raise UsageError("--against", text, "expected p=lo:hi, e.g. b=-400:400") from None
    if not name.isidentifier():
        raise UsageError("--against", text, "expected p=lo:hi, e.g. b=-400:400")
    return name, lo, hi


def _render(args, document, report):
    """What the command prints: ``document`` as JSON with --json, else ``report(document)``."""
    return (json.dumps(document, indent=2) if args.json else terminal_safe(report(document))) + "\n"


# Control characters (ESC starts terminal commands) and bidirectional overrides (which
# reorder what is shown) from a scene's names and text are shown escaped, never obeyed.
_UNSAFE = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\u061c\u200e\u200f\u2028\u2029\u202a-\u202e\u2066-\u2069]")


def terminal_safe(text):
    r"""``text`` with control and bidi characters escaped; newlines and tabs kept.

    >>> terminal_safe("scene \x1b[31mred\u202e\n")
    'scene \\x1b[31mred\\u202e\n'
    """
    return _UNSAFE.sub(lambda m: m.group().encode("unicode_escape").decode("ascii"), text)


def _cmd_list(args):
    from .scene import catalog_names, load_scene

    scenes = [load_scene(n) for n in catalog_names()]
    document = {"scenes": [{"name": s.name, "description": s.description} for s in scenes]}
    return _render(args, document, lambda d: "\n".join(f"{s['name']:24} {s['description']}" for s in d["scenes"])), 0


def _cmd_show(args):
    from .budget import current
    from .scene import compile_scene, load_scene

    current().note(f"loading {args.scene}")
    scene = load_scene(args.scene)
    current().note(f"compiling {scene.name}")
    compiled = compile_scene(scene, args.outputs, args.param)
    document = {
        "scene": scene.name,
        "description": scene.description,
        "points": {n: type(c).__name__.lower() for n, c in scene.points.items()},
        "outputs": {n: list(v) for n, v in compiled.outputs.items()},
        "inputs": {n: {"cos": c, "sin": s} for n, (c, s) in compiled.system.inputs.items()},
        "system": compiled.system.to_json(),
    }
    return _render(args, document, _report_show), 0


def _report_show(d):
    lines = [f"scene {d['scene']}: {d['description']}",
             "points: " + ", ".join(f"{n} ({k})" for n, k in d["points"].items()),
             "unknowns: " + ", ".join(d["system"]["unknowns"]),
             "parameters: " + (", ".join(d["system"]["parameters"]) or "none (all exact)"),
             "inputs: " + ", ".join(f"{n} as ({v['cos']}, {v['sin']})" for n, v in d["inputs"].items()),
             "equations (= 0):"]
    lines += [f"  {eq}" for eq in d["system"]["equations"]]
    return "\n".join(lines)


def _cmd_derive(args):
    from .pipeline import derive

    result = derive(args.scene, args.outputs, _method(args), args.backend, args.param, args.samples, args.seed)
    return _render(args, result.to_json(), _report_derive), _verdict(result.verification)


def _verdict(verification):
    """Exit code: 0 when the check passed or was skipped on request, 1 when it failed."""
    return 0 if verification.status in ("passed", "skipped") else 1


def _verification_line(v):
    if v["status"] == "skipped":
        return "verification skipped (--samples 0)"
    verdict = "passed" if v["passed"] else "FAILED"
    line = (f"verification {verdict}: {v['compared']} branch values on {v['samples']} samples, "
            f"max abs error {v['max_abs_error']:.2e}")
    return "\n".join([line] + [f"  {f}" for f in v["failures"]])


def _timings_line(t):
    return "timings: " + ", ".join(f"{k} {v * 1e3:.1f} ms" for k, v in t.items())


def _report_derive(d):
    lines = [f"scene {d['scene']}  (method {d['method']}, backend {d['backend']})", "eliminants:"]
    for unknown, poly in d["eliminants"].items():
        figures = d["eliminant_figures"][unknown]
        lines.append(f"  {unknown}: {poly}")
        lines.append(f"      degree {figures['degree']}, {figures['terms']} terms, "
                     f"dropped {len(figures['dropped_factors'])} extraneous factor(s)")
    lines.append("branches:")
    for branch in d["branches"]:
        mark = "  (scene's choice)" if branch["selected"] else ""
        lines.append(f"  [{branch['label']}]{mark} valid when {branch['valid_when']}")
        lines += [f"      {u} = {v}" for u, v in branch["values"].items()]
    lines += [_verification_line(d["verification"]), _timings_line(d["timings"])]
    return "\n".join(lines)


def _cmd_curve(args):
    from .pipeline import curve

    result = curve(args.scene, args.point, _method(args), args.backend, args.param, args.samples, args.seed)
    return _render(args, result.to_json(), _report_curve), _verdict(result.verification)


def _report_curve(d):
    lines = [f"curve of {d['point']} in {d['scene']}  (method {d['method']}, backend {d['backend']})",
             f"  {d['curve']} = 0",
             f"degree {d['degree']}, circularity {d['circularity']}, "
             f"{'irreducible' if d['irreducible'] else 'reducible'}, {d['terms']} terms",
             f"dropped {len(d['dropped_factors'])} extraneous factor(s):"]
    lines += [f"  {f}" for f in d["dropped_factors"]]
    lines += [_verification_line(d["verification"]), _timings_line(d["timings"])]
    return "\n".join(lines)


def _cmd_verify(args):
    from .pipeline import derive

    if args.samples == 0:
        raise UsageError("--samples", 0, "verify needs at least one sample (derive and curve take 0 to skip it)")
    result = derive(args.scene, args.outputs, _method(args), args.backend, args.param, args.samples, args.seed,
                    certify=False)
    document = {"scene": result.compiled.scene.name, "verification": result.verification.to_json(),
                "branches": [b.label for b in result.branches], "timings": result.timings}
    text = _render(args, document, lambda d: f"scene {d['scene']}, branches {', '.join(d['branches'])}\n"
                                            + _verification_line(d["verification"]))
    return text, _verdict(result.verification)


COMMANDS = {"list": _cmd_list, "show": _cmd_show, "derive": _cmd_derive, "curve": _cmd_curve,
            "verify": _cmd_verify, "extremum": _cmd_extremum, "plot": _cmd_plot,
            "toggles": _cmd_toggles, "accuracy": _cmd_accuracy, "bench": _cmd_bench}


def main(argv=None):
    """Run one command line (``argv``, by default the process's) and return its exit code.

    Signal handlers are installed only while it runs, so that calling it in-process (tests)
    leaves the caller's in place.
    """
    argv = sys.argv[1:] if argv is None else list(argv)
    args = None  # until parsed: an error before then still says what it can
    with _stopping_signals():
        try:
            args = build_parser().parse_args(argv)
            text, code, *files = _run(args)
            _save(*files)
            return _write(text, code)  # a signal while writing (to a slow reader) is caught too
        except _Stopped as stop:
            return _write(_failed(argv, args, "interrupted", str(stop), str(stop)), 128 + stop.signum)
        except (SceneError, UsageError) as err:
            return _write(_failed(argv, args, _kind(err), str(err), f"error: {err}"), 2)
        except AlgkinError as err:
            return _write(_failed(argv, args, _kind(err), str(err), f"failed: {err}"), 1)


def _run(args):
    """The command's output and exit code, all of its work (imports, loading, compiling, the algebra,
    formatting) done within its budget: in a child process killed at the deadline, if it has one."""
    from .budget import Budget

    budget = Budget(seconds=getattr(args, "max_seconds", None), terms=getattr(args, "max_terms", None))
    budget.note(f"starting {args.command}")  # until the command says more (its imports come first)
    return budget.run(functools.partial(COMMANDS[args.command], args))


def _save(files=()):
    """Write the files a command made (path, bytes), each replacing its target only when whole."""
    from .files import write_atomic

    for path, data in files:
        write_atomic(path, data)


def _failed(argv, args, kind, message, line):
    """Say ``line`` on stderr; what stdout gets: with --json, the error as the one JSON document."""
    print(f"algkin: {terminal_safe(line)}", file=sys.stderr)
    if not (getattr(args, "json", False) if args is not None else "--json" in argv):
        return ""
    command = args.command if args is not None else next(iter(argv), None)
    document = {"error": {"kind": kind, "message": message},
                "command": command if command in COMMANDS else None, "scene": getattr(args, "scene", None)}
    return json.dumps(document, indent=2) + "\n"


def _kind(err):
    """The error's kind in a JSON error document: usage, scene, budget or computation."""
    return next((kind for cls, kind in _ERROR_KINDS if isinstance(err, cls)), "computation")


def _write(text, code):
    """Write ``text`` to stdout and flush it now, so that a closed pipe shows here and not at
    exit; the exit code: ``code``, or _STDOUT_CLOSED if the reader has gone."""
    try:
        sys.stdout.write(text)
        sys.stdout.flush()
    except BrokenPipeError:
        # The Python docs' recipe (signal module, "Note on SIGPIPE"): point stdout at devnull so
        # that the interpreter's own flush at exit finds no broken pipe either.
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return _STDOUT_CLOSED
    return code


class _Stopped(BaseException):
    """A stopping signal (SIGINT, SIGTERM, SIGHUP) while a command runs, raised so that every
    ``finally`` on the way out runs: a budget's child is killed and joined. Not an AlgkinError:
    like KeyboardInterrupt, no ``except Exception`` may swallow it."""

    def __init__(self, signum):
        super().__init__(_STOPS[signum])
        self.signum = signum


@contextlib.contextmanager
def _stopping_signals():
    """While the block runs, the stopping signals raise ``_Stopped``; then the handlers found are back."""
    if threading.current_thread() is not threading.main_thread():
        yield  # only the main thread may set handlers, and only it receives signals
        return
    found = {signum: signal.signal(signum, _stop) for signum in _STOPS}
    try:
        yield
    finally:
        for signum, handler in found.items():
            # None: a handler not set from Python; the default is the nearest we can put back.
            signal.signal(signum, signal.SIG_DFL if handler is None else handler)


def _stop(signum, frame):
    """Raise the signal as ``_Stopped``, once: a second signal must not cut the clean-up short."""
    for each in _STOPS:
        signal.signal(each, signal.SIG_IGN)
    raise _Stopped(signum)
