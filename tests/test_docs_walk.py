"""The docs walk: every ``algkin ...`` command of docs/cli/*.md and docs/tutorials/*.md (a line of
a code block, or a command with its arguments in the text) runs as written, in a scratch directory
of its page's own (the page's commands in order, as a reader copies them), and ends as the page
says: exit 0, or, where the next line is a ``# algkin: failed: ...`` (or ``error``) comment, exit 1
(or 2) with that line's opening on stderr. Where the text says what a command gives (a number, a
count, a verdict), that is asserted, worked out apart from algkin where it can be. A page's output
is drawn by its code cells when the site is built: each cell's ``main([...])`` is a command the
page shows, so that the output under a command is that command's."""

import ast
import math
import os
import re
import shlex
import subprocess
import sys
from dataclasses import dataclass
from fractions import Fraction
from pathlib import Path

import pytest

from .ui.cli.in_process import run_main

# Every command of the pages, a Dask sweep, a 3 s budget and an animation among them: about 35 s, run
# by CI (make test-slow), as the README's walk.
pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parents[1]
PAGES = sorted((ROOT / "docs" / "cli").glob("*.md")) + sorted((ROOT / "docs" / "tutorials").glob("*.md"))
_FENCED = re.compile(r"^```([^\n]*)\n(.*?)^```", re.S | re.M)
_INLINE = re.compile(r"`(algkin [^`]+)`")
_PROGRAM = re.compile(r"^(python3? -m algkin|\S*/algkin) ")  # the program as a page may call it
_EXPECTED = re.compile(r"^# (algkin: (failed|error): [^:]+:)")

# Commands the walk does not run, and why. A page that gains a command fails the walk until it
# runs or is listed here; a command listed here that no page shows any more fails too.
SKIPPED = {
    # Its scheduler is the reader's own cluster, at an address they fill in; tests/sweep/test_cluster.py
    # runs a sweep on a real `dask scheduler` and `dask worker`s.
    "algkin sweep fourbar --grid a=1/2:2:40 --grid d=2:10:25 --analyses curve,grashof --out fourbars "
    "--scheduler tcp://HOST:8786": "a Dask scheduler at the placeholder tcp://HOST:8786",
    # SCENE stands for any scene: the same command with a named one is walked (plot fourbar --out ...).
    "algkin plot SCENE --out page.html": "SCENE is a placeholder",
}

# Run as the program: its default executor starts a Dask LocalCluster of worker processes, the
# command's own to start and close, not the test process's.
APART = {"algkin sweep fourbar --grid a=1/2:2:4 --grid d=2:10:3 --analyses curve,grashof,transmission --out fourbars"}

# Cells that build a command's arguments (not a literal list), which the cell check cannot read.
BUILT_IN_CELLS = {"plot.md": "each picture is drawn into a temporary folder (--out a path made there) and shown"}


@dataclass(frozen=True)
class Command:
    page: str
    text: str  # as the page writes it, its whitespace and line continuations made single spaces
    exit_code: int
    stderr_opening: str | None

    @property
    def args(self):
        return shlex.split(self.text, comments=True)[1:]


def _code_block_commands(page, text):
    for info, block in _FENCED.findall(text):
        if info.startswith("{code-cell}"):
            continue
        lines = [_PROGRAM.sub("algkin ", line) for line in block.replace("\\\n", " ").splitlines()]
        for line, following in zip(lines, lines[1:] + [""]):
            if line.startswith("algkin "):
                expected = _EXPECTED.match(following)
                code = 0 if expected is None else (1 if expected.group(2) == "failed" else 2)
                yield Command(page, _normal(line), code, expected and expected.group(1))


def _text_commands(page, text):
    """Commands in the text with their arguments (`algkin solve hart-inversor --at angle=290`),
    not a command's bare name (`algkin solve`)."""
    for span in _INLINE.findall(_FENCED.sub("", text)):
        if len(span.split()) > 2:
            yield Command(page, _normal(span), 0, None)


def _normal(command):
    return " ".join(command.split())


def page_commands():
    commands = []
    for path in PAGES:
        text = path.read_text(encoding="utf-8")
        commands += [*_code_block_commands(path.name, text), *_text_commands(path.name, text)]
    return commands


COMMANDS = page_commands()
WALKED = [c for c in COMMANDS if c.text not in SKIPPED]


def test_the_pages_show_commands_and_the_skipped_are_still_there():
    shown = {c.text for c in COMMANDS}
    assert len(WALKED) > 40 and any(c.exit_code for c in WALKED)
    assert set(SKIPPED) <= shown, set(SKIPPED) - shown
    assert APART <= shown, APART - shown


@pytest.fixture(scope="module")
def walk(tmp_path_factory):
    """``walk(command)``: its result, each page's commands run in order in the page's own directory
    (the atlas reads the sweep its page ran first), each once."""
    done, folders = {}, {}

    def run(command):
        if command.page not in folders:
            folders[command.page] = tmp_path_factory.mktemp(Path(command.page).stem)
        for earlier in WALKED[:WALKED.index(command) + 1]:
            if earlier.page == command.page and earlier not in done:
                done[earlier] = _run(earlier, folders[command.page])
        return done[command]

    return run


def _run(command, folder):
    if command.text not in APART:
        return run_main(command.args, folder)
    return subprocess.run([sys.executable, "-m", "algkin", *command.args], cwd=folder, capture_output=True,
                          text=True, env=dict(os.environ, PYTHONPATH=str(ROOT)), timeout=300)


def _params():
    for command in WALKED:
        yield pytest.param(command, id=f"{command.page}: {command.text[7:70]}")


@pytest.mark.parametrize("command", list(_params()))
def test_the_command_runs_as_its_page_says(command, walk):
    result = walk(command)
    assert result.returncode == command.exit_code, (command.text, result.returncode, result.stderr[-2000:])
    if command.stderr_opening:
        assert result.stderr.startswith(command.stderr_opening), (command.stderr_opening, result.stderr)
    for check in SAYS.get(command.text, ()):
        check(result.stdout)


def _numbers(text):
    return [float(x) for x in re.findall(r"-?\d+\.\d+(?:e[-+]?\d+)?", text)]


def shows(*fragments):
    def check(out):
        for fragment in fragments:
            assert fragment in out, (fragment, out)
    return check


def shows_number(value, *, within):
    def check(out):
        assert any(abs(x - value) <= within for x in _numbers(out)), (value, out)
    return check


def shows_no(fragment):
    def check(out):
        assert fragment not in out, (fragment, out)
    return check


def matches(pattern):
    def check(out):
        assert re.search(pattern, out, re.M), (pattern, out)
    return check


def lines_with(fragment, count):
    def check(out):
        assert sum(fragment in line for line in out.splitlines()) == count, (fragment, count, out)
    return check


def _degrees(cosine):
    return math.degrees(math.acos(cosine))


def _transmission_cosine(theta_cos, *, a=1, d=4, l=3, m=Fraction(7, 2)):
    """The page's textbook transmission angle's cosine, at the catalog four-bar's dimensions."""
    return Fraction(l**2 + m**2 - a**2 - d**2 + 2 * a * d * theta_cos) / (2 * l * m)


def hart_pieces(out):
    # D is on circles of radii b = 2 and 2r = 2 about A = 2 (cos, sin) and W = 2Z - A, |AW|**2 =
    # 20 - 16 cos: it folds (D's toggle) where that is 16, cos = 1/4; the flat configuration at 300 deg.
    pieces = [(float(lo), float(hi), label) for lo, hi, label
              in re.findall(r"^\s+([\d.]+) to ([\d.]+): \[(.*)\]$", out, re.M)]
    toggle = _degrees(1 / 4)
    expected = [(0, toggle, "D:left C:left"), (360 - toggle, 300, "D:left C:right"), (300, 360, "D:left C:left")]
    assert [label for *_, label in pieces] == [label for *_, label in expected], out
    assert all(abs(lo - elo) < 1e-3 and abs(hi - ehi) < 1e-3 for (lo, hi, _), (elo, ehi, _) in zip(pieces, expected))


def rates_error(out):
    # the page: "the largest relative error is 1.5e-36 on the lambda's B and P" (40 samples, seed 0)
    error = float(re.search(r"rates verification passed: .* max rel error (\S+)", out).group(1))
    assert f"{error:.1e}" == "1.5e-36", out


def _designs_assembling():
    """The atlas page's sweep, assembled where |DA| can reach |l - m| to l + m (l = 3, m = 7/2)."""
    cranks, grounds = [Fraction(1, 2), 1, Fraction(3, 2), 2], [2, 6, 10]
    return sum(max(abs(d - a), Fraction(1, 2)) <= min(d + a, Fraction(13, 2)) for a in cranks for d in grounds)


SLIDER_STROKE = math.sqrt((3 + 1) ** 2 - 0.25) - math.sqrt((3 - 1) ** 2 - 0.25)  # r = 1, l = 3, e = 1/2

# What the pages' text says a command gives, by the command.
SAYS = {
    "algkin curve stephenson-iii-triad --point P": [shows("degree 6, circularity 3")],  # "a tricircular sextic"
    "algkin derive hart-inversor --outputs Q": [hart_pieces, shows("C right -> left")],
    "algkin derive chebyshev-lambda --outputs P --rates": [rates_error],
    # the catalog: "eliminant of degree 6, two real modes at 0 deg"
    "algkin derive stephenson-iii-triad": [shows("modes at theta = 0°: 2 real of 6 complex")],
    # the arm-string tutorial by hand: |OB| - r where A lies on OB, tan(theta) = 400/80
    "algkin extremum arm-string --of AB --range 0:180": [
        shows_number(math.hypot(400, 80) - 350, within=1e-9),
        shows_number(math.degrees(math.atan2(400, 80)), within=1e-8)],
    # the catalog four-bar (a = 1, d = 4, l = 3): a Grashof crank-rocker for a + d < l + m and
    # a + m < d + l; no assembly past a + d + l
    "algkin extremum fourbar --of B.y --param m": [
        shows(f"holds for {1 + 4 - 3} < m < {4 + 3 - 1}", f"({1 + 4 + 3}, oo): the output is not real anywhere")],
    "algkin extremum fourbar-instant-centre --of I.x": [
        shows_number(_degrees(-53 / 80), within=1e-9), shows_number(360 - _degrees(109 / 144), within=1e-9)],
    "algkin extremum fourbar --of \"angle(A, B, D)\"": [
        shows(f"exactly 180*acos({_transmission_cosine(1)})/pi deg", f"exactly 180*acos({_transmission_cosine(-1)})/pi deg")],
    # the dead centre: |DA| = l + m = 13/2, so 4 + 25 - 20 cos(theta) = 169/4
    "algkin follow fourbar-nongrashof --mode left --from theta=0 --to 180 --digits 8": [
        shows("meets another mode"), shows_number(_degrees(-53 / 80), within=1e-5)],
    "algkin follow 3rpr --mode=--- --from r1=6 --to 12 --max-step 1/2 --digits 6": [
        shows("meets another mode"), shows_number(7.9228, within=1e-4)],
    # "asking for |AB| in the arm scene leaves the centre of gravity out"; its unit said first
    "algkin show arm-string --outputs AB": [shows("\nlengths in mm\n"), shows_no("G_x")],
    "algkin show 3rpr": [shows("solved together: P1, P2")],
    # "crossing itself at the centre, with two isolated points besides"
    "algkin singular watt-straight-line --point P": [
        lines_with("crunode (A1, multiplicity 2, 2 real of 2 tangents) at (0, 0)", 1), lines_with("acnode", 2)],
    # "three finite double points: one real, an acnode, and two complex"
    "algkin singular fourbar --point P": [
        shows("degree 6, circularity 3", "and 2 complex (not real) singular points"), lines_with("acnode", 1)],
    "algkin solve 3rpr-six-modes --at r1=14.98 --digits 10": [shows("6 configurations")],  # all six real
    # the crank tip of length 1 at 30 degrees
    "algkin solve fourbar --at theta=30 --digits 12": [shows(f"A = ({math.sqrt(3) / 2:.12f}, 0.5)")],
    # Q on the line x = -(a**2 - b**2) / (8 r), a = 4, b = 2, r = 1
    "algkin solve hart-inversor --at angle=290": [shows("2 configurations"), lines_with(f"Q = ({-(16 - 4) / 8},", 2)],
    "algkin solve stephenson-iii-triad --at theta=10": [shows("2 configurations")],
    "algkin sweep fourbar --grid a=1/2:2:4 --grid d=2:10:3 --analyses grashof,transmission --out fourbars "
    "--executor serial": [shows(f"12 designs (12 computed now): ok {_designs_assembling()}, ")],
    # "Each design that moves gets a thumbnail (not one that does not assemble...)"
    "algkin atlas fourbars --out atlas.html": [shows(f"wrote atlas.html: {_designs_assembling()} of 12 designs drawn")],
    "algkin synthesize motion fourbar-poses --digits 12": [
        matches(r"^  fourbar-poses-1\.toml: crank-rocker, .*; usable$"),
        shows("branch defect")],
    "algkin synthesize function three-pairs": [
        shows("1 real", "ground 6, crank 2, coupler ", ", rocker 5;"), shows_number(math.sqrt(41), within=1e-12)],
    # "exactly that four-bar reaches the other two; its transmission angle is its one defect"
    "algkin synthesize path seven-points-path --digits 12": [
        shows("1 real", "crank 2.00000000000, coupler 4.12310562562, rocker 5.00000000000"),
        matches(r"^  seven-points-path-1\.toml: .*; not usable: transmission defect \([^;]*\)$")],
    "algkin toggles slider-crank": [shows("output stroke: travel"), shows_number(SLIDER_STROKE, within=1e-12)],
    "algkin toggles fourbar-nongrashof": [shows("time ratio: none (the input does not turn fully")],
    # the catalog: "they meet at r1 = 7.92 and 11.21"
    "algkin toggles 3rpr": [shows_number(7.92, within=0.005), shows_number(11.21, within=0.005)],
    "algkin verify chebyshev-lambda --samples 100 --seed 3": [shows("verification passed: 200 branch values")],
    "algkin verify stephenson-iii-triad": [shows("verification passed", "none missing, none extra")],
}


def test_what_the_text_says_is_of_commands_it_shows():
    assert set(SAYS) <= {c.text for c in WALKED}, set(SAYS) - {c.text for c in WALKED}


def test_options_and_the_scene_in_any_order(walk):
    # docs/cli/index.md: "`algkin derive --outputs B chebyshev-lambda` reads as `algkin derive
    # chebyshev-lambda --outputs B`"
    first, then = (walk(Command("index.md", text, 0, None)) for text in
                   ("algkin derive --outputs B chebyshev-lambda", "algkin derive chebyshev-lambda --outputs B"))
    assert _without_timings(first.stdout) == _without_timings(then.stdout) != []


def _without_timings(out):
    return [line for line in out.splitlines() if not line.startswith("timings:")]


def _cell_calls(text):
    """The arguments of each ``main([...])`` in the page's code cells, None where a cell builds them."""
    cells = [ast.parse("\n".join(line for line in cell.splitlines() if not line.startswith(":")))
             for info, cell in _FENCED.findall(text) if info.startswith("{code-cell}")]
    names = {node.targets[0].id: node.value.value for tree in cells for node in ast.walk(tree)
             if isinstance(node, ast.Assign) and isinstance(node.targets[0], ast.Name)
             and isinstance(node.value, ast.Constant)}
    for tree in cells:
        for node in ast.walk(tree):
            if isinstance(node, ast.Call) and getattr(node.func, "id", None) == "main":
                yield _literal(node.args[0], names)


def _literal(node, names):
    values = []
    for element in node.elts:
        if isinstance(element, ast.Constant):
            values.append(element.value)
        elif isinstance(element, ast.Name) and element.id in names:
            values.append(names[element.id])
        else:
            return None
    return values


@pytest.mark.parametrize("path", [p for p in PAGES if p.parent.name == "cli"], ids=lambda p: p.name)
def test_a_pages_cells_draw_what_its_commands_say(path):
    shown = [c.args for c in COMMANDS if c.page == path.name]
    for args in _cell_calls(path.read_text(encoding="utf-8")):
        if args is None:
            assert path.name in BUILT_IN_CELLS, f"{path.name}: a cell builds its command: list the page"
        else:
            assert args in shown, f"{path.name}: a cell runs {args}, which the page does not show"


def _refused_on_groups(page):
    """The flags a page says are refused on a scene with points solved together."""
    text = " ".join((ROOT / "docs" / "cli" / page).read_text(encoding="utf-8").split())
    listed = re.search(r"((?:`--[a-z-]+`(?:, | and ))+`--[a-z-]+`) are refused on such a scene", text)
    return re.findall(r"`(--[a-z-]+)`", listed.group(1))


# A value each flag takes on the 3-RPR (whose dimensions r2, r3 and point P1 exist).
_GROUP_FLAG_VALUES = {"--param": ["r2"], "--outputs": ["P1"], "--method": ["resultant"], "--backend": ["sympy"]}


@pytest.mark.parametrize("flag", _refused_on_groups("derive.md"))
def test_what_derive_says_it_refuses_on_points_solved_together_it_refuses(flag, tmp_path):
    # The page once listed --rates among them, which derive had come to take.
    said = run_main(["derive", "3rpr", flag, *_GROUP_FLAG_VALUES.get(flag, [])], tmp_path)
    assert said.returncode == 2 and "is not taken with points solved together" in said.stderr, (flag, said.stderr)
