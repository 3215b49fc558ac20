"""The seed documents' figures, drawn from derived closed forms (matplotlib, loaded only here).

Figures are built on ``matplotlib.figure.Figure`` with the Agg canvas, never through
``pyplot``'s global state, so plotting leaves no backend or style changed; as a notebook
cell's last line each shows as an image, once (``algkin.ui.figure``).

- ``quantity_figure``: a quantity against the input with its minimum marked, or its
  derivative with the zero marked (the seed's two plots);
- ``minimum_figure``: the minimum against a dimension, from the closed form per region,
  with certified minima at sample dimensions drawn on top (they must lie on the line).
"""

from __future__ import annotations

import io
import os
import pathlib
from collections.abc import Callable, Mapping, Sequence
from typing import TYPE_CHECKING, Any, TypeVar, Union

import numpy as np
import sympy
from numpy.typing import ArrayLike, NDArray

from ..errors import AlgkinError, UsageError
from ..runtime.files import write_atomic
from ..runtime.terminal import one_line

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from ..analyses.extremum import Extremum
    from ..analyses.quantities import Quantity
    from ..bench.accuracy import Accuracy
    from ..bench.groupaccuracy import GroupAccuracy
    from ..bench.row import BenchRow

_PathT = TypeVar("_PathT", bound=Union[str, "os.PathLike[str]"])  # a path given back as it came

__all__ = ["quantity_figure", "minimum_figure", "accuracy_figure", "bench_figure", "new_figure", "save", "image", "FORMATS"]

FORMATS = (".png", ".svg", ".pdf")


def new_figure() -> Figure:
    """An empty figure on the Agg canvas (no pyplot state) that a notebook shows as an image
    (``algkin.ui.figure.ShownFigure``); AlgkinError without matplotlib."""
    try:
        from matplotlib.backends.backend_agg import FigureCanvasAgg

        from .figure import ShownFigure
    except ImportError:
        raise AlgkinError("plotting needs matplotlib: pip install 'algkin[plot]'") from None
    figure = ShownFigure(figsize=(6.4, 4.4), layout="constrained")
    FigureCanvasAgg(figure)
    return figure


def image(figure: Figure, suffix: str) -> bytes:
    """The bytes of ``figure`` in the format of ``suffix`` (.png, .svg or .pdf), drawn before any
    file is opened: a figure that fails to draw leaves nothing behind."""
    buffer = io.BytesIO()
    figure.savefig(buffer, format=suffix.lower().lstrip("."), dpi=120)
    return buffer.getvalue()


def save(figure: Figure, out: _PathT) -> _PathT:
    """Write ``figure`` to ``out`` (.png, .svg or .pdf), replacing any earlier file only once complete."""
    write_atomic(out, image(figure, pathlib.Path(out).suffix))
    return out


def _sampler(quantity: Quantity, expr: sympy.Expr) -> Callable[[ArrayLike], NDArray[np.float64]]:
    """numpy function of degrees for ``expr`` in the input, dimensions at their defaults."""
    defaults = quantity.derivation.compiled.parameter_values
    fixed = expr.xreplace({p: sympy.Rational(str(defaults[p.name])) for p in quantity.symbolic_dimensions})
    return sympy.lambdify(quantity.input, fixed, "numpy")


def math_name(quantity: Quantity) -> str:
    """``quantity`` as mathtext: a distance as the seed writes it (``$|AB|$``), a coordinate
    subscripted (``$P_x$``), any other output as its text."""
    output = quantity.mechanism.scene.outputs.get(quantity.text)
    if output is not None and output.kind == "dist":
        return f"$|{''.join(output.points)}|$"
    if output is not None and output.kind in ("x", "y"):
        return f"${output.points[0]}_{output.kind}$"
    return one_line(quantity.text)  # typed by the user (--of): one line


def _unit(quantity: Quantity) -> str:
    """`` (mm)`` after a length when the scene says its unit, else nothing."""
    unit = quantity.mechanism.scene.unit
    return f" ({unit})" if unit and not quantity.degrees else ""


def _symbol(name: str) -> str:
    """A variable's name as mathtext: ``theta`` -> ``$\\theta$``."""
    return f"${sympy.latex(sympy.Symbol(name))}$"


def quantity_figure(quantity: Quantity, found: Extremum, derivative: bool = False, points: int = 721) -> Figure:
    """``quantity`` over the range of ``found`` (an ``Extremum``) with its minimum marked.

    With ``derivative`` the slope d/d(input) (per radian, as the seed computes it) is drawn
    with its zero at the certified minimiser.
    """
    lo, hi = found.range
    degrees = np.linspace(lo, hi, points)
    expr = quantity.derivative if derivative else quantity.expr
    if derivative or quantity.degrees:
        values = np.broadcast_to(_sampler(quantity, expr)(np.radians(degrees)), degrees.shape)
    else:  # the stabilised form (numba's loop where installed and it pays): no cancellation in the curve
        values = np.asarray(quantity.at(**{quantity.input.name: degrees}))
    best = found.minimum
    figure = new_figure()
    axes = figure.add_subplot()
    name, text = _symbol(quantity.input.name), math_name(quantity)
    unit = _unit(quantity)
    text += " (degrees)" if quantity.degrees else ""
    label = f"d{text}/d{name}" if derivative else text
    axes.plot(degrees, values, color="tab:blue", label=label)
    mark = 0.0 if derivative else float(best.value)
    if derivative:
        axes.axhline(0, color="black", linestyle="--", linewidth=0.8)
    axes.plot([float(best.input_deg)], [mark], "o", color="red", markersize=7,
              label=f"minimum of {text}: {float(best.value):.6g}{unit} at {float(best.input_deg):.6g}°")
    axes.annotate(f"[{float(best.input_deg):.2f}°, {mark:.4g}]", (float(best.input_deg), mark),
                  textcoords="offset points", xytext=(8, 8))
    axes.set_xlabel(f"{name} (degrees)")
    per = f"{unit[:-1]} per radian)" if unit else " (per radian)"
    axes.set_ylabel(f"{label}{per}" if derivative else f"{text}{unit}")
    axes.set_title(f"{'Derivative of ' if derivative else ''}{one_line(quantity.text)} in {one_line(quantity.mechanism.scene.name)}",
                   parse_math=False)  # a scene's name is text, never mathtext
    axes.grid(True)
    axes.legend()
    return figure


def minimum_figure(quantity: Quantity, found: Extremum, parameter: str, lo: float, hi: float, checks: int = 9,
                   points: int = 401) -> Figure:
    """The minimum of ``quantity`` against ``parameter`` in ``[lo, hi]``, region by region."""
    form = found.closed_form
    if form is None or [p.name for p in quantity.symbolic_dimensions] != [parameter]:
        raise UsageError("--against", parameter, "needs the quantity with exactly that dimension symbolic")
    symbol = quantity.symbolic_dimensions[0]
    figure = new_figure()
    axes = figure.add_subplot()
    grid = np.linspace(lo, hi, points)
    for region, value in zip(form.regions, form.region_values):
        inside = grid[[_within(region, x) for x in grid]]
        if inside.size and value is not None:
            line = sympy.lambdify(symbol, value, "numpy")
            kind = "at a range end" if region["at"] == "endpoint" else "stationary"
            axes.plot(inside, np.broadcast_to(line(inside), inside.shape),
                      label=f"${sympy.latex(value)}$  ({kind})")
        if region["to"] is not None and lo < region["to"] < hi:
            axes.axvline(region["to"], color="gray", linestyle=":", linewidth=0.8)
    samples = np.linspace(lo, hi, checks)
    certified = [_certified_minimum(found, quantity, symbol, x) for x in samples]
    axes.plot(samples, certified, "o", color="red", markersize=5, label="certified minimum at that value")
    unit = _unit(quantity)
    axes.set_xlabel(f"{_symbol(parameter)}{unit}")  # a dimension: a length
    axes.set_ylabel(f"minimum of {math_name(quantity)}{unit}")
    axes.set_title(f"Minimum of {one_line(quantity.text)} over {quantity.input.name} in "
                   f"[{found.range[0]:g}°, {found.range[1]:g}°] against {parameter}")
    axes.grid(True)
    axes.legend(fontsize="small")
    return figure


def _within(region: Mapping[str, Any], x: float) -> bool:
    """Whether ``x`` is in a closed form's region (a ``Region``, kept frozen)."""
    return (region["from"] is None or region["from"] <= x) and (region["to"] is None or x <= region["to"])


def _certified_minimum(found: Extremum, quantity: Quantity, symbol: sympy.Symbol, x: float) -> float:
    """The minimum at one dimension, by the fixed-dimension certified path (independent of the regions)."""
    from ..analyses.extremum import extreme_at

    assert found.problem is not None and found.stationary is not None, "a closed form's extremum keeps its problem"
    values = {symbol: sympy.Rational(str(x))}
    return float(extreme_at(found.problem, found.stationary, values, *found.range).value)


def accuracy_figure(result: Accuracy | GroupAccuracy) -> Figure:
    """Time per sample against max relative error, log-log: marker per strategy, colour per case.

    Two legends name them instead of text beside each point (labels would pile up where
    strategies cost the same). A zero error (the reference, exact by definition) has no place
    on a log axis: it is drawn hollow on a dotted floor below every other error, marked
    "exact (0)".
    """
    from matplotlib.lines import Line2D

    figure = new_figure()
    figure.set_size_inches(7.6, 4.4)
    axes = figure.add_subplot()
    rows = [r for r in result.rows if np.isfinite(r["max_rel_error"])]
    floor = _zero_floor([r["max_rel_error"] for r in rows])
    cases = list(dict.fromkeys(r["case"] for r in rows))
    colors = {case: f"C{k % 10}" for k, case in enumerate(cases)}
    markers = {"closed-form": "s", "stabilised": "o", "compiled": "P", "numeric": "^", "reference": "D",
               "eliminant-roots": "v", "newton": "<", "certified": "d"}  # the last three: points solved together
    for r in rows:
        exact = r["max_rel_error"] == 0
        axes.scatter([r["ns_per_sample"]], [floor if exact else r["max_rel_error"]],
                     marker=markers.get(r["strategy"], "X"), s=42, edgecolors=colors[r["case"]],
                     facecolors="none" if exact else colors[r["case"]])
    if any(r["max_rel_error"] == 0 for r in rows):
        axes.axhline(floor, color="gray", linestyle=":", linewidth=0.8)
        axes.annotate("exact (0)", (0, floor), xycoords=("axes fraction", "data"), xytext=(4, 3),
                      textcoords="offset points", fontsize="x-small", color="gray")
    axes.set_xscale("log")
    axes.set_yscale("log")
    axes.set_ylim(bottom=floor / 3)
    axes.set_xlabel("time per sample (ns)")
    axes.set_ylabel("max relative error")
    axes.set_title(f"Speed against error: {one_line(result.point)} of {one_line(result.scene)}", parse_math=False)
    axes.grid(True, which="both", linewidth=0.3)
    shown = [s for s in markers if any(r["strategy"] == s for r in rows)]
    # Beside the axes (the constrained layout makes room): inside, they would cover points.
    figure.legend([Line2D([], [], marker=markers[s], color="dimgray", linestyle="none") for s in shown],
                  shown, title="strategy", fontsize="small", loc="outside right upper")
    figure.legend([Line2D([], [], marker="o", color=colors[c], linestyle="none") for c in cases], cases,
                  title="case", fontsize="small", loc="outside right lower")
    return figure


def _zero_floor(errors: Sequence[float]) -> float:
    """A y below every non-zero error, a decade under the smallest, where zero errors are drawn."""
    positive = [e for e in errors if e > 0]
    return 10.0 ** (np.floor(np.log10(min(positive))) - 1) if positive else 1e-17


def bench_figure(rows: Sequence[BenchRow]) -> Figure:
    """Seconds per problem (log scale), one bar per method/backend or peer; over budget not drawn."""
    from matplotlib import colormaps

    figure = new_figure()
    figure.set_size_inches(11, 5)
    axes = figure.add_subplot()
    problems = list(dict.fromkeys(r.problem for r in rows))
    series = list(dict.fromkeys((r.method, r.backend) for r in rows))
    width, colors = 0.8 / len(series), colormaps["tab20"]
    for k, (method, backend) in enumerate(series):
        xs: list[float] = []
        ys: list[float] = []
        for i, problem in enumerate(problems):
            found = [r.seconds for r in rows if (r.problem, r.method, r.backend) == (problem, method, backend)]
            if found and found[0]:
                xs.append(i - 0.4 + (k + 0.5) * width)
                ys.append(found[0])
        peer = backend == "peer"
        axes.bar(xs, ys, width=width, color=colors(k % 20), hatch="//" if peer else None,
                 label=method if peer else f"{method} / {backend}")
    axes.set_yscale("log")
    axes.set_xticks(range(len(problems)), problems, rotation=20, ha="right", fontsize="small")
    axes.set_ylabel("seconds (median of repeats)")
    axes.set_title("Elimination methods compared (no bar: over budget, failed or skipped)")
    axes.grid(True, axis="y", which="both", linewidth=0.3)
    axes.legend(fontsize="x-small", loc="upper left", bbox_to_anchor=(1.01, 1))
    return figure
