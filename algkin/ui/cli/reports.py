"""The text reports a person reads: long forms summarised, scene text escaped, LaTeX lines."""

from __future__ import annotations

import argparse
import math
from collections.abc import Callable, Iterable, Mapping, Sequence
from typing import TYPE_CHECKING, Any

from ...runtime.strict_json import json_text
from ...runtime.terminal import one_line, terminal_safe

if TYPE_CHECKING:
    import sympy

    from ...analyses.extremum import Extremum

__all__ = ["render", "report_show", "report_derive", "report_curve", "report_singular", "report_solve", "report_follow", "report_toggles",
           "report_extremum", "report_accuracy", "verification_line", "latex_lines", "extremum_forms", "terminal_safe",
           "Document", "Form"]

# A command's JSON document (``to_json()``): JSON values of many shapes, read here by key.
Document = Mapping[str, Any]
# A form for --latex: (caption, the sympy expression, the relation after it, e.g. "= 0")
Form = tuple[str, "sympy.Expr", str]


def extremum_forms(found: Extremum) -> list[Form]:
    """The minimum and maximum for ``--latex``; with ``--param``, the closed form and its input."""
    import sympy

    forms = [(f"{key} of {found.output} (at {found.input} = {float(point.input_deg):.12g} deg)",
              sympy.Float(float(point.value), 15), "") for key, point in (("minimum", found.minimum),
                                                                   ("maximum", found.maximum))]
    if found.closed_form is not None:
        forms.append((f"minimum of {found.output} as a closed form", found.closed_form.value, ""))
        if found.closed_form.input is not None:
            forms.append((f"{found.input} at the minimum, in degrees", found.closed_form.input, ""))
    return forms


def report_extremum(d: Document) -> str:
    """``algkin extremum``'s text: the critical points and range ends, the minimum and maximum, the closed form."""
    dims = ", ".join(f"{n} = {v}" for n, v in d["parameters"].items())
    angle = d.get("angle")
    unit = " deg" if angle else ""
    suffix = "_deg" if d["unit"] == "deg" else "_length"  # the input's unit, in the keys and after values
    at = " deg" if d["unit"] == "deg" else ""
    lines = [f"{d['of']} of {d['scene']} over {d['input']} in [{d['range'][0]:g}, {d['range'][1]:g}]{at}"
             + (f" (at {dims})" if dims else "") + ":"]
    if angle:
        lines.append(f"  (an angle in degrees, {angle['degrees']}, found through {angle['via']})")
    lines += [f"  {p['kind']:10} {p['value']:+.12g} as {d['input']} {_towards(p)} {p['enclosure' + suffix]}{at}"
              if "limit" in p else f"  {p['kind']:10} {p['value']:.12g}{unit} at {p['enclosure' + suffix]}{at}"
              for p in d["critical_points"]]
    lines += [f"  {'end':10} {_end_value(p['value'], unit)} at {p['input' + suffix]:g}{at}" for p in d["endpoints"]]
    for key in ("minimum", "maximum"):
        p = d[key]
        if "limit" in p:
            lines.append(f"{key}: {p['limit']}: unbounded near {d['input']} = {p['input' + suffix]:.12g}{at} "
                         f"(a pole: {p['limit']} as {d['input']} {_towards(p)} it)")
            continue
        lines.append(f"{key}: {p['value']:.12g}{unit} at {p['input' + suffix]:.12g}{at} ({p['kind']})")
        if p.get("exact"):
            lines.append(f"  exactly {p['exact']} deg, where {d['angle']['via']} = {p['exact_via']}")
    if "closed_form" in d:
        lines += _report_closed_form(d["closed_form"], d["input"], at)
    return "\n".join(lines)


def _end_value(value: float | None, unit: str) -> str:
    """A range end's value, or that the mechanism does not assemble there (its value nan, null in JSON)."""
    return "(does not assemble)" if value is None or math.isnan(value) else f"{value:.12g}{unit}"


def _towards(point: Document) -> str:
    """How the input comes to a pole the output runs off at: rising to it or falling to it (or at a range end)."""
    return {"below": "rises to", "above": "falls to"}.get(point.get("side", ""), "tends to")


def _report_closed_form(form: Document, name: str, at: str = " deg") -> list[str]:
    lines = ["minimum as a closed form:",
             f"  value = {form['value']}",
             f"  {name} = {form['input']}{at}" + ("  (a range end)" if form["at"] == "endpoint" else ""),
             "  holds for " + " or ".join(form["valid_when"]) if form["regions"]
             else "  holds where " + " and ".join(form["valid_when"]) + " (the defaults' cell)"]
    if len(form["regions"]) > 1:
        lines.append("  elsewhere:")
        for region in form["regions"]:
            where = _interval(region)
            if region["at"] == "nowhere":
                lines.append(f"    {where}: the output is not real anywhere on the range (no assembly)")
                continue
            if region["at"] == "unbounded":
                lines.append(f"    {where}: the output is unbounded (a pole in the range): no extreme")
                continue
            what = {"endpoint": "the minimiser leaves the range; the minimum is at the end",
                    "dead centre": "at the dead centre (where the branch stops assembling)"}.get(region["at"],
                                                                                              "stationary")
            lines.append(f"    {where}: {what} {name} = {region['input']}{at}, value {region['value']}")
    return lines


def _interval(region: Document) -> str:
    lo, hi = region["from"], region["to"]
    return f"({'-oo' if lo is None else f'{lo:.12g}'}, {'oo' if hi is None else f'{hi:.12g}'})"


def report_toggles(d: Document) -> str:
    """``algkin toggles``'s text: each certified toggle, the Grashof class, the dropped artefacts (and limits)."""
    lo, hi = d["range"]
    unit = " deg" if d["unit"] == "deg" else ""
    lines = [f"toggles of {d['scene']} over {d['input']} in [{lo:g}, {hi:g}]{unit}:"]
    lines += [f"  {g['kind']:9} {g['point']} at {g.get('enclosure_deg', g.get('enclosure_length'))}{unit} (certified)"
              for g in d["toggles"]]
    if not d["toggles"]:
        lines.append("  none: every dyad and slider assembles, in both modes apart, over the whole range")
    if d["grashof"]:
        g = d["grashof"]
        bars = ", ".join(f"{k} {v}" for k, v in g["bars"].items())
        lines.append(f"four-bar ({bars}): {g['class']} ({g['rule']}: margin {g['margin']})")
    for artefact in d["artefacts"]:
        lines.append(f"dropped from disc({artefact['eliminant']}): {_brief(artefact['factor'])}: "
                     f"{_brief(' '.join(artefact['why'].split()))}")
    lines += _hint([a["factor"] for a in d["artefacts"]], "full factors: --json")
    if "limits" in d:  # the output's limit positions and time ratio (algkin.analyses.limits)
        lines += _report_limits(d)
    return "\n".join(lines)


def _report_limits(d: Document) -> list[str]:
    """The limit positions (where the output stops and turns back) and the time ratio, after the toggles."""
    lines = ["limit positions (the output stops and turns back), certified:"]
    for g in d["limits"]:
        lines.append(f"  {g['kind']:10} {g['point']} [{g['branch']}]{' *' if g['selected'] else ''} "
                     f"at {g['enclosure_deg']} deg: {g['point']} {_place(g['position'])}")
        lines.append(f"      {d['input']} = {_brief(g['exact_deg'])} deg exactly")
    if not d["limits"]:
        lines.append("  none")
    for skipped in d["limits_skipped"]:
        lines.append(f"  {skipped['point']}: none looked for ({skipped['why']})")
    if d["limits"] and not all(g["selected"] for g in d["limits"]):
        lines.append("  (* on the scene's branch)")
    dropped = [g for g in d["limits_dropped"] if not g["why"].startswith("undecided")]
    for point in dict.fromkeys(g["point"] for g in dropped):
        angles = ", ".join(f"{a:.12g}" for a in sorted({g["input_deg"] for g in dropped if g["point"] == point}))
        lines.append(f"  not limits of {point}: roots of its eliminant at {angles} deg, where no branch stops "
                     "(certified)")
    lines += [f"  UNDECIDED: {g['point']} at {g['input_deg']:.12g} deg: {g['why']}"
              for g in d["limits_dropped"] if g["why"].startswith("undecided")]
    forms = [g["exact_deg"] for g in d["limits"]]
    ratio = d["time_ratio"]
    if ratio is None:
        lines.append(f"time ratio: none ({d['time_ratio_reason']})")
    else:
        lines += _report_time_ratio(ratio)
        forms += [ratio["exact"], *(s["exact"] for s in ratio["strokes"])]
    return lines + _hint(forms, "full exact forms: --json")


def _report_time_ratio(ratio: Document) -> list[str]:
    working, quick = ratio["strokes"]
    lines = [f"time ratio of {ratio['point']} [{ratio['branch']}]: {ratio['ratio']:.15g} "
             f"= (180 + alpha)/(180 - alpha), alpha = {ratio['alpha_deg']:.12g} deg"]
    for stroke in (working, quick):
        lines.append(f"  {stroke['stroke']:7} stroke: {stroke['crank_deg']:.15g} deg of crank, "
                     f"{stroke['from_deg']:.12g} ({stroke['from_kind']}) -> {stroke['to_deg']:.12g} deg "
                     f"({stroke['to_kind']})")
    stroke = ratio["stroke"]
    if stroke["kind"] == "swing":
        what = f"swing {stroke['angle_deg']:.15g} deg about {stroke['about']}"
    else:
        what = f"travel {stroke['length']:.15g}"
    exact = f" = {_brief(stroke['exact'])}" if stroke["exact"] else ""
    lines.append(f"  output stroke: {what}{exact}")
    lines.append(f"  exactly Q = {_brief(ratio['exact'])}")
    return lines


def _place(position: Document) -> str:
    """A limit position in words: the rocker's angle about its pivot, or the slider's place on its line."""
    if "angle_deg" in position:
        return f"at {position['angle_deg']:.12g} deg about {position['about']}"
    direction = ", ".join(position["direction"])
    return f"at {position['along']:.15g} along ({direction})"


def report_accuracy(d: Document) -> str:
    """``algkin accuracy``'s text: one row per strategy and case (time per sample, worst error, condition)."""
    if d.get("solved_together"):
        return _report_group_accuracy(d)
    lines = [f"accuracy of {d['point']} in {d['scene']}; truth: {d['reference']}",
             f"  {'strategy':12} {'case':13} {'samples':>7} {'ns/sample':>10} {'max rel err':>11} "
             f"{'condition':>9} {'err/(k eps)':>11}"]
    lines += [f"  {r['strategy']:12} {r['case']:13} {r['samples']:7} {r['ns_per_sample']:10.1f} "
              f"{r['max_rel_error']:11.2e} {r['condition']:9.2e} {r['error_over_kappa_eps']:11.2e}"
              + (f"\n    note: {r['note']}" if r.get("note") else "") for r in d["rows"]]
    return "\n".join(lines)


def _report_group_accuracy(d: Document) -> str:
    """``report_accuracy`` for points solved together: the modes compared and missed in place of the condition."""
    lines = [f"accuracy of {d['point']} in {d['scene']}; truth: {d['reference']}",
             f"  {'strategy':15} {'case':12} {'samples':>7} {'ns/sample':>11} {'max abs err':>11} {'max rel err':>11} "
             f"{'compared':>8} {'missed':>6}"]
    lines += [f"  {r['strategy']:15} {r['case']:12} {r['samples']:7} {r['ns_per_sample']:11.1f} {r['max_abs_error']:11.2e} "
              f"{r['max_rel_error']:11.2e} {r['compared']:8} {r['missed']:6}"
              + (f"\n    unsolved: {r['unsolved']}" if r.get("unsolved") else "")
              + (f"\n    note: {r['note']}" if r.get("note") else "") for r in d["rows"]]
    return "\n".join(lines + ([f"note: {d['note']}"] if d.get("note") else []))


# The keys of a command's document whose text the user typed (the scene's name, --of, --point, a
# file to write): each shown as one line in the text report, where a newline must not start a line
# that reads as algkin's own.
_TYPED = ("scene", "of", "point", "out", "plot")


def render(args: argparse.Namespace, document: Document, report: Callable[[Document], str]) -> str:
    """What the command prints: ``document`` as JSON with --json, else ``report(document)``, where
    what the user typed (``_TYPED``: the scene's name, a flag's value) is one line.

    >>> from types import SimpleNamespace
    >>> render(SimpleNamespace(json=False), {"out": "a.svg"}, lambda d: d["out"])
    'a.svg\\n'
    >>> render(SimpleNamespace(json=False), {"scene": "x\\nverification passed"}, lambda d: f"scene {d['scene']}")
    'scene x\\\\nverification passed\\n'
    >>> render(SimpleNamespace(json=False), {"of": "dist(A,\\nB)"}, lambda d: f"accuracy of {d['of']}")
    'accuracy of dist(A,\\\\nB)\\n'
    """
    if args.json:
        return json_text(document)
    shown = {key: one_line(value) if key in _TYPED and isinstance(value, str) else value
             for key, value in document.items()}
    return terminal_safe(report(shown)) + "\n"


def report_solve(d: Document) -> str:
    """``algkin solve``'s text: each configuration's mode and points, or that none assembles.

    >>> print(report_solve({"scene": "s", "at": {"t": "30"}, "digits": 5, "configurations": [
    ...     {"mode": "left", "points": {"B": ["1.5", "2.4495"]}, "radius": 1e-40}]}))
    s at t = 30: 1 configuration (5 digits, enclosures within 1e-40)
      left: B = (1.5, 2.4495)
    """
    at = ", ".join(f"{n} = {v}" for n, v in d["at"].items()) or "its only configuration"
    found = d["configurations"]
    named = [f"on the mode the scene names for {', '.join(d['named_modes'])}: {d['left_out']} configuration"
             f"{'s' * (d['left_out'] != 1)} of other modes left out"] if d.get("named_modes") else []
    if not found:
        return "\n".join([f"{d['scene']} at {at}: no configuration: nothing assembles there"] + named)
    radius = max(c["radius"] for c in found)
    lines = [f"{d['scene']} at {at}: {len(found)} configuration{'s' * (len(found) != 1)} "
             f"({d['digits']} digits, enclosures within {radius:.2g})"]
    if "complex_count" in d:
        lines.append(f"  complex solutions of the group's eliminant: {d['complex_count']}")
    lines += [f"  {c['mode']}: " + ", ".join(f"{p} = ({x}, {y})" for p, (x, y) in c["points"].items())
              for c in found]
    return "\n".join(lines + named)


def report_follow(d: Document) -> str:
    """``algkin follow``'s text: how the path ended, then each proven step's end and its points.

    >>> print(report_follow({"scene": "s", "mode": "left", "input": "t", "from": "0", "to": "90", "digits": 5,
    ...     "ended": "meets", "steps": 1, "samples": [{"at": "0", "points": {"B": ["1", "0"]}, "radius": 1e-30}],
    ...     "meeting": {"from": "45", "to": "45.001", "determinant": "[+/- 1e-30]", "holds_zero": True,
    ...                 "proved": True}}))
    s, mode left, t from 0 to 90: meets another mode for t in [45, 45.001] after 1 proven step
      det J there: [+/- 1e-30] (holds 0; the meeting point proved)
      t = 0: B = (1, 0)
    """
    head = f"{d['scene']}, mode {d['mode']}, {d['input']} from {d['from']} to {d['to']}: "
    steps = f"{d['steps']} proven step{'s' * (d['steps'] != 1)}"
    meeting = d["meeting"]
    if meeting is None:
        lines = [head + f"reached {d['to']} in {steps}"]
    else:
        proved = "the meeting point proved" if meeting["proved"] else "where the proof could go no further"
        zero = "holds 0" if meeting["holds_zero"] else "does not hold 0"
        lines = [head + f"meets another mode for {d['input']} in [{meeting['from']}, {meeting['to']}] after {steps}",
                 f"  det J there: {meeting['determinant']} ({zero}; {proved})"]
    lines += [f"  {d['input']} = {s['at']}: " + ", ".join(f"{p} = ({x}, {y})" for p, (x, y) in s["points"].items())
              for s in d["samples"]]
    return "\n".join(lines)


def report_show(d: Document) -> str:
    """``algkin show``'s text: the points, unknowns, parameters, inputs and equations of the scene."""
    lines = [f"scene {d['scene']}: {one_line(d['description'])}",  # a newline in it must not start a line
             *([f"lengths in {d['length_unit']}"] if d.get("length_unit") else []),
             "points: " + ", ".join(f"{n} ({k})" for n, k in d["points"].items()),
             "unknowns: " + ", ".join(d["system"]["unknowns"]),
             "parameters: " + (", ".join(d["system"]["parameters"]) or "none (all exact)"),
             "inputs: " + (", ".join(_input_said(n, v) for n, v in d["inputs"].items()) or "none (a structure)"),
             *[f"geared: {n} = {g['ratio']}*{g['driven_by']}" for n, g in d.get("geared", {}).items()],
             "equations (= 0):"]
    lines += [f"  {eq}" for eq in d["system"]["equations"]]
    lines += [f"never assembles: {point}: {why}" for point, why in d.get("never_assembles", {}).items()]
    for group in d.get("groups", ()):
        lines.append(f"solved together: {', '.join(group['points'])} (unknowns {', '.join(group['unknowns'])}; "
                     f"constraints {', '.join(group['constraints'])})")
    return "\n".join(lines)


def _input_said(name: str, variables: Mapping[str, str]) -> str:
    """An input and its variables: an angle as its (cos, sin), a length as itself.

    >>> _input_said("theta", {"cos": "c_theta", "sin": "s_theta"}), _input_said("s", {"value": "s"})
    ('theta as (c_theta, s_theta)', 's (a length)')
    """
    if "value" in variables:
        return f"{name} (a length)"
    return f"{name} as ({variables['cos']}, {variables['sin']})"


def latex_lines(forms: Iterable[Form]) -> str:
    """Each (caption, sympy expression, relation) as a LaTeX comment and a display equation.

    >>> import sympy
    >>> print(latex_lines([("the radius", sympy.sqrt(2), "")]), end="")
    % the radius
    \\[ \\sqrt{2} \\]
    """
    import sympy

    return "".join(f"% {one_line(caption)}\n\\[ {' '.join([sympy.latex(expr), relation]).strip()} \\]\n"
                   for caption, expr, relation in forms)  # a newline in a caption (an output typed so) ends no comment


def verification_line(v: Document) -> str:
    """A verification (``Verification.to_json()``) in one line, then one line per failure.

    >>> print(verification_line({"status": "skipped"}))
    verification skipped (--samples 0)
    >>> print(verification_line({"status": "passed", "passed": True, "compared": 40, "samples": 20,
    ...                          "max_abs_error": 1e-15, "failures": []}))
    verification passed: 40 branch values on 20 samples, max abs error 1.00e-15
    """
    if v["status"] == "skipped":
        return "verification skipped (--samples 0)"
    verdict = "passed" if v["passed"] else "FAILED"
    line = (f"verification {verdict}: {v['compared']} branch values on {v['samples']} samples, "
            f"max abs error {v['max_abs_error']:.2e}")
    return "\n".join([line] + [f"  {f}" for f in v["failures"]])


def _timings_line(t: Mapping[str, float]) -> str:
    return "timings: " + ", ".join(f"{k} {v * 1e3:.1f} ms" for k, v in t.items())


def report_derive(d: Document) -> str:
    """``algkin derive``'s text: the eliminants' figures, each branch's closed forms, the verification."""
    reduced = "eliminants_reduced" in d  # shorter: c**2 + s**2 gone; the figures stay the eliminated ones
    shown = d["eliminants_reduced"] if reduced else d["eliminants"]
    lines = [f"scene {d['scene']}  (method {d['method']}, backend {d['backend']})",
             "eliminants, reduced on each input's circle c**2 + s**2 = 1 (--json: eliminants as eliminated, "
             "eliminants_reduced):" if reduced else "eliminants:"]
    for unknown, poly in shown.items():
        figures = d["eliminant_figures"][unknown]
        lines.append(f"  {unknown}: {_brief(poly)}")
        lines.append(f"      as eliminated: degree {figures['degree']}, {figures['terms']} terms, "
                     f"{figures['coefficient_bits']}-bit coefficients, "
                     + _dropped(len(figures['dropped_factors'])))
    lines.append("branches:")
    for branch in d["branches"]:
        mark = "  (scene's choice)" if branch["selected"] else ""
        lines.append(f"  [{branch['label']}]{mark} valid when {_brief(branch['valid_when'])}")
        lines += [f"      {u} = {_brief(v)}" for u, v in branch["values"].items()]
    for mode in d.get("modes", ()):
        lines += _mode_lines(mode)
    lines.append(verification_line(d["verification"]))
    forms = [*shown.values(), *(f for b in d["branches"] for f in (b["valid_when"], *b["values"].values()))]
    if "rates" in d:
        lines += _rates_lines(d)
        forms += [f for b in d["rates"].values() for r in b.values() for f in r.values()]
    return "\n".join(lines + [_timings_line(d["timings"])] + _hint(forms))


def _mode_lines(mode: Document) -> list[str]:
    """A named mode: where it was named, the factor it traces, its pieces (each the branch whose
    closed forms are above) and its change points."""
    at = ", ".join(f"{n} = {v}" for n, v in mode["at"].items())
    near = ", ".join(mode["near"])
    traced = f"on the factor {_brief(mode['factor'])} of its curve" if mode["factor"] else \
        f"{mode['label_at']} (no factor of its curve tells its modes apart: the label is held)" if mode["pieces"] else \
        f"{mode['label_at']} (not followed: it moves with several inputs)"
    lines = [f"named mode of {mode['point']} (at {at}, near [{near}]), {traced}:"]
    for piece in mode["pieces"]:
        lo, hi = (piece.get(k, piece.get(k.replace("deg", "length"))) for k in ("from_deg", "to_deg"))
        what = f"[{piece['branch']}]" if piece["branch"] else piece["status"]
        lines.append(f"  {lo:.6g} to {hi:.6g}: {what}")
    for change in mode["change_points"]:
        where = change.get("enclosure_deg", change.get("enclosure_length"))
        lines.append(f"  change point at {where} (a root of {change['polynomial']}): {mode['point']} "
                     f"{change['from']} -> {change['to']}")
    return lines


def _rates_lines(d: Document) -> list[str]:
    """``derive --rates``: per branch, each coordinate's velocity (') and acceleration ('') in the input."""
    name = d["rates_input"]["name"]
    per = "per radian" if d["rates_input"]["per"] == "radian" else "per unit of the length"
    lines = [f"rates in {name} (x' = dx/d{name}, x'' = d2x/d{name}2, {per}: the velocity and "
             "acceleration for a unit input rate):"]
    for label, rates in d["rates"].items():
        lines.append(f"  [{label}]")
        for u, r in rates.items():
            lines += [f"      {u}' = {_brief(r['velocity'])}", f"      {u}'' = {_brief(r['acceleration'])}"]
    v = d["rates_verification"]
    if v["status"] == "skipped":
        return lines + ["rates verification skipped (--samples 0)"]
    verdict = "passed" if v["passed"] else "FAILED"
    lines.append(f"rates verification {verdict}: {v['compared']} branch rates on {v['samples']} samples against "
                 f"central differences of independent numeric solutions, max rel error {v['max_rel_error']:.2e}")
    return lines + [f"  {f}" for f in v["failures"]]


def _dropped(count: int) -> str:
    """How many extraneous factors were dropped, said in words that read when there are none or one.

    >>> _dropped(0), _dropped(1), _dropped(3)
    ('no extraneous factor dropped', 'dropped 1 extraneous factor', 'dropped 3 extraneous factors')
    """
    if not count:
        return "no extraneous factor dropped"
    return f"dropped {count} extraneous factor{'s' if count > 1 else ''}"


def report_curve(d: Document) -> str:
    """``algkin curve``'s text: the curve, its figures, the dropped factors, the verification."""
    lines = [f"curve of {d['point']} in {d['scene']}  (method {d['method']}, backend {d['backend']})",
             f"  {_brief(d['curve'])} = 0",
             f"degree {d['degree']}, circularity {d['circularity']}, "
             f"{'irreducible' if d['irreducible'] else 'reducible'}, {d['terms']} terms, "
             f"{d['coefficient_bits']}-bit coefficients",
             _dropped(len(d["dropped_factors"])) + (":" if d["dropped_factors"] else "")]
    lines += [f"  {_brief(f)}" for f in d["dropped_factors"]]
    for mode in d.get("modes", ()):
        at = ", ".join(f"{n} = {v}" for n, v in mode["at"].items())
        lines.append(f"on the named mode of {mode['point']} (at {at}, near [{', '.join(mode['near'])}]): "
                     f"{len(d['other_modes_dropped'])} of the dropped factors are other modes' paths")
    lines += [verification_line(d["verification"]), _timings_line(d["timings"])]
    return "\n".join(lines + _hint([d["curve"], *d["dropped_factors"]]))


def report_singular(d: Document) -> str:
    """``algkin singular``'s text: each real singular point, its class and exact coordinates."""
    lines = [f"singular points of the curve of {d['point']} in {d['scene']}: degree {d['degree']}, "
             f"circularity {d['circularity']}"]
    for p in d["singular_points"]:
        order = f"A{p['a_k']}, " if p["a_k"] else ""
        tangents = p["tangents"]
        lines += [f"  {p['kind']} ({order}multiplicity {p['multiplicity']}, {tangents['real']} real of "
                  f"{tangents['distinct']} tangents) at ({p['x']:.12g}, {p['y']:.12g})"]
        lines += [f"      {c} = {_brief(p['exact'][c])}" + ("" if p["enclosure"][c] == p["exact"][c]
                                                          else f" in {p['enclosure'][c]}") for c in ("x", "y")]
    if not d["singular_points"]:
        lines.append("  no real singular point")
    for c in d["complex_singular_points"]:
        lines.append(f"  and {c['count']} complex (not real) singular points of multiplicity {c['multiplicity']}")
    lines += [verification_line(d["curve_verification"]), _timings_line(d["timings"])]
    return "\n".join(lines + _hint([p["exact"][c] for p in d["singular_points"] for c in ("x", "y")]))


# A text report is read by a person: a form longer than this is summarised there (its leading
# terms); --json and --out keep every form whole. The seed lambda's sextic (213) stays whole.
_WHOLE = 230


def _brief(form: str) -> str:
    """``form`` whole when short, else its leading terms, ``...`` and its length in characters."""
    if len(form) <= _WHOLE:
        return form
    head = form[:_WHOLE // 2]
    cut = max(head.rfind(" + "), head.rfind(" - "))  # end on a whole term where there is one
    return f"{head[:cut] if cut > 0 else head} ... ({len(form)} characters)"


def _hint(forms: Sequence[str], where: str = "full forms: --json or --out FILE") -> list[str]:
    """The line that says where the whole forms are, when ``_brief`` shortened any of ``forms``."""
    return [where] if any(len(f) > _WHOLE for f in forms) else []


def report_group_derive(d: Document) -> str:
    """``algkin derive``'s text on a scene with points solved together: per group, its eliminant,
    the other unknowns rational in its variable, and each mode's closed form at the reference input."""
    reference = d["reference"]
    lines = [f"scene {d['scene']}  (points solved together: {len(d['groups'])} group(s))"]
    for group in d["groups"]:
        lines.append(f"group {', '.join(group['points'])} ({', '.join(group['constraints'])}):")
        after = f" and {', '.join(group['after'])}" if group.get("after") else ""
        lines.append(f"  eliminant in {group['variable']}, degree {group['degree']} "
                     f"(inputs{after} as parameters; {_dropped(len(group['dropped_factors']))}):")
        lines.append(f"      {_brief(group['eliminant'])} = 0")
        lines += [f"  {u} = {_brief(v)}" for u, v in group["lifts"].items()]
        where = f" at {reference['input']} = {reference['shown']}" if reference else ""
        each = f" ({group['complex_count']} complex for each configuration of {', '.join(group['after'])})" \
            if group.get("after") else f" of {group['complex_count']} complex"
        lines.append(f"  modes{where}: {group['real_modes']} real{each}")
        for mode in group["modes"]:
            lines.append(f"    [{mode['label']}] {group['variable']} = {_brief(mode['values'][group['variable']])}"
                         f" = {mode['value']}")
    lines.append(_group_verification_line(d["verification"]))
    forms = [f for g in d["groups"] for f in (g["eliminant"], *g["lifts"].values())]
    if "rates" in d:
        lines += _group_rates_lines(d)
        forms += [f for g in d["rates"]["groups"] for f in (*g["velocity"].values(), *g["acceleration"].values())]
    return "\n".join(lines + [_timings_line(d["timings"])] + _hint(forms))


def _group_rates_lines(d: Document) -> list[str]:
    """``derive --rates`` on a group scene: per group the forms (the same for every mode), then
    each mode's values at the reference input, and the check."""
    name = d["rates_input"]["name"]
    per = "per radian" if d["rates_input"]["per"] == "radian" else "per unit of the length"
    lines = [f"rates in {name} (x' = dx/d{name}, x'' = d2x/d{name}2, {per}), by the implicit function "
             "theorem on each group's equations, rational in the mode's coordinates:"]
    for group in d["rates"]["groups"]:
        lines.append(f"  group {', '.join(group['points'])}:")
        for u, v in group["velocity"].items():
            lines += [f"      {u}' = {_brief(v)}", f"      {u}'' = {_brief(group['acceleration'][u])}"]
        for label, values in group["modes"].items():
            lines.append(f"    [{label}] " + ", ".join(f"{u}' = {r['velocity']}, {u}'' = {r['acceleration']}"
                                                    for u, r in values.items()))
    v = d["rates_verification"]
    if v["status"] == "skipped":
        return lines + ["rates verification skipped (--samples 0)"]
    verdict = "passed" if v["passed"] else "FAILED"
    lines.append(f"rates verification {verdict}: {v['compared']} modes against central differences of proved "
                 f"numeric solutions, {v['eliminant_compared']} against the eliminant's implicit derivative; "
                 f"max rel error {v['max_rel_error']:.2e}")
    return lines + [f"  {f}" for f in v["failures"][:10]]


def _group_verification_line(v: Document) -> str:
    """The check of a group scene (``algkin.analyses.groups.verify``) in one line, then its failures."""
    if v["status"] == "skipped":
        return "verification skipped (--samples 0)"
    verdict = "passed" if v["passed"] else "FAILED"
    line = (f"verification {verdict}: {v['configurations']} proved numeric solutions on {v['samples']} samples, "
            f"each matched to one mode, none missing, none extra; max abs error {v['max_abs_error']:.2e}")
    return "\n".join([line] + [f"  {f}" for f in v["failures"][:10]])


def report_group_verify(d: Document) -> str:
    """``algkin verify``'s text on a scene with points solved together."""
    return f"scene {d['scene']}\n" + _group_verification_line(d["verification"])


def report_group_curve(d: Document) -> str:
    """``algkin curve``'s text on a scene with points solved together."""
    lines = [f"curve of {d['point']} in {d['scene']}  (points solved together)",
             f"  {_brief(d['curve'])} = 0",
             f"degree {d['degree']}, circularity {d['circularity']}, {len(d['factors'])} factor(s) kept",
             _dropped(len(d["dropped_factors"])) + (":" if d["dropped_factors"] else "")]
    lines += [f"  {_brief(f)}" for f in d["dropped_factors"]]
    v = d["verification"]
    if v["status"] == "skipped":
        lines.append("verification skipped (--samples 0)")
    else:
        lines.append(f"verification {'passed' if v['passed'] else 'FAILED'}: the point at {v['compared']} real "
                     f"modes of sampled inputs on the curve, max abs value {v['max_abs_error']:.2e}")
        lines += [f"  {f}" for f in v["failures"][:10]]
    lines.append(_timings_line(d["timings"]))
    return "\n".join(lines + _hint([d["curve"], *d["dropped_factors"]]))


def report_group_toggles(d: Document) -> str:
    """``algkin toggles``'s text on a scene with points solved together: where its modes meet."""
    lo, hi = d["range"]
    unit = " deg" if d["unit"] == "deg" else ""
    lines = [f"toggles of {d['scene']} over {d['input']} in [{lo:g}, {hi:g}]{unit} (modes meet):"]
    for g in d["toggles"]:
        where = g.get("enclosure_deg", g.get("enclosure_length"))
        said = "certified" if g["certified"] else f"NOT certified: {g['why']}"
        lines.append(f"  {g['kind']} ({g['point']}) at {where}{unit} ({said})")
    if not d["toggles"]:
        lines.append("  none: no two modes meet over the range")
    return "\n".join(lines)
