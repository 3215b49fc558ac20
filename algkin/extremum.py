"""Stationary points of an output over its input, by elimination and certified roots.

On the motion the output ``u`` satisfies its eliminant ``F(u, c, s) = 0``; it is
stationary where ``dF/dtheta = -s*F_c + c*F_s = 0`` (the ``F_u * du/dtheta`` term
vanishes there). With the half-angle ``t = tan(theta/2)`` both become polynomials in
``(u, t)``; their resultant in ``u`` is a polynomial in ``t`` whose real roots, isolated
by python-flint with certified enclosures, hold every stationary input. No calculus on
square roots, no numeric minimiser.

>>> result = extremum("arm-string", "AB", (0, 180))
>>> round(float(result.minimum["value"]), 9), round(float(result.minimum["input_deg"]), 6)
(57.921561087, 78.690068)
"""

from dataclasses import dataclass

import flint
import mpmath
import sympy

from .errors import UsageError
from .evaluate import MPMATH, evaluate
from .pipeline import derive
from .system import symbol

__all__ = ["extremum", "Extremum"]

ROOT_BITS = 128


@dataclass
class Extremum:
    scene: str
    output: str
    input: str
    range: tuple
    critical_points: list
    minimum: dict
    maximum: dict

    def to_json(self):
        return {"scene": self.scene, "of": self.output, "input": self.input, "range": list(self.range),
                "critical_points": self.critical_points, "minimum": self.minimum, "maximum": self.maximum}


def _stationary_polynomial(eliminant, u, c, s, t):
    """Resultant in u of F and dF/dtheta after c, s -> rational functions of t."""
    along = -s * sympy.diff(eliminant, c) + c * sympy.diff(eliminant, s)
    half_angle = {c: (1 - t**2) / (1 + t**2), s: 2 * t / (1 + t**2)}
    numerators = [sympy.numer(sympy.together(e.xreplace(half_angle))) for e in (eliminant, along)]
    return sympy.Poly(sympy.resultant(*numerators, u), t)


def _real_roots(poly):
    """Certified real roots of an integer univariate polynomial, as arb balls."""
    _, coeffs = poly.clear_denoms()
    fpoly = flint.fmpz_poly([int(a) for a in reversed(coeffs.all_coeffs())])
    roots = []
    for factor, _ in fpoly.factor()[1]:
        roots += [r.real for r, _ in factor.complex_roots() if r.imag.is_zero()]
    return roots


def extremum(scene, output, angle_range=None, method="resultant", backend="flint"):
    """Critical points, minimum and maximum of ``output`` over the scene's one input."""
    derived = derive(scene, [output], method, backend, samples=0)
    compiled = derived.compiled
    if len(compiled.system.inputs) != 1:
        raise UsageError("scene", compiled.scene.name, "extremum needs exactly one input")
    (name, (c_name, s_name)), = compiled.system.inputs.items()
    spec = compiled.scene.inputs[name]
    lo, hi = angle_range or (float(spec.lo), float(spec.hi))
    unknowns = compiled.outputs.get(output) or (output,)
    if len(unknowns) != 1:
        raise UsageError("--of", output, "name a scalar output (a distance or a coordinate)")
    u, c, s, t = symbol(unknowns[0]), symbol(c_name), symbol(s_name), sympy.Symbol("t")
    eliminant = derived.eliminations[unknowns[0]].polynomial
    chosen = next(b for b in derived.branches if b.selected)
    closed = chosen.values[unknowns[0]]
    with flint.ctx.workprec(ROOT_BITS), mpmath.workdps(40):
        candidates = []
        for root in _real_roots(_stationary_polynomial(eliminant, u, c, s, t)):
            degrees = 2 * root.atan() * 180 / flint.arb.pi()
            candidates.append((mpmath.mpf(degrees.mid().str(40, radius=False)), degrees))
        candidates.append((mpmath.mpf(180), flint.arb(180)))  # t = infinity
        value_at = lambda deg: _value(closed, c_name, s_name, deg)  # noqa: E731
        critical = []
        for deg, ball in candidates:
            for turn in (-360, 0, 360):
                d = deg + turn
                if lo <= d <= hi and _is_stationary(closed, c_name, s_name, d):
                    critical.append({"input_deg": float(d), "value": float(value_at(d)),
                                     "kind": _kind(value_at, d),
                                     "enclosure_deg": (ball + turn).str(20)})
        ends = [{"input_deg": float(x), "value": float(value_at(mpmath.mpf(x))), "kind": "endpoint"}
                for x in (lo, hi)]
    everything = [p for p in critical + ends if p["value"] == p["value"]]
    return Extremum(compiled.scene.name, output, name, (lo, hi), critical,
                    min(everything, key=lambda p: p["value"]), max(everything, key=lambda p: p["value"]))


def _value(expr, c_name, s_name, deg):
    angle = mpmath.radians(deg)
    result = evaluate(expr, {c_name: mpmath.cos(angle), s_name: mpmath.sin(angle)}, MPMATH)
    return result if isinstance(result, mpmath.mpf) else mpmath.nan


def _is_stationary(expr, c_name, s_name, deg):
    step = mpmath.mpf(10) ** -12
    slope = (_value(expr, c_name, s_name, deg + step) - _value(expr, c_name, s_name, deg - step)) / (2 * step)
    scale = 1 + abs(_value(expr, c_name, s_name, deg))
    return abs(slope) <= mpmath.mpf(10) ** -9 * scale


def _kind(value_at, deg):
    step = mpmath.mpf(10) ** -4
    here, left, right = value_at(deg), value_at(deg - step), value_at(deg + step)
    if left > here and right > here:
        return "minimum"
    if left < here and right < here:
        return "maximum"
    return "inflection"
