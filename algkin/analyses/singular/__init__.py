"""Singular points of an implicit plane curve, found exactly, certified and classified.

``singular_points(F)`` takes a curve ``F(x, y) = 0`` with rational coefficients (a sympy
polynomial, or what ``algkin.curve`` returns with every dimension a number) and finds every
point where ``F = F_x = F_y = 0``: exactly, by resultants and gcds over number fields
(``locate``), as a rational univariate representation ``t = x + shear*y``, ``p(t) = 0``,
``x = x(t)``, ``y = y(t)``. The real ones get certified enclosures (balls about the real roots of
``p``, python-flint), exact values (sympy) and their type (``local``): multiplicity, tangents,
and for a double point crunode, acnode, cusp, tacnode..., told by the Hessian and, where it
vanishes, by the ``A_k`` of the splitting lemma. ``singular(scene, point)`` finds the curve first.

Also the curve's degree and circularity (how many times ``x**2 + y**2`` divides its top form: the
multiplicity of the circular points at infinity on it).

>>> import sympy
>>> x, y = sympy.symbols("x y")
>>> found = singular_points((x**2 + y**2)**2 - 2*(x**2 - y**2))       # the lemniscate
>>> [(p.x.exact, p.y.exact, p.kind) for p in found.points], found.degree, found.circularity
([(0, 0, 'crunode')], 4, 2)
>>> [p.kind for p in singular_points(y**2 - x**3).points]
['cusp']
>>> [(p.x.exact, p.kind) for p in singular_points(y**2 - (x**2 - 2)**2*(x + 3)).points]
[(-sqrt(2), 'crunode'), (sqrt(2), 'crunode')]
>>> singular_points(y**2 + (x**2 + 1)**2*(x - 5)).counts     # nodes at x = +-i only
{'complex': 2}
"""

from __future__ import annotations

import time
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any, TypedDict, Union

import attrs
import flint
import sympy

from ...errors import ComputationError, UsageError
from ...runtime.budget import Budget, Deadline, started
from ...runtime.frozen import FrozenDict, frozen
from ...runtime.exclusive import one_at_a_time
from ...system.convert import flint_context, to_flint, to_flint_integer
from .exact import ENCLOSURE_BITS, Coordinate, coordinates, polynomial_text
from .local import describe, multiplicity, shift
from .numberfield import RealRoot
from .locate import ExactPoint, locate, top_form
from ..frozen import deep_frozen, frozen_rows, thawed

if TYPE_CHECKING:
    from ...derivation.pipeline import CurveResult
    from ...scene.load import SceneLike, Values

__all__ = ["singular", "singular_points", "SingularPoint", "Singularities", "degree_and_circularity"]

_INTEGER = flint.fmpz_mpoly_ctx.get(("x", "y"), "lex")

Terms = dict[tuple[int, int], int]  # the curve's: (x power, y power) -> integer coefficient
Representation = dict[str, Union[str, int]]  # t = x + shear*y: {t, shear, polynomial p(t), x(t), y(t)}


class ComplexPoints(TypedDict):
    """A conjugate class of singular points none of which is real."""

    count: int
    multiplicity: int
    representation: Representation


@attrs.frozen
class SingularPoint:
    """One real singular point: coordinates (each exact, as a ball and a float) and local type."""

    x: Coordinate
    y: Coordinate
    local: FrozenDict[str, Any] = attrs.field(converter=deep_frozen)  # a Local, frozen
    representation: FrozenDict[str, Union[str, int]] = attrs.field(converter=frozen)  # a Representation

    @property
    def kind(self) -> str:
        return self.local["kind"]

    @property
    def multiplicity(self) -> int:
        return self.local["multiplicity"]

    def to_json(self) -> dict[str, Any]:
        return {"x": self.x.value, "y": self.y.value, "kind": self.kind, "multiplicity": self.multiplicity,
                "a_k": self.local["a_k"], "hessian_sign": self.local["hessian_sign"],
                "real_branches": self.local["real_branches"], "tangents": thawed(self.local["tangents"]),
                "enclosure": {"x": self.x.ball.str(20), "y": self.y.ball.str(20)},
                "exact": {"x": str(self.x.exact), "y": str(self.y.exact)},
                "minimal_polynomials": {"x": str(self.x.minimal), "y": str(self.y.minimal)},
                "representation": dict(self.representation), "certified": True}


def _points(points: Any) -> tuple[SingularPoint, ...]:
    return tuple(points)


@attrs.frozen
class Singularities:
    """The singular points of a curve: the real ones in full, the complex ones counted."""

    curve: sympy.Expr
    variables: tuple[str, str]
    degree: int
    circularity: int
    points: tuple[SingularPoint, ...] = attrs.field(converter=_points)
    complex: tuple[FrozenDict[str, Any], ...] = attrs.field(converter=frozen_rows)  # ComplexPoints, frozen
    timings: FrozenDict[str, float] = attrs.field(default=FrozenDict(), converter=frozen, eq=False)
    # scene, point, verification: when from a scene
    source: FrozenDict[str, Any] = attrs.field(default=FrozenDict(), converter=deep_frozen)

    @property
    def counts(self) -> dict[str, int]:
        """How many real singular points of each kind, and ``complex``: how many non-real ones
        (a sweep's columns, an atlas's filters)."""
        counts: dict[str, int] = {}
        for point in self.points:
            counts[point.kind] = counts.get(point.kind, 0) + 1
        return dict(sorted(counts.items()), complex=sum(c["count"] for c in self.complex))

    def to_json(self) -> dict[str, Any]:
        return {**thawed(self.source), "variables": list(self.variables), "curve": str(self.curve),
                "degree": self.degree, "circularity": self.circularity, "counts": self.counts,
                "singular_points": [p.to_json() for p in self.points],
                "complex_singular_points": thawed(self.complex), "timings": dict(self.timings)}


@one_at_a_time
def singular(scene: SceneLike, point: str, *, set: Values | None = None,  # noqa: A002 - the public name (--set)
             samples: int = 40, seed: int = 0, budget: Budget | Deadline | None = None) -> Singularities:
    """The singular points of the curve ``point`` traces in ``scene`` (``algkin.curve``, its
    verification on ``samples`` inputs included), every dimension at its default or ``set``;
    ``scene`` may be a ``Prepared`` one (``prepare``) with ``point`` among its outputs. A
    ``Budget`` (or the ``Deadline`` of one running) bounds the curve's time and eliminants' terms."""
    from ...derivation.pipeline import curve

    deadline = started(budget)
    traced = curve(scene, point, samples=samples, seed=seed, set=set, budget=deadline)
    deadline.note(f"finding the singular points of the curve of {point} in {traced.compiled.scene.name}")
    found = singular_points(traced)
    return attrs.evolve(found, source={"scene": traced.compiled.scene.name, "point": point,
                                       "curve_verification": traced.verification.to_json()},
                        timings={"curve": traced.timings["total"], **found.timings})


def singular_points(curve: sympy.Expr | CurveResult, variables: Sequence[str] | None = None) -> Singularities:
    """The singular points of ``curve = 0``: a sympy polynomial with rational coefficients in two
    ``variables`` (default: its two free symbols, sorted), or a ``CurveResult``."""
    start = time.perf_counter()
    expr, names = _polynomial(curve, variables)
    integer = to_flint_integer(to_flint(expr, flint_context(names)), flint.fmpz_mpoly_ctx.get(names, "lex"))
    integer = _INTEGER.from_dict(integer.to_dict())
    _check_squarefree(integer, expr)
    degree, circularity = degree_and_circularity(integer)
    terms = {(int(i), int(j)): int(c) for (i, j), c in integer.to_dict().items()}
    real: list[SingularPoint] = []
    complex_: list[ComplexPoints] = []
    for exact in locate(integer):
        roots = exact.field.real_roots()
        representation = _representation(exact)
        xs, ys = (coordinates(exact.field, value, roots, name) for value, name in zip((exact.x, exact.y), names))
        real += [_real_point(exact, terms, degree, root, x, y, representation) for root, x, y in zip(roots, xs, ys)]
        complex_ += _complex_points(exact, terms, len(roots), representation)
    real.sort(key=lambda p: (p.x.value, p.y.value))
    return Singularities(expr, names, degree, circularity, real, complex_,
                         {"singular": time.perf_counter() - start})


def _polynomial(curve: sympy.Expr | CurveResult, variables: Sequence[str] | None) -> tuple[sympy.Expr, tuple[str, str]]:
    """``(sympy polynomial, (x name, y name))`` from what ``singular_points`` accepts."""
    if hasattr(curve, "elimination") and hasattr(curve, "variables"):  # a CurveResult
        if curve.compiled.system.parameters:
            raise UsageError("curve", ", ".join(curve.compiled.system.parameters),
                             "these dimensions are symbolic; singular points need every dimension a number")
        x, y = curve.variables
        return curve.elimination.polynomial, (x, y)
    if not isinstance(curve, sympy.Expr):
        raise UsageError("curve", type(curve).__name__, "expected a sympy polynomial or what algkin.curve returns")
    expr = curve
    names = tuple(variables) if variables is not None else tuple(sorted(str(s) for s in expr.free_symbols))
    if len(names) != 2 or len(set(names)) != 2:
        raise UsageError("variables", names, "a plane curve needs two distinct variables")
    extra = sorted(str(s) for s in expr.free_symbols if str(s) not in names)
    if extra:
        raise UsageError("curve", str(expr), f"has symbols besides {names[0]}, {names[1]}: {', '.join(extra)}")
    by_name = {str(s): s for s in expr.free_symbols}
    gens = [by_name.get(n, sympy.Symbol(n)) for n in names]
    try:
        poly = sympy.Poly(expr, *gens)
    except sympy.PolynomialError:
        raise UsageError("curve", str(expr), "is not a polynomial") from None
    if poly.domain not in (sympy.ZZ, sympy.QQ):
        raise UsageError("curve", str(expr), f"needs rational coefficients, has {poly.domain}")
    if poly.total_degree() < 1:
        raise UsageError("curve", str(expr), "is a constant, not a curve")
    return poly.as_expr(), (names[0], names[1])


def _check_squarefree(integer: flint.fmpz_mpoly, expr: sympy.Expr) -> None:
    """A repeated factor is singular all along: no finite set of points to report."""
    _, factors = integer.factor_squarefree()
    repeated = [str(f) for f, e in factors if e > 1]
    if repeated:
        raise UsageError("curve", str(expr), f"has a repeated factor ({repeated[0]}): every point on it is singular")


def degree_and_circularity(curve: flint.fmpz_mpoly) -> tuple[int, int]:
    """The total degree, and how many times ``x**2 + y**2`` divides the top-degree form.

    >>> x, y = _INTEGER.gens()
    >>> degree_and_circularity((x**2 + y**2 - 2*x)**2 - 4*(x**2 + y**2))    # a cardioid
    (4, 2)
    """
    terms: dict[tuple[int, ...], int] = {m: c for m, c in top_form(curve).items()}
    top = _INTEGER.from_dict(terms)
    x, y = _INTEGER.gens()
    circle, count = x * x + y * y, 0
    while not top.is_constant():
        quotient, remainder = divmod(top, circle)
        if not remainder.is_zero():
            break
        top, count = quotient, count + 1
    return int(curve.total_degree()), count


def _real_point(exact: ExactPoint, terms: Terms, degree: int, root: RealRoot, x: Coordinate, y: Coordinate,
                representation: Representation) -> SingularPoint:
    _check_enclosure(terms, x.ball, y.ball)
    local = describe(exact.field, shift(exact.field, terms, exact.x, exact.y), degree, root)
    return SingularPoint(x, y, local, representation)


def _representation(exact: ExactPoint) -> Representation:
    return {"t": f"x + {exact.shear}*y" if exact.shear else "x", "shear": exact.shear,
            "polynomial": str(polynomial_text(exact.field.minimal, "t")),
            "x": str(polynomial_text(exact.x, "t")), "y": str(polynomial_text(exact.y, "t"))}


def _complex_points(exact: ExactPoint, terms: Terms, real: int, representation: Representation
                    ) -> list[ComplexPoints]:
    count = exact.field.degree - real
    if not count:
        return []
    m = multiplicity(shift(exact.field, terms, exact.x, exact.y))
    return [{"count": count, "multiplicity": m, "representation": representation}]


def _check_enclosure(terms: Terms, x: flint.arb, y: flint.arb) -> None:
    """The exact algebra's point must make ``F, F_x, F_y`` contain zero in balls (a guard on the
    whole chain: ball, field element, shear)."""
    with flint.ctx.workprec(ENCLOSURE_BITS + 64):
        values = [sum((c * x ** i * y ** j for (i, j), c in terms.items()), flint.arb(0)),
                  sum((c * i * x ** (i - 1) * y ** j for (i, j), c in terms.items() if i), flint.arb(0)),
                  sum((c * j * x ** i * y ** (j - 1) for (i, j), c in terms.items() if j), flint.arb(0))]
    if not all(v.contains(0) for v in values):
        raise ComputationError(f"a singular point's enclosure ({x}, {y}) does not meet F = F_x = F_y = 0")
