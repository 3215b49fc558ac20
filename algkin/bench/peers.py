"""Peer engines for ``algkin bench``: the problem as they see it, running them, reading them back.

The engines themselves (Singular, PARI/GP, Macaulay2, msolve) are in ``engines``. Each
peer function takes a ``PeerProblem`` and returns a ``PeerResult``. The computation runs
inside the engine's own script, timed by the engine's own clock, so engine start-up and
script parsing are not counted: one warm-up run, then repeated runs until they add up to
at least ``MIN_SECONDS`` over at least ``MIN_REPEATS`` runs, stopping early when one more
run would pass half the time budget. msolve is a binary with no loop of its own: it is run
once per repeat, and its median wall time less its start-up (the wall time of a trivial
system, measured right after) is used; its own clock has 10 ms ticks and counts start-up.

An engine that is missing, fails or runs past its budget gives ``seconds_per_run=None``
and a one-line note. Nothing here is needed by algkin itself; ``make peers`` installs them.
"""

import math
import os
import re
import shutil
import signal
import subprocess
import tempfile
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

import sympy
from sympy.polys.groebnertools import groebner
from sympy.polys.orderings import grevlex
from sympy.polys.rings import PolyElement, PolyRing, ring as sparse_ring

__all__ = ["PeerProblem", "PeerResult", "PeerFailure", "Encoded", "Peer", "BUDGET", "MIN_SECONDS", "MIN_REPEATS",
           "encode", "decode", "execute", "failure", "parse", "polynomial_ring", "eliminant", "side_relations", "peer"]

MIN_SECONDS = 0.2
MIN_REPEATS = 5
BUDGET = 60.0  # seconds per engine per problem, start-up and warm-up included


@dataclass(frozen=True)
class PeerProblem:
    """Eliminate ``eliminate`` (in this order) from ``equations`` (sympy syntax), keeping ``keep``."""

    name: str
    equations: tuple[str, ...]
    eliminate: tuple[str, ...]
    keep: tuple[str, ...]


@dataclass
class PeerResult:
    """What one engine gave: ``seconds_per_run`` is None when it was missing, failed or ran
    past its budget, and ``note`` says why. ``polynomial`` is in the problem's names and
    sympy syntax; read a long one with ``parse``, as ``sympy.sympify`` recurses once per
    term and fails on thousands of them."""

    engine: str
    seconds_per_run: float | None
    polynomial: str | None  # in the problem's variable names, sympy syntax
    note: str


class PeerFailure(Exception):
    """An engine could not give a result; the message is the one-line note."""


# -- the problem as the engines see it ------------------------------------------------------

@dataclass(frozen=True)
class Encoded:
    """The problem with variables renamed v1, v2, ... (eliminated first, in order) and
    integer coefficients: every engine accepts these names and none of them has a meaning
    of its own there (``I``, ``E``, ``pi``; ``_`` is an operator in Macaulay2)."""

    names: tuple[str, ...]  # engine names, eliminated variables first
    originals: tuple[str, ...]
    polys: tuple[str, ...]  # engine syntax, ``^`` for powers
    k: int  # how many variables to eliminate


def encode(problem: PeerProblem) -> Encoded:
    originals = tuple(problem.eliminate) + tuple(problem.keep)
    names = tuple(f"v{i + 1}" for i in range(len(originals)))
    symbols = [sympy.Symbol(n) for n in originals]
    polys = []
    for text in problem.equations:
        expr = sympy.sympify(text, locals={n: s for n, s in zip(originals, symbols)})
        _, poly = sympy.Poly(expr, *symbols, domain="QQ").clear_denoms(convert=True)
        polys.append(_engine_syntax(poly.primitive()[1], names))
    return Encoded(names, originals, tuple(polys), len(problem.eliminate))


def _engine_syntax(poly: sympy.Poly, names: Sequence[str]) -> str:
    """Each monomial once, as sympy's Poly gives them: msolve 0.10 does not add up a
    repeated monomial but keeps the last one (it reads ``y+3-7`` as ``y-7``)."""
    terms = []
    for monom, coeff in poly.terms():
        factors = [str(abs(coeff))] if coeff not in (1, -1) or not any(monom) else []
        factors += [n if e == 1 else f"{n}^{e}" for n, e in zip(names, monom) if e]
        terms.append(("-" if coeff < 0 else "+") + "*".join(factors))
    return "".join(terms).lstrip("+")


def polynomial_ring(variables: Sequence[str]) -> PolyRing:
    """The sparse polynomial ring over QQ that engine output is read into."""
    return sparse_ring(",".join(variables), sympy.QQ, grevlex)[0]


_TOKEN = re.compile(r"\s*(?:(\d+)|([A-Za-z_]\w*)|(\*\*|[-+*/^()]))")


def parse(text: str, ring: PolyRing) -> PolyElement:
    """A polynomial in ``ring`` from engine or sympy syntax (``^`` or ``**``, nested
    parentheses as PARI prints them). Sums are read in a loop, not recursively: sympy's
    own parser recurses once per term and fails on the thousands of terms a symbolic
    four-bar gives. Names are looked up in ``ring`` by their text."""
    tokens: list[tuple[str | None, str | None, str | None]] = [
        (m.group(1), m.group(2), m.group(3)) for m in _TOKEN.finditer(text)]
    if "".join(m.group(0) for m in _TOKEN.finditer(text)).strip() != text.strip():
        raise ValueError(f"cannot read polynomial: {text[:80]}")
    gens = {str(g): g for g in ring.gens}
    position = 0

    def peek() -> str | None:
        return tokens[position][2] if position < len(tokens) else None

    def take() -> tuple[str | None, str | None, str | None]:
        nonlocal position
        position += 1
        return tokens[position - 1]

    def number() -> int:
        digits = take()[0] if position < len(tokens) else None
        if digits is None:  # an exponent or a divisor is a whole number
            raise ValueError(f"cannot read polynomial: {text[:80]}")
        return int(digits)

    def atom() -> PolyElement:
        number, name, op = take()
        if number:
            return ring(int(number))
        if name:
            return gens[name]
        if op == "(":
            value = expression()
            take()
            return value
        if op == "-":
            return -factor()
        raise ValueError(f"unexpected {op!r} in polynomial")

    def factor() -> PolyElement:
        base = atom()
        if peek() in ("^", "**"):
            take()
            return base ** number()
        return base

    def term() -> PolyElement:
        value = factor()
        while peek() in ("*", "/"):
            if take()[2] == "*":
                value *= factor()
            else:
                value = value.quo_ground(sympy.QQ(number()))
        return value

    def expression() -> PolyElement:
        value = term() if peek() not in ("+", "-") else ring(0)
        while peek() in ("+", "-"):
            value = value + term() if take()[2] == "+" else value - term()
        return value

    value = expression()
    if position != len(tokens):
        raise ValueError(f"cannot read polynomial: {text[:80]}")
    return value


def decode(text: str, encoded: Encoded, ring: PolyRing) -> PolyElement:
    """An engine's polynomial (in v1, v2, ...) as an element of ``ring`` (the kept names)."""
    table = dict(zip(encoded.names, encoded.originals))
    return parse(re.sub(r"\bv\d+\b", lambda m: table[m.group(0)], text), ring)


# -- one polynomial from what an engine returns ---------------------------------------------

def eliminant(generators: Sequence[PolyElement], problem: PeerProblem, ring: PolyRing) -> tuple[str, str]:
    """One polynomial (a string in sympy syntax) from the generators an elimination
    returned (elements of ``ring``), and a note.

    Equations of the problem that hold no variable to eliminate (``c**2 + s**2 - 1``) are
    side relations: every elimination returns them, so generators in their ideal are
    dropped. Of the rest, the gcd if it is not a constant (a resultant chain's extraneous
    factors differ between its branches), else the smallest generator (the same rule as
    algkin's own ``eliminate``). Made primitive with integer coefficients.
    """
    polys = [g for g in generators if g]
    if not polys:
        raise PeerFailure("the elimination ideal is zero")
    note = ""
    side = side_relations(problem, ring)
    if side and len(polys) > 1:
        basis = groebner(side, ring)
        rest = [p for p in polys if p.rem(basis)]
        note = f"{len(polys) - len(rest)} side relation(s) dropped" if rest else ""
        polys = rest or polys
    common = polys[0]
    for poly in polys[1:]:
        common = common.gcd(poly)
    if len(polys) > 1 and common.is_ground:
        common = min(polys, key=lambda p: (max(sum(m) for m in p.monoms()), len(p)))
        note = f"not principal beyond the side relations: smallest of {len(polys)} generators"
    elif len(polys) > 1:
        note = f"gcd of {len(polys)} generators"
    return str(_primitive(common)), note


def side_relations(problem: PeerProblem, ring: PolyRing) -> list[PolyElement]:
    """The problem's equations that hold only kept variables, as elements of ``ring``."""
    return [parse(e, ring) for e in problem.equations
            if set(re.findall(r"[A-Za-z_]\w*", e)) <= set(problem.keep)]


def _primitive(poly: PolyElement) -> PolyElement:
    """``poly`` with coprime integer coefficients and a positive leading one."""
    _, poly = poly.clear_denoms()
    content = sympy.QQ(math.gcd(*(int(c) for c in poly.coeffs())))
    if poly.LC < 0:
        content = -content
    return poly.quo_ground(content)


# -- running an engine ----------------------------------------------------------------------

def execute(command: Sequence[str], timeout: float, cwd: str | None = None) -> tuple[int, str, str] | None:
    """(exit code, stdout, stderr) of ``command``, or None when it ran past ``timeout``:
    its whole process group is killed then (Macaulay2 and Singular start helpers). No
    standard input: after an error in a script, gp and Singular go on reading it."""
    proc = subprocess.Popen(command, cwd=cwd, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, start_new_session=True)
    try:
        out, err = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        _kill_group(proc)
        return None
    except BaseException:  # a signal's exception (algkin.ui.cli): in a session of its own, the engine would run on
        _kill_group(proc)
        raise
    return proc.returncode, out, err


def _kill_group(proc: subprocess.Popen[str]) -> None:
    """Kill the engine and the helpers it started (its process group), and reap it."""
    os.killpg(proc.pid, signal.SIGKILL)
    proc.communicate()


def failure(code: int, out: str, err: str) -> PeerFailure:
    """The engine's first line that mentions an error (else its last line) as a failure."""
    lines = [line.strip() for line in (err + "\n" + out).splitlines() if line.strip()]
    line = next((x for x in lines if "error" in x.lower()), lines[-1] if lines else "")
    line = re.sub(r"\S*/(problem\.\w+)", r"\1", line)  # no temporary paths in notes
    return PeerFailure(f"failed (exit code {code}): {line[:160]}")


def _run(command: list[str], script: str, suffix: str, budget: float) -> str:
    """stdout of ``command`` run on ``script`` (written to a file), within ``budget``."""
    with tempfile.TemporaryDirectory(prefix="algkin-peer-") as tmp:
        path = Path(tmp) / f"problem{suffix}"
        path.write_text(script)
        done = execute(command + [str(path)], budget, cwd=tmp)
    if done is None:
        raise PeerFailure(f"over budget ({budget:g} s)")
    code, out, err = done
    if code != 0 or "ALGKIN-TIME" not in out:
        raise failure(code, out, err)
    return out


def _read_output(out: str, ticks_per_second: float) -> tuple[float, list[str]]:
    """(seconds per run, generator strings) from the ALGKIN-TIME / ALGKIN-POLY lines."""
    total, repeats = next(line.split()[1:3] for line in out.splitlines()
                          if line.startswith("ALGKIN-TIME"))
    polys = [line[len("ALGKIN-POLY"):].strip() for line in out.splitlines()
             if line.startswith("ALGKIN-POLY")]
    return float(total) / ticks_per_second / int(repeats), polys


# a peer engine: the problem and a budget (seconds) to what it gave
Peer = Callable[[PeerProblem, float], PeerResult]


def peer(engine: str, executable: str, make_script: Callable[[Encoded, float], str], suffix: str,
         ticks_per_second: float, command: list[str]) -> Peer:
    """A peer function from an engine's script maker and how to run it."""
    def peer(problem: PeerProblem, budget: float = BUDGET) -> PeerResult:
        found = shutil.which(executable)
        if found is None:
            return PeerResult(engine, None, None, f"skipped: {executable} not found")
        encoded = encode(problem)
        try:
            out = _run([found] + command, make_script(encoded, budget / 2), suffix, budget)
            seconds, generators = _read_output(out, ticks_per_second)
            ring = polynomial_ring(problem.keep)
            polynomial, note = eliminant([decode(g, encoded, ring) for g in generators],
                                         problem, ring)
        except PeerFailure as failure:
            return PeerResult(engine, None, None, str(failure))
        return PeerResult(engine, seconds, polynomial, note)
    peer.__doc__ = f"{engine}: seconds per run and eliminant of a Problem, timed in the engine."
    return peer
