"""Synthesis against pylinkage: its Burmester points and Freudenstein four-bars on algkin's data.

pylinkage (the optional extra: ``pip install 'algkin[compare]'``) finds five-pose Burmester
points by a grid search (body points on 16 rings x 72 rays about the first pose's origin, kept
where the five positions are concyclic within 1%, the best six), and Freudenstein four-bars by
a linear solve of three absolute pairs, by least squares beyond; it has no unknown starting
angles. The run gives both the same data (floats to pylinkage, exact rationals to algkin),
times both in the same process (the best of ``--repeat`` calls each), and prints per set what
each found: algkin's real solutions (certified balls), the ones pylinkage missed, its
candidates that match none, and for each matched one the error |pylinkage - algkin|, algkin's
ball midpoints the reference (their radii are below 1e-30).

Matching: a pylinkage Burmester candidate matches algkin's nearest pair when both its centre
and its circle point are within ``BURMESTER_MATCH`` x the largest distance between the poses'
origins (pylinkage's own scale for its grid); a four-bar matches when every length is within
``FREUDENSTEIN_MATCH`` x the ground and both starting angles within ``FREUDENSTEIN_MATCH``
radians.

The run fails (an AssertionError) where algkin's answer does not hold: a Burmester pair's
circle point not at one distance from its centre in all five poses (the five squared
distances' balls must overlap, and be narrow), a four-bar not closing its loop at every pair
(|crank end - rocker end|**2 against coupler**2, in balls), or a pylinkage candidate that
Newton's method on the dyad equations refines to a solution algkin does not have.

Run: ``python benchmarks/bench_pylinkage_synthesis.py [--repeat N]``.
"""

import argparse
import cmath
import math
import sys
import time
from importlib.metadata import version

import flint
import mpmath
import numpy as np

from algkin.synthesis.data import Angle, AnglePair, Pose, dyad_poses
from algkin.synthesis.function import freudenstein
from algkin.synthesis.motion import burmester

BURMESTER_MATCH = 0.1
FREUDENSTEIN_MATCH = 1e-6
BITS = 128
q = flint.fmpq


# ---------------------------------------------------------------- small helpers

def _mpf(value):
    return mpmath.mpf(int(value.p)) / int(value.q)


def _radians(angle, *, precise=False):
    if precise:
        return mpmath.atan2(_mpf(angle.sin), _mpf(angle.cos))
    return math.atan2(float(angle.sin), float(angle.cos))


def _mid(value):
    return float(value) if isinstance(value, flint.fmpq) else float(value.mid())


def _narrow(ball):
    return ball.rad() < 1e-30 * (1 + abs(ball.mid()))


def _timed(call, repeat):
    """The call's result and its best time over ``repeat`` calls."""
    best = math.inf
    for _ in range(repeat):
        start = time.perf_counter()
        result = call()
        best = min(best, time.perf_counter() - start)
    return result, best


def _ratio(value, to):
    return f"{value / to:.2f}" if value < 100 * to else f"{value / to:.0f}"


def _print_times(pylinkage_time, algkin_time):
    print(f"  time: pylinkage {_seconds(pylinkage_time)}, algkin {_seconds(algkin_time)} "
          f"(algkin / pylinkage {_ratio(algkin_time, pylinkage_time)})")


def _point(z, digits):
    return f"({z.real:.{digits}g}, {z.imag:.{digits}g})"


def _count(number, noun):
    return f"{number} {noun}" + ("" if number == 1 else "s")


def _cos_sin(angle):
    return angle.cos, angle.sin


def _seconds(value):
    if value < 1e-3:
        return f"{value * 1e6:.0f} us"
    return f"{value * 1e3:.1f} ms" if value < 1 else f"{value:.2f} s"


# ---------------------------------------------------------------- the data

def _pose(x, y, cos, sin):
    return Pose(q(x), q(y), Angle.of_cos_sin(q(cos), q(sin)))


def _on_dyad(crank_halves, coupler_halves, *, circle, centre, radius):
    """Poses the dyad (``circle``, ``centre``) reaches, the crank's and the plane's angles by
    half-angle tangents: the set has at least that real pair, rational."""
    half = lambda t: Angle.of_tan_half(q(t))  # noqa: E731
    return dyad_poses([half(t) for t in crank_halves], [half(t) for t in coupler_halves],
                      circle=(q(circle[0]), q(circle[1])), centre=(q(centre[0]), q(centre[1])), radius=q(radius))


FOUR_POSES = [_pose(0, 0, 1, 0), _pose(1, "1/2", "4/5", "3/5"), _pose(2, "3/2", "5/13", "12/13"), _pose(3, 1, 0, 1)]
MOTION_SETS = {
    "algkin.synthesis.motion's example": FOUR_POSES + [Pose(q(4), q(-1), Angle.of_tan_half(q(3, 2)))],
    "four real pairs": [_pose(-2, -3, 0, -1), _pose(3, 3, 1, 0), _pose(2, -1, "-5/13", "-12/13"), _pose(-4, 2, 1, 0),
                        _pose(-4, 3, "4/5", "-3/5")],
    "on the dyad (2, 2)-(-2, 2)": _on_dyad(["1/2", "6/5", 4, "3/5", -2], ["5/8", "1/5", "-3/4", "-1/6", -1],
                                           circle=(2, 2), centre=(-2, 2), radius=4),
    "on the dyad (-1, 0)-(0, 3)": _on_dyad([-4, 2, -8, "-1/3", -1], ["1/4", "-1/3", "1/10", 0, "-3/10"],
                                           circle=(-1, 0), centre=(0, 3), radius=1),
    "no real pair": [_pose(-1, -3, 0, -1), _pose(-4, -4, "5/13", "12/13"), _pose(-4, 2, "-3/5", "4/5"),
                     _pose(2, -4, 0, 1), _pose(3, 3, 0, 1)],
}


def _pairs(inputs, outputs):
    return [AnglePair(Angle.of_tan_half(q(i)), Angle.of_tan_half(q(o))) for i, o in zip(inputs, outputs)]


KNOWN = dict(crank=q(2, 5), coupler=q(7, 5), rocker=q(1), ground=q(6, 5))
"""A Grashof crank-rocker whose five positions give the five-pair set (starts unknown)."""
KNOWN_START = "1/4"   # the crank's start, by its half-angle tangent
KNOWN_OFFSETS = [0, "1/6", "1/3", "1/2", "2/3"]
OUTPUT_DIGITS = 20   # the rocker's offsets rounded so: its pairs are the four-bar's within 1e-19


def _rocker_angle(phi):
    """The known four-bar's rocker angle with its crank at ``phi`` (one assembly mode): the
    rocker's end on the circle about (ground, 0) and at the coupler's length from the crank's end."""
    a, b, c, d = (_mpf(KNOWN[k]) for k in ("crank", "coupler", "rocker", "ground"))
    ax, ay = a * mpmath.cos(phi), a * mpmath.sin(phi)
    dx, dy = d - ax, -ay
    distance = mpmath.hypot(dx, dy)
    along = (b**2 - c**2 + distance**2) / (2 * distance)
    across = mpmath.sqrt(b**2 - along**2)
    bx, by = ax + (along * dx - across * dy) / distance, ay + (along * dy + across * dx) / distance
    return mpmath.atan2(by, bx - d)


def _half_tangent(radians):
    """The angle whose half-angle tangent is the decimal of OUTPUT_DIGITS digits next to tan(radians / 2)."""
    scale = 10**OUTPUT_DIGITS
    return Angle.of_tan_half(q(int(mpmath.nint(mpmath.tan(radians / 2) * scale)), scale))


def _known_five():
    """The known four-bar's five pairs as offsets from its starts (exact inputs, rounded outputs),
    and its absolute angles in radians (what pylinkage needs)."""
    with mpmath.workdps(80):
        start = _radians(Angle.of_tan_half(q(KNOWN_START)), precise=True)
        offsets = [Angle.of_tan_half(q(t)) for t in KNOWN_OFFSETS]
        phis = [start + _radians(o, precise=True) for o in offsets]
        psis = [_rocker_angle(phi) for phi in phis]
        pairs = [AnglePair(o, _half_tangent(psi - psis[0])) for o, psi in zip(offsets, psis)]
        return pairs, [(float(phi), float(psi)) for phi, psi in zip(phis, psis)]


FIVE, FIVE_ABSOLUTE = _known_five()
THREE = _pairs([-1, "1/3", 1], [-1, 0, 2])
FUNCTION_SETS = {   # name: (pairs, unknown starts, ground, what pylinkage is given in radians)
    "three pairs": (THREE, False, 1, None),
    "three pairs, crank read from its other end": (_pairs([1, -3, -1], [-1, 0, 2]), False, 1, None),
    "five pairs, offsets (pylinkage: as absolute)": (FIVE, True, KNOWN["ground"], None),
    "five pairs, offsets (pylinkage: the true starts)": (FIVE, True, KNOWN["ground"], FIVE_ABSOLUTE),
}


# ---------------------------------------------------------------- Burmester

def _pair_reaches_every_pose(pair, poses):
    """The circle point placed in each pose at one distance from the centre, in narrow balls."""
    with flint.ctx.workprec(BITS + 64):
        x, y = pair.circle
        big_x, big_y = pair.centre
        # not ** 2: python-flint's arb ** 2 is nan on a ball about 0
        squares = [(px - big_x) * (px - big_x) + (py - big_y) * (py - big_y)
                   for px, py in (pose.place(x, y) for pose in poses)]
        return all(_narrow(s) and s.overlaps(squares[0]) for s in squares)


def _float_poses(poses):
    return [(float(p.x), float(p.y), float(p.angle.cos), float(p.angle.sin)) for p in poses]


def _dyad_residuals(v, poses):
    """Pose i's squared distance minus the first's (i = 2..5) at v = (X, Y, x, y), and the Jacobian."""
    centre, circle = v[:2], v[2:]
    rotations = [np.array([[c, -s], [s, c]]) for _, _, c, s in poses]
    placed = [np.array([px, py]) + r @ circle for (px, py, _, _), r in zip(poses, rotations)]
    f = np.array([(p - centre) @ (p - centre) - (placed[0] - centre) @ (placed[0] - centre) for p in placed[1:]])
    first = 2 * rotations[0].T @ (placed[0] - centre)
    jac = np.array([np.concatenate([-2 * (p - placed[0]), 2 * r.T @ (p - centre) - first])
                    for p, r in zip(placed[1:], rotations[1:])])
    return f, jac


def _newton(start, poses, *, scale, steps=60):
    """Newton's method on the dyad equations from ``start``: the solution it reaches, or None."""
    v = np.array(start, dtype=float)
    for _ in range(steps):
        f, jac = _dyad_residuals(v, poses)
        try:
            step = np.linalg.solve(jac, f)
        except np.linalg.LinAlgError:
            return None
        v = v - step
        if not np.all(np.isfinite(v)) or np.linalg.norm(v) > 1e6 * scale:
            return None
        if np.linalg.norm(step) < 1e-13 * (scale + np.linalg.norm(v)):
            return v
    return None


def _pylinkage_dyads(curves, first):
    """pylinkage's candidates as (centre, circle point in the moving frame): it gives the
    circle point where it is in the first pose."""
    origin, turn = complex(float(first.x), float(first.y)), _radians(first.angle)
    return [(centre, (circle - origin) * cmath.exp(-1j * turn))
            for circle, centre in zip(curves.circle_curve, curves.center_curve)]


def _algkin_dyads(found):
    return [(complex(_mid(p.centre[0]), _mid(p.centre[1])), complex(_mid(p.circle[0]), _mid(p.circle[1])))
            for p in found.pairs]


def _nearest(candidate, references, distance):
    """The index of the reference nearest ``candidate`` and its distance (None, inf without references)."""
    distances = [distance(candidate, reference) for reference in references]
    return min(enumerate(distances), key=lambda item: item[1], default=(None, math.inf))


def _dyad_distance(one, other):
    return max(abs(one[0] - other[0]), abs(one[1] - other[1]))


def _scale(poses):
    return max(math.dist((float(a.x), float(a.y)), (float(b.x), float(b.y))) for a in poses for b in poses)


def compare_burmester(name, poses, pylinkage, repeat):
    """Print one pose set's comparison; return its summary row."""
    pylinkage_poses = [pylinkage.Pose(float(p.x), float(p.y), _radians(p.angle)) for p in poses]
    curves, pylinkage_time = _timed(lambda: pylinkage.compute_circle_point_curve(pylinkage_poses), repeat)
    found, algkin_time = _timed(lambda: burmester(poses, bits=BITS), repeat)
    assert all(_pair_reaches_every_pose(pair, poses) for pair in found.pairs), f"{name}: a pair misses a pose"
    assert len(found.pairs) <= found.complex_count <= 4, f"{name}: counts {len(found.pairs)}, {found.complex_count}"
    reference, candidates, scale = _algkin_dyads(found), _pylinkage_dyads(curves, poses[0]), _scale(poses)
    print(f"\nmotion: {name} (5 poses, scale {scale:.3g}; a match within {BURMESTER_MATCH} x scale)")
    _print_times(pylinkage_time, algkin_time)
    fourbars = pylinkage.motion_generation(pylinkage_poses, max_solutions=None, require_grashof=False).raw_solutions
    print(f"  algkin: {_count(len(found.pairs), 'real pair')} of {found.complex_count} complex; pylinkage: "
          f"{_count(len(candidates), 'candidate dyad')} (its motion_generation makes "
          f"{_count(len(fourbars), 'four-bar')} of them)")
    matched = _report_matches(reference, candidates, scale=scale, poses=_float_poses(poses))
    return dict(set=name, algkin=f"{len(found.pairs)} of {found.complex_count}", pylinkage=len(candidates),
                **matched, pylinkage_time=pylinkage_time, algkin_time=algkin_time)


def _report_matches(reference, candidates, *, scale, poses):
    """Print algkin's pairs (found or missed by pylinkage, with the error) and pylinkage's extra
    candidates (where Newton's method takes them); assert none refines to a pair algkin lacks."""
    nearest = [_nearest(c, reference, _dyad_distance) for c in candidates]
    errors = []
    for k, (centre, circle) in enumerate(reference):
        hits = [candidates[i] for i, (j, d) in enumerate(nearest) if j == k and d <= BURMESTER_MATCH * scale]
        label = f"  pair {k + 1}: centre {_point(centre, 6)}, circle {_point(circle, 6)}"
        if not hits:
            print(f"{label}: missed")
            continue
        best = min(hits, key=lambda c: _dyad_distance(c, (centre, circle)))
        errors.append(_dyad_distance(best, (centre, circle)))
        print(f"{label}: found, error centre {abs(best[0] - centre):.1e}, circle {abs(best[1] - circle):.1e}"
              + (f" ({len(hits)} candidates)" if len(hits) > 1 else ""))
    extra = [c for c, (j, d) in zip(candidates, nearest) if d > BURMESTER_MATCH * scale]
    for centre, circle in extra:
        print(f"  extra: centre {_point(centre, 4)}, circle {_point(circle, 4)}: "
              + _refined(centre, circle, reference, scale=scale, poses=poses))
    return dict(matched=len(errors), missed=len(reference) - len(errors), extra=len(extra),
                error=max(errors, default=None))


def _refined(centre, circle, reference, *, scale, poses):
    """Where Newton's method from a candidate goes; an AssertionError if to a pair algkin lacks."""
    solution = _newton([centre.real, centre.imag, circle.real, circle.imag], poses, scale=scale)
    if solution is None:
        return "Newton from it reaches no solution"
    index, distance = _nearest((complex(*solution[:2]), complex(*solution[2:])), reference, _dyad_distance)
    assert distance <= 1e-6 * scale, f"Newton reaches a pair algkin does not have: {solution}"
    return f"Newton from it reaches pair {index + 1}"


# ---------------------------------------------------------------- Freudenstein

def _turn(one, other, sign=1):
    """The angle ``one`` turned by ``other`` (by minus ``other`` when ``sign`` is -1), as (cos, sin)."""
    (c1, s1), (c2, s2) = one, (other[0], sign * other[1])
    return c1 * c2 - s1 * s2, s1 * c2 + c1 * s2


def _closes_the_loop(solution, pairs):
    """At each pair (the solution's starts turned by the pair's offset from the first), the crank's
    end and the rocker's are the coupler's length apart, in narrow balls."""
    with flint.ctx.workprec(BITS + 64):
        lengths = (solution.crank, solution.rocker, solution.ground, solution.coupler_squared)
        a, c, d, b2 = (flint.arb(x) for x in lengths)
        first_input, first_output = _cos_sin(pairs[0].input), _cos_sin(pairs[0].output)
        for pair in pairs:
            phi = _turn(solution.start_input, _turn(_cos_sin(pair.input), first_input, -1))
            psi = _turn(solution.start_output, _turn(_cos_sin(pair.output), first_output, -1))
            dx, dy = a * phi[0] - d - c * psi[0], a * phi[1] - c * psi[1]
            gap = dx * dx + dy * dy   # not ** 2: python-flint's arb ** 2 is nan on a ball about 0
            if not (_narrow(gap) and gap.overlaps(b2)):
                return False
        return True


def _algkin_fourbars(found):
    """Each solution as (crank, coupler, rocker, start input, start output), lengths and radians."""
    return [(_mid(s.crank), _mid(s.coupler), _mid(s.rocker),
             math.atan2(_mid(s.start_input[1]), _mid(s.start_input[0])),
             math.atan2(_mid(s.start_output[1]), _mid(s.start_output[0]))) for s in found.solutions]


def _pylinkage_fourbars(result, radians):
    """pylinkage's four-bars, the same way: its starts are the first pair's angles as given."""
    return [(s.crank_length, s.coupler_length, s.rocker_length, *radians[0]) for s in result.raw_solutions]


def _fourbar_distance(one, other):
    turns = [abs(math.remainder(x - y, math.tau)) for x, y in zip(one[3:], other[3:])]
    return max([abs(x - y) for x, y in zip(one[:3], other[:3])] + turns)


def compare_freudenstein(name, spec, pylinkage, repeat):
    """Print one set of pairs' comparison; return its summary row."""
    pairs, unknown_start, ground, given = spec
    radians = given or [(_radians(p.input), _radians(p.output)) for p in pairs]
    result, pylinkage_time = _timed(lambda: pylinkage.function_generation(
        radians, ground_length=float(ground), require_grashof=False), repeat)
    found, algkin_time = _timed(lambda: freudenstein(pairs, unknown_start=unknown_start, ground=ground, bits=BITS),
                                repeat)
    assert all(_closes_the_loop(s, pairs) for s in found.solutions), f"{name}: a four-bar misses a pair"
    reference, candidates = _algkin_fourbars(found), _pylinkage_fourbars(result, radians)
    tolerance = FREUDENSTEIN_MATCH * float(ground)
    print(f"\nfunction: {name} ({len(pairs)} pairs, ground {float(ground):g}; a match within {FREUDENSTEIN_MATCH:g})")
    _print_times(pylinkage_time, algkin_time)
    print(f"  algkin: {_count(len(reference), 'four-bar')} ({found.real_count} real of {found.complex_count} complex "
          f"solutions); pylinkage: {_count(len(candidates), 'four-bar')}"
          + "".join(f"; it says: {w}" for w in result.warnings))
    nearest = [_nearest(c, reference, _fourbar_distance) for c in candidates]
    errors = []
    for k, bar in enumerate(reference):
        hit = min((d for j, d in nearest if j == k), default=math.inf)
        label = (f"  four-bar {k + 1}: crank {bar[0]:.6g}, coupler {bar[1]:.6g}, rocker {bar[2]:.6g}, "
                 f"starts {math.degrees(bar[3]):.4f}, {math.degrees(bar[4]):.4f} deg")
        if hit <= tolerance:
            errors.append(hit)
        print(f"{label}: " + (f"found, error {hit:.1e}" if hit <= tolerance else "missed"))
    extra = [c for c, (j, d) in zip(candidates, nearest) if d > tolerance]
    for bar in extra:
        print(f"  extra: crank {bar[0]:.6g}, coupler {bar[1]:.6g}, rocker {bar[2]:.6g}")
    return dict(set=name, algkin=f"{len(reference)} of {found.complex_count}", pylinkage=len(candidates),
                matched=len(errors), missed=len(reference) - len(errors), extra=len(extra),
                error=max(errors, default=None), pylinkage_time=pylinkage_time, algkin_time=algkin_time)


# ---------------------------------------------------------------- the run

def summary(rows):
    print("\n| set | algkin: real of complex | pylinkage candidates | matched | missed | extra | largest error "
          "| pylinkage | algkin | algkin / pylinkage |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        error = "" if r["error"] is None else f"{r['error']:.1e}"
        print(f"| {r['set']} | {r['algkin']} | {r['pylinkage']} | {r['matched']} | {r['missed']} | {r['extra']} "
              f"| {error} | {_seconds(r['pylinkage_time'])} | {_seconds(r['algkin_time'])} "
              f"| {_ratio(r['algkin_time'], r['pylinkage_time'])} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=5, help="calls timed per solver and set (the best counts)")
    args = parser.parse_args()
    try:
        from pylinkage import synthesis as pylinkage
    except ImportError as missing:
        print(f"pylinkage's synthesis is not installed ({missing}; pip install 'algkin[compare]'): skipped")
        return 0
    print(f"pylinkage {version('pylinkage')}, algkin {version('algkin')}; each time the best of {args.repeat} calls")
    rows = [compare_burmester(name, poses, pylinkage, args.repeat) for name, poses in MOTION_SETS.items()]
    rows += [compare_freudenstein(name, spec, pylinkage, args.repeat) for name, spec in FUNCTION_SETS.items()]
    summary(rows)
    return 0


if __name__ == "__main__":
    sys.exit(main())
