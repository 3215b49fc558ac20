"""The catalog's closed forms changed in form only when they came to be shown with primitive factors
(issue 35, item 8): each string of catalog_before.json.gz that changed then is, beside its old text in
catalog_forms_changed.json.gz, the same function of the inputs (exactly, at rational points of the inputs'
circles; a branch condition, the same conditions up to positive numbers).
"""

from __future__ import annotations

import gzip
import json
from fractions import Fraction
from pathlib import Path

import pytest
import sympy

CHANGED = Path(__file__).with_name("catalog_forms_changed.json.gz")
SLOPES = (Fraction(1, 3), Fraction(-2, 7), Fraction(5, 4))  # t of (c, s) = ((1 - t^2), 2t) / (1 + t^2)


def _points(symbols: set[sympy.Symbol]) -> list[dict[sympy.Symbol, sympy.Rational]]:
    """Rational points on every input's circle, each input at its own angle."""
    inputs = sorted({s.name[2:] for s in symbols if s.name[:2] in ("c_", "s_")})
    points = []
    for t in SLOPES:
        point = {}
        for i, name in enumerate(inputs):
            u = sympy.Rational(t.numerator, t.denominator) + sympy.Rational(i, 11)
            point[sympy.Symbol(f"c_{name}")], point[sympy.Symbol(f"s_{name}")] = (1 - u**2) / (1 + u**2), 2 * u / (1 + u**2)
        points.append(point)
    return points


def _value(expr: sympy.Expr, point: dict) -> sympy.Expr:
    return sympy.expand(sympy.radsimp(expr.xreplace(point)))


def _same_function(new: sympy.Expr, old: sympy.Expr) -> bool:
    compared = [(_value(new, p), _value(old, p)) for p in _points(new.free_symbols | old.free_symbols)]
    defined = [(a, b) for a, b in compared if a.is_finite and b.is_finite]
    return len(defined) >= 2 and all(sympy.expand(a - b) == 0 for a, b in defined)


def _same_conditions(new: str, old: str) -> bool:
    """``(f >= 0) & ...`` beside ``(k*f >= 0) & ...`` with each ``k`` a positive number (in any order)."""
    parts = [sympy.And.make_args(sympy.sympify(text)) for text in (new, old)]
    return len(parts[0]) == len(parts[1]) and all(any(_positive_multiple(a, b) for b in parts[1]) for a in parts[0])


def _positive_multiple(a: sympy.Rel, b: sympy.Rel) -> bool:
    ratios = {_value(a.lhs, p) / _value(b.lhs, p) for p in _points(a.lhs.free_symbols | b.lhs.free_symbols)}
    ratios = {sympy.expand(sympy.radsimp(r)) for r in ratios if r.is_finite and r != 0}
    return type(a) is type(b) and len(ratios) == 1 and bool(ratios.pop().is_positive)


@pytest.mark.slow  # 20 s: 169 forms evaluated exactly (CI runs the slow set too)
def test_every_changed_form_is_the_same_function():
    with gzip.open(CHANGED, "rt", encoding="utf-8") as text:
        changed = json.load(text)
    assert changed  # the forms that changed, with their paths in the reference
    for entry in changed:
        new, old = entry["new"], entry["old"]
        if entry["path"][-1] == "valid_when":
            assert _same_conditions(new, old), entry["path"]
        else:
            assert _same_function(sympy.sympify(new), sympy.sympify(old)), entry["path"]
