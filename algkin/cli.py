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


class _Help(argparse.ArgumentDefaultsHelpFormatter):
    """``--help`` with each option's default, where it has one worth saying (not None, False or [])."""

    def _get_help_string(self, action):
        if action.default is None or action.default is False or action.default == [] \
                or action.default is argparse.SUPPRESS:
            return action.help
        return super()._get_help_string(action)


def _command(commands, name, summary):
    """A subcommand whose ``--help`` starts with its one-line summary and shows the defaults."""
    return commands.add_parser(name, help=summary, description=summary, formatter_class=_Help)


def _scene(parser):
    """The scene argument, and ``--set``: every command that takes a scene takes both (SPEC §3)."""
    parser.add_argument("scene", help="catalog name (see `algkin list`) or path of a scene file (.toml)")
    parser.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                        help="an exact value for a dimension (3/2, 0.1 = 1/10, sqrt(2)); repeatable")


def _json(parser, what="the whole result"):
    parser.add_argument("--json", action="store_true", help=f"one JSON document on stdout: {what}")


def _common(parser, method=True):
    _scene(parser)
    _json(parser)
    if method:
        parser.add_argument("--method", default=None,
                            help="elimination method: linear (the default), resultant, groebner")
        parser.add_argument("--backend", default="flint", help="polynomial backend: flint, sympy")
        parser.add_argument("--param", action="append", default=[], metavar="NAME",
                            help="keep this dimension symbolic (repeatable); the others take their defaults")
        parser.add_argument("--samples", type=int, default=40,
                            help="numeric samples the closed forms are checked on (0 skips the check)")
        parser.add_argument("--seed", type=int, default=0, help="random seed of the verification samples")
        _budget_options(parser)


def _full_forms(parser):
    """``--out`` and ``--latex``: the complete results, which the text report only summarises."""
    parser.add_argument("--out", metavar="FILE", help="also write the full JSON document to FILE")
    _latex(parser)


def _latex(parser):
    parser.add_argument("--latex", action="store_true",
                        help="print the results as LaTeX instead of the text report (not with --json)")


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
    from . import __version__

    parser = _Parser(prog="algkin", description="Closed forms of planar mechanisms by elimination.",
                     formatter_class=_Help)
    parser.add_argument("--version", action="version", version=f"algkin {__version__}",
                        help="print the version and exit")
    commands = parser.add_subparsers(dest="command", required=True, parser_class=_Parser, metavar="command",
                                     help="one of the commands below; `algkin COMMAND --help` for its options")
    listing = _command(commands, "list", "the catalog")
    _json(listing, "each scene's name and description")
    show = _command(commands, "show", "the scene and the system it compiles to")
    _common(show, method=False)
    show.add_argument("--outputs", nargs="+", metavar="OUTPUT",
                      help="outputs (names, points, dist(P, Q), P.x); default: the scene's")
    show.add_argument("--param", action="append", default=[], metavar="NAME",
                      help="keep this dimension symbolic (repeatable)")
    _budget_options(show, terms=False)
    derive = _command(commands, "derive", "eliminants, closed-form branches, verification")
    _common(derive)
    derive.add_argument("--outputs", nargs="+", metavar="OUTPUT",
                        help="outputs (names, points, dist(P, Q), P.x); default: the scene's")
    _full_forms(derive)
    curve = _command(commands, "curve", "implicit trajectory curve of a point")
    _common(curve)
    curve.add_argument("--point", required=True, help="the point whose trajectory is wanted")
    _full_forms(curve)
    verify = _command(commands, "verify", "closed forms against independent numeric solutions")
    _common(verify)
    verify.add_argument("--outputs", nargs="+", metavar="OUTPUT",
                        help="outputs (names, points, dist(P, Q), P.x); default: the scene's")
    extremum = _command(commands, "extremum", "stationary points of an output over the input")
    _scene(extremum)
    extremum.add_argument("--of", required=True, help="a scalar output: distance or coordinate")
    extremum.add_argument("--range", metavar="LO:HI", help="lo:hi in the input's unit; default: its declared range")
    extremum.add_argument("--param", action="append", default=[], metavar="NAME",
                          help="keep this dimension symbolic: the minimum as a closed form in it")
    _json(extremum)
    _latex(extremum)
    _budget_options(extremum)
    toggles = _command(commands, "toggles", "input angles where assembly modes meet, certified")
    _scene(toggles)
    _json(toggles)
    _budget_options(toggles)
    accuracy = _command(commands, "accuracy", "speed against error of each evaluation strategy")
    _scene(accuracy)
    accuracy.add_argument("--samples", type=int, default=2000, help="samples per case")
    accuracy.add_argument("--seed", type=int, default=0, help="random seed of the samples")
    accuracy.add_argument("--of", help="the output measured: a point, an output's name, dist(A, B), B.x "
                                       "(default: the first dyad point, else the first output)")
    accuracy.add_argument("--plot", metavar="FILE",
                          help="also draw time against error (log-log) to this .png/.svg/.pdf")
    _json(accuracy)
    _budget_options(accuracy)
    plot = _command(commands, "plot", "the mechanism with its trajectories and implicit curves "
                                      "(.png/.svg/.pdf), animated (.gif/.mp4), an interactive page "
                                      "(.html); with --of a quantity against the input")
    _scene(plot)
    plot.add_argument("--out", required=True, help="the file to write: .png, .svg, .pdf, .gif, .mp4 or .html")
    _json(plot, "what was written")
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
    bench = _command(commands, "bench", "elimination methods compared on a problem set, peers beside")
    bench.add_argument("--problems", nargs="+", help="problem names (default: the whole suite)")
    bench.add_argument("--methods", nargs="+", help="elimination methods (default: all)")
    bench.add_argument("--backends", nargs="+", help="polynomial backends (default: all)")
    bench.add_argument("--budget", type=float, default=60.0, help="seconds per row before it is stopped")
    bench.add_argument("--no-peers", action="store_true", help="skip Singular, PARI/GP, Macaulay2, msolve")
    bench.add_argument("--rounds", type=int, default=3,
                       help="rows under 2 s are measured this many times in turn, each keeping its best")
    bench.add_argument("--out", help="directory for bench.json, bench.csv and bench.png")
    _json(bench)
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


def _scene_of(args, params=None):
    """The command's scene: the name or path given (loaded by the command, as from Python), or with
    ``--set``, the scene loaded with those dimensions set (``params``, by default ``--param``, are
    kept symbolic and cannot be set)."""
    if not args.set:
        return args.scene
    from .scene import load_scene
    from .scene.settings import parse_settings, with_values

    symbolic = getattr(args, "param", ()) if params is None else params
    return with_values(load_scene(args.scene), parse_settings(args.set), symbolic)


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

    _check_latex(args)
    angles = _range(args.range) if args.range else None
    found = extremum(_scene_of(args), args.of, angles, params=args.param)
    if args.latex:
        return _latex_lines(_extremum_forms(found)), 0
    return _render(args, found.to_json(), _report_extremum), 0


def _extremum_forms(found):
    """The minimum and maximum for ``--latex``; with ``--param``, the closed form and its input."""
    import sympy

    forms = [(f"{key} of {found.output} (at {found.input} = {float(point.input_deg):.12g} deg)",
              sympy.Float(float(point.value), 15), "") for key, point in (("minimum", found.minimum),
                                                                   ("maximum", found.maximum))]
    if found.closed_form is not None:
        forms.append((f"minimum of {found.output} as a closed form", found.closed_form.value, ""))
        if found.closed_form.input is not None:
            forms.append((f"{found.input} at the minimum, in degrees", found.closed_form.input, ""))
    return forms


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

    return _render(args, toggles(_scene_of(args)).to_json(), _report_toggles), 0


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
        lines.append(f"dropped from disc({artefact['eliminant']}): {_brief(artefact['factor'])}: "
                     f"{_brief(' '.join(artefact['why'].split()))}")
    return "\n".join(lines + _hint([a["factor"] for a in d["artefacts"]], "full factors: --json"))


def _cmd_accuracy(args):
    from .accuracy import accuracy

    if args.samples < 10:
        raise UsageError("--samples", args.samples, "needs at least 10 samples per case")
    out = _figure_path("--plot", args.plot) if args.plot else None
    result = accuracy(_scene_of(args), args.samples, args.seed, of=args.of)
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
              + (f"\n    note: {r['note']}" if r.get("note") else "") for r in d["rows"]]
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
        # plot's --param names the page's sliders, which start at the values set: no clash
        written = plot_mechanism(_scene_of(args, ()), args.out, args.input, args.branch, args.modes, args.param,
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

    params = [against[0]] if against else []
    quantity = load(_scene_of(args, params), params).output(args.of)
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
    from .scene import compile_scene
    from .scene.load import as_scene

    current().note(f"loading {args.scene}")
    scene = as_scene(_scene_of(args))
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

    out = _full_forms_target(args)
    result = derive(_scene_of(args), args.outputs, _method(args), args.backend, args.param, args.samples, args.seed)
    forms = [(f"eliminant of {u}", e.polynomial, "= 0") for u, e in result.eliminations.items()]
    forms += [(f"{u}, branch {b.label}", v, "") for b in result.branches for u, v in b.values.items()]
    return _finish(args, out, result.to_json(), _report_derive, forms, _verdict(result.verification))


def _check_latex(args):
    """--latex replaces the text report; --json has the strings (in sympy syntax): one or the other."""
    if args.latex and args.json:
        raise UsageError("--latex", True, "prints LaTeX instead of the text report; leave out --json or --latex")


def _full_forms_target(args):
    """``--out``'s path, checked before the work starts; ``--latex`` and ``--json`` refused together."""
    _check_latex(args)
    if args.out is None:
        return None
    from .files import check_output

    check_output("--out", args.out)
    return pathlib.Path(args.out)


def _finish(args, out, document, report, forms, code):
    """What derive and curve return: the JSON, the LaTeX of ``forms`` or the text report, and with
    ``--out`` the whole JSON document as a file for the parent to write."""
    text = _latex_lines(forms) if args.latex else _render(args, document, report)
    if out is None:
        return text, code
    if not args.json:
        text += terminal_safe(f"wrote the full JSON document to {out}\n")
    return text, code, [(out, json.dumps(document, indent=2) + "\n")]


def _latex_lines(forms):
    """Each (caption, sympy expression, relation) as a LaTeX comment and a display equation."""
    import sympy

    return "".join(f"% {caption}\n\\[ {' '.join([sympy.latex(expr), relation]).strip()} \\]\n"
                   for caption, expr, relation in forms)


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
        lines.append(f"  {unknown}: {_brief(poly)}")
        lines.append(f"      degree {figures['degree']}, {figures['terms']} terms, "
                     f"{figures['coefficient_bits']}-bit coefficients, "
                     f"dropped {len(figures['dropped_factors'])} extraneous factor(s)")
    lines.append("branches:")
    for branch in d["branches"]:
        mark = "  (scene's choice)" if branch["selected"] else ""
        lines.append(f"  [{branch['label']}]{mark} valid when {_brief(branch['valid_when'])}")
        lines += [f"      {u} = {_brief(v)}" for u, v in branch["values"].items()]
    lines += [_verification_line(d["verification"]), _timings_line(d["timings"])]
    forms = [*d["eliminants"].values(), *(f for b in d["branches"] for f in (b["valid_when"], *b["values"].values()))]
    return "\n".join(lines + _hint(forms))


def _cmd_curve(args):
    from .pipeline import curve

    out = _full_forms_target(args)
    result = curve(_scene_of(args), args.point, _method(args), args.backend, args.param, args.samples, args.seed)
    forms = [(f"curve of {result.point}", result.elimination.polynomial, "= 0")]
    return _finish(args, out, result.to_json(), _report_curve, forms, _verdict(result.verification))


def _report_curve(d):
    lines = [f"curve of {d['point']} in {d['scene']}  (method {d['method']}, backend {d['backend']})",
             f"  {_brief(d['curve'])} = 0",
             f"degree {d['degree']}, circularity {d['circularity']}, "
             f"{'irreducible' if d['irreducible'] else 'reducible'}, {d['terms']} terms, "
             f"{d['coefficient_bits']}-bit coefficients",
             f"dropped {len(d['dropped_factors'])} extraneous factor(s):"]
    lines += [f"  {_brief(f)}" for f in d["dropped_factors"]]
    lines += [_verification_line(d["verification"]), _timings_line(d["timings"])]
    return "\n".join(lines + _hint([d["curve"], *d["dropped_factors"]]))


# A text report is read by a person: a form longer than this is summarised there (its leading
# terms); --json and --out keep every form whole. The seed lambda's sextic (213) stays whole.
_WHOLE = 230


def _brief(form):
    """``form`` whole when short, else its leading terms, ``...`` and its length in characters."""
    if len(form) <= _WHOLE:
        return form
    head = form[:_WHOLE // 2]
    cut = max(head.rfind(" + "), head.rfind(" - "))  # end on a whole term where there is one
    return f"{head[:cut] if cut > 0 else head} ... ({len(form)} characters)"


def _hint(forms, where="full forms: --json or --out FILE"):
    """The line that says where the whole forms are, when ``_brief`` shortened any of ``forms``."""
    return [where] if any(len(f) > _WHOLE for f in forms) else []


def _cmd_verify(args):
    from .pipeline import derive

    if args.samples == 0:
        raise UsageError("--samples", 0, "verify needs at least one sample (derive and curve take 0 to skip it)")
    result = derive(_scene_of(args), args.outputs, _method(args), args.backend, args.param, args.samples, args.seed,
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
    if not argv:
        # Bare ``algkin`` is a question ("what can it do?"), not a mistake: the help listing the
        # commands, on stdout, exit 0 (as ``--help``); a wrong command line is still exit 2.
        return _write(build_parser().format_help(), 0)
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
