"""``algkin export`` on a scene with points solved together: what is exact, as code, and how a mode is chosen.

A group's closed form is "root k of this polynomial" with the other unknowns rational in it
(``algkin.analyses.groups.derive``). The numpy code holds exactly that: each mode's factor of
the eliminant, its coefficients polynomials in the input's variables (dimensions folded in as
exact rationals), and the lifts. A value is a root of that factor found by ``numpy.roots``; which
root is the mode is decided by continuation: from the mode's root at the reference input (where
``algkin derive`` labels it, as ``algkin solve`` does), the code walks to each input given, in
order, in small steps, each time taking the real root nearest the last one. Where the walk
finds no real root near the last (the mode met another and left the reals) the outputs are
NaN from there on. LaTeX prints the factors and the lifts. C and JavaScript would need a
polynomial root finder written out: refused, in one line, rather than half honest.

>>> code = export_groups("3rpr", None, "numpy")
>>> "def x3rpr_mmm(r1):" in code and "np.roots" in code
True
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

import sympy

from ..analyses.groups.derive import GroupDerivation, GroupForms, derive_groups
from ..errors import UsageError
from ..scene.load import SceneLike, as_scene
from .identifiers import comment, docstring_text, identifiers, latex_text

__all__ = ["export_groups"]

WALK = 256
"""Continuation steps over the input's whole range: a walk's step is at most its span over this."""

_HELPERS = {"algkin_walk", "algkin_roots", "algkin_nan"}

_WALKER = '''
def algkin_roots(coefficients):
    """The real roots of a polynomial (coefficients highest first, leading zeros dropped)."""
    c = np.trim_zeros(np.asarray(coefficients, dtype=float), "f")
    if c.size < 2 or not np.all(np.isfinite(c)):
        return np.empty(0)
    roots = np.roots(c)
    scale = 1.0 + np.abs(roots)
    return np.sort(roots.real[np.abs(roots.imag) <= 1e-7 * scale])


def algkin_walk(coefficients, reference, root, values, step):
    """The mode's root at each of values (in order), walked to in steps of at most step from the
    last value where it was found (first: root at reference), each the real root nearest the
    last; NaN where the walk finds none near (the mode does not exist there)."""
    out = np.full(len(values), np.nan)
    here, last, moved = reference, root, 0.0
    for i, value in enumerate(values):
        if value != value:
            continue
        count = max(1, int(np.ceil(abs(value - here) / step)))
        now, change = last, moved
        for k in range(1, count + 1):
            roots = algkin_roots(coefficients(here + (value - here) * k / count))
            nearest = roots[np.argmin(np.abs(roots - now))] if roots.size else np.nan
            others = roots[roots != nearest]
            gap = np.min(np.abs(others - nearest)) if others.size else np.inf
            jump = abs(nearest - now)
            if not jump == jump or (jump > 0.5 * gap and jump > 10 * change + 1e-9 * (1 + abs(now))):
                now = np.nan  # no real root, or the nearest is another mode's: this one left the reals
                break
            now, change = nearest, jump
        if now == now:
            here, last, moved = value, now, change
            out[i] = now
    return out
'''


def export_groups(scene: SceneLike, outputs: Sequence[str] | None, to: str) -> str:
    """The source text of every mode of ``scene``'s groups evaluating the points ``outputs``."""
    scene = as_scene(scene)
    if to in ("c", "js"):
        raise UsageError("--to", to, "with points solved together a mode is a root of a polynomial found by a root "
                         "finder and continuation: --to numpy writes it, --to latex its forms")
    points = _points(scene, outputs)
    found = derive_groups(scene, samples=0)
    if found.prepared.input is None or found.reference is None:
        raise UsageError("scene", scene.name, "its points solved together move with no input: nothing to export")
    if to == "latex":
        return _latex(found)
    return _numpy(found, points)


def _points(scene: SceneLike, outputs: Sequence[str] | None) -> list[str]:
    scene = as_scene(scene)
    names = list(outputs) if outputs else [p for o in scene.outputs.values() if o.kind == "point" for p in o.points]
    for name in names:
        if name not in scene.points:
            raise UsageError("--outputs", name, "with points solved together export takes points of the scene "
                             f"({', '.join(scene.points)})")
    return names or list(scene.unknown_points)


def _numpy(found: GroupDerivation, points: Sequence[str]) -> str:
    from .groupmotion import GroupMotion

    prepared = found.prepared
    spec = prepared.input
    assert spec is not None
    scene = found.scene
    paths = GroupMotion(scene).paths  # every mode, each with the input where solve labels it
    labels = [p.name for p in paths]
    readable = [label.replace("+", "p").replace("-", "m") for label in labels]  # the sign vector kept in the name
    functions = list(identifiers([f"{scene.name}_{label}" for label in readable], "numpy", taken=_HELPERS).values())
    argument = identifiers([spec.name], "numpy", taken=[*functions, *_HELPERS])[spec.name]
    names = [f"{p}_{axis}" for p in points for axis in "xy"]
    lo, hi = spec.span
    span = (hi - lo) if not spec.is_angle else (hi - lo) * math.pi / 180
    unit = "radians" if spec.is_angle else "a length"
    header = (f"{scene.name}: outputs {', '.join(names)} from {argument} ({unit}"
              + (f", the input {spec.name}" if argument != spec.name else "") + "), one function per mode. "
              "Generated by algkin export.")
    notes = [f"{f}: mode {p.label} at {spec.name} = {spec.shown(float(p.start))} (as algkin solve labels it there)"
             for f, p in zip(functions, paths)]
    notes += ["A mode is a root of its group's eliminant, the other unknowns rational in it. The root is",
              f"followed from that input by continuation (steps of at most the range over {WALK}), through",
              "the inputs in the order given, from the last input where the mode was found; NaN where it does",
              "not exist."]
    lines = [f'"""{docstring_text(header)}', "", *map(docstring_text, notes), '"""', "", "import numpy as np", "",
             _WALKER]
    variables = _variables(spec.is_angle, prepared.variables)
    coordinates = prepared.compiled.coordinates
    for name, path in zip(functions, paths):
        reference = float(path.start) * (math.pi / 180 if spec.is_angle else 1)
        summary = docstring_text(f"Mode {path.name}: ({', '.join(names)}), arrays shaped as the input.")
        lines += ["", f"def {name}({argument}):", f'    """{summary}"""',
                  f"    algkin_flat = np.atleast_1d(np.asarray({argument}, dtype=float)).ravel()"]
        for k, group in enumerate(found.groups):
            point, axis = group.variable.rsplit("_", 1)
            root = float(path.points[point][int(np.argmin(np.abs(path.inputs - float(path.start)))), "xy".index(axis)])
            lines += _group_code(group, root, k, variables=variables, reference=reference, span=span)
            lines += _polish(prepared.compiled.groups[k].equations, group.unknowns, variables)
        lines += [f"    {v} = {e}" for v, e in variables.items()]
        out = [_numpy_expr(sympy.sympify(value), variables) for p in points for value in coordinates[p]]
        lines += ["    with np.errstate(invalid='ignore', divide='ignore'):",
                  "        algkin_values = [" + ", ".join(f"np.broadcast_to({o}, algkin_flat.shape)" for o in out) + "]",
                  f"    return tuple(np.reshape(v, np.shape({argument})) for v in algkin_values)", ""]
    return "\n".join(lines)


def _variables(angle: bool, names: Sequence[str]) -> dict[str, str]:
    """The input's variables as code of the flat input (``algkin_flat``)."""
    if angle:
        c, s = names
        return {f"algkin_{c}": "np.cos(algkin_flat)", f"algkin_{s}": "np.sin(algkin_flat)"}
    return {f"algkin_{names[0]}": "algkin_flat"}


def _numpy_expr(expr: sympy.Expr, variables: dict[str, str]) -> str:
    """``expr`` (in the inputs' variables and the groups' unknowns) as numpy code."""
    rename = {s: sympy.Symbol(f"algkin_{s.name}") for s in expr.free_symbols}
    return sympy.pycode(expr.xreplace(rename), fully_qualified_modules=False).replace("math.", "np.")


def _group_code(group: GroupForms, root: float, index: int, *, variables: dict[str, str], reference: float,
                span: float) -> list[str]:
    """The group's root (``root`` at ``reference``) walked to each input, then its lifts."""
    variable = sympy.Symbol(group.variable)
    eliminant = sympy.Mul(*(_plain(f) for f in group.factors))  # the kept factors, each once
    coefficients = sympy.Poly(sympy.expand(eliminant), variable).all_coeffs()
    inner = {v: e.replace("algkin_flat", "algkin_at") for v, e in variables.items()}
    lines = [f"    def algkin_coefficients_{index}(algkin_at):"]
    lines += [f"        {v} = {e}" for v, e in inner.items()]
    lines += ["        return [" + ", ".join(_numpy_expr(c, variables) for c in coefficients) + "]",
              f"    algkin_{group.variable} = algkin_walk(algkin_coefficients_{index}, {reference!r}, {root!r}, "
              f"algkin_flat, {span / WALK!r})"]
    lines += [f"    {v} = {e}" for v, e in variables.items()]
    lines.append("    with np.errstate(invalid='ignore', divide='ignore'):")
    lines += [f"        algkin_{unknown} = {_numpy_expr(_plain(lift), variables)}" for unknown, lift in group.lifts.items()]
    return lines


def _polish(equations: Sequence[sympy.Expr], unknowns: Sequence[str], variables: dict[str, str]) -> list[str]:
    """Newton steps on the group's own equations from the lifted values: the lifts in floats lose
    digits where their coefficients are large; a step from that close keeps the root and the mode."""
    plain = [e.xreplace({s: sympy.Symbol(s.name) for s in e.free_symbols}) for e in equations]
    names = [sympy.Symbol(u) for u in unknowns]
    jacobian = [[_numpy_expr(sympy.diff(e, u), variables) for u in names] for e in plain]
    size = len(names)
    return [
        f"    algkin_u = np.array([{', '.join(f'np.broadcast_to(algkin_{u}, algkin_flat.shape)' for u in unknowns)}])",
        "    for algkin_step in range(3):",
        *(f"        algkin_{u} = algkin_u[{k}]" for k, u in enumerate(unknowns)),
        "        algkin_F = np.array([" + ", ".join(f"np.broadcast_to({_numpy_expr(e, variables)}, algkin_flat.shape)"
                                             for e in plain) + "])",
        "        algkin_J = np.array([" + ", ".join("[" + ", ".join(f"np.broadcast_to({j}, algkin_flat.shape)" for j in row)
                                             + "]" for row in jacobian) + "]).transpose(2, 0, 1)",
        "        algkin_ok = np.isfinite(algkin_J).all(axis=(1, 2)) & np.isfinite(algkin_F).all(axis=0)",
        f"        algkin_J[~algkin_ok] = np.eye({size})",
        "        algkin_F[:, ~algkin_ok] = 0",
        "        algkin_u = algkin_u - np.linalg.solve(algkin_J, algkin_F.T[..., None])[..., 0].T",
        *(f"    algkin_{u} = algkin_u[{k}]" for k, u in enumerate(unknowns)),
    ]


def _latex(found: GroupDerivation) -> str:
    """Per group: its eliminant's factors, the lifts, and each mode as a root of a factor at the reference."""
    assert found.reference is not None and found.prepared.input is not None
    name = found.prepared.input.name
    lines = [comment(f"{found.scene.name}: per group, the eliminant's factors and the other unknowns rational in "
                     "its variable. Generated by algkin export.", "latex")]
    for group in found.groups:
        variable = sympy.Symbol(group.variable)
        lines += [comment(f"group {', '.join(group.points)}", "latex"), r"\begin{align*}"]
        rows = [rf"F_{{{k + 1}}} &= {sympy.latex(_plain(f))} = 0" for k, f in enumerate(group.factors)]
        rows += [f"{sympy.latex(sympy.Symbol(u))} &= {sympy.latex(_plain(v))}" for u, v in group.lifts.items()]
        rows += [rf"&\text{{mode {latex_text(m.label)}: {sympy.latex(variable)} is root {m.rank} of }} F_{{{m.factor}}}"
                 rf"\text{{ at {latex_text(name)} = {latex_text(found.reference.shown)} (about {m.value})}}"
                 for m in group.modes]
        lines += [" \\\\\n".join(rows), r"\end{align*}", ""]
    return "\n".join(lines)


def _plain(text: str) -> sympy.Expr:
    expr = sympy.sympify(text)
    return expr.xreplace({s: sympy.Symbol(s.name) for s in expr.free_symbols})
