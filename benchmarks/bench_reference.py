"""The certified reference of ``algkin accuracy``: per-sample time, before and after, in one run.

Three ways to the truth at the same float64 angles of an output of a scene (a dyad point, a
frame point, a point on a dyad on a dyad), each at 200 bits:

- ``mpmath``: the reference ``accuracy`` had first: the branch's closed form evaluated in
  mpmath at 61 digits, the condition number by a central difference (three evaluations);
  fast to write, but not independent of the closed forms it judges;
- ``scalar arb``: the reference that replaced it: per sample, Newton on the original equations
  in python-flint ``arb`` with ``arb_mat`` solves, one Krawczyk step proving a unique root in
  a small box, the label's signs decided on the enclosure, the condition number from the
  Jacobian (re-implemented here as it was, so that it can be timed beside the others);
- ``vectorised``: ``algkin.bench.reference.Reference``, the same proof with every sample in numpy
  arrays of balls, so that Python's overhead is paid per batch, not per sample.

Times are medians of repeats after a warm-up (one repeat for the slow two); ratios are the
others' time over the vectorised one's. The run asserts that the three agree: the
vectorised enclosures' midpoints within 1e-30 (relative) of the mpmath values and of the
scalar arb enclosures, the floats identical.

Run: ``python benchmarks/bench_reference.py [--samples N] [--scenes SCENE:OUTPUT ...]``.
"""

import argparse

import mpmath
import numpy as np
import sympy
from flint import arb, arb_mat, ctx

from algkin.branches import closed_forms
from algkin.evaluate import MPMATH, evaluate
from algkin.bench.reference import BITS, Reference
from algkin.scene import compile_scene, load_scene
from bench_evaluation import timed  # the same median-of-runs timer (this directory is on sys.path)

# (scene, output): a dyad point, then a frame point on one, then points on a dyad on a dyad
SCENES = (("chebyshev-lambda", "B"), ("fourbar", "B"), ("fourbar-near-toggle", "B"), ("chebyshev-lambda", "P"),
          ("stephenson-iii", "F"), ("watt-i", "P"))
AGREE = 1e-30  # relative: far below float64, far above 200 bits


def mpmath_reference(branch, cs, unknowns, theta):
    """The closed form at 61 digits (200 bits), kappa by a central difference: ``(points, kappas)``."""
    c, s = cs
    at = lambda a: [evaluate(branch.values[u], {c: mpmath.cos(a), s: mpmath.sin(a)}, MPMATH)  # noqa: E731
                    for u in unknowns]
    points, kappas = [], []
    with mpmath.workdps(61):
        step = mpmath.mpf(10) ** -25
        for angle in theta:
            a = mpmath.mpf(float(angle))
            x = at(a)
            slope = [(p - q) / (2 * step) for p, q in zip(at(a + step), at(a - step))]
            size = mpmath.sqrt(sum(v * v for v in x))
            kappas.append(float(abs(a) * mpmath.sqrt(sum(v * v for v in slope)) / size) + 1)
            points.append(x)
    return points, kappas


class ScalarReference:
    """The per-sample arb reference, as ``algkin.bench.reference`` had it before it was vectorised."""

    def __init__(self, reference):
        arguments = reference.unknowns + list(reference.cs)
        self.f = _arb_function(reference.equations, arguments)
        self.j = _arb_function(sympy.Matrix(reference.equations).jacobian(arguments), arguments)
        self.signs = _arb_function(reference.indicators, arguments)
        self.expected, self.n, self.outputs = reference.expected, len(reference.unknowns), reference.outputs
        self.start = reference.start

    def __call__(self, theta):
        starts = self.start(theta)
        with ctx.workprec(BITS):
            return [self.one(float(angle), starts[:, k]) for k, angle in enumerate(theta)]

    def one(self, angle, start):
        a = arb(angle)
        cs = (a.cos(), a.sin())
        root = self._krawczyk(self._newton([arb(v) for v in start], cs), cs)
        if not self._labelled(root, cs):
            mirror = [arb(2 * float(v) - float(r.mid())) for v, r in zip(start, root)]
            root = self._krawczyk(self._newton(mirror, cs), cs)
            assert self._labelled(root, cs), angle
        return root, self._kappa(root, a, cs)

    def _labelled(self, root, cs):
        return all(v > 0 if e else v < 0 for v, e in zip(self.signs(*root, *cs), self.expected))

    def _jacobian(self, x, cs):
        return arb_mat(self.n, self.n + 2, self.j(*x, *cs))

    def _newton(self, x, cs):
        size = max(abs(float(v)) for v in x) or 1.0
        for _ in range(80):
            step = _columns(self._jacobian(x, cs), self.n).solve(arb_mat(self.n, 1, self.f(*x, *cs)))
            x = [arb((x[i] - step[i, 0]).mid()) for i in range(self.n)]
            if max(abs(float(step[i, 0].mid())) for i in range(self.n)) < 2.0**-160 * size:
                break
        return x

    def _krawczyk(self, x, cs):
        size = max(abs(float(v.mid())) for v in x) or 1.0
        box = [v + arb(0, 2.0**-140 * size) for v in x]
        y = _columns(self._jacobian(x, cs), self.n).mid().inv().mid()
        over = _columns(self._jacobian(box, cs), self.n)
        spread = arb_mat(self.n, 1, [b - v for b, v in zip(box, x)])
        identity = arb_mat([[int(i == j) for j in range(self.n)] for i in range(self.n)])
        k = arb_mat(self.n, 1, x) - y * arb_mat(self.n, 1, self.f(*x, *cs)) + (identity - y * over) * spread
        root = [k[i, 0] for i in range(self.n)]
        assert all(b.contains_interior(r) for b, r in zip(box, root))
        return root

    def _kappa(self, root, angle, cs):
        jac = self._jacobian(root, cs)
        c, s = cs
        moved = arb_mat(self.n, 1, [-s * jac[i, self.n] + c * jac[i, self.n + 1] for i in range(self.n)])
        slope = _columns(jac, self.n).solve(-moved)
        rate = sum(slope[i, 0] ** 2 for i in self.outputs).sqrt()
        size = sum(root[i] ** 2 for i in self.outputs).sqrt()
        return float((abs(angle) * rate / size).mid()) + 1


def _arb_function(exprs, arguments):
    """``exprs`` over scalar ``arb``, each non-integer rational an exact quotient made at call time."""
    exprs = [sympy.sympify(e) for e in exprs]
    rationals = sorted({r for e in exprs for r in e.atoms(sympy.Rational) if not r.is_Integer}, key=str)
    names = [sympy.Dummy() for _ in rationals]
    body = sympy.lambdify(list(arguments) + names, [e.xreplace(dict(zip(rationals, names))) for e in exprs],
                          modules=[{"sqrt": lambda v: v.sqrt()}])
    return lambda *values: body(*values, *(arb(int(r.p)) / int(r.q) for r in rationals))


def _columns(matrix, n):
    return arb_mat([[matrix[i, j] for j in range(n)] for i in range(matrix.nrows())])


def _relative(a, b, size):
    return float(abs(a - b) / size)


def bench(name, output, samples, repeats):
    compiled = compile_scene(load_scene(name), [output])
    branch = next(b for b in closed_forms(compiled) if b.selected)
    (unknowns,) = compiled.outputs.values()
    reference = Reference(compiled, branch, unknowns)
    theta = np.sort(np.random.default_rng(0).uniform(0, 2 * np.pi, samples))
    cs = next(iter(compiled.system.inputs.values()))
    (exact, _), mpmath_seconds = timed(lambda: mpmath_reference(branch, cs, unknowns, theta), 1)
    scalar_reference = ScalarReference(reference)
    scalar, scalar_seconds = timed(lambda: scalar_reference(theta), 1)
    new, new_seconds = timed(lambda: reference.certify(theta), repeats)
    assert new.ok.all()
    worst = 0.0
    with mpmath.workdps(61), ctx.workprec(BITS):
        for k in range(samples):
            size = mpmath.sqrt(sum(v * v for v in exact[k]))
            for i, unknown in enumerate(reference.outputs):
                ball = new.roots[k, unknown]
                mid = mpmath.mpf(ball.mid().str(70, radius=False))
                worst = max(worst, _relative(mid, exact[k][i], size))
                assert (scalar[k][0][unknown] - ball).abs_upper() < AGREE * float(size)
    assert worst < AGREE, worst
    assert np.array_equal(new.points, np.array([[float(r[0][i].mid()) for r in scalar] for i in reference.outputs]))
    assert np.allclose(new.kappas, [r[1] for r in scalar], rtol=1e-6)
    per = lambda seconds: seconds / samples * 1e6  # noqa: E731
    return {"scene": f"{name} {output}", "samples": samples, "mpmath_us": per(mpmath_seconds),
            "scalar_us": per(scalar_seconds), "vectorised_us": per(new_seconds),
            "mpmath_ratio": mpmath_seconds / new_seconds, "scalar_ratio": scalar_seconds / new_seconds,
            "agreement": worst}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--samples", type=int, default=200)
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--scenes", nargs="+", metavar="SCENE:OUTPUT",
                        default=[f"{name}:{output}" for name, output in SCENES])
    args = parser.parse_args()
    print(f"{'scene, output':22} {'samples':>7} {'mpmath us':>10} {'scalar arb us':>13} {'vectorised us':>13} "
          f"{'mpmath/vect':>11} {'scalar/vect':>11} {'|vect - mpmath| (rel)':>22}")
    for pair in args.scenes:
        r = bench(*pair.split(":"), args.samples, args.repeats)
        print(f"{r['scene']:22} {r['samples']:7} {r['mpmath_us']:10.1f} {r['scalar_us']:13.1f} "
              f"{r['vectorised_us']:13.1f} {r['mpmath_ratio']:10.0f}x {r['scalar_ratio']:10.1f}x "
              f"{r['agreement']:22.1e}")


if __name__ == "__main__":
    main()
