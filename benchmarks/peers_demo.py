"""Time the peer engines on algkin's elimination problems and check their answers.

For each problem and peer (see peers.py; ``make peers`` installs them) prints the seconds
per run, timed inside the engine, and whether its eliminant agrees with a reference that
sympy computes here: equal up to a constant after dividing out the factors the two do not
share, or else equal up to a constant modulo the side relations (``c**2 + s**2 - 1``)
when the elimination ideal is not principal.

    python benchmarks/peers_demo.py [--budget SECONDS] [--json] [--problem NAME]...
"""

import argparse
import json
import multiprocessing
import subprocess
import sys
import time
from pathlib import Path

import sympy
from sympy.polys.groebnertools import groebner

sys.path.insert(0, str(Path(__file__).resolve().parent))
import peers  # noqa: E402  (a sibling script, not a package)


def two_circles(eliminated):
    """The Chebyshev lambda connector: B on circles about A = (c, s) and D = (2, 0)."""
    kept = "y" if eliminated == "x" else "x"
    return peers.Problem(
        f"two circles (eliminate {eliminated})",
        ("(x - c)**2 + (y - s)**2 - 25/4", "(x - 2)**2 + y**2 - 25/4", "c**2 + s**2 - 1"),
        (eliminated,), (kept, "c", "s"))


def lambda_coupler():
    """The lambda coupler curve: algkin's own system for point P, all but P_x, P_y eliminated."""
    shown = subprocess.run(
        [sys.executable, "-m", "algkin", "show", "chebyshev-lambda", "--outputs", "P", "--json"],
        check=True, capture_output=True, text=True)
    system = json.loads(shown.stdout)["system"]
    keep = ("P_x", "P_y")
    inputs = [name for pair in system["inputs"].values() for name in (pair["cos"], pair["sin"])]
    eliminate = tuple(u for u in system["unknowns"] if u not in keep) + tuple(inputs)
    return peers.Problem("lambda coupler P", tuple(system["equations"]), eliminate, keep)


def arm_extremum():
    """Stationary |AB| of the arm with b symbolic: F, its angle derivative G, the circle."""
    return peers.Problem(
        "arm |AB| extremum, b symbolic",
        ("AB**2 - b**2 + 700*b*c - 122500*c**2 - 122500*s**2 + 280000*s - 160000",
         "-700*b*s + 280000*c", "c**2 + s**2 - 1"),
        ("c", "s"), ("AB", "b"))


def four_bar():
    """The general four-bar coupler curve: crank A = a*(c, s), rocker pivot D = (d, 0),
    |AB| = l, |DB| = m, coupler point P = A + p*(B - A) + q*rot90(B - A)."""
    return peers.Problem(
        "four-bar coupler, all symbolic",
        ("c**2 + s**2 - 1",
         "(Bx - a*c)**2 + (By - a*s)**2 - l**2",
         "(Bx - d)**2 + By**2 - m**2",
         "Px - (a*c + p*(Bx - a*c) - q*(By - a*s))",
         "Py - (a*s + p*(By - a*s) + q*(Bx - a*c))"),
        ("Bx", "By", "c", "s"), ("Px", "Py", "a", "d", "l", "m", "p", "q"))


# -- references computed by sympy -----------------------------------------------------------

def chain_reference(problem):
    """Successive resultants in the problem's order, each divided by its content in its
    main variable (as the PARI peer does), then ``peers.eliminant``'s choice of one."""
    gens = sympy.symbols(problem.eliminate + problem.keep)
    table = {str(g): g for g in gens}
    polys = [sympy.Poly(sympy.sympify(e, locals=table), *gens) for e in problem.equations]
    for var in gens[:len(problem.eliminate)]:
        holders = [p for p in polys if p.degree(var) > 0]
        polys = [p for p in polys if p.degree(var) <= 0]
        if len(holders) < 2:
            continue
        others = [g for g in gens if g != var]
        pivot = min(holders, key=lambda p: p.degree(var))
        for poly in holders:
            if poly is not pivot:
                result = pivot.reorder(var, *others).resultant(poly.reorder(var, *others))
                if not result.is_zero:
                    polys.append(_primitive_in_main(sympy.Poly(result.as_expr(), *gens)))
    return _eliminant([p.as_expr() for p in polys], problem)


def _primitive_in_main(poly):
    """``poly`` divided by the gcd of its coefficients in its first generator present."""
    main = next(g for g in poly.gens if poly.degree(g) > 0)
    content = sympy.gcd_list(sympy.Poly(poly.as_expr(), main).all_coeffs())
    return poly.exquo(sympy.Poly(content, *poly.gens))


def _eliminant(exprs, problem):
    kept = peers.polynomial_ring(problem.keep)
    return peers.eliminant([kept.from_expr(e) for e in exprs], problem, kept)[0]


def four_bar_reference(problem):
    """The classical derivation, not a generic elimination (sympy's resultant chain takes
    many minutes here): with z = p + i*q, B - A = (P - A)/z, so |AB| = l and |DB| = m
    become |P - A| = l*|z| and |z*(A - D) + P - A| = m*|z|, linear in (c, s) once
    c**2 + s**2 = 1 is used; Cramer's rule put into c**2 + s**2 = 1 gives the curve."""
    Px, Py, a, d, l, m, p, q, c, s = sympy.symbols("Px Py a d l m p q c s")
    A, P, D = sympy.Matrix([a * c, a * s]), sympy.Matrix([Px, Py]), sympy.Matrix([d, 0])
    times_z = sympy.Matrix([[p, -q], [q, p]])
    moved = P - A + times_z * (A - D)
    rows = []
    for equation in ((P - A).dot(P - A) - l**2 * (p**2 + q**2),
                     moved.dot(moved) - m**2 * (p**2 + q**2)):
        linear = sympy.Poly(sympy.expand(equation).subs(s**2, 1 - c**2), c, s)
        if linear.total_degree() != 1:
            raise ArithmeticError("the loop equation is not linear in (c, s)")
        rows.append((linear.coeff_monomial(c), linear.coeff_monomial(s), -linear.coeff_monomial(1)))
    (a1, b1, g1), (a2, b2, g2) = rows
    det, cos_num, sin_num = a1 * b2 - a2 * b1, g1 * b2 - g2 * b1, a1 * g2 - a2 * g1
    return _eliminant([sympy.expand(cos_num**2 + sin_num**2 - det**2)], problem)


def _reference_child(reference, problem, pipe):
    """Send (polynomial, note), or (None, why) when the reference fails."""
    try:
        pipe.send((reference(problem), "one run, wall time"))
    except Exception as error:  # the parent reports it and goes on to the peers
        pipe.send((None, f"failed: {type(error).__name__}: {error}"))


def run_reference(reference, problem, budget):
    """(seconds, polynomial string or None, note) of ``reference`` in a child process,
    ended at ``budget``: sympy cannot be interrupted from inside."""
    receive, send = multiprocessing.Pipe(duplex=False)
    child = multiprocessing.get_context("fork").Process(
        target=_reference_child, args=(reference, problem, send), daemon=True)
    start = time.perf_counter()
    child.start()
    ready = receive.poll(budget)
    seconds = time.perf_counter() - start
    if not ready:
        child.kill()
        child.join()
        return None, None, f"over budget ({budget:g} s)"
    polynomial, note = receive.recv()
    child.join()
    return (seconds if polynomial else None), polynomial, note


# -- agreement ------------------------------------------------------------------------------

def agreement(polynomial, reference, problem):
    """'yes'; 'yes, extra deg P/R' when the peer's and the reference's polynomials have
    extraneous factors of total degree P and R besides their gcd; 'yes, mod side rel.'
    when they are proportional modulo the side relations; or 'NO'. The shared part must
    hold every kept variable, so that a common extraneous factor (a power of p**2 + q**2,
    say) is not taken for agreement."""
    ring = peers.polynomial_ring(problem.keep)
    mine, theirs = peers.parse(polynomial, ring), peers.parse(reference, ring)
    shared = mine.gcd(theirs)
    if all(d > 0 for d in shared.degrees()):
        extra = (_degree(mine) - _degree(shared), _degree(theirs) - _degree(shared))
        if extra == (0, 0):
            return "yes"
        return f"yes, extra deg {extra[0]}/{extra[1]}"
    side = peers.side_relations(problem, ring)
    if side:
        basis = groebner(side, ring)
        mine, theirs = mine.rem(basis), theirs.rem(basis)
        if mine and theirs and mine * theirs.LC == theirs * mine.LC:
            return "yes, mod side rel."
    return "NO"


def _degree(poly):
    return max(sum(m) for m in poly.monoms())


# -- the table ------------------------------------------------------------------------------

PROBLEMS = {
    "circles-x": (lambda: two_circles("x"), chain_reference),
    "circles-y": (lambda: two_circles("y"), chain_reference),
    "lambda-coupler": (lambda_coupler, chain_reference),
    "arm-extremum": (arm_extremum, chain_reference),
    "four-bar": (four_bar, four_bar_reference),
}


def rows(selected, budget):
    """One dict per problem and engine, the sympy reference first."""
    for key in selected:
        make, reference = PROBLEMS[key]
        problem = make()
        seconds, expected, note = run_reference(reference, problem, budget)
        yield {"problem": problem.name, "engine": "sympy reference", "seconds_per_run": seconds,
               "agrees": "", "note": note, **_figures(expected, problem)}
        for result in peers.run_peers(problem, budget):
            agrees = ""
            if result.polynomial is not None:
                agrees = agreement(result.polynomial, expected, problem) if expected else "no reference"
            yield {"problem": problem.name, "engine": result.engine,
                   "seconds_per_run": result.seconds_per_run, "agrees": agrees, "note": result.note,
                   **_figures(result.polynomial, problem)}


def _figures(polynomial, problem):
    if polynomial is None:
        return {"degree": None, "terms": None}
    poly = peers.parse(polynomial, peers.polynomial_ring(problem.keep))
    return {"degree": _degree(poly), "terms": len(poly)}


def _seconds(value):
    if value is None:
        return "-"
    unit, scale = next(((u, k) for u, k in (("s", 1), ("ms", 1e-3)) if value >= k), ("µs", 1e-6))
    return f"{value / scale:.3g} {unit}"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--budget", type=float, default=peers.BUDGET,
                        help="seconds per engine per problem (default %(default)g)")
    parser.add_argument("--json", action="store_true", help="print JSON instead of a table")
    parser.add_argument("--problem", action="append", choices=sorted(PROBLEMS),
                        help="only this problem (repeatable)")
    args = parser.parse_args()
    selected = args.problem or list(PROBLEMS)
    if args.json:
        json.dump(list(rows(selected, args.budget)), sys.stdout, indent=2)
        print()
        return 0
    print(f"{'problem':31} {'engine':20} {'per run':>9} {'deg':>4} {'terms':>6}  {'agrees':20} note")
    for row in rows(selected, args.budget):
        figures = [("-" if row[k] is None else row[k]) for k in ("degree", "terms")]
        print(f"{row['problem']:31} {row['engine']:20} {_seconds(row['seconds_per_run']):>9} "
              f"{figures[0]:>4} {figures[1]:>6}  {row['agrees']:20} {row['note']}", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
