"""Elimination methods compared on mechanism problems: every method x backend, the default
path end to end, and the peer engines that are installed, in one run.

Each row is timed in a child process within the budget (``measure``), carries the
eliminant's figures (degree, terms, coefficient bits) and whether it agrees with the
problem's reference (``_verdicts``): the Gröbner basis over python-flint (a different
algorithm from the resultants and the linear method) when it is in the run and finished;
else a peer's elimination ideal (Singular, Macaulay2 or msolve ``eliminate``) when one
finished, and always then a fresh Gröbner elimination at random rational values of the
dimensions (``specialise``). algkin's default is never its own reference. Each row's note
says what it was checked against. ``ratio`` is each row's time over algkin's default (the ``linear``
method over ``flint``) on the same problem: above 1, algkin is faster.
"""

import functools
import os
import platform
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import flint
import sympy

from ..derivation.tasks import EliminationTask
from ..eliminate import BACKENDS, DEFAULT_METHOD, METHODS, Elimination
from ..runtime import progress, validation
from ..runtime.budget import time_budget
from . import specialise
from .agree import PASSING, Agreement, Verdict, agreement, from_sympy, portable, rebuild
from .kinematics import KINEMATICS, kinematics_rows
from .synthesis import SYNTHESIS
from .measure import measure
from .problems import PROBLEMS, Problem, build, problem_names
from .row import BenchRow
from .specialise import Specialisation

if TYPE_CHECKING:
    from .peers import PeerProblem

__all__ = ["bench", "BenchReport", "BenchRow", "PROBLEMS", "problem_names", "machine"]

REFERENCE = ("groebner", "flint")
PEER_REFERENCES = ("Singular eliminate", "msolve eliminate", "Macaulay2 eliminate")  # elimination ideals
SPECIALISATIONS = 2  # random rational specialisations checked where the Gröbner reference did not finish
DEFAULT = (DEFAULT_METHOD, "flint")
ROUNDS = 3  # rows measured in turn, each keeping its best round (``bench(rounds=...)``)...
ROUND_CAP = 2.0  # ...when one run takes less than this many seconds
MAX_ROUNDS = 100  # past this the quick rows alone take hours: a bench that never ends


@dataclass
class BenchReport:
    rows: list[BenchRow]
    machine: dict[str, object]

    def to_json(self) -> dict[str, object]:
        return {"rows": [row.to_json() for row in self.rows], "machine": self.machine}


def machine() -> dict[str, object]:
    """What the run was measured on."""
    from .engines import found_peers

    model = next((line.split(":", 1)[1].strip() for line in _cpuinfo() if line.startswith("model name")), None)
    return {"cpu": model or platform.processor() or platform.machine(), "cores": os.cpu_count(),
            "system": platform.platform(terse=True), "python": platform.python_version(),
            "python-flint": flint.__version__, "sympy": sympy.__version__, "peers": found_peers()}


def _cpuinfo() -> list[str]:
    try:
        with open("/proc/cpuinfo") as f:
            return f.read().splitlines()
    except OSError:
        return []


def bench(problems: Sequence[str] | None = None, methods: Sequence[str] | None = None,
          backends: Sequence[str] | None = None, budget: float = 60.0, peers: bool = True,
          rounds: int = ROUNDS) -> BenchReport:
    """Time every method x backend (and peers) on every problem; a ``BenchReport``. Within
    ``algkin.runtime.progress.shown()``, the row being measured shows, and the count of rows measured once."""
    from .engines import PEERS

    time_budget(budget, "budget")  # a row's deadline, so a week at most (past that the timer overflows)
    validation.count("rounds", rounds, MAX_ROUNDS, minimum=1)
    names = validation.names("problems", problems) or problem_names()  # each once: a row is measured once
    pairs = sorted({(m, b) for m in methods or METHODS for b in backends or BACKENDS} | {DEFAULT})
    rows: list[BenchRow] = []
    with progress.counting(len(names) * (len(pairs) + 1 + (len(PEERS) if peers else 0)), "rows"):
        for name in names:
            solved_together = KINEMATICS.get(name) or SYNTHESIS.get(name)
            rows += kinematics_rows(solved_together(), budget, peers, rounds) if solved_together else \
                _problem_rows(build(name), pairs, budget, peers, rounds)
    return BenchReport(rows, machine())


def _problem_rows(problem: Problem, pairs: Sequence[tuple[str, str]], budget: float, peers: bool,
                  rounds: int) -> list[BenchRow]:
    task = problem.task
    side = [e for e in task.equations if not ({str(v) for v in e.free_symbols} & set(task.eliminate))]
    results: dict[tuple[str, str], BenchRow] = {}
    for method, backend in pairs:
        progress.stage(f"{problem.name}: {method} / {backend}")
        seconds, summary, note = measure(functools.partial(task.run, method, backend), _summary, budget)
        results[(method, backend)] = BenchRow(problem.name, method, backend, seconds, note=note, **(summary or {}))
        progress.step()
    progress.stage(f"{problem.name}: algkin default path, end to end")
    seconds, summary, note = measure(problem.end_to_end, lambda result: _end_summary(result, task.keep[0]), budget)
    progress.step()
    rows = list(results.values())
    rows.append(BenchRow(problem.name, "default path, end to end", "flint", seconds, note=note, **(summary or {})))
    if peers:
        rows += _peer_rows(problem, budget)
    _rounds(problem, rows, budget, rounds)
    _verdicts(task, rows, side, budget)
    default = results[DEFAULT].seconds
    for row in rows:
        row.ratio = row.seconds / default if row.seconds and default else None
    return rows


def _verdicts(task: EliminationTask, rows: list[BenchRow], side: Sequence[sympy.Expr], budget: float) -> None:
    """Set each row's ``agrees`` (its verdict's kind) and add what it was checked against
    to its note: the reference row, then, unless that is the Gröbner basis over flint, the
    fresh eliminations at random rational specialisations, which every row must also pass."""
    keep = list(task.keep)
    reference, name = _reference(rows)
    target = None if reference is None or reference.form is None else rebuild(reference.form, keep)
    flint_side = [from_sympy(e, keep) for e in side]
    found: list[Specialisation] = []
    if name != "Gröbner basis over flint":
        progress.stage(f"{rows[0].problem}: fresh eliminations at random rational specialisations")
        found = [specialise.fresh(task, values, budget)
                 for values in specialise.specialisations(task, side, SPECIALISATIONS, seed=17)]
    for row in rows:
        form, row.form = row.form, None
        if form is None:
            continue  # did not finish: nothing to compare
        poly = rebuild(form, keep)
        compared = [Verdict(Agreement.REFERENCE) if row is reference else
                    agreement(poly, target, flint_side, task.parameters)] if target is not None else []
        specialised = [specialise.check(poly, found)] if found else []
        verdicts = compared + specialised or [Verdict(Agreement.NOT_COMPARED, "no reference finished")]
        # a check that did not finish (a specialisation past the budget) overrules none that did
        checked = [v for v in verdicts if v.kind is not Agreement.NOT_COMPARED] or verdicts
        verdict = next((v for v in checked if v.kind not in PASSING), checked[0])
        said = [v.detail for v in verdicts if v is verdict or v in specialised]
        row.agrees = verdict.kind
        row.note = "; ".join(filter(None, [row.note, f"vs {name}" if name else None, *said]))


def _reference(rows: Sequence[BenchRow]) -> tuple[BenchRow, str] | tuple[None, None]:
    """``(row, what it is)``: the Gröbner basis over flint if it finished, else the first
    peer elimination ideal that did, else ``(None, None)``: never algkin's default."""
    finished = {(r.method, r.backend): r for r in rows if r.form is not None}
    if REFERENCE in finished:
        return finished[REFERENCE], "Gröbner basis over flint"
    peer = next((p for p in PEER_REFERENCES if (p, "peer") in finished), None)
    return (finished[peer, "peer"], peer) if peer else (None, None)


def _summary(elimination: Elimination[Any]) -> dict[str, Any]:
    # measured in the child, where the elimination still holds its backend's polynomials
    assert elimination.engine is not None and elimination.raw is not None
    return {"degree": elimination.degree, "terms": elimination.terms, "bits": elimination.bits,
            "form": portable(elimination.engine, elimination.raw)}


def _end_summary(result: object, unknown: str) -> dict[str, Any]:
    """The figures of the command's eliminant for ``unknown`` (a curve's, or a derivation's)."""
    elimination = getattr(result, "elimination", None) or getattr(result, "eliminations", {}).get(unknown)
    return _summary(elimination) if elimination is not None else {}


def _peer_problem(problem: Problem) -> "PeerProblem":
    from .peers import PeerProblem

    task = problem.task
    return PeerProblem(problem.name, tuple(str(e) for e in task.equations), task.eliminate, task.keep)


def _rounds(problem: Problem, rows: list[BenchRow], budget: float, rounds: int) -> None:
    """Measure every row that finished within ``ROUND_CAP`` again, in turn, ``rounds`` times
    in all; each keeps its least time. The machine's speed drifts over seconds (a shared
    virtual machine: up to 2x), and a ratio of two rows is only fair when each had its
    chance at the same speed."""
    from .engines import PEERS

    def again(row: BenchRow) -> float | None:
        if row.backend == "peer":
            return PEERS[row.method](_peer_problem(problem), budget).seconds_per_run
        run = problem.end_to_end if row.method == "default path, end to end" else \
            (lambda: problem.task.run(row.method, row.backend))
        return measure(run, lambda result: None, budget)[0]

    quick = [row for row in rows if row.seconds and row.seconds < ROUND_CAP] if rounds > 1 else []
    for round_ in range(2, rounds + 1):
        progress.stage(f"{problem.name}: round {round_} of {rounds}")
        for row in quick:
            row.seconds = min(filter(None, [row.seconds, again(row)]))
    for row in quick:
        row.note = "; ".join(filter(None, [row.note, f"best of {rounds} rounds"]))


def _peer_rows(problem: Problem, budget: float) -> list[BenchRow]:
    from .engines import PEERS
    from .peers import parse, polynomial_ring

    task = problem.task
    peer_problem = _peer_problem(problem)
    rows: list[BenchRow] = []
    for engine, run in PEERS.items():
        progress.stage(f"{problem.name}: {engine}")
        result = run(peer_problem, budget)
        progress.step()
        row = BenchRow(problem.name, engine, "peer", result.seconds_per_run, note=result.note)
        if result.polynomial is not None:
            poly = parse(result.polynomial, polynomial_ring(task.keep))
            terms = [(m, int(c.numerator), int(c.denominator)) for m, c in poly.terms()]
            row.degree, row.terms, row.form = max(sum(m) for m, _, _ in terms), len(terms), (task.keep, terms)
        rows.append(row)
    return rows
