"""Closed-form branches of a compiled scene, labelled geometrically, paired by construction.

A dyad's point is ``X = P + a*d + sigma*h*rot90(d)`` with ``d = Q - P``,
``a = (l1**2 - l2**2 + |d|**2) / (2|d|**2)`` and ``h = sqrt(disc) / (2|d|**2)``, where
``disc = ((l1+l2)**2 - |d|**2) * (|d|**2 - (l1-l2)**2)``. Since
``cross(d, X - P) = sigma*h*|d|**2``, ``sigma = +1`` is the point left of P -> Q: the
label is the geometry, not the sign in a quadratic formula. Both coordinates come from
the one expression, so they are paired by construction.

A slider's point, on the line through P with direction d at distance l from Q, is
``X = P + (dot(d, w) + sigma*sqrt(disc)) / |d|**2 * d`` with ``w = Q - P`` and
``disc = l**2*|d|**2 - cross(d, w)**2``. Since ``dot(d, X - Q) = sigma*sqrt(disc)``,
``sigma = +1`` is the point ahead of the foot of the perpendicular from Q, along d.

>>> from algkin.scene import load_scene, compile_scene
>>> branches = closed_forms(compile_scene(load_scene("chebyshev-lambda"), ["B"]))
>>> [b.label for b in branches]
['left', 'right']
>>> branches[0].values["B_x"]
c_angle/2 + s_angle*sqrt((5 - 4*c_angle)*(c_angle + 5))/(5 - 4*c_angle) + 1
"""

import itertools
from dataclasses import dataclass

import sympy

from ..scene.compile import SliderSpec
from ..system import symbol

__all__ = ["Branch", "closed_forms", "reduce_on_circles"]


@dataclass(frozen=True)
class Branch:
    """One assembly mode: its labels, the closed form of every unknown, where it is real."""

    label: str
    labels: dict  # dyad point -> 'left' / 'right', slider point -> 'ahead' / 'behind'
    values: dict  # unknown -> sympy expression in inputs' c_*, s_* and parameters
    discriminants: dict  # dyad or slider point -> expression that must be >= 0
    selected: bool  # the branch the scene file asks for

    @property
    def valid_when(self):
        """Where the branch is real, each discriminant without its positive numeric factor."""
        return " & ".join(f"({_without_positive_number(d)} >= 0)" for d in self.discriminants.values()) or "True"

    def to_json(self):
        return {
            "label": self.label,
            "labels": dict(self.labels),
            "values": {k: str(v) for k, v in self.values.items()},
            "valid_when": self.valid_when,
            "discriminants": {k: str(v) for k, v in self.discriminants.items()},
            "selected": self.selected,
        }


def reduce_on_circles(expr, inputs):
    """Normal form of a polynomial modulo ``c**2 + s**2 - 1`` for each input (s**2 -> 1 - c**2)."""
    expr = sympy.expand(expr)
    if not expr.is_polynomial():
        return expr
    for c, s in inputs:
        expr = sympy.expand(sympy.rem(expr, s**2 + c**2 - 1, s)) if expr.has(s) else expr
    return expr


def _without_positive_number(expr):
    """``4*(5 - 4*c)*(c + 5)`` as ``(5 - 4*c)*(c + 5)``: the same sign, fewer symbols to read."""
    factors = sympy.Mul.make_args(expr)
    return sympy.Mul(*[f for f in factors if not (f.is_Number and f > 0)])


def _primitive(expr):
    """``(content, part)`` with ``expr = content * part`` and integer coprime numbers in ``part``:
    a factor reads ``23 - 16*c``, not ``23/4 - 4*c`` (sympy would spread the 1/4 back in)."""
    return expr.primitive() if expr.is_Add else (sympy.Integer(1), expr)


def _tidy_ratio(expr):
    """A ratio of polynomials as ``k * p / q`` with ``p``, ``q`` primitive: ``(80*c - 103)/(8*(20*c - 29))``."""
    numerator, denominator = sympy.fraction(sympy.cancel(expr))
    (cn, pn), (cd, pd) = _primitive(numerator), _primitive(denominator)
    return sympy.Mul(cn / cd, pn, 1 / pd)  # one Mul: a product by a number would spread it back in


def _tidy_product(*factors):
    """The product of ``factors`` with every numeric content gathered in front."""
    parts = [_primitive(sympy.expand(f)) for f in factors]
    return sympy.Mul(*[c for c, _ in parts], *[sympy.factor_terms(p) for _, p in parts])


def _dyad_closed_form(dyad, substitution, sigma, inputs):
    reduce = lambda e: reduce_on_circles(e.xreplace(substitution), inputs)  # noqa: E731
    px, py = (reduce(v) for v in dyad.base_p)
    qx, qy = (reduce(v) for v in dyad.base_q)
    dx, dy = reduce(qx - px), reduce(qy - py)
    dist2 = reduce(dx**2 + dy**2)
    l1, l2 = dyad.lengths
    along = _tidy_ratio((l1**2 - l2**2 + dist2) / (2 * dist2))
    disc = _tidy_product(reduce((l1 + l2) ** 2 - dist2), reduce(dist2 - (l1 - l2) ** 2))
    across = sigma * (sympy.sqrt(disc) / 2) / _tidy_product(dist2)
    return (px + along * dx - across * dy, py + along * dy + across * dx), disc


def _slider_closed_form(slider, substitution, sigma, inputs):
    reduce = lambda e: reduce_on_circles(e.xreplace(substitution), inputs)  # noqa: E731
    px, py = (reduce(v) for v in slider.through)
    qx, qy = (reduce(v) for v in slider.center)
    dx, dy = slider.direction
    wx, wy = reduce(qx - px), reduce(qy - py)
    norm2 = dx**2 + dy**2
    dot, cross = reduce(dx * wx + dy * wy), reduce(dx * wy - dy * wx)
    norm = sympy.sqrt(norm2)
    if norm.is_rational:  # a difference of squares: (l|d| - cross)(l|d| + cross)
        disc = _tidy_product(reduce(slider.length * norm - cross), reduce(slider.length * norm + cross))
    else:
        disc = _tidy_product(reduce(slider.length**2 * norm2 - cross**2))
    along = (dot + sigma * sympy.sqrt(disc)) / norm2
    return (px + along * dx, py + along * dy), disc


def closed_forms(compiled):
    """Every branch (all label combinations of the dyads and sliders) of ``compiled``."""
    inputs = [tuple(symbol(v) for v in pair) for pair in compiled.system.inputs.values()]
    dyads = compiled.implicit or compiled.dyads
    branches = []
    for labels in itertools.product(*(d.labels for d in dyads)):
        substitution, discriminants = {}, {}
        for dyad, label in zip(dyads, labels):
            form = _slider_closed_form if isinstance(dyad, SliderSpec) else _dyad_closed_form
            (x, y), disc = form(dyad, substitution, 1 if label == dyad.labels[0] else -1, inputs)
            substitution[symbol(dyad.unknowns[0])] = x
            substitution[symbol(dyad.unknowns[1])] = y
            discriminants[dyad.point] = disc
        values = {u: substitution[symbol(u)] for d in dyads for u in d.unknowns}
        for unknown, definition in compiled.definitions.items():
            values[unknown] = _output_value(definition, substitution, inputs)
        chosen = dict(zip((d.point for d in dyads), labels))
        label = labels[0] if len(labels) == 1 else " ".join(f"{p}:{l}" for p, l in chosen.items())
        selected = all(chosen[d.point] == d.branch for d in dyads)
        branches.append(Branch(label or "unique", chosen, values, discriminants, selected))
    return branches


def _output_value(definition, substitution, inputs):
    if definition.is_Pow and definition.exp == sympy.Rational(1, 2):
        return sympy.sqrt(reduce_on_circles(definition.base.xreplace(substitution), inputs))
    return sympy.expand(reduce_on_circles(definition, inputs).xreplace(substitution), deep=False)
