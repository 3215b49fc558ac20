"""hypothesis strategies for random *assemblable* scenes with exact rational dimensions.

Every strategy draws dimensions as exact fractions, writes them into scene TOML and reads
it with ``algkin.scene.load_scene_text``: what a test gets is exactly what a scene file
with those numbers gives. Dimensions are parameters (``a``, ``g``, ``l``, ``m``, ... with
exact defaults), so ``compile_scene(scene, params=["l"])`` keeps any of them symbolic;
``with_symbolic`` draws such a choice too.

Four-bars (crank ``a`` about ``O``, ground ``g`` from ``O`` to ``D`` in a random rational
direction, coupler ``l``, rocker ``m``, coupler point ``P`` at ``(p, q)`` in the frame of
``AB``) come by Grashof class, built so that the class holds by construction: with the
sorted lengths ``s <= u <= v <= w``, ``s + w < u + v`` (Grashof, the role of the shortest
link decides the class), ``s + w = u + v`` (change point) or ``s + w > u + v``
(non-Grashof). Every scene assembles on at least ``MIN_ASSEMBLED_DEGREES`` of its input
range, checked in floating point from the lengths alone.

Besides four-bars and slider-cranks: sliders on a moving line (``moving_sliders``: B on the
line through the ground point L and the crank tip A, ``toward``, at ``l`` from L, A or a
ground point Q) and inversor cells (``inversors``: a four-bar's B and its twin E, the other
intersection of the same two circles, with P on the bar AE (a kite) or the rhombus ABPE
closed at P, a Peaucellier cell). Every scene keeps the points O, A (the crank), B and P
(a point of the bar AB, or of the cell) and the outputs ``B`` and ``P``; some carry an angle
output ``phi = "angle(X, B)"`` too, X a point at a fixed distance from B (or
``angle(O, A)``, the crank's own).

Scenes with points solved together (``unknown = true``; ``group_scenes``): 3-RPR parallel
manipulators (``three_rprs``) and Stephenson six-bars driven from the link that closes no
four-bar (``triads``), each built around an assembled design: the pose is drawn first (rational
points, rational unit directions), the fixed joints placed at rational distances from it, so the
design assembles exactly at the middle of its input's range (a length, or a multiple of 90 degrees,
where ``algkin.solve`` takes an angle). ``scenes()`` keeps to the scenes every command takes.

>>> from hypothesis import given, settings
>>> @settings(max_examples=10, database=None)
... @given(four_bars("crank-rocker"))
... def check(scene):
...     assert list(scene.parameters) == ["a", "g", "l", "m", "p", "q"]
...     crank, *others = (scene.parameters[n] for n in "aglm")
...     assert crank < min(others) and crank + max(others) < sum(others) - max(others)
>>> check()
"""

import math
from fractions import Fraction

import attrs
import numpy as np
import sympy
from hypothesis import assume, strategies as st
from numpy.typing import NDArray

from ..scene import Scene, load_scene_text
from ..scene.implicit.base import FloatPoint

Point = tuple[Fraction, Fraction]

__all__ = ["GRASHOF_KINDS", "lengths", "four_bar_lengths", "four_bars", "near_toggle_four_bars",
           "slider_cranks", "moving_sliders", "inversors", "length_driven", "scenes", "with_symbolic",
           "MIN_ASSEMBLED_DEGREES", "three_rprs", "triads", "group_scenes", "design_input"]

# Which link is the shortest decides a Grashof four-bar's class.
_SHORTEST = {"crank-rocker": "crank", "double-crank": "ground", "double-rocker": "coupler",
             "rocker-crank": "rocker"}
GRASHOF_KINDS = tuple(_SHORTEST) + ("change-point", "non-grashof")
_ROLES = ("crank", "ground", "coupler", "rocker")
MIN_ASSEMBLED_DEGREES = 5
_GRID = 720


def lengths(min_value: Fraction = Fraction(1, 2), max_value: Fraction = Fraction(8),
            max_denominator: int = 12) -> st.SearchStrategy[Fraction]:
    """Positive exact lengths (``fractions.Fraction``) with small denominators."""
    return st.fractions(min_value=min_value, max_value=max_value, max_denominator=max_denominator)


def _fraction_in(lo: Fraction, hi: Fraction, steps: int = 16) -> st.SearchStrategy[Fraction]:
    """A fraction strictly inside (lo, hi), on a grid of ``steps`` parts."""
    return st.integers(1, steps - 1).map(lambda k: lo + (hi - lo) * Fraction(k, steps))


def four_bar_lengths(kind: str | None = None) -> st.SearchStrategy[dict[str, Fraction]]:
    """``{crank, ground, coupler, rocker}`` (fractions) of a four-bar of Grashof class ``kind``.

    ``kind`` is one of ``GRASHOF_KINDS`` (any when None).
    """
    if kind is not None and kind not in GRASHOF_KINDS:
        raise ValueError(f"kind={kind!r}: not a four-bar class; valid: {', '.join(GRASHOF_KINDS)}")
    return _four_bar_lengths(kind)


@st.composite
def _four_bar_lengths(draw: st.DrawFn, kind: str | None) -> dict[str, Fraction]:
    kind = draw(st.sampled_from(GRASHOF_KINDS)) if kind is None else kind
    s, u, v = sorted(draw(st.lists(lengths(), min_size=3, max_size=3, unique=True)))
    if kind == "change-point":
        w = u + v - s
    elif kind == "non-grashof":  # u + v - s < w < u + v + s: it still closes somewhere
        w = draw(_fraction_in(u + v - s, u + v + s))
    else:  # v <= w < u + v - s: Grashof, and w still the longest
        w = draw(_fraction_in(v, u + v - s))
    others = draw(st.permutations([u, v, w]))
    if kind in _SHORTEST:
        roles = [r for r in _ROLES if r != _SHORTEST[kind]]
        return dict(zip(roles, others), **{_SHORTEST[kind]: s})
    return dict(zip(_ROLES, draw(st.permutations([s] + others))))


# A rational point of the unit circle, ((1 - t**2), 2 t) / (1 + t**2): the ground's direction.
_directions = st.fractions(min_value=-3, max_value=3, max_denominator=4).map(
    lambda t: ((1 - t * t) / (1 + t * t), 2 * t / (1 + t * t)))
_coordinates = st.fractions(min_value=-5, max_value=5, max_denominator=4)
_frame = st.fractions(min_value=-1, max_value=1, max_denominator=8)


def _q(value: Fraction | int) -> str:
    return f'"{Fraction(value)}"'


def _assembled_degrees(center: Point, crank: Fraction, phase: int, pivot: tuple[Fraction, ...], span_lo: Fraction,
                       span_hi: Fraction) -> float:
    """Degrees of the input turn where |A pivot| lies strictly inside (span_lo, span_hi)."""
    angles = np.radians(np.arange(_GRID) * 360 / _GRID + phase)
    ax, ay = float(center[0]) + float(crank) * np.cos(angles), float(center[1]) + float(crank) * np.sin(angles)
    span = np.hypot(float(pivot[0]) - ax, float(pivot[1]) - ay)
    return np.count_nonzero((float(span_lo) < span) & (span < float(span_hi))) * 360 / _GRID


def _angle_line(angle: tuple[str, str] | None) -> str:
    """The optional angle output's line of ``[outputs]``: ``phi = "angle(X, Y)"``, or nothing."""
    return "" if angle is None else f'phi = "angle({angle[0]}, {angle[1]})"\n'


def _angle_output(pairs: list[tuple[str, str]]) -> st.SearchStrategy[tuple[str, str] | None]:
    """None (no angle output) or one of ``pairs``: two points a fixed distance apart."""
    return st.none() | st.sampled_from(pairs)


def _four_bar_text(bars: dict[str, Fraction], origin: Point, direction: Point, phase: int, at: Point, branch: str,
                   name: str, angle: tuple[str, str] | None = None, extra_points: str = "", p_line: str | None = None,
                   what: str = "four-bar") -> str:
    (ox, oy), (ux, uy) = origin, direction
    return f"""name = "{name}"
description = "random {what}: crank {bars['crank']}, ground {bars['ground']}, coupler {bars['coupler']}, \
rocker {bars['rocker']}"
[parameters]
a = {_q(bars['crank'])}
g = {_q(bars['ground'])}
l = {_q(bars['coupler'])}
m = {_q(bars['rocker'])}
p = {_q(at[0])}
q = {_q(at[1])}
[inputs]
theta = {{ range = [0, 360], unit = "deg" }}
[points]
O = {{ fixed = [{_q(ox)}, {_q(oy)}] }}
D = {{ fixed = ["{ox} + ({ux})*g", "{oy} + ({uy})*g"] }}
A = {{ crank = "O", length = "a", input = "theta", phase = {phase} }}
B = {{ dyad = ["A", "D"], lengths = ["l", "m"], branch = "{branch}" }}
{extra_points}{p_line or 'P = { frame = ["A", "B"], at = ["p", "q"] }'}
[outputs]
B = "B"
P = "P"
{_angle_line(angle)}"""


def _assembles(bars: dict[str, Fraction], origin: Point, direction: Point, phase: int) -> bool:
    pivot = tuple(o + bars["ground"] * d for o, d in zip(origin, direction))
    span = (abs(bars["coupler"] - bars["rocker"]), bars["coupler"] + bars["rocker"])
    return _assembled_degrees(origin, bars["crank"], phase, pivot, *span) >= MIN_ASSEMBLED_DEGREES


def _placed(draw: st.DrawFn, bars: dict[str, Fraction]) -> tuple[Point, Point, int, Point, str]:
    """Where a four-bar of ``bars`` lies (its crank's centre, the ground's direction, the crank's
    phase), assembling over enough of the turn, with a coupler point and a branch."""
    origin = (draw(_coordinates), draw(_coordinates))
    direction = draw(_directions)
    phase = draw(st.sampled_from([0, 90, 180, 270, -90]))
    assume(_assembles(bars, origin, direction, phase))
    return origin, direction, phase, (draw(_frame), draw(_frame)), draw(st.sampled_from(["left", "right"]))


@st.composite
def _four_bar(draw: st.DrawFn, bars: dict[str, Fraction], name: str) -> Scene:
    origin, direction, phase, at, branch = _placed(draw, bars)
    angle = draw(_angle_output([("A", "B"), ("D", "B"), ("O", "A")]))
    return load_scene_text(_four_bar_text(bars, origin, direction, phase, at, branch, name, angle), f"{name}.toml")


def four_bars(kind: str | None = None) -> st.SearchStrategy[Scene]:
    """Four-bar scenes of Grashof class ``kind`` (one of ``GRASHOF_KINDS``; any when None)."""
    return four_bar_lengths(kind).flatmap(lambda bars: _four_bar(bars, f"four-bar-{kind or 'any'}"))


@st.composite
def _near_toggle_lengths(draw: st.DrawFn, digits: tuple[int, int]) -> dict[str, Fraction]:
    # A crank-rocker 10**-k short of the change point (s + w = u + v - 10**-k, the crank the
    # shortest s): at some crank angle the coupler and rocker come within about 10**-k of
    # folding into a line, a toggle the crank passes by without reaching.
    s, u, v = sorted(draw(st.lists(lengths(), min_size=3, max_size=3, unique=True)))
    w = u + v - s - Fraction(1, 10 ** draw(st.integers(*digits)))  # >= v: u - s >= 1/144
    return dict(zip(("ground", "coupler", "rocker"), draw(st.permutations([u, v, w]))), crank=s)


def near_toggle_four_bars(digits: tuple[int, int] = (3, 8)) -> st.SearchStrategy[Scene]:
    """Grashof four-bars ``10**-k`` (k in ``digits``) away from the change point."""
    return _near_toggle_lengths(digits).flatmap(lambda bars: _four_bar(bars, "near-toggle"))


def _crank_and_line(name: str, description: str, r: Fraction, rod: Fraction, at: Point, origin: Point,
                    line: Point) -> str:
    """A slider scene's opening: its dimensions (crank r, rod l, coupler point p, q), its input,
    the crank's centre O and the ground point L of the slider's line."""
    return f"""name = "{name}"
description = "{description}"
[parameters]
r = {_q(r)}
l = {_q(rod)}
p = {_q(at[0])}
q = {_q(at[1])}
[inputs]
theta = {{ range = [0, 360], unit = "deg" }}
[points]
O = {{ fixed = [{_q(origin[0])}, {_q(origin[1])}] }}
L = {{ fixed = [{_q(line[0])}, {_q(line[1])}] }}
"""


def _slider_text(r: Fraction, rod: Fraction, origin: Point, line: Point, direction: tuple[int, int], at: Point,
                 branch: str, angle: tuple[str, str] | None = None) -> str:
    head = _crank_and_line("slider-crank", f"random slider-crank: crank {r}, rod {rod}", r, rod, at, origin, line)
    return head + f"""A = {{ crank = "O", length = "r", input = "theta" }}
B = {{ slider = {{ through = "L", direction = [{direction[0]}, {direction[1]}] }}, \
distance = {{ to = "A", length = "l" }}, branch = "{branch}" }}
P = {{ frame = ["A", "B"], at = ["p", "q"] }}
[outputs]
B = "B"
P = "P"
{_angle_line(angle)}"""


@st.composite
def slider_cranks(draw: st.DrawFn) -> Scene:
    """Slider-cranks: crank ``r`` about ``O``, rod ``l`` to a slider on a line through ``L``.

    The line has a small integer direction; the rod is longer than the crank tip's largest
    distance to the line (by at least 1/8), so the crank turns fully on either branch.
    """
    origin = (draw(_coordinates), draw(_coordinates))
    line = (draw(_coordinates), draw(_coordinates))
    direction = draw(st.tuples(st.integers(-3, 3), st.integers(-3, 3)).filter(lambda d: d != (0, 0)))
    r = draw(lengths(max_value=Fraction(4)))
    # distance from O to the line, in floats: only a lower bound for the rod is needed
    cross = direction[0] * (origin[1] - line[1]) - direction[1] * (origin[0] - line[0])
    reach = abs(cross) / math.hypot(*direction) + float(r)
    rod = Fraction(math.ceil(reach * 8) + 1, 8) + draw(lengths(min_value=Fraction(0), max_value=Fraction(4)))
    at = (draw(_frame), draw(_frame))
    branch = draw(st.sampled_from(["ahead", "behind"]))
    angle = draw(_angle_output([("A", "B"), ("O", "A")]))
    return load_scene_text(_slider_text(r, rod, origin, line, direction, at, branch, angle), "slider-crank.toml")


def _moving_slider_text(r: Fraction, l: Fraction, origin: Point, line: Point, other: Point, through: str, to: str,
                        at: Point, branch: str, angle: tuple[str, str] | None) -> str:
    q = f'Q = {{ fixed = [{_q(other[0])}, {_q(other[1])}] }}\n' if to == "Q" else ""
    toward = "A" if through == "L" else "L"
    head = _crank_and_line("moving-slider", f"random slider on the line through L and the crank tip A: crank {r}, "
                           f"{l} from {to}", r, l, at, origin, line)
    return head + f"""{q}A = {{ crank = "O", length = "r", input = "theta" }}
B = {{ slider = {{ through = "{through}", toward = "{toward}" }}, distance = {{ to = "{to}", length = "l" }}, \
branch = "{branch}" }}
P = {{ frame = ["A", "B"], at = ["p", "q"] }}
[outputs]
B = "B"
P = "P"
{_angle_line(angle)}"""


def _line_meets(origin: Point, r: Fraction, line: Point, other: Point, length: Fraction) -> float:
    """Degrees of the input turn where the line through L and the crank tip A passes within
    ``length`` of ``other`` (by a margin), the tip at least 1/2 from L."""
    angles = np.radians(np.arange(_GRID) * 360 / _GRID)
    ax, ay = float(origin[0]) + float(r) * np.cos(angles), float(origin[1]) + float(r) * np.sin(angles)
    dx, dy = ax - float(line[0]), ay - float(line[1])
    norm = np.hypot(dx, dy)
    gap = np.abs(dx * (float(other[1]) - float(line[1])) - dy * (float(other[0]) - float(line[0]))) / norm
    return np.count_nonzero((gap < float(length) * (1 - 1 / 64)) & (norm > 0.5)) * 360 / _GRID


@st.composite
def moving_sliders(draw: st.DrawFn) -> Scene:
    """Sliders on a moving line: B on the line through the ground point L and the crank tip A
    (``slider = { through = L, toward = A }`` or through A toward L), at ``l`` from L, from A or
    from a ground point Q, ahead or behind; P rigid with AB.

    The crank's circle stays at least 1/2 from L, so the line always has a direction; with Q,
    the line passes within ``l`` of it on at least ``MIN_ASSEMBLED_DEGREES`` of the turn.
    """
    origin, line = (draw(_coordinates), draw(_coordinates)), (draw(_coordinates), draw(_coordinates))
    r = draw(lengths(max_value=Fraction(4)))
    assume(abs(math.hypot(float(line[0] - origin[0]), float(line[1] - origin[1])) - float(r)) >= 0.5)
    through, to = draw(st.sampled_from(["L", "A"])), draw(st.sampled_from(["L", "A", "Q"]))
    other = (draw(_coordinates), draw(_coordinates)) if to == "Q" else line
    length = draw(lengths())
    if to == "Q":
        assume(_line_meets(origin, r, line, other, length) >= MIN_ASSEMBLED_DEGREES)
    at = (draw(_frame), draw(_frame))
    branch = draw(st.sampled_from(["ahead", "behind"]))
    angle = draw(_angle_output([(to, "B"), ("O", "A")]))
    return load_scene_text(_moving_slider_text(r, length, origin, line, other, through, to, at, branch, angle),
                           "moving-slider.toml")


def _twins(bars: dict[str, Fraction], origin: Point, direction: Point, phase: int,
           branch: str) -> tuple[NDArray[np.bool_], FloatPoint, FloatPoint, FloatPoint]:
    """Per assembled grid angle: the crank tip A, B on ``branch`` of A -> D and its twin E (floats)."""
    angles = np.radians(np.arange(_GRID) * 360 / _GRID + phase)
    ax = float(origin[0]) + float(bars["crank"]) * np.cos(angles)
    ay = float(origin[1]) + float(bars["crank"]) * np.sin(angles)
    gx, gy = (float(o + bars["ground"] * d) for o, d in zip(origin, direction))
    dx, dy = gx - ax, gy - ay
    d2 = dx * dx + dy * dy
    l, m = float(bars["coupler"]), float(bars["rocker"])
    along = (l * l - m * m + d2) / (2 * d2)
    with np.errstate(invalid="ignore"):
        across = np.sqrt(l * l / d2 - along * along) * (1 if branch == "left" else -1)
    ok = np.isfinite(across) & (np.abs(across) * np.sqrt(d2) > 1e-3)
    b = (ax + along * dx - across * dy, ay + along * dy + across * dx)
    e = (ax + along * dx + across * dy, ay + along * dy - across * dx)
    return ok, (ax, ay), b, e


@st.composite
def inversors(draw: st.DrawFn) -> Scene:
    """Inversor cells on a four-bar: B (``dyad = [A, D]``) and its twin E, the other intersection
    of the same two circles (the same dyad, the other branch), with P on the bar AE (``kite``)
    or the cell closed at P, the second intersection of the circles of radius ``l`` about B and
    E (``cell``: the rhombus ABPE, P the inverse of A about D; its branch is the side A is not
    on, constant over the turn by construction, a margin kept).
    """
    bars = draw(four_bar_lengths())
    origin, direction, phase, at, branch = _placed(draw, bars)
    other = "right" if branch == "left" else "left"
    twin = f'E = {{ dyad = ["A", "D"], lengths = ["l", "m"], branch = "{other}" }}\n'
    kind = draw(st.sampled_from(["kite", "cell"]))
    if kind == "kite":
        p_line = 'P = { frame = ["A", "E"], at = ["p", "q"] }'
    else:
        ok, a, b, e = _twins(bars, origin, direction, phase, branch)
        # A's side of B -> E, relative to the cell's size: it never comes near the line BE
        cross = ((e[0] - b[0]) * (a[1] - b[1]) - (e[1] - b[1]) * (a[0] - b[0])) / float(bars["coupler"]) ** 2
        assume(np.count_nonzero(ok) and (np.all(cross[ok] > 1e-2) or np.all(cross[ok] < -1e-2)))
        side = "right" if cross[ok][0] > 0 else "left"  # A is left of B -> E: P is on its right
        p_line = f'P = {{ dyad = ["B", "E"], lengths = ["l", "l"], branch = "{side}" }}'
    angle = draw(_angle_output([("A", "B"), ("D", "B"), ("O", "A")]))
    name = f"inversor-{kind}"
    text = _four_bar_text(bars, origin, direction, phase, at, branch, name, angle, twin, p_line,
                          f"{kind} on the four-bar")
    return load_scene_text(text, f"{name}.toml")


@st.composite
def length_driven(draw: st.DrawFn) -> Scene:
    """Scenes driven by a length ``s`` (an actuator, a string), not an angle: a bar OA of length
    ``r`` about the ground point O, with A at ``s`` from the ground point D (``actuator``), or A
    at ``l`` from the slider B = O + s (D - O) (``piston``: B runs along OD). The range of ``s``
    is drawn inside the one where the triangle closes, a margin from its ends (the toggles);
    P is a point of the bar OA, the output ``phi`` its direction.
    """
    origin = (draw(_coordinates), draw(_coordinates))
    toward = (origin[0] + draw(lengths()), origin[1] + draw(_coordinates))
    ground = math.hypot(*(float(toward[k] - origin[k]) for k in (0, 1)))
    r, l = draw(lengths()), draw(lengths())
    kind = draw(st.sampled_from(["actuator", "piston"]))
    # where |OA| = r, |AX| = l close a triangle: |r - l| < |OX| < r + l, X = D or the piston B
    low, high = (abs(float(r) - ground), float(r) + ground) if kind == "actuator" \
        else (abs(float(r - l)) / ground, float(r + l) / ground)
    margin = (high - low) / 16
    assume(high - low > 1e-3 and low + margin > 1e-3)
    lo = Fraction(low + margin).limit_denominator(64)
    hi = Fraction(high - margin).limit_denominator(64)
    assume(low < lo < hi < high)
    a_line = (f'A = {{ dyad = ["O", "D"], lengths = ["r", "s"], branch = "{draw(st.sampled_from(["left", "right"]))}" }}'
              if kind == "actuator" else
              f'B = {{ frame = ["O", "D"], at = ["s", 0] }}\n'
              f'A = {{ dyad = ["O", "B"], lengths = ["r", "l"], branch = "{draw(st.sampled_from(["left", "right"]))}" }}')
    text = f"""name = "length-{kind}"
description = "A bar OA moved by a length s ({kind})."

[parameters]
r = {_q(r)}
l = {_q(l)}
u = {_q(draw(_frame))}

[inputs]
s = {{ range = [{_q(lo)}, {_q(hi)}], unit = "length" }}

[points]
O = {{ fixed = [{_q(origin[0])}, {_q(origin[1])}] }}
D = {{ fixed = [{_q(toward[0])}, {_q(toward[1])}] }}
{a_line}
P = {{ frame = ["O", "A"], at = ["u", 0] }}

[outputs]
A = "A"
P = "P"
phi = "angle(O, A)"
"""
    return load_scene_text(text, f"length-{kind}.toml")


def scenes() -> st.SearchStrategy[Scene]:
    """Any of the above: four-bars of every class, near-toggle four-bars, slider-cranks, sliders on
    a moving line, inversor cells."""
    return st.one_of(four_bars(), near_toggle_four_bars(), slider_cranks(), moving_sliders(), inversors())


@st.composite
def with_ranges(draw: st.DrawFn, scene_strategy: st.SearchStrategy[Scene] | None = None) -> Scene:
    """A scene with declared slider ranges ``lo < hi`` (exact) on some of its parameters, each about
    its default."""
    scene = draw(scene_strategy or scenes())
    names = draw(st.lists(st.sampled_from(sorted(scene.parameters)), unique=True)) if scene.parameters else []
    ranges = {}
    for name in names:
        default, below, above = scene.parameters[name], draw(lengths()), draw(lengths())
        ranges[name] = (default - sympy.Rational(below), default + sympy.Rational(above))
    return attrs.evolve(scene, parameter_ranges=ranges)


def with_symbolic(scene_strategy: st.SearchStrategy[Scene] | None = None,
                  max_symbols: int = 2) -> st.SearchStrategy[tuple[Scene, tuple[str, ...]]]:
    """``(scene, params)``: a scene and 1..``max_symbols`` of its parameters to keep symbolic."""
    scene_strategy = scenes() if scene_strategy is None else scene_strategy
    return scene_strategy.flatmap(lambda scene: st.tuples(st.just(scene), st.lists(
        st.sampled_from(sorted(scene.parameters)), min_size=1, max_size=max_symbols, unique=True).map(tuple)))


def _plus(point: Point, length: Fraction, direction: Point) -> Point:
    return point[0] + length * direction[0], point[1] + length * direction[1]


def _framed(first: Point, second: Point, at: Point) -> Point:
    """``frame = [first, second], at = [u, v]``: ``first + u*(second - first) + v*rot90(second - first)``."""
    dx, dy = second[0] - first[0], second[1] - first[1]
    return first[0] + at[0] * dx - at[1] * dy, first[1] + at[0] * dy + at[1] * dx


def _legs_apart(joints: list[Point], directions: list[Point]) -> bool:
    """Whether three legs (through ``joints``, along ``directions``) hold a rigid body firmly: their
    lines neither meet in one point nor are all parallel (where they do, the design is a toggle)."""
    lines = [(-dy, dx, dy * x - dx * y) for (x, y), (dx, dy) in zip(joints, directions)]
    (a, b, c), (d, e, f), (g, h, i) = lines
    return a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g) != 0


def _fixed(name: str, point: Point) -> str:
    return f"{name} = {{ fixed = [{_q(point[0])}, {_q(point[1])}] }}\n"


def design_input(scene: Scene) -> tuple[str, Fraction]:
    """The input of a drawn group scene and the value where its design assembles: its range's middle.

    >>> from hypothesis import given, settings
    >>> @settings(max_examples=3, database=None, deadline=None)
    ... @given(group_scenes())
    ... def check(scene):
    ...     name, value = design_input(scene)
    ...     assert scene.unknown_points and (value in (90, 180, 270) or not scene.inputs[name].is_angle)
    >>> check()
    """
    (name, spec), = scene.inputs.items()
    lo, hi = spec.span
    return name, Fraction(lo + hi).limit_denominator(1000) / 2


@st.composite
def three_rprs(draw: st.DrawFn) -> Scene:
    """A 3-RPR parallel manipulator: the platform P1 P2 (side ``d``) with P3 rigid with it, on
    three legs from base joints A1, A2, A3 (the first, ``r1``, the input; ``r2``, ``r3`` parameters),
    assembled at ``r1`` in the middle of its range."""
    p1 = (draw(_coordinates), draw(_coordinates))
    d = draw(lengths(Fraction(1), Fraction(6), 4))
    p2 = _plus(p1, d, draw(_directions))
    at = (draw(_frame), draw(_frame.filter(lambda v: v != 0)))  # off the side: a triangle
    p3 = _framed(p1, p2, at)
    legs = [draw(lengths(Fraction(2), Fraction(8), 4)) for _ in range(3)]
    directions = [draw(_directions) for _ in legs]
    assume(_legs_apart([p1, p2, p3], directions))
    bases = [_plus(p, leg, u) for p, leg, u in zip((p1, p2, p3), legs, directions)]
    text = f"""name = "3rpr-drawn"
description = "random 3-RPR: side {d}, legs {', '.join(map(str, legs))}"
[inputs]
r1 = {{ range = [{float(legs[0] - Fraction(1, 2))}, {float(legs[0] + Fraction(1, 2))}], unit = "length" }}
[parameters]
r2 = {_q(legs[1])}
r3 = {_q(legs[2])}
d = {_q(d)}
[points]
{_fixed("A1", bases[0])}{_fixed("A2", bases[1])}{_fixed("A3", bases[2])}P1 = {{ unknown = true }}
P2 = {{ unknown = true }}
P3 = {{ frame = ["P1", "P2"], at = [{_q(at[0])}, {_q(at[1])}] }}
[constraints]
leg1 = "dist(A1, P1) = r1"
leg2 = "dist(A2, P2) = r2"
leg3 = "dist(A3, P3) = r3"
side = "dist(P1, P2) = d"
[outputs]
P3 = "P3"
"""
    return load_scene_text(text, "3rpr-drawn.toml")


_QUARTERS: dict[int, Point] = {90: (Fraction(0), Fraction(1)), 180: (Fraction(-1), Fraction(0)),
                               270: (Fraction(0), Fraction(-1))}  # a quarter turn's cos and sin


@st.composite
def triads(draw: st.DrawFn) -> Scene:
    """A Stephenson six-bar driven from the binary link EF that closes no four-bar: the coupler's
    joints A, B (C rigid with them) on the legs OA, DB and FC, a triad solved together; assembled
    at ``theta`` in the middle of its range (a multiple of 90 degrees)."""
    middle = draw(st.sampled_from(sorted(_QUARTERS)))
    a = (draw(_coordinates), draw(_coordinates))
    coupler = draw(lengths(Fraction(1), Fraction(5), 4))
    b = _plus(a, coupler, draw(_directions))
    at = (draw(_frame), draw(_frame.filter(lambda v: v != 0)))
    c = _framed(a, b, at)
    crank, link, first, second = (draw(lengths(Fraction(1), Fraction(5), 4)) for _ in range(4))
    directions = [draw(_directions) for _ in range(3)]
    assume(_legs_apart([a, b, c], directions))
    o, d, f = (_plus(p, leg, u) for p, leg, u in zip((a, b, c), (first, second, link), directions))
    e = _plus(f, -crank, _QUARTERS[middle])  # F = E + crank*(cos theta, sin theta) at the middle
    text = f"""name = "triad-drawn"
description = "random Stephenson triad: coupler {coupler}, crank {crank}, link {link}, legs {first}, {second}"
[inputs]
theta = {{ range = [{middle - 30}, {middle + 30}], unit = "deg" }}
[parameters]
k = {_q(crank)}
[points]
{_fixed("O", o)}{_fixed("D", d)}{_fixed("E", e)}F = {{ crank = "E", length = "k", input = "theta" }}
A = {{ unknown = true }}
B = {{ unknown = true }}
C = {{ frame = ["A", "B"], at = [{_q(at[0])}, {_q(at[1])}] }}
[constraints]
crank = "dist(O, A) = {first}"
rocker = "dist(D, B) = {second}"
coupler = "dist(A, B) = {coupler}"
link = "dist(C, F) = {link}"
[outputs]
C = "C"
"""
    return load_scene_text(text, "triad-drawn.toml")


def group_scenes() -> st.SearchStrategy[Scene]:
    """Scenes with points solved together: 3-RPRs and Stephenson triads."""
    return st.one_of(three_rprs(), triads())
