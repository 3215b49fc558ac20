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
"""

from __future__ import annotations

import functools
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

from ..analyses.motion import Motion, Pose
from ..scene.load import SceneLike
from .html import Slider, parameter_slider

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from .draw import LiveFigure

# What the sliders give: input names (degrees) and dimension names to numbers, ``branch`` to a label
SliderValues = dict[str, Any]

__all__ = ["interact", "Explorer"]


class Explorer:
    """What the sliders drive: a ``Motion`` and the picture for any slider values."""

    def __init__(self, scene: SceneLike | Motion, params: Sequence[str] | None = None,
                 ranges: Mapping[str, tuple[float, float]] | None = None) -> None:
        self.motion = scene if isinstance(scene, Motion) else Motion(scene, params)
        self.ranges = ranges  # name -> (lo, hi): overrides the scene's declared slider ranges

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


def interact(scene: SceneLike | Motion, params: Sequence[str] | None = None,
             ranges: Mapping[str, tuple[float, float]] | None = None) -> Any:
    """A widget with a slider per input and symbolic dimension driving the drawing.

    ``scene``: a catalog name, a path, a ``Scene`` or a ``Motion``; ``params``: the
    dimensions with sliders (default: every one that keeps the system polynomial);
    ``ranges``: name -> (lo, hi) of a dimension's slider, over the scene's declared range.
    """
    try:
        import ipywidgets
    except ImportError:
        from ..errors import AlgkinError

        raise AlgkinError("interact needs ipywidgets: pip install 'algkin[notebook]'") from None
    explorer = Explorer(scene, params, ranges)
    controls = {s["name"]: ipywidgets.FloatSlider(value=s["value"], min=s["lo"], max=s["hi"],
                                                  step=(s["hi"] - s["lo"]) / 720, description=s["name"],
                                                  continuous_update=False)
                for s in explorer.sliders}
    branches = explorer.motion.branches
    if len(branches) > 1:
        controls["branch"] = ipywidgets.Dropdown(options=[b.label for b in branches],
                                                 value=branches[explorer.motion.selected].label,
                                                 description="mode")

    def picture() -> bytes:
        return explorer.png(**{name: control.value for name, control in controls.items()})

    # One Image widget whose bytes are replaced on a move: the figure behind it is never rebuilt.
    image = ipywidgets.Image(value=picture(), format="png")
    for control in controls.values():
        control.observe(lambda change: setattr(image, "value", picture()), names="value")
    return ipywidgets.VBox([ipywidgets.VBox(list(controls.values())), image])
