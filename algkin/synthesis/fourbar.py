"""A synthesized four-bar: its pivots and the precision positions it must reach, and its scene.

Every synthesis ends in the same mechanism: a crank about ``crank_pivot`` (its tip ``A``), a
rocker about ``rocker_pivot`` (its tip ``B``), the coupler ``AB`` carrying a point ``P``. Its
numbers are certified balls (roots of the synthesis equations); the scene written for it holds
their midpoints to ``digits`` significant digits, exact rationals, so the scene is a
mechanism algkin derives like any other, within those digits of the solution.

>>> import flint
>>> design = FourBar("demo", crank_pivot=_exact(0, 0), rocker_pivot=_exact(4, 0),
...                  positions=(Position(_exact(1, 0), _exact(4, 3)),), coupler_point=_exact(2, 2))
>>> print(scene_text(design, branch="left").split("[points]")[1].split("[outputs]")[0].strip())
O = { fixed = ["0", "0"] }
D = { fixed = ["4", "0"] }
A = { crank = "O", length = "a", input = "theta" }
B = { dyad = ["A", "D"], lengths = ["l", "m"], branch = "left" }
P = { frame = ["A", "B"], at = ["p", "q"] }
>>> design.branch_at(0)
'left'
"""

from __future__ import annotations

import re

import attrs
import flint

__all__ = ["FourBar", "Position", "scene_text", "safe_name", "DIGITS", "BITS", "NAME_CHARS"]

Ball2 = tuple[flint.arb, flint.arb]
DIGITS = 40
"""Significant digits of a written scene's numbers."""
NAME_CHARS = 80
"""Characters of a written scene's name at most: it names the scene files too."""
BITS = 192
"""Working precision of the arithmetic on a design's balls (above DIGITS' 133 bits)."""


def _exact(x: int, y: int) -> Ball2:
    return flint.arb(x), flint.arb(y)


@attrs.frozen
class Position:
    """Where the crank tip ``A`` and the rocker tip ``B`` must be at one precision position."""

    crank_tip: Ball2 = attrs.field(eq=False)
    rocker_tip: Ball2 = attrs.field(eq=False)


@attrs.frozen
class FourBar:
    """A four-bar, by its ground pivots, its positions (the scene is written at the first) and
    the coupler point it traces (at the first position; None: the coupler's middle)."""

    name: str
    crank_pivot: Ball2 = attrs.field(eq=False)
    rocker_pivot: Ball2 = attrs.field(eq=False)
    positions: tuple[Position, ...] = attrs.field(eq=False)
    coupler_point: Ball2 | None = attrs.field(eq=False, default=None)

    def crank_angle(self, index: int) -> flint.arb:
        """The crank's angle at position ``index``, in degrees, in (-180, 180]."""
        with flint.ctx.workprec(BITS):
            x, y = _minus(self.positions[index].crank_tip, self.crank_pivot)
            return flint.arb.atan2(y, x) * 180 / flint.arb.pi()

    def branch_at(self, index: int) -> str | None:
        """The dyad's assembly mode at position ``index``: ``left`` where B lies left of the line
        from A to the rocker pivot (algkin's dyad convention), None where the balls cannot tell."""
        position = self.positions[index]
        with flint.ctx.workprec(BITS):
            ux, uy = _minus(self.rocker_pivot, position.crank_tip)
            vx, vy = _minus(position.rocker_tip, position.crank_tip)
            cross = ux * vy - uy * vx
        return "left" if cross > 0 else "right" if cross < 0 else None

    def lengths(self) -> dict[str, flint.arb]:
        """Crank, coupler, rocker and ground, at the first position."""
        first = self.positions[0]
        return {"crank": _distance(first.crank_tip, self.crank_pivot),
                "coupler": _distance(first.rocker_tip, first.crank_tip),
                "rocker": _distance(first.rocker_tip, self.rocker_pivot),
                "ground": _distance(self.rocker_pivot, self.crank_pivot)}


def scene_text(design: FourBar, *, branch: str, digits: int = DIGITS) -> str:
    """The scene file of ``design`` with its dyad on ``branch``, numbers to ``digits`` digits."""
    first = design.positions[0]
    with flint.ctx.workprec(BITS):
        a, b = first.crank_tip, first.rocker_tip
        lengths = design.lengths()
        point = design.coupler_point or ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
        # P = A + p (B - A) + q rot90(B - A): p, q its coordinates in the coupler's frame
        ux, uy = _minus(b, a)
        wx, wy = _minus(point, a)
        norm = ux * ux + uy * uy
        p, q = (wx * ux + wy * uy) / norm, (wy * ux - wx * uy) / norm

    def number(ball: flint.arb) -> str:
        return _decimal(ball, digits)

    return "\n".join([
        f'name = "{safe_name(design.name)}"',
        'description = "A four-bar synthesized by algkin: crank OA, coupler AB, rocker DB, coupler point P."',
        "",
        f"# Numbers to {digits} significant digits of the certified solution.",
        "[parameters]",
        f'a = "{number(lengths["crank"])}"    # crank |OA|',
        f'l = "{number(lengths["coupler"])}"    # coupler |AB|',
        f'm = "{number(lengths["rocker"])}"    # rocker |DB|',
        f'p = "{number(p)}"    # P = A + p*(B - A) + q*rot90(B - A)',
        f'q = "{number(q)}"',
        "",
        "[inputs]",
        'theta = { range = [0, 360], unit = "deg" }',
        "",
        "[points]",
        f'O = {{ fixed = ["{number(design.crank_pivot[0])}", "{number(design.crank_pivot[1])}"] }}',
        f'D = {{ fixed = ["{number(design.rocker_pivot[0])}", "{number(design.rocker_pivot[1])}"] }}',
        'A = { crank = "O", length = "a", input = "theta" }',
        f'B = {{ dyad = ["A", "D"], lengths = ["l", "m"], branch = "{branch}" }}',
        'P = { frame = ["A", "B"], at = ["p", "q"] }',
        "",
        "[outputs]",
        'B = "B"',
        'P = "P"',
        ""])


def safe_name(name: str) -> str:
    """A name from user text, as scene names and files are written: letters, digits, ``-`` and
    ``_`` only, at most NAME_CHARS (it goes into TOML and into file names: no quote, no ``/``, no ``..``).

    >>> safe_name("../../etc/x y"), safe_name("fourbar-poses"), safe_name("/")
    ('etc-x-y', 'fourbar-poses', 'synthesized')
    """
    return re.sub(r"[^A-Za-z0-9_-]+", "-", name).strip("-")[:NAME_CHARS] or "synthesized"


def _decimal(ball: flint.arb, digits: int) -> str:
    """The ball's midpoint to ``digits`` significant digits, as an exact decimal the scene reads."""
    text: str = ball.mid().str(digits, radius=False)
    mantissa, e, exponent = text.partition("e")
    if "." in mantissa:  # 4.000...0 is written 4
        mantissa = mantissa.rstrip("0").rstrip(".")
    return "0" if mantissa in ("0", "-0") else mantissa + e + exponent


def _minus(p: Ball2, q: Ball2) -> Ball2:
    return p[0] - q[0], p[1] - q[1]


def _distance(p: Ball2, q: Ball2) -> flint.arb:
    with flint.ctx.workprec(BITS):
        dx, dy = _minus(p, q)
        return (dx * dx + dy * dy).sqrt()
