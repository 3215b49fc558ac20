"""Figures from the Python API show in a notebook as images, once, whatever the backend.

Issue 35: ``mechanism_figure(...)`` as a cell's last line showed ``<Figure size 640x440 with
1 Axes>`` and no image unless ``%matplotlib inline`` was on.
"""

import pytest

pytest.importorskip("matplotlib")
formatters = pytest.importorskip("IPython.core.formatters")

from algkin.analyses.motion import Motion  # noqa: E402
from algkin.analyses.quantities import load_quantities  # noqa: E402
from algkin.scene import load_scene_text  # noqa: E402
from algkin.ui.draw import mechanism_figure, modes_figure  # noqa: E402
from algkin.ui.plot import quantity_figure  # noqa: E402

from .notebooks import code_notebook, execute, images  # noqa: E402

PNG = b"\x89PNG\r\n\x1a\n"
CRANK = '''
name = "crank"
[inputs]
angle = { range = [0, 360], unit = "deg" }
[points]
O = { fixed = [0, 0] }
A = { crank = "O", length = 1, input = "angle" }
'''


def shown(figure):
    """What IPython's display machinery makes of ``figure``, without a kernel: {mime type: data}."""
    data, _ = formatters.DisplayFormatter().format(figure)
    return data


def test_a_quantity_figure_is_an_image():
    quantity = load_quantities("arm-string").output("AB")
    data = shown(quantity_figure(quantity, quantity.extremum((0, 90))))
    assert data["image/png"][:8] == PNG


def test_a_mechanism_figure_is_an_image():
    motion = Motion(load_scene_text(CRANK))
    for figure in (mechanism_figure(motion, {"angle": 18}), modes_figure(motion, {"angle": 18})):
        assert shown(figure)["image/png"][:8] == PNG


def test_a_figure_shows_once_whatever_the_backend():
    # One kernel, the backends as a user meets them in turn: none, pyplot imported,
    # %matplotlib inline; then display() by hand, and a figure kept in a name (not shown).
    figure = f"mechanism_figure(Motion(load_scene_text({CRANK!r})), {{'angle': 18}})"
    notebook = execute(code_notebook(
        "from algkin.analyses.motion import Motion\nfrom algkin.scene import load_scene_text\n"
        "from algkin.ui.draw import mechanism_figure",
        figure,
        f"import matplotlib.pyplot\n{figure}",
        f"%matplotlib inline\n{figure}",
        f"display({figure})",
        f"kept = {figure}",
    ))
    assert [len(images(cell)) for cell in notebook.cells] == [0, 1, 1, 1, 1, 0]
