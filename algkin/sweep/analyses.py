"""The analyses a sweep runs on each design, by name: each one's columns and how it fills them.

An ``Analysis`` says its columns (name -> Arrow type, in order) and computes them from a
``Design`` (the scene with the design's exact dimensions, compiled, known to assemble). Exact
results are strings (sympy's, or JSON of exact pieces), figures are floats. An analysis that
cannot answer raises; the sweep records the design as failed with that one line.

``register`` adds one (a new name, its columns prefixed by it). Each says how long it takes on
one design at least (``seconds``): the median on a catalog four-bar on the project's 2-core
machine, rounded down, as measured for the 12 designs of ``a=1/2:3/2:4, d=7/2:9/2:3`` (with
what the designs share worked out once: ``algkin.sweep.family``); a sweep
refuses to start a run projected from them past a day without ``--yes``. ``singular`` gives the real
singular points of the coupler curve, exactly (``algkin.analyses.singular``): their count by
kind (``singular_count``, all real ones, is what the atlas filters on) and the points.

A scene with points solved together (``unknown = true``) takes the analyses that have a way for
its groups (``groups``): ``modes`` (its real modes at the reference input, where ``derive`` counts
them: ``algkin.analyses.groups``) and ``toggles`` (where its modes meet, the same columns as a
dyad scene's); ``applicable`` names them, and refuses the others in one line.

>>> list(ANALYSES)
['curve', 'grashof', 'toggles', 'limits', 'transmission', 'singular', 'modes']
>>> ANALYSES["grashof"].columns
{'grashof_class': 'string', 'grashof_margin': 'string', 'grashof_margin_float': 'float64'}
>>> analyses_named(["grashof", "wobble"])
Traceback (most recent call last):
...
algkin.errors.UsageError: analyses='wobble': unknown (valid: curve, grashof, toggles, limits, transmission, singular, modes)
>>> applicable(["modes"], solved_together=False)
Traceback (most recent call last):
...
algkin.errors.UsageError: analyses='modes': is for points solved together (unknown = true); this scene takes curve, grashof, toggles, limits, transmission, singular
"""

from __future__ import annotations

import json
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field
from fractions import Fraction
from typing import TYPE_CHECKING, Any

from ..runtime import suggest
from ..errors import ComputationError, UsageError

if TYPE_CHECKING:
    from ..analyses.groups.scene import GroupScene
    from ..derivation.pipeline import CurveResult
    from ..scene import Scene
    from ..scene.compile import Compiled
    from .family import Family, SharedCurve, SharedDesign

__all__ = ["Analysis", "Design", "ANALYSES", "register", "analyses_named", "applicable", "GRASHOF_CLASSES"]

# algkin.analyses.toggles.grashof's words -> the sweep's class names (the input link's view)
GRASHOF_CLASSES = {"crank-rocker": "crank-rocker", "double crank": "double-crank", "double rocker": "double-rocker",
                   "rocker-crank": "rocker-crank", "non-grashof (triple rocker)": "triple-rocker",
                   "change point": "change-point"}


@dataclass
class Design:
    """One design: its scene (exact dimensions), compiled with its implicit points, and the traced point;
    a scene with points solved together has its ``groups`` solved instead (and no ``compiled``).
    A design of a ``family`` (``shared``) has the family's compiled scene, its values the dimensions'."""

    scene: Scene
    compiled: Compiled | None
    point: str
    found: dict[str, Any] = field(default_factory=dict)  # what one analysis computed that another reuses
    groups: GroupScene | None = None
    family: Family | None = None
    shared: SharedDesign | None = None


def _verified_curve(design: Design) -> CurveResult:
    """The design's coupler curve, verified, computed once for every analysis that needs it."""
    from ..derivation.pipeline import curve

    if "curve" not in design.found:
        found = curve(design.scene, design.point)
        if found.verification.status == "failed":
            failures = "; ".join(found.verification.to_json().get("failures") or ["no reason given"])
            raise ComputationError(f"the curve of {design.point} failed its check: {failures}")
        design.found["curve"] = found
    return design.found["curve"]


@dataclass(frozen=True)
class Analysis:
    name: str
    columns: dict[str, str]  # column -> Arrow type: string, float64, int64, bool, list<float64>
    run: Callable[[Design], dict[str, Any]] | None  # None: not for a scene of dyads and sliders
    # seconds one design takes at least (a four-bar's, rounded down): what a sweep's length is projected from
    seconds: float = 0.0
    groups: Callable[[Design], dict[str, Any]] | None = None  # the way for points solved together, if any

    def __call__(self, design: Design) -> dict[str, Any]:
        """The design's columns, by the way its scene takes (``applicable`` checked it has one)."""
        run = self.groups if design.groups is not None else self.run
        assert run is not None, f"{self.name}: no way for this design (applicable refuses it)"
        return run(design)


def _shared_curve(design: Design) -> SharedCurve | None:
    """The design's curve from its family's generic one, when the family answers for it."""
    if design.family is None or design.shared is None:
        return None
    if "shared curve" not in design.found:
        design.found["shared curve"] = design.family.curve(design.shared)
    found: SharedCurve | None = design.found["shared curve"]
    return found


def _curve(design: Design) -> dict[str, Any]:
    shared = _shared_curve(design)
    if shared is not None:
        return {"curve_point": design.point, "curve_degree": shared.degree, "curve_circularity": shared.circularity,
                "curve_irreducible": True, "curve_polynomial": shared.text,
                "curve_verification": shared.verification}
    found = _verified_curve(design)
    return {"curve_point": design.point, "curve_degree": found.degree, "curve_circularity": found.circularity,
            "curve_irreducible": bool(found.irreducible), "curve_polynomial": str(found.elimination.polynomial),
            "curve_verification": found.verification.status.value}


def _grashof(design: Design) -> dict[str, Any]:
    from ..analyses.toggles import grashof

    assert design.compiled is not None  # a scene of dyads: points solved together have no grashof
    found = grashof(design.compiled)
    if found is None:
        raise ComputationError("not a four-bar: no dyad on a crank tip and a ground pivot")
    return {"grashof_class": GRASHOF_CLASSES[found["class"]], "grashof_margin": found["margin"],
            "grashof_margin_float": _float_of(found["margin"])}


def _float_of(text: str) -> float:
    """The float of an exact number's text: a rational read directly (sympy's parser takes far
    longer than the rest of the analysis), a radical (a ground of ``sqrt(...)``) by sympy.

    >>> _float_of("-7/2"), round(_float_of("3 - 2*sqrt(2)"), 12)
    (-3.5, 0.171572875254)
    """
    try:
        return float(Fraction(text))
    except (ValueError, OverflowError):  # past a float's range: sympy says inf, as before
        import sympy

        return float(sympy.sympify(text))


def _toggles(design: Design) -> dict[str, Any]:
    from ..analyses.toggles import toggles

    found = toggles(design.scene, artefacts=False).toggles
    return {"toggles_count": len(found), "toggles_deg": [t.input_deg for t in found],
            "toggles_exact": json.dumps([{k: v for k, v in t.to_json().items() if k != "certified"} for t in found])}


def _group_toggles(design: Design) -> dict[str, Any]:
    """Where the modes of a scene with points solved together meet (``algkin.analyses.groups.toggles``)."""
    from ..analyses.groups.toggles import toggles_groups

    assert design.groups is not None
    found = toggles_groups(design.groups).to_json()["toggles"]
    return {"toggles_count": len(found),
            "toggles_deg": [t.get("input_deg", t.get("input_length")) for t in found],
            "toggles_exact": json.dumps([{k: v for k, v in t.items() if k != "certified"} for t in found])}


def _modes(design: Design) -> dict[str, Any]:
    """The real modes at the reference input (the evenly spaced input with the most, as ``derive``
    counts them) of a scene with points solved together, every group's together, and its complex count:
    the reference exactly (a length's rational; an angle's degrees, to 6 digits) and as a float."""
    import math

    assert design.groups is not None
    reference = design.groups.reference()
    found = design.groups.configurations(reference)  # one mode per group (a later group's at each earlier one)
    exact = reference.shown if len(reference.values) == 2 else str(next(iter(reference.values.values())))
    return {"modes_reference": exact, "modes_reference_float": reference.value,
            "modes_real": len(found),
            "modes_complex": math.prod(s.complex_count for s in design.groups.solutions)}


def _limits(design: Design) -> dict[str, Any]:
    from ..analyses.limits import limits

    found = limits(design.scene)
    chosen = [g for g in found.limits if g.selected]
    ratio = found.time_ratio
    stroke = ratio.stroke if ratio is not None else {}
    return {"limits_count": len(chosen), "limits_deg": [g.input_deg for g in chosen],
            "limits_exact": json.dumps([{"point": g.point, "kind": g.kind, "exact_deg": str(g.exact_deg),
                                         "enclosure_deg": g.enclosure.str(20)} for g in chosen]),
            "limits_time_ratio": None if ratio is None else ratio.ratio,
            "limits_time_ratio_exact": None if ratio is None else str(ratio.exact),
            "limits_time_ratio_reason": found.time_ratio_reason,
            "limits_stroke": stroke.get("angle_deg", stroke.get("length")), "limits_stroke_exact": stroke.get("exact")}


def transmission_output(design: Design) -> str:
    """``angle(A, B, D)``: at the coupler-rocker joint B, between the crank tip A and the ground pivot D."""
    return transmission_of(design.scene)


def transmission_of(scene: Scene) -> str:
    """``transmission_output`` of a scene: its four-bar's ``angle(A, B, D)``."""
    from ..scene.constructions import Crank, Dyad, Fixed

    points = scene.points
    for name, point in points.items():
        if isinstance(point, Dyad):
            tip, pivot = point.bases
            if isinstance(points[pivot], Crank) and isinstance(points[tip], Fixed):
                tip, pivot = pivot, tip
            if isinstance(points[tip], Crank) and isinstance(points[pivot], Fixed):
                return f"angle({tip}, {name}, {pivot})"
    raise ComputationError("no transmission angle: no dyad on a crank tip and a ground pivot")


def _transmission(design: Design) -> dict[str, Any]:
    from ..analyses.extremum import extremum

    output = transmission_output(design)
    family = design.family.extremum(output) if design.family is not None else None
    if family is None or design.shared is None:
        found = extremum(design.scene, output)
    else:  # the dimensions the output is free of (a coupler point's, for the angle at B) are not the family's
        found = family.at({n: v for n, v in design.shared.values.items() if n in family.defaults})
    exact: Mapping[str, Any] = found.exact or {}
    row: dict[str, Any] = {"transmission_of": output}
    for key, point in (("min", found.minimum), ("max", found.maximum)):
        degrees = exact.get("minimum" if key == "min" else "maximum", (None, None))[0]
        row.update({f"transmission_{key}_deg": float(point.value), f"transmission_{key}_at_deg": float(point.input_deg),
                    f"transmission_{key}_exact": None if degrees is None else str(degrees)})
    return row


def _singular(design: Design) -> dict[str, Any]:
    from ..analyses.singular import singular_points

    shared = _shared_curve(design)
    found = singular_points(_verified_curve(design)) if shared is None else \
        singular_points(shared.polynomial, shared.variables)
    counts = found.counts
    return {"singular_count": len(found.points), **{f"singular_{kind}s": counts.get(kind, 0) for kind in _KINDS},
            "singular_complex": counts["complex"],
            "singular_points": json.dumps([p.to_json() for p in found.points])}


_KINDS = ("crunode", "acnode", "cusp")  # a four-bar's double points; others count in singular_count alone

ANALYSES: dict[str, Analysis] = {}


def register(analysis: Analysis) -> Analysis:
    """Add ``analysis`` to the table (a new name, its columns prefixed by it), so that ``--analyses`` takes it.

    >>> register(Analysis("limits", {}, len, seconds=0.2))
    Traceback (most recent call last):
    ...
    algkin.errors.UsageError: analysis='limits': is registered already
    """
    if analysis.name in ANALYSES:
        raise UsageError("analysis", analysis.name, "is registered already")
    # each column named after its analysis: no clash with another's, the design's or the timings
    strays = [c for c in analysis.columns if not c.startswith(f"{analysis.name}_")]
    if strays:
        raise UsageError("analysis", analysis.name, f"columns must start with {analysis.name}_: {', '.join(strays)}")
    ANALYSES[analysis.name] = analysis
    return analysis


register(Analysis("curve", {"curve_point": "string", "curve_degree": "int64", "curve_circularity": "int64",
                            "curve_irreducible": "bool", "curve_polynomial": "string",
                            "curve_verification": "string"}, _curve, seconds=0.005))
register(Analysis("grashof", {"grashof_class": "string", "grashof_margin": "string",
                              "grashof_margin_float": "float64"}, _grashof, seconds=0.0005))
register(Analysis("toggles", {"toggles_count": "int64", "toggles_deg": "list<float64>",
                              "toggles_exact": "string"}, _toggles, seconds=0.003, groups=_group_toggles))
register(Analysis("limits", {"limits_count": "int64", "limits_deg": "list<float64>", "limits_exact": "string",
                             "limits_time_ratio": "float64", "limits_time_ratio_exact": "string",
                             "limits_time_ratio_reason": "string", "limits_stroke": "float64",
                             "limits_stroke_exact": "string"}, _limits, seconds=0.2))
register(Analysis("transmission", {"transmission_of": "string",
                                   **{f"transmission_{k}_{f}": t for k in ("min", "max")
                                      for f, t in (("deg", "float64"), ("at_deg", "float64"), ("exact", "string"))}},
                  _transmission, seconds=0.004))
register(Analysis("singular", {"singular_count": "int64", **{f"singular_{kind}s": "int64" for kind in _KINDS},
                               "singular_complex": "int64", "singular_points": "string"}, _singular, seconds=0.01))


register(Analysis("modes", {"modes_reference": "string", "modes_reference_float": "float64", "modes_real": "int64",
                            "modes_complex": "int64"}, None, seconds=0.05, groups=_modes))


def applicable(names: Iterable[str], *, solved_together: bool) -> None:
    """UsageError, in one line naming the analyses that apply, for the first of ``names`` that has
    no way for the scene (``solved_together``: it has points solved together)."""
    def fits(analysis: Analysis) -> bool:
        return (analysis.groups if solved_together else analysis.run) is not None

    for name in names:
        if not fits(ANALYSES[name]):
            takes = ", ".join(n for n, a in ANALYSES.items() if fits(a))
            what = ("does not apply to points solved together (unknown = true)" if solved_together
                    else "is for points solved together (unknown = true)")
            raise UsageError("analyses", name, f"{what}; this scene takes {takes}")


def analyses_named(names: Iterable[str]) -> list[Analysis]:
    """The analyses called ``names`` (comma-separated on the command line), in that order, each once."""
    names = [n.strip() for n in names]
    for name in names:
        if name not in ANALYSES:
            raise UsageError("analyses", name, "unknown" + suggest.known(name, ANALYSES, plural="valid"))
        if names.count(name) > 1:
            raise UsageError("analyses", name, "given twice")
    if not names:
        raise UsageError("analyses", "", f"name at least one of {', '.join(ANALYSES)}")
    return [ANALYSES[n] for n in names]
