"""Sliders in Jupyter (the seed notebook's ``@interact``, extended): ``algkin.interact(scene)``.

One slider per input and per symbolic dimension, and a choice of assembly mode. The
closed forms are derived once when ``interact`` is called (``algkin.analyses.motion.Motion``,
dimensions symbolic); moving a slider only evaluates them. Where the mechanism cannot
assemble, the picture says so instead of drawing nothing. ipywidgets (the ``notebook``
extra) is imported only here (a module named ``widgets``, so that importing it does not
hide the function ``algkin.interact``); the logic lives in ``Explorer`` and needs no notebook:

>>> explorer = Explorer("fourbar")
>>> [s["name"] for s in explorer.sliders]
['theta', 'a', 'd', 'l', 'm', 'p', 'q']
>>> explorer.pose(theta=180, l=0.75).blocked     # |DA| = 5 > l + m = 4.25
('B',)
>>> explorer.caption(theta=180, l=0.75)
'left: cannot assemble at theta = 180° (B: the two circles never meet)'

A scene with points solved together (``unknown = true``) gets ``GroupExplorer``: one slider,
its input, and the picture ``algkin plot`` draws for it (every real mode at the input, certified
by ``algkin solve``; 'not assembled here' where none exists).
"""

from __future__ import annotations

import functools
import math
import numbers
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

from ..analyses.motion import Motion, Pose
from ..errors import UsageError
from ..scene.load import SceneLike, as_scene
from .html import Slider, parameter_slider

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from .draw import LiveFigure
    from .groupmotion import GroupMotion

# What the sliders give: input names (degrees) and dimension names to numbers, ``branch`` to a label
SliderValues = dict[str, Any]

__all__ = ["interact", "Explorer", "GroupExplorer", "explorer", "slider_ranges"]


class Explorer:
    """What the sliders drive: a ``Motion`` and the picture for any slider values."""

    def __init__(self, scene: SceneLike | Motion, params: Sequence[str] | None = None,
                 ranges: Mapping[str, tuple[float, float]] | None = None) -> None:
        self.motion = scene if isinstance(scene, Motion) else Motion(scene, params)
        self.ranges = slider_ranges(ranges)  # name -> (lo, hi): overrides the scene's declared slider ranges

    @property
    def sliders(self) -> list[Slider]:
        """[{name, lo, hi, value}]: inputs in degrees (starting where the scene assembles), then dimensions."""
        start = self.motion.start()
        inputs = [Slider(name=n, lo=s.span[0], hi=s.span[1], value=start[n])
                  for n, s in self.motion.inputs.items()]
        return inputs + [parameter_slider(self.motion, p, self.ranges) for p in self.motion.params]

    def _split(self, values: SliderValues) -> tuple[dict[str, float], dict[str, float], str | None]:
        branch = values.pop("branch", None)
        inputs = {n: values.pop(n) for n in list(values) if n in self.motion.inputs}
        return inputs, values, branch

    def pose(self, **values: Any) -> Pose:
        """The configuration at slider values (input names in degrees, dimension names, ``branch``)."""
        return self.motion.at(*self._split(dict(values)))

    def caption(self, **values: Any) -> str:
        """One line: the branch, and whether it assembles at these values."""
        return self._caption(self.pose(**values))

    def _caption(self, pose: Pose) -> str:
        angles = ", ".join(f"{n} = {self.motion.inputs[n].shown(v)}" for n, v in pose.inputs.items())
        if pose.assembles:
            return f"{pose.branch}: {angles}"
        reasons = {d.point: d.never_meets for d in self.motion.compiled.implicit}
        why = "; ".join(f"{p}: {reasons[p]}" for p in pose.blocked)
        return f"{pose.branch}: cannot assemble at {angles} ({why})"

    def figure(self, **values: Any) -> Figure:
        """The mechanism at these values with its trajectories (no re-derivation): a new figure."""
        from .draw import mechanism_figure

        inputs, parameters, branch = self._split(dict(values))
        figure = mechanism_figure(self.motion, inputs, parameters, branch, curve=False)
        figure.axes[0].set_title(self.caption(**values), fontsize="medium")
        return figure

    @functools.cached_property
    def live(self) -> LiveFigure:
        """The one figure the sliders move (``algkin.ui.draw.LiveFigure``), captioned like ``figure``."""
        from .draw import LiveFigure

        return LiveFigure(self.motion, title=self._caption)

    def png(self, **values: Any) -> bytes:
        """The picture at these values as PNG bytes (what the notebook shows): the live figure
        moved there and rendered, no new figure.

        >>> Explorer("chebyshev-lambda").png(angle=90)[:8]
        b'\\x89PNG\\r\\n\\x1a\\n'
        """
        self.live.update(*self._split(dict(values)))
        return self.live.png()


class GroupExplorer:
    """What the slider drives on a scene with points solved together: its ``GroupMotion`` (the
    modes' paths found once) and ``groupdraw.modes_figure`` at the slider's value.

    >>> explorer = GroupExplorer("3rpr")
    >>> [(s["name"], s["lo"], s["hi"]) for s in explorer.sliders]
    [('r1', 5.0, 12.0)]
    """

    def __init__(self, scene: SceneLike) -> None:
        from .groupmotion import GroupMotion

        self.motion: GroupMotion = GroupMotion(as_scene(scene))

    @property
    def sliders(self) -> list[Slider]:
        """The one input's slider, starting where the most modes were found."""
        lo, hi = self.motion.input.span
        return [Slider(name=self.motion.input.name, lo=float(lo), hi=float(hi), value=float(self.motion.start()))]

    def _value(self, values: SliderValues) -> float:
        return float(values[self.motion.input.name])

    def figure(self, **values: Any) -> Figure:
        """Every real mode at the slider's value, one panel each (or 'not assembled here'): a new figure."""
        from .groupdraw import modes_figure

        return modes_figure(self.motion, self._value(values))

    def png(self, **values: Any) -> bytes:
        """The picture at the slider's value as PNG bytes (what the notebook shows)."""
        from .plot import image

        return image(self.figure(**values), ".png")


def slider_ranges(ranges: object) -> dict[str, tuple[float, float]] | None:
    """``ranges`` checked: a mapping of names to finite numbers (lo, hi), lo below hi; a UsageError
    naming ``ranges`` otherwise (ipywidgets' own error, or sympy's, came out of a slider made of it).

    >>> slider_ranges({"a": (1, 2.5)})
    {'a': (1.0, 2.5)}
    >>> slider_ranges({"a": (2, 1)})
    Traceback (most recent call last):
    ...
    algkin.errors.UsageError: ranges={'a': (2, 1)}: expected (lo, hi) of each dimension, finite numbers with lo below hi, such as {'a': (0.5, 2)}
    """
    if ranges is None:
        return None
    spans = dict(ranges) if isinstance(ranges, Mapping) else {}
    checked = {name: _span(span) for name, span in spans.items()}
    if not isinstance(ranges, Mapping) or None in checked.values():
        raise UsageError("ranges", ranges, "expected (lo, hi) of each dimension, finite numbers with lo below hi, "
                                           "such as {'a': (0.5, 2)}")
    return {name: span for name, span in checked.items() if span is not None}


def _span(span: object) -> tuple[float, float] | None:
    """``span`` as (lo, hi), finite numbers with lo below hi; None if it is not one."""
    if isinstance(span, (str, bytes)) or not isinstance(span, Sequence) or len(span) != 2:
        return None
    if not all(isinstance(v, numbers.Real) and not isinstance(v, bool) for v in span):
        return None
    lo, hi = float(span[0]), float(span[1])
    return (lo, hi) if math.isfinite(lo) and math.isfinite(hi) and lo < hi else None


def explorer(scene: SceneLike | Motion, params: Sequence[str] | None = None,
             ranges: Mapping[str, tuple[float, float]] | None = None) -> Explorer | GroupExplorer:
    """The sliders' logic for ``scene``: ``GroupExplorer`` for points solved together (no
    dimension sliders: a UsageError for ``params`` or ``ranges``), else ``Explorer``."""
    if isinstance(scene, Motion) or not as_scene(scene).unknown_points:
        return Explorer(scene, params, ranges)
    if params or ranges:
        raise UsageError("params" if params else "ranges", list(params or ranges or ()),
                         "points solved together take their dimensions' values: only the input has a slider")
    return GroupExplorer(scene)


def interact(scene: SceneLike | Motion, params: Sequence[str] | None = None,
             ranges: Mapping[str, tuple[float, float]] | None = None) -> Any:
    """A widget with a slider per input and symbolic dimension driving the drawing.

    ``scene``: a catalog name, a path, a ``Scene`` or a ``Motion``; ``params``: the
    dimensions with sliders (default: every one that keeps the system polynomial);
    ``ranges``: name -> (lo, hi) of a dimension's slider, over the scene's declared range.
    A scene with points solved together gets one slider, its input, and every real mode drawn.
    """
    try:
        import ipywidgets
    except ImportError:
        from ..errors import AlgkinError

        raise AlgkinError("interact needs ipywidgets: pip install 'algkin[notebook]'") from None
    chosen = explorer(scene, params, ranges)
    controls = {s["name"]: ipywidgets.FloatSlider(value=s["value"], min=s["lo"], max=s["hi"],
                                                  step=(s["hi"] - s["lo"]) / 720, description=s["name"],
                                                  continuous_update=False)
                for s in chosen.sliders}
    if isinstance(chosen, Explorer) and len(chosen.motion.branches) > 1:  # a group scene draws every mode
        branches = chosen.motion.branches
        controls["branch"] = ipywidgets.Dropdown(options=[b.label for b in branches],
                                                 value=branches[chosen.motion.selected].label,
                                                 description="mode")

    def picture() -> bytes:
        return chosen.png(**{name: control.value for name, control in controls.items()})

    # One Image widget whose bytes are replaced on a move: the figure behind it is never rebuilt.
    image = ipywidgets.Image(value=picture(), format="png")
    for control in controls.values():
        control.observe(lambda change: setattr(image, "value", picture()), names="value")
    return ipywidgets.VBox([ipywidgets.VBox(list(controls.values())), image])
