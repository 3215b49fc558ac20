"""The figure every algkin drawing is: a matplotlib ``Figure`` that shows itself in Jupyter.

A plain ``Figure`` made without ``pyplot`` (as algkin makes them, so that drawing changes no
backend) shows as ``<Figure size 640x440 with 1 Axes>`` as a cell's last line unless
``%matplotlib inline`` registered its formatter. ``ShownFigure`` carries its own
``_repr_png_``, which IPython asks for whatever the backend: the figure shows once, as an
image. Where ``%matplotlib inline`` is on, IPython's formatter for ``Figure`` answers
instead of this method (a registered formatter comes first), still once, and ``pyplot``
never shows it again at the end of the cell since it does not know the figure. Imported
only where matplotlib is (``algkin.ui.plot.new_figure``).

>>> figure = ShownFigure()
>>> figure._repr_png_()[:8]
b'\\x89PNG\\r\\n\\x1a\\n'
"""

from __future__ import annotations

import io

from matplotlib.figure import Figure

__all__ = ["ShownFigure"]


class ShownFigure(Figure):
    """A ``Figure`` that Jupyter shows as a PNG image as a cell's last line or through ``display``."""

    def _repr_png_(self) -> bytes:
        """The figure as it stands, as PNG bytes at its own dpi (what IPython displays)."""
        buffer = io.BytesIO()
        self.savefig(buffer, format="png", dpi=self.dpi)
        return buffer.getvalue()
