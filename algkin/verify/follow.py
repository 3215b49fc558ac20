"""Certified continuation: one real solution of polynomial equations followed along an input.

The equations ``F(x, t) = 0`` hold ``n`` unknowns ``x`` and one input ``t``: an angle, entering
through its cosine and sine (``t`` in degrees outside, radians in the balls), or a length. From a
solution at ``t0``, each step to ``tb = ta + h`` is a float predictor (the tangent ``dx/dt =
-J^-1 dF/dt``, then Newton at ``tb`` and at the step's middle) and a proof in python-flint balls:
the path is sheared straight, ``x = y + (t - tm) v`` with ``v`` the step's secant, and the
Krawczyk operator of ``y -> F(y + (t - tm) v, t)``, evaluated over the step's whole interval ``T``
and a box ``B`` around the predicted ``y``,

    K = c - Y G(c, T) + (I - Y J(B + (T - tm) v, T)) (B - c),

lies inside ``B``: then for every ``t`` in the step there is exactly one solution in ``B``'s
sheared section, and ``J`` is regular there, so the solutions form one smooth path through the step. ``G`` and ``J`` along the line are
bounded to second order in ``t - tm`` (the first derivatives at the middle point, the second over
the step, each multiplied by ``Y`` before the interval of ``t - tm``): ``Y`` keeps its cancellations,
so a step stays long next to a toggle, where ``Y`` is large. Each step's end is enclosed on its
own (``BlockCertifier``) and checked inside both steps' sections at that ``t``: the path cannot
jump to another root, at any step size. A failed proof halves the step, a success doubles it
(up to ``max_step``); a step below ``min_step`` stops the path where it meets another solution (a
toggle): the fold itself, the solution where ``J`` is singular, is then proved in balls when it is
a simple one (``F = 0, J w = 0, l.w = 1`` solved with ``t`` as an unknown), and the meeting is
reported with its input interval and ``det J`` over it (a ball holding 0), never crossed.

>>> import sympy
>>> from fractions import Fraction
>>> from algkin.system import symbol
>>> x, c = symbol("x"), symbol("c")
>>> around = Follower(["x"], [x**2 - 2 - c], ("c", "s"))   # x = sqrt(2 + cos t): never singular
>>> path = around.follow([3**0.5], Fraction(0), Fraction(360))
>>> path.meeting is None, path.samples[-1].t, path.samples[-1].values["x"].overlaps(flint.arb(3).sqrt())
(True, Fraction(360, 1), True)
>>> folding = Follower(["x"], [x**2 - c], ("c", "s"))      # x = sqrt(cos t): meets -x at 90 degrees
>>> meeting = folding.follow([1.0], Fraction(0), Fraction(180)).meeting
>>> meeting.lo <= 90 <= meeting.hi, meeting.fold, meeting.determinant.contains(0)
(True, True, True)
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from fractions import Fraction
from typing import Any

import attrs
import flint
import numpy as np
import sympy
from flint import arb, arb_mat
from numpy.typing import NDArray

from ..errors import BudgetExceeded, ComputationError
from ..evaluate import ARB, FLOAT
from ..evaluate.program import compile_program
from ..runtime.budget import Deadline
from ..runtime.frozen import FrozenDict, frozen
from ..system import symbol
from .balls import BlockCertifier

__all__ = ["Follower", "Path", "Sample", "Meeting", "BITS"]

BITS = 128  # working precision: ends enclosed to about 30 digits
STEPS = 8  # default largest step: the span over this
MIN_STEP = 2.0**-36  # default smallest step, relative to the span: below it the path meets another
NEWTON = 12  # float Newton iterations before a predictor is given up
SETTLED = 1e-9  # a float Newton move this small (relative) after NEWTON iterations: settled
INFLATIONS = 3  # tube radii tried per step, each 4 times the last

Floats = NDArray[np.float64]


@attrs.frozen
class Sample:
    """The path at the input ``t`` (exact; degrees for an angle): each unknown's enclosure."""

    t: Fraction
    values: FrozenDict[str, arb] = attrs.field(converter=frozen, eq=False, repr=False)


@attrs.frozen
class Meeting:
    """Where the path stops: it meets another solution (a toggle) for an input in [``lo``, ``hi``];
    ``determinant``, ``det J`` there, holds 0; ``fold``: the meeting point itself was proved in balls
    (a simple fold), else [``lo``, ``hi``] is only where the proof could go no further."""

    lo: Fraction
    hi: Fraction
    determinant: arb = attrs.field(eq=False)
    fold: bool


@attrs.frozen
class Path:
    """A solution followed: its ``samples`` (the proven steps' ends, the start first), ``steps``
    proven, and ``meeting`` (None: the end was reached)."""

    names: tuple[str, ...]
    samples: tuple[Sample, ...]
    steps: int
    meeting: Meeting | None


class Follower:
    """Follows solutions of ``equations`` in the unknowns ``names`` along the input whose variables
    are ``variables`` (an angle's cosine and sine, or a length), ``parameters`` fixed balls."""

    def __init__(self, names: Sequence[str], equations: Sequence[sympy.Expr], variables: tuple[str, ...],
                 parameters: Sequence[str] = ()) -> None:
        self.names, self.variables, self.parameters = tuple(names), variables, tuple(parameters)
        self.n = len(names)
        self.angle = len(variables) == 2
        unknowns = [symbol(n) for n in names]
        jacobian = sympy.Matrix(list(equations)).jacobian(unknowns)
        rate = [self._rate(e) for e in equations]
        # F and J along the sheared path y + (t - tm) v, to second order in t (v per radian for an
        # angle): the first derivatives at the step's middle point, the second over the whole step,
        # and J's own derivatives in x (F's second) for the box around the path
        slope = [symbol(f"follow_v{k}") for k in range(self.n)]
        entries = list(equations) + list(jacobian)
        along = [self._along(e, unknowns, slope) for e in entries]
        bend = [self._along(a, unknowns, slope) for a in along]
        second = [sympy.diff(e, u) for u in unknowns for e in jacobian]
        arguments = list(names) + list(variables) + list(parameters)
        self.equations, self.jacobian_matrix = list(equations), jacobian
        self.floats = (compile_program(list(equations), arguments, FLOAT),
                       compile_program(list(jacobian), arguments, FLOAT), compile_program(rate, arguments, FLOAT))
        self.residual = compile_program(list(equations), arguments, ARB)
        self.jacobian = compile_program(list(jacobian), arguments, ARB)
        with_slope = arguments + [str(v) for v in slope]
        self.along = compile_program(along, with_slope, ARB)
        self.bend = compile_program(bend, with_slope, ARB)
        self.second = compile_program(second, arguments, ARB)
        self.point = BlockCertifier(names, equations, list(variables) + list(parameters))
        self._fold: Fold | None = None

    def _along(self, expr: sympy.Expr, unknowns: Sequence[sympy.Symbol], slope: Sequence[sympy.Symbol]) -> sympy.Expr:
        """d/dt of ``expr`` at ``x = y + (t - tm) slope``."""
        return sum((sympy.diff(expr, u) * v for u, v in zip(unknowns, slope)), self._rate(expr))

    def _rate(self, expr: sympy.Expr) -> sympy.Expr:
        """d/dt of ``expr`` through the input's variables (t in radians for an angle: d cos = -sin, d sin = cos)."""
        if self.angle:
            c, s = (symbol(v) for v in self.variables)
            return sympy.diff(expr, c) * -s + sympy.diff(expr, s) * c
        return sympy.diff(expr, symbol(self.variables[0]))

    def follow(self, start: Sequence[float], t0: Fraction, t1: Fraction, *, known: Sequence[arb] = (),
               max_step: Fraction | None = None, min_step: Fraction | None = None,
               deadline: Deadline | None = None, bits: int = BITS) -> Path:
        """The solution next to ``start`` at ``t0`` followed to ``t1`` (or to where it meets another),
        ``known`` the parameters' balls. ComputationError when ``start`` is no regular solution;
        BudgetExceeded past ``deadline``."""
        span = abs(t1 - t0)
        largest = max_step if max_step is not None else span / STEPS
        smallest = min_step if min_step is not None else span * Fraction(MIN_STEP)
        direction = 1 if t1 >= t0 else -1
        with flint.ctx.workprec(bits):
            track = _Track(self, [arb(k) for k in known])
            x = track.newton(np.array(start, dtype=float), t0)
            enclosure = None if x is None else track.enclose(x, t0)
            if x is None or enclosure is None:
                raise ComputationError(f"the start {list(start)} at {t0} is not proved to be next to a regular solution "
                                       "(modes meet there, at a toggle?): start a little away from it")
            samples = [Sample(t0, dict(zip(self.names, enclosure)))]
            h, t = min(largest, span), t0
            while t != t1:
                _check(deadline)
                h = min(h, abs(t1 - t))
                stepped = track.step(x, enclosure, t, t + direction * h)
                if stepped is not None:
                    t, (x, enclosure) = t + direction * h, stepped
                    samples.append(Sample(t, dict(zip(self.names, enclosure))))
                    h = min(2 * h, largest)
                elif h / 2 >= smallest:
                    h /= 2
                else:
                    meeting = track.meeting(x, enclosure, t, t + direction * h, t1)
                    return Path(self.names, tuple(samples), len(samples) - 1, meeting)
        return Path(self.names, tuple(samples), len(samples) - 1, None)

    def fold(self) -> Fold:
        """The fold system of these equations, built when a path first stops."""
        if self._fold is None:
            self._fold = Fold(self)
        return self._fold


def _check(deadline: Deadline | None) -> None:
    """BudgetExceeded once ``deadline`` has passed (checked before each step)."""
    left = None if deadline is None else deadline.left()
    if deadline is not None and left is not None and left <= 0:
        seconds = deadline.budget.seconds
        elapsed = deadline.budget.clock() - deadline.begun
        raise BudgetExceeded(f"max_seconds={seconds:g}: stopped after {elapsed:.2f} s while following a mode")


class _Track:
    """One path's arithmetic at the working precision: floats for the predictor, balls for the proofs."""

    def __init__(self, follower: Follower, known: list[arb]) -> None:
        self.f = follower
        self.known = known
        self.known_floats = [float(k.mid()) for k in known]
        self.unit = arb.pi() / 180 if follower.angle else arb(1)  # radians per degree

    # the input's variables
    def inputs(self, t: arb) -> list[arb]:
        if self.f.angle:
            radians = t * self.unit
            return [radians.cos(), radians.sin()]
        return [t]

    def float_inputs(self, t: float) -> list[float]:
        return [math.cos(math.radians(t)), math.sin(math.radians(t))] if self.f.angle else [t]

    # floats
    def float_parts(self, x: Floats, t: float) -> tuple[Floats, Floats, Floats]:
        residual, jacobian, rate = self.f.floats
        arguments = [*map(float, x), *self.float_inputs(t), *self.known_floats]
        unit = math.pi / 180 if self.f.angle else 1.0
        return (np.array(residual(*arguments), dtype=float),
                np.array(jacobian(*arguments), dtype=float).reshape(self.f.n, self.f.n),
                np.array(rate(*arguments), dtype=float) * unit)

    def newton(self, x: Floats, t: Fraction) -> Floats | None:
        """The float solution at ``t`` next to ``x``, or None when Newton's method does not settle
        (near a fold, rounding keeps the last moves at ``J``'s condition times 1e-16: the balls decide)."""
        return _newton(lambda y: self.float_parts(y, float(t))[:2], x, NEWTON, settled=SETTLED)

    def tangent(self, x: Floats, t: Fraction) -> Floats | None:
        _, jacobian, rate = self.float_parts(x, float(t))
        try:
            tangent: Floats = -np.linalg.solve(jacobian, rate).astype(np.float64)
        except np.linalg.LinAlgError:
            return None
        return tangent

    # balls
    def enclose(self, x: Floats, t: Fraction) -> list[arb] | None:
        """The solution next to ``x`` at ``t`` proved unique in a small box, in balls."""
        return self.f.point(x.tolist(), self.inputs(_ball(t)) + self.known)

    def step(self, x: Floats, enclosure: list[arb], ta: Fraction, tb: Fraction) -> tuple[Floats, list[arb]] | None:
        """The path from ``enclosure`` at ``ta`` proved to ``tb``: the float solution and enclosure there, or None."""
        h = float(tb - ta)
        tangent = self.tangent(x, ta)
        if tangent is None:
            return None
        end = self.newton(x + h * tangent, tb)
        middle = None if end is None else self.newton((x + end) / 2, (ta + tb) / 2)
        if end is None or middle is None:
            return None
        closing = self.enclose(end, tb)
        if closing is None:
            return None
        slope = (end - x) / h
        centre = middle + ((x + end) / 2 - middle) / 2  # between the chord and the path's middle
        scale = 1 + float(np.max(np.abs(centre)))
        radius = max(float(np.max(np.abs(middle - (x + end) / 2))), 1e-12 * scale)
        for _ in range(INFLATIONS):
            if self.tube(centre, radius, slope, (ta, enclosure), (tb, closing)):
                return end, closing
            radius *= 4
        return None

    def tube(self, centre: Floats, radius: float, slope: Floats, start: tuple[Fraction, list[arb]],
             end: tuple[Fraction, list[arb]]) -> bool:
        """Whether the Krawczyk test proves one solution in each section of the sheared box
        ``centre +- radius + (t - tm) slope`` for every ``t`` between the ends, each end's enclosure in its section."""
        (ta, at_start), (tb, at_end) = start, end
        residual, jacobian = self.f.residual, self.f.jacobian
        n = self.f.n
        tm = (ta + tb) / 2
        offset = _ball(tm, abs(tb - ta) / 2) - _ball(tm)  # t - tm over the step
        c = [arb(float(v)) for v in centre]
        v = [arb(float(s)) for s in slope]
        box = [ci + arb(0, radius) for ci in c]
        sections = [(at_start, _ball(ta) - _ball(tm)), (at_end, _ball(tb) - _ball(tm))]
        if not all(b.contains(e - d * vi) for enclosure, d in sections for b, e, vi in zip(box, enclosure, v)):
            return False
        inputs = self.inputs(_ball(tm, abs(tb - ta) / 2))
        at_middle = [*c, *self.inputs(_ball(tm)), *self.known]
        tube = [b + offset * vi for b, vi in zip(box, v)]
        line = [ci + offset * vi for ci, vi in zip(c, v)]
        _, float_jacobian, _ = self.float_parts(centre, float(tm))
        try:
            inverse = arb_mat(np.linalg.inv(float_jacobian).tolist())
        except np.linalg.LinAlgError:
            return False
        # F and J on the path's line to second order in t - tm: the first derivatives at one point,
        # the second over the step; each times Y before the interval of t - tm multiplies it, so
        # that Y keeps its cancellations (Y F'' is the path's bend, small however large Y is)
        per_radian = [vi / self.unit for vi in v]
        first = [a * self.unit for a in self.f.along(*at_middle, *per_radian)]
        bend = [b * (self.unit * self.unit / 2) for b in self.f.bend(*line, *inputs, *self.known, *per_radian)]
        half = abs(tb - ta) / 2
        square = _ball(half * half / 2, half * half / 2)  # (t - tm)**2: [0, half**2]

        def taylor(value: Sequence[Any], rate: Sequence[Any], curve: Sequence[Any], columns: int) -> arb_mat:
            return (inverse * arb_mat(n, columns, list(value)) + (inverse * arb_mat(n, columns, list(rate))) * offset
                    + (inverse * arb_mat(n, columns, list(curve))) * square)

        newton = taylor(residual(*at_middle), first[:n], bend[:n], 1)
        turned = taylor(jacobian(*at_middle), first[n:], bend[n:], n)
        second = self.f.second(*tube, *inputs, *self.known)
        for axis in range(n):  # J's spread over the box around the line: F's second derivatives
            turned += (inverse * arb_mat(n, n, second[axis * n * n:(axis + 1) * n * n])) * arb(0, radius)
        identity = arb_mat([[int(i == j) for j in range(n)] for i in range(n)])
        spread = arb_mat(n, 1, [arb(0, radius)] * n)
        k = arb_mat(n, 1, c) - newton + (identity - turned) * spread
        return all(b.contains_interior(k[i, 0]) for i, b in enumerate(box))

    def meeting(self, x: Floats, enclosure: list[arb], ta: Fraction, tried: Fraction, t1: Fraction) -> Meeting:
        """Where the path stopped, after ``ta``: the fold proved in balls when it is a simple one,
        else [ta, tried] with ``det J`` over a box holding the path up to there."""
        fold = self.f.fold().prove(self, x, ta)
        if fold is not None:
            at, values = fold
            lo, hi = _bounds(at)
            near = max(abs(float(v.mid()) - a) for v, a in zip(values, x)) <= 1e-2 * (1 + float(np.max(np.abs(x))))
            if min(ta, t1) <= hi and lo <= max(ta, t1) and near:
                determinant = arb_mat(self.f.n, self.f.n, self.f.jacobian(*values, *self.inputs(at),
                                                                                   *self.known)).det()
                return Meeting(min(ta, lo), max(ta, hi), determinant, True)
        tangent = self.tangent(x, ta)
        reach = 4 * abs(float(tried - ta)) * (float(np.max(np.abs(tangent))) if tangent is not None else 1.0)
        box = [e + arb(0, reach + 1e-12 * (1 + abs(float(e.mid())))) for e in enclosure]
        lo, hi = min(ta, tried), max(ta, tried)
        inputs = self.inputs(_ball((lo + hi) / 2, (hi - lo) / 2))
        determinant = arb_mat(self.f.n, self.f.n, self.f.jacobian(*box, *inputs, *self.known)).det()
        return Meeting(lo, hi, determinant, False)


class Fold:
    """The fold system of a follower's equations: ``F = 0``, ``J w = 0``, ``l.w = 1`` (and ``c^2 + s^2 = 1``
    for an angle), in the unknowns, ``w`` and the input's variables, ``l`` a parameter: regular at a simple fold."""

    def __init__(self, follower: Follower) -> None:
        n = follower.n
        w = [symbol(f"fold_w{k}") for k in range(n)]
        l = [symbol(f"fold_l{k}") for k in range(n)]
        equations = list(follower.equations) + list(follower.jacobian_matrix * sympy.Matrix(w)) \
            + [sum(a * b for a, b in zip(l, w)) - 1]
        if follower.angle:
            c, s = (symbol(v) for v in follower.variables)
            equations.append(c**2 + s**2 - 1)
        self.names = list(follower.names) + [str(v) for v in w] + list(follower.variables)
        parameters = [str(v) for v in l] + list(follower.parameters)
        arguments = self.names + parameters
        unknowns = [symbol(v) for v in self.names]
        self.residual = compile_program(equations, arguments, FLOAT)
        self.jacobian = compile_program(list(sympy.Matrix(equations).jacobian(unknowns)), arguments, FLOAT)
        self.certifier = BlockCertifier(self.names, equations, parameters)
        self.n = n

    def prove(self, track: _Track, x: Floats, t: Fraction) -> tuple[arb, list[arb]] | None:
        """The fold next to ``x`` at ``t`` proved: its input (degrees for an angle) and unknowns, in balls."""
        _, jacobian, _ = track.float_parts(x, float(t))
        null = np.linalg.svd(jacobian)[2][-1]
        guess = np.concatenate([x, null, track.float_inputs(float(t))])
        parameters = [*map(float, null), *track.known_floats]
        solved = self._newton(guess, parameters)
        if solved is None:
            return None
        enclosure = self.certifier(solved.tolist(), [arb(p) for p in null] + track.known)
        if enclosure is None:
            return None
        values, variables = enclosure[:self.n], enclosure[2 * self.n:]
        if not track.f.angle:
            return variables[0], values
        radians = arb.atan2(variables[1], variables[0])
        degrees = radians * 180 / arb.pi()
        turns = round((float(t) - float(degrees.mid())) / 360)  # the turn the path is on
        return degrees + 360 * turns, values

    def _newton(self, guess: Floats, parameters: list[float]) -> Floats | None:
        size = len(guess)

        def parts(x: Floats) -> tuple[Floats, Floats]:
            arguments = [*map(float, x), *parameters]
            return (np.array(self.residual(*arguments), dtype=float),
                    np.array(self.jacobian(*arguments), dtype=float).reshape(size, size))

        return _newton(parts, guess, 4 * NEWTON)


def _newton(parts: Callable[[Floats], tuple[Floats, Floats]], x: Floats, iterations: int, *,
            settled: float = 0.0) -> Floats | None:
    """Newton's method from ``x`` on the system ``parts`` gives (``x`` -> residual, Jacobian): the
    solution once a move is below 1e-14 (relative to ``x``), or after ``iterations`` the last ``x``
    when its move was below ``settled``; None when not settled, ``J`` singular or ``x`` not finite.

    >>> _newton(lambda x: (x**2 - 2, np.diag(2 * x)), np.array([1.0]), 8)
    array([1.41421356])
    >>> _newton(lambda x: (x**2 + 1, np.diag(2 * x)), np.array([1.0]), 8) is None   # no real root
    True
    """
    move = np.array([np.inf])
    for _ in range(iterations):
        residual, jacobian = parts(x)
        try:
            move = np.linalg.solve(jacobian, residual)
        except np.linalg.LinAlgError:
            return None
        x = x - move
        if not np.all(np.isfinite(x)):
            return None
        if np.max(np.abs(move)) <= 1e-14 * (1 + np.max(np.abs(x))):
            return x
    return x if np.max(np.abs(move)) <= settled * (1 + np.max(np.abs(x))) else None


def _ball(t: Fraction, radius: Fraction = Fraction(0)) -> arb:
    """``t`` +- ``radius`` as a ball holding the whole interval."""
    centre = arb(flint.fmpq(t.numerator, t.denominator))
    return centre if radius == 0 else centre + arb(0, math.nextafter(float(radius), math.inf))


def _bounds(ball: arb) -> tuple[Fraction, Fraction]:
    """Rationals below and above ``ball``."""
    middle, radius = _fraction(ball.mid()), _fraction(ball.rad())
    return middle - radius, middle + radius


def _fraction(exact: arb) -> Fraction:
    mantissa, exponent = exact.mid().man_exp()
    return Fraction(int(mantissa)) * Fraction(2) ** int(exponent)
