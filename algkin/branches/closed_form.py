"""Closed-form branches of a compiled scene, labelled geometrically, paired by construction.

Each implicit point's branch algebra gives its own closed form on each of its two labels (see
``algkin.branches.constructions``: a dyad's ``left``/``right``, a slider's ``ahead``/``behind``),
in the closed forms of the points it is built on; a branch is one label per point.

>>> from algkin.scene import load_scene, compile_scene
>>> branches = closed_forms(compile_scene(load_scene("chebyshev-lambda"), ["B"]))
>>> [b.label for b in branches]
['left', 'right']
>>> branches[0].values["B_x"]
c_angle/2 + s_angle*sqrt((5 - 4*c_angle)*(c_angle + 5))/(5 - 4*c_angle) + 1
"""

import contextlib
import functools
import itertools

import attrs
import sympy

from ..runtime.frozen import FrozenDict, frozen
from ..scene import Compiled
from ..scene.implicit.algebra import HALF, Circles, reduce_on_circles
from ..system import symbol
from .algebra import FormText, product, tidy_ratio, unsplit_root
from .constructions import Mode, algebra_of
from .constructions.dyad import NestedModes
from .tower import Tower, Unsupported, roots_in, varying_radicands

__all__ = ["Branch", "closed_forms"]


@attrs.frozen
class Branch:
    """One assembly mode: its labels, the closed form of every unknown, where it is real (an
    immutable, hashable value)."""

    label: str
    # dyad point -> 'left' / 'right', slider point -> 'ahead' / 'behind'
    labels: FrozenDict[str, str] = attrs.field(converter=frozen)
    # unknown -> sympy expression in inputs' c_*, s_* and parameters
    values: FrozenDict[str, sympy.Expr] = attrs.field(converter=frozen)
    # dyad or slider point -> expression that must be >= 0
    discriminants: FrozenDict[str, sympy.Expr] = attrs.field(converter=frozen)
    selected: bool  # the branch the scene file asks for
    # points whose discriminant is a square f**2: they exist where f != 0 (a meet of two lines)
    squares: frozenset[str] = frozenset()

    @property
    def valid_when(self) -> str:
        """Where the branch is real, each discriminant without its positive numeric factor (a square's
        base != 0)."""
        return self._valid_when(FormText())

    def _valid_when(self, text: FormText) -> str:
        shown = {p: text.readable(d) for p, d in self.discriminants.items()}
        return " & ".join(f"({text.text(d.base)} != 0)" if p in self.squares and d.is_Pow else
                          f"({text.text(_without_positive_number(d))} >= 0)" for p, d in shown.items()) or "True"

    def shown_values(self, text: FormText | None = None) -> dict[str, str]:
        """Each closed form as text, every factor primitive with integer coefficients (``readable``);
        ``text`` writes them (one for a document does its shared subexpressions once)."""
        text = text or FormText()
        return {k: text(v) for k, v in self.values.items()}

    def to_json(self, text: FormText | None = None) -> dict[str, object]:
        """The branch as JSON; ``text`` as for ``shown_values``."""
        text = text or FormText()
        return {
            "label": self.label,
            "labels": dict(self.labels),
            "values": self.shown_values(text),
            "valid_when": self._valid_when(text),
            "discriminants": {k: text(v) for k, v in self.discriminants.items()},
            "selected": self.selected,
        }


def _without_positive_number(expr: sympy.Expr) -> sympy.Expr:
    """``4*(5 - 4*c)*(c + 5)`` as ``(5 - 4*c)*(c + 5)``: the same sign, fewer symbols to read."""
    factors = sympy.Mul.make_args(expr)
    return sympy.Mul(*[f for f in factors if not (f.is_Number and f > 0)])


def closed_forms(compiled: Compiled) -> list[Branch]:
    """Every branch (all label combinations of the dyads and sliders) of ``compiled``; a point
    without modes of its own (an inversor's second intersection) follows the others."""
    moded = [spec for spec in compiled.implicit if spec.labels]
    built: Built = {}  # branches sharing the labels before a point share its algebra
    return [_branch(compiled, dict(zip((spec.point for spec in moded), labels)), built)
            for labels in itertools.product(*(spec.labels for spec in moded))]


Built = dict[tuple[int, tuple[str, ...]], tuple[Mode, Tower | None]]  # (point, labels before) -> modes, tower


def _branch(compiled: Compiled, chosen: dict[str, str], built: Built) -> Branch:
    """The branch with the label ``chosen[point]`` for each point with modes, each built on the ones before
    it; ``built`` holds each point's modes by the labels before it, for the other branches."""
    inputs, specs = compiled.circles, compiled.implicit
    substitution: dict[sympy.Symbol, sympy.Expr] = {}
    discriminants: dict[str, sympy.Expr] = {}
    squares: set[str] = set()
    last: Tower | None = None  # the tower the last nested point was built in
    for index, spec in enumerate(specs):
        sigma = spec.sign(chosen[spec.point]) if spec.labels else 1
        algebra = algebra_of(spec)
        before = (index, tuple(chosen[s.point] for s in specs[:index] if s.labels))
        if before not in built:  # each mode built once, for every branch it is in
            modes = algebra.modes(substitution, inputs=inputs)
            built[before] = functools.cache(modes), modes.tower if isinstance(modes, NestedModes) else None
        modes, tower = built[before]
        (x, y), discriminants[spec.point] = modes(sigma)
        last = tower or last
        if algebra.square:
            squares.add(spec.point)
        substitution.update({symbol(spec.unknowns[0]): x, symbol(spec.unknowns[1]): y})
    values = {u: substitution[symbol(u)] for spec in specs for u in spec.unknowns}
    for unknown, definition in compiled.definitions.items():
        values[unknown] = _output_value(definition, substitution, inputs, last)
    labels = list(chosen.values())
    label = labels[0] if len(labels) == 1 else " ".join(f"{p}:{l}" for p, l in chosen.items())
    selected = all(chosen[spec.point] == spec.branch for spec in specs if spec.labels)
    return Branch(label or "unique", chosen, values, discriminants, selected, frozenset(squares))


def _output_value(definition: sympy.Expr, substitution: dict[sympy.Symbol, sympy.Expr],
                  inputs: Circles, tower: Tower | None) -> sympy.Expr:
    nested = _nested_value(definition, substitution, inputs, tower)
    if nested is not None:
        return nested
    if definition.is_Pow and definition.exp == sympy.Rational(1, 2):
        return sympy.sqrt(reduce_on_circles(definition.base.xreplace(substitution), inputs))
    roots = [p for p in definition.atoms(sympy.Pow) if p.exp in (sympy.Rational(1, 2), sympy.Rational(-1, 2))]
    if roots:  # an angle's cosine or sine over a length that varies: numerator / sqrt(square)
        nested = _nested_over_roots(definition, roots, substitution, inputs, tower)
        return nested if nested is not None else _over_roots(definition, roots, substitution, inputs)
    value = sympy.expand(reduce_on_circles(definition, inputs).xreplace(substitution), deep=False)
    if not value.is_polynomial() and value.is_rational_function():  # over symbolic lengths: one fraction
        return tidy_ratio(value)
    return value


def _nested_value(definition: sympy.Expr, substitution: dict[sympy.Symbol, sympy.Expr],
                  inputs: Circles, tower: Tower | None) -> sympy.Expr | None:
    """``definition`` (a polynomial or ratio in the unknowns, or the root of one) in a ``Tower``, where
    the unknowns' closed forms hold more than one square root or one inside another: ``tower`` (the
    last nested point's) where it has them all, else a new one; None elsewhere (and for what a tower
    does not take)."""
    root = definition.is_Pow and definition.exp == HALF
    inside = definition.base if root else definition
    if roots_in([inside]):
        return None
    value = None
    if tower is not None:
        with contextlib.suppress(Unsupported):  # a root it has no room for
            given = {u: tower.value(substitution[u]) for u in inside.free_symbols if u in substitution}
            value = tower.expr(tower.value_given(inside, given))
    if value is None:
        placed = inside.xreplace(substitution)
        if varying_radicands(placed) < 2:  # one root at most (a tower would say so, after sympy's roots of them)
            return None
        try:
            tower = Tower([placed], inputs)
            if tower.roots < 2:  # one root at most: sympy's forms of a single dyad read well
                return None
            value = tower.expr(tower.value(placed))
        except Unsupported:
            return None
    return unsplit_root(value) if root else value


def _nested_over_roots(definition: sympy.Expr, roots: list[sympy.Pow], substitution: dict[sympy.Symbol, sympy.Expr],
                       inputs: Circles, tower: Tower | None) -> sympy.Expr | None:
    """``definition``, a root-free part times roots of sums or their reciprocals (an angle's cosine
    or sine), each part in a tower (``_nested_value``) where the points hold nested roots: sympy's
    expansion of the whole took seconds on Hart's Q. None elsewhere."""
    if not definition.is_Mul:
        return None
    powers = [f for f in definition.args if f in roots]
    rest = sympy.Mul(*[f for f in definition.args if f not in roots])
    if roots_in([rest]):
        return None
    parts = [_nested_value(e, substitution, inputs, tower) for e in (rest, *(p.base for p in powers))]
    if any(part is None for part in parts):
        return None
    numerator, *radicands = parts
    return product(numerator, *[_root_power(r, p.exp) for r, p in zip(radicands, powers)])


def _root_power(radicand: sympy.Expr, exponent: sympy.Rational) -> sympy.Expr:
    """``radicand**exponent`` for an exponent of 1/2 or -1/2, without sympy's sign questions
    (``unsplit_root``): its number's root inverted by sympy, the rest's power written as it is."""
    root = unsplit_root(radicand)
    if exponent == HALF:
        return root
    number, rest = root.as_coeff_Mul()
    inverted = [sympy.Pow(f.base, -f.exp, evaluate=False) if f.is_Pow and f.base.free_symbols else 1 / f
                for f in sympy.Mul.make_args(rest)]
    return product(1 / number, *inverted)


def _over_roots(definition: sympy.Expr, roots: list[sympy.Pow], substitution: dict[sympy.Symbol, sympy.Expr],
                inputs: Circles) -> sympy.Expr:
    """``definition`` with each square root's radicand and the rest in closed form, apart: the
    radicands reduced on the circles before they go under their roots."""
    stand_ins = {p.base: sympy.Dummy("root") for p in roots}
    plain = definition.xreplace({p: stand_ins[p.base] ** (2 * p.exp) for p in roots})
    value = sympy.expand(reduce_on_circles(plain, inputs).xreplace(substitution), deep=False)
    return value.xreplace({d: sympy.sqrt(reduce_on_circles(base.xreplace(substitution), inputs))
                           for base, d in stand_ins.items()})
