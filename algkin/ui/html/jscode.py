"""Closed forms as JavaScript: one function per branch, shared subexpressions computed once.

sympy's own JavaScript printer writes each expression; ``sympy.cse`` pulls out what the
discriminants and coordinates share. Every scene variable is renamed ``v_<name>`` and
every temporary ``t_<k>``, so no scene name can shadow JavaScript (``Math``, ``v``...).

>>> import sympy
>>> c, l = sympy.symbols("c_angle l")
>>> print(branch_function([l**2 - c**2], [(c, sympy.sqrt(l**2 - c**2))], ["c_angle", "l"]))
function (v) {
  const v_c_angle = v["c_angle"];
  const v_l = v["l"];
  const t_0 = -Math.pow(v_c_angle, 2) + Math.pow(v_l, 2);
  return {disc: [t_0], points: [[v_c_angle, Math.sqrt(t_0)]]};
}
"""

from collections.abc import Sequence

import sympy

__all__ = ["branch_function"]


def branch_function(discriminants: Sequence[sympy.Expr], points: Sequence[tuple[sympy.Expr, sympy.Expr]],
                    variables: Sequence[str]) -> str:
    """JavaScript source of ``function (v) {...}`` returning ``{disc: [...], points: [[x, y], ...]}``.

    ``v`` maps each name in ``variables`` to a number; ``points`` is a list of (x, y)
    sympy expressions, ``discriminants`` a list of expressions that must be >= 0.
    """
    rename = {sympy.Symbol(n): sympy.Symbol(f"v_{n}") for n in variables}
    rename.update({sympy.Symbol(n, real=True): sympy.Symbol(f"v_{n}") for n in variables})
    flat = [sympy.sympify(e).xreplace(rename) for e in [*discriminants, *(v for xy in points for v in xy)]]
    shared, reduced = sympy.cse(flat, symbols=sympy.numbered_symbols("t_"))
    lines = [f'  const v_{n} = v["{n}"];' for n in variables]
    lines += [f"  const {name} = {sympy.jscode(value)};" for name, value in shared]
    code = [sympy.jscode(e) for e in reduced]
    disc, coords = code[:len(discriminants)], code[len(discriminants):]
    pairs = ", ".join(f"[{x}, {y}]" for x, y in zip(coords[::2], coords[1::2]))
    lines.append(f"  return {{disc: [{', '.join(disc)}], points: [{pairs}]}};")
    return "function (v) {\n" + "\n".join(lines) + "\n}"
