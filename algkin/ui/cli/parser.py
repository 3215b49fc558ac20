"""The command line's grammar: every command, option and help text (``algkin --help``)."""

from __future__ import annotations

import argparse
import re
import sys
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any, NoReturn

from ...errors import UsageError
from ...runtime import suggest
from ...runtime.terminal import shortened
from ...runtime.validation import real, whole

if TYPE_CHECKING:
    from _typeshed import SupportsWrite

    Subcommands = argparse._SubParsersAction["_Parser"]  # generic in typeshed only

__all__ = ["build_parser", "usage", "Shown", "BENCH_QUICK", "BENCH_FULL"]

# ``algkin bench``'s (seconds per row, rounds): by default a run of a few minutes (rows past 5 s are
# reported over budget, each measured once); ``--full`` lets the largest problems finish, and measures
# the quick rows in three rounds (a run of about half an hour).
ARGUMENTS_SHOWN = 200  # characters of the command line an error line repeats (a value may be 100000 long)
BENCH_QUICK = (5.0, 1)
BENCH_FULL = (60.0, 3)


class Shown(Exception):  # noqa: N818 - not an error: the answer to --help or --version
    """``--help`` or ``--version`` asked: ``text``, for the command line to write to stdout (where
    argparse would print it and ignore a failed write: ``algkin --help > /dev/full``, exit 0)."""

    def __init__(self, text: str) -> None:
        super().__init__(text)
        self.text = text


class _Parser(argparse.ArgumentParser):
    """argparse with a one-line error and exit code 2; help and version raised as ``Shown``;
    ``type=int`` and ``type=float`` read ASCII numbers only (Python's own also read other scripts' digits);
    a value that starts with a minus and a digit is a value (``--range -90:90``, ``--max-step -1e-3``), where
    argparse takes only ``-90`` or ``-0.5`` as one and else said "expected one argument"."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self.register("type", int, _whole)
        self.register("type", float, _real)
        for name in (None, "store"):  # the default action, and said by name
            self.register("action", name, _StoreOnce)
        self.given: set[str] = set()  # the flags of one value met in this parse
        self.arguments: list[str] = sys.argv[1:]  # those of this parse, which its errors quote
        self._negative_number_matcher = re.compile(r"^-\.?[0-9]")  # no flag of algkin's starts so

    def error(self, message: str) -> NoReturn:
        raise UsageError("arguments", shortened(" ".join(self.arguments), ARGUMENTS_SHOWN), message)

    def parse_known_args(self, args: Sequence[str] | None = None,  # type: ignore[override]
                         namespace: argparse.Namespace | None = None) -> tuple[argparse.Namespace, list[str]]:
        """As argparse, and with the positional a list option swallowed given back to it:
        ``derive --outputs B chebyshev-lambda`` reads as ``derive chebyshev-lambda --outputs B``."""
        given = self.arguments = list(sys.argv[1:] if args is None else args)
        try:
            try:
                self.given = set()
                return super().parse_known_args(args, namespace)
            except UsageError as err:
                moved = _positional_first(given, self._list_options()) if "are required" in err.message else None
                if moved is None:
                    raise
                self.given = set()
                return super().parse_known_args(moved, namespace)
        except UsageError as err:
            if err.argument != "arguments":
                raise
            # a command's own parser saw what follows its name: the error quotes all that was given
            raise UsageError("arguments", shortened(" ".join(given), ARGUMENTS_SHOWN), err.message) from None

    def _list_options(self) -> set[str]:
        return {flag for action in self._actions if action.nargs in ("+", "*") for flag in action.option_strings}

    def _check_value(self, action: argparse.Action, value: Any) -> None:
        """An unknown choice said with the close match (``dervie``: did you mean 'derive'?)."""
        if action.choices is not None and value not in action.choices:
            name = action.option_strings[0] if action.option_strings else action.dest
            raise UsageError(name, value, f"not a valid {action.dest}"
                             + suggest.known(str(value), map(str, action.choices), plural="valid"))

    def _print_message(self, message: str, file: SupportsWrite[str] | None = None) -> None:
        if file is sys.stdout:  # help and version (None too: a closed stdout, said as such)
            raise Shown(message)
        super()._print_message(message, file)


def _positional_first(args: list[str], list_options: set[str]) -> list[str] | None:
    """``args`` with the last value of the last list option that took two or more moved to the
    front (where a positional argument is read), or None if no list option took two."""
    found = None
    for start, token in enumerate(args):
        if token not in list_options:
            continue
        end = start + 1
        while end < len(args) and not args[end].startswith("-"):
            end += 1
        if end - start > 2:
            found = end - 1
    return None if found is None else [args[found]] + args[:found] + args[found + 1:]


def _whole(text: str) -> int:
    try:
        return whole(text)
    except ValueError:
        raise argparse.ArgumentTypeError(_long(text) or f"expected a whole number (ASCII digits 0-9), got "
                                                        f"{shortened(text)!r}") from None


def _long(text: str) -> str | None:
    """What is wrong with a whole number in ASCII digits that Python's int() refuses: its length
    (past 4300 digits), not that it is no number; None for other text."""
    digits = text.strip()
    return f"a number of {len(digits)} digits, far past any this option takes" \
        if text.isascii() and digits.isdigit() else None


def _real(text: str) -> float:
    try:
        return real(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number (ASCII digits 0-9), got {text!r}") from None


class _Once(argparse.Action):
    """Names gathered from one option, repeated (``--param a --param b``) or listed (``--outputs A B``):
    a name given twice is refused when it is met, before any work (sympy would fail on it later)."""

    def __call__(self, parser: argparse.ArgumentParser, namespace: argparse.Namespace,
                 values: str | Sequence[Any] | None, option_string: str | None = None) -> None:
        given = list(getattr(namespace, self.dest, None) or [])  # a repetition adds to the names before it
        for value in values if isinstance(values, list) else [values]:
            if value in given:
                raise UsageError(option_string or self.dest, value, "given twice")
            given.append(value)
        setattr(namespace, self.dest, given)


class _StoreOnce(argparse._StoreAction):
    """A flag of one value given twice is refused (``--to c --to js --out f.c``: which was meant?),
    where argparse would keep the last without a word."""

    def __call__(self, parser: argparse.ArgumentParser, namespace: argparse.Namespace,
                 values: str | Sequence[Any] | None, option_string: str | None = None) -> None:
        given = parser.given if isinstance(parser, _Parser) else set()
        if option_string is not None:
            if self.dest in given:
                raise UsageError(option_string, values, "given twice")
            given.add(self.dest)
        super().__call__(parser, namespace, values, option_string)


class _Help(argparse.ArgumentDefaultsHelpFormatter):
    """``--help`` with each option's default, where it has one worth saying (not None, False or [])."""

    def _get_help_string(self, action: argparse.Action) -> str | None:
        if action.default is None or action.default is False or action.default == [] \
                or action.default is argparse.SUPPRESS:
            return action.help
        return super()._get_help_string(action)


def _command(commands: Subcommands, name: str, summary: str) -> argparse.ArgumentParser:
    """A subcommand whose ``--help`` starts with its one-line summary and shows the defaults."""
    return commands.add_parser(name, help=summary, description=summary, formatter_class=_Help)


def _scene(parser: argparse.ArgumentParser) -> None:
    """The scene argument, and ``--set``: every command that takes a scene takes both."""
    parser.add_argument("scene", help="catalog name (see `algkin list`) or path of a scene file (.toml)")
    parser.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                        help="an exact value for a dimension (3/2, 0.1 = 1/10, sqrt(9/4)); repeatable")


def _quiet(parser: argparse.ArgumentParser, default: object = False) -> None:
    parser.add_argument("--quiet", action="store_true", default=default,
                        help="show no progress on stderr (shown only while stderr is a terminal)")


def _json(parser: argparse.ArgumentParser, what: str = "the whole result") -> None:
    parser.add_argument("--json", action="store_true", help=f"one JSON document on stdout: {what}")


def _common(parser: argparse.ArgumentParser, method: bool = True) -> None:
    _scene(parser)
    _json(parser)
    if method:
        parser.add_argument("--method", default=None,
                            help="elimination method: linear (the default), resultant, groebner")
        parser.add_argument("--backend", default="flint", help="polynomial backend: flint, sympy")
        parser.add_argument("--param", nargs="+", action=_Once, default=[], metavar="NAME",
                            help="keep this dimension symbolic (repeatable); the others take their defaults")
        parser.add_argument("--samples", type=int, default=40,
                            help="numeric samples the closed forms are checked on (0 skips the check)")
        parser.add_argument("--seed", type=int, default=0, help="random seed of the verification samples")
        _budget_options(parser)


def _full_forms(parser: argparse.ArgumentParser) -> None:
    """``--out`` and ``--latex``: the complete results, which the text report only summarises."""
    parser.add_argument("--out", metavar="FILE", help="also write the full JSON document to FILE")
    _latex(parser)


def _latex(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--latex", action="store_true",
                        help="print the results as LaTeX instead of the text report (not with --json)")


def _budget_options(parser: argparse.ArgumentParser, terms: bool = True) -> None:
    parser.add_argument("--max-seconds", type=_seconds,
                        help="stop (exit 1) past this many seconds of the whole command, loading included "
                             "(at most a week)")
    if terms:
        parser.add_argument("--max-terms", type=_terms,
                            help="stop (exit 1) when an eliminant passes this many terms")


def _seconds(text: str) -> float:
    from ...runtime.budget import MAX_SECONDS  # here: the parser stays light (no multiprocessing)

    try:
        value = real(text)
    except ValueError:
        value = None
    if value is None or not 0 < value <= MAX_SECONDS:  # nan and inf too
        raise argparse.ArgumentTypeError(f"expected a positive number of seconds, at most a week ({MAX_SECONDS}), "
                                         f"got {text!r}")
    return value


def _terms(text: str) -> int:
    try:
        terms = whole(text) if text.isascii() and text.strip().isdigit() else 0
    except ValueError:
        raise argparse.ArgumentTypeError(_long(text)) from None
    if terms < 1:
        raise argparse.ArgumentTypeError(f"expected a positive whole number of terms, got {shortened(text)!r}")
    return terms


def build_parser() -> argparse.ArgumentParser:
    from ... import __version__

    parser = _Parser(prog="algkin", description="Closed forms of planar mechanisms by elimination.",
                     formatter_class=_Help)
    parser.add_argument("--version", action="version", version=f"algkin {__version__}",
                        help="print the version and exit")
    _quiet(parser)
    commands = parser.add_subparsers(dest="command", required=True, parser_class=_Parser, metavar="command",
                                     help="one of the commands below; `algkin COMMAND --help` for its options")
    listing = _command(commands, "list", "the catalog")
    _json(listing, "each scene's name and description")
    show = _command(commands, "show", "the scene and the system it compiles to")
    _common(show, method=False)
    show.add_argument("--outputs", nargs="+", action=_Once, metavar="OUTPUT",
                      help="outputs (names, points, dist(P, Q), P.x, angle(P, Q), angle(P, Q, R)); default: the scene's")
    show.add_argument("--param", nargs="+", action=_Once, default=[], metavar="NAME",
                      help="keep this dimension symbolic (repeatable)")
    _budget_options(show, terms=False)
    derive = _command(commands, "derive", "eliminants, closed-form branches, verification")
    _common(derive)
    derive.add_argument("--outputs", nargs="+", action=_Once, metavar="OUTPUT",
                        help="outputs (names, points, dist(P, Q), P.x, angle(P, Q), angle(P, Q, R)); default: the scene's")
    derive.add_argument("--rates", action="store_true",
                        help="also each output coordinate's velocity and acceleration per branch (derivatives "
                             "in the input angle, per radian), checked against central differences of "
                             "independent numeric solutions on --samples inputs; with points solved together, "
                             "every unknown's per mode")
    _full_forms(derive)
    curve = _command(commands, "curve", "implicit trajectory curve of a point")
    _common(curve)
    curve.add_argument("--point", required=True, help="the point whose trajectory is wanted")
    _full_forms(curve)
    verify = _command(commands, "verify", "closed forms against independent numeric solutions")
    _common(verify)
    verify.add_argument("--outputs", nargs="+", action=_Once, metavar="OUTPUT",
                        help="outputs (names, points, dist(P, Q), P.x, angle(P, Q), angle(P, Q, R)); default: the scene's")
    extremum = _command(commands, "extremum", "stationary points of an output over the input")
    _scene(extremum)
    extremum.add_argument("--of", required=True, type=str.strip, help="a scalar output: distance, coordinate or angle (in degrees)")
    extremum.add_argument("--range", metavar="LO:HI", help="lo:hi in the input's unit; default: its declared range")
    extremum.add_argument("--param", nargs="+", action=_Once, default=[], metavar="NAME",
                          help="keep this dimension symbolic: the minimum as a closed form in it")
    _json(extremum)
    _latex(extremum)
    _budget_options(extremum)
    toggles = _command(commands, "toggles", "input angles where assembly modes meet, the output's limit "
                                            "positions and time ratio; certified")
    _scene(toggles)
    _json(toggles)
    _budget_options(toggles)
    singular = _command(commands, "singular", "singular points of a point's implicit curve (crunodes, acnodes, "
                                              "cusps, ...), exact and certified; the curve's degree and circularity")
    _scene(singular)
    singular.add_argument("--point", required=True, help="the point whose trajectory's curve is examined")
    singular.add_argument("--samples", type=int, default=40,
                          help="numeric samples the curve is checked on (0 skips the check)")
    singular.add_argument("--seed", type=int, default=0, help="random seed of the verification samples")
    _json(singular)
    _budget_options(singular)
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
    plot.add_argument("--param", nargs="+", action=_Once,
                      help="a dimension with a slider in the .html page (default: every dimension)")
    plot.add_argument("--range-of", action="append", default=[], metavar="NAME=LO:HI",
                      help="the range of dimension NAME's slider in the .html page (repeatable), e.g. a=0.5:2")
    plot.add_argument("--of", help="a scalar output (an angle in degrees): draw it against the input instead")
    plot.add_argument("--range", help="with --of: lo:hi of the input, in its unit")
    plot.add_argument("--derivative", action="store_true", help="with --of: the slope, with its zero marked")
    plot.add_argument("--against", help="with --of: p=lo:hi, the minimum against the dimension p")
    _budget_options(plot)
    export = _command(commands, "export", "every branch's stabilised formulas as a self-contained function "
                                          "(C, numpy, JavaScript) or its closed forms (LaTeX)")
    _scene(export)
    export.add_argument("--outputs", nargs="+", action=_Once, metavar="OUTPUT",
                        help="outputs (names, points, dist(P, Q), P.x, angle(P, Q), angle(P, Q, R)); default: the scene's")
    export.add_argument("--to", required=True, choices=("c", "numpy", "js", "latex"), help="the language written")
    export.add_argument("--out", metavar="FILE", help="write to FILE instead of stdout")
    export.add_argument("--param", nargs="+", action=_Once, default=[], metavar="NAME",
                        help="with --to latex: keep this dimension symbolic (repeatable)")
    _json(export, "the scene, the language, and the code (or the file it was written to)")
    _budget_options(export, terms=False)
    solve = _command(commands, "solve", "every real configuration (each mode or branch) at given inputs, "
                                        "certified in balls; none when nothing assembles there (exit 0)")
    _scene(solve)
    solve.add_argument("--at", nargs="+", action="extend", default=[], metavar="INPUT=VALUE",
                       help="an input's exact value (degrees for an angle, e.g. 30, 1/3, 22.5; a length as it "
                            "is), one for each input")
    solve.add_argument("--mode", metavar="LABEL", help="only the configuration of this mode or branch")
    solve.add_argument("--digits", type=int, default=30, help="significant digits of each coordinate")
    _json(solve)
    _budget_options(solve, terms=False)
    follow = _command(commands, "follow", "one mode followed along an input by certified continuation, up to "
                                          "the end or to where it meets another mode (a toggle), reported")
    _scene(follow)
    follow.add_argument("--mode", metavar="LABEL", required=True,
                        help="the mode or branch, as `algkin solve` labels it at the start")
    follow.add_argument("--from", dest="start", metavar="INPUT=VALUE", required=True,
                        help="the input followed and its exact start value (degrees for an angle)")
    follow.add_argument("--to", dest="stop", metavar="VALUE", required=True, help="its exact end value")
    follow.add_argument("--at", nargs="+", action="extend", default=[], metavar="INPUT=VALUE",
                        help="each other input's exact value, where the scene has more than one")
    follow.add_argument("--max-step", dest="max_step", metavar="STEP",
                        help="the largest step, in the input's unit (default: an eighth of the way)")
    follow.add_argument("--digits", type=int, default=15, help="significant digits of each coordinate")
    _json(follow)
    _budget_options(follow, terms=False)
    bench = _command(commands, "bench", "elimination methods compared on a problem set, peers beside")
    bench.add_argument("--problems", nargs="+", help="problem names (default: the whole suite)")
    bench.add_argument("--methods", nargs="+", help="elimination methods (default: all)")
    bench.add_argument("--backends", nargs="+", help="polynomial backends (default: all)")
    budgets = bench.add_mutually_exclusive_group()
    budgets.add_argument("--budget", type=_seconds,
                         help=f"seconds per row before it is stopped (default {BENCH_QUICK[0]:g}: a run of a few "
                              "minutes in all)")
    budgets.add_argument("--full", action="store_true",
                         help=f"the long run: {BENCH_FULL[0]:g} s per row (the largest problems finish) and "
                              f"{BENCH_FULL[1]} rounds (about half an hour in all)")
    bench.add_argument("--no-peers", action="store_true", help="skip Singular, PARI/GP, Macaulay2, msolve")
    bench.add_argument("--rounds", type=int,
                       help=f"rows under 2 s are measured this many times in turn (at most 100), each keeping its best "
                            f"(default {BENCH_QUICK[1]}, {BENCH_FULL[1]} with --full)")
    bench.add_argument("--out", help="directory for bench.json, bench.csv and bench.png")
    _json(bench)
    from .sweep import add_commands
    from .synthesis import add_command as add_synthesis

    add_commands(commands, _command, _json, scene_arguments=_scene)
    add_synthesis(commands, _command, _json)
    _budget_options(commands.choices["synthesize"], terms=False)
    for command in commands.choices.values():
        # after the command too; SUPPRESS: not given there, it leaves the value given before the command
        _quiet(command, default=argparse.SUPPRESS)
    return parser


def usage(command: str) -> str:
    """The ``--help`` text of one command (the docs print it)."""
    commands = next(a for a in build_parser()._actions if isinstance(a, argparse._SubParsersAction))
    return commands.choices[command].format_help()
