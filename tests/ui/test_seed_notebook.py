"""The Sage seed notebook redone with algkin's API (docs/notebooks/chebyshev-lambda-seed.ipynb),
run in a kernel: its outputs against the seed's own printed results and against algkin's curve.

The seed ("The Chebyshev Four Bar Mechanism") prints the resultants ``ry`` and ``rx`` of the two
circles and the connector's coordinates ``xv`` (its second solution for x) and ``yv`` (its
first for y); its coupler point is the crank end A = (c, s) reflected through the connector,
2·(xv, yv) − (c, s). The texts below are copied from the seed's outputs.
"""

import math
import pathlib
import re

import pytest
import sympy

from .notebooks import execute, images, nbformat

NOTEBOOK = pathlib.Path(__file__).resolve().parents[2] / "docs" / "notebooks" / "chebyshev-lambda-seed.ipynb"
c, s, x, y = sympy.symbols("c s x y")
SEED_RY = ("4*y^2*c^2 - 16*y^2*c + 4*y^2*s^2 + 16*y^2 - 4*y*c^2*s + 16*y*c*s - 4*y*s^3 - 16*y*s + c^4 - 8*c^3"
           " + 2*c^2*s^2 - c^2 - 8*c*s^2 + 68*c + s^4 + 8*s^2 - 84")
SEED_RX = ("4*x^2*c^2 - 16*x^2*c + 4*x^2*s^2 + 16*x^2 - 4*x*c^3 + 8*x*c^2 - 4*x*c*s^2 + 16*x*c - 8*x*s^2 - 32*x"
           " + c^4 + 2*c^2*s^2 - 8*c^2 + s^4 - 17*s^2 + 16")
SEED_ROOT = "sqrt(-c^4 - s^4 + 8*c^3 - (2*c^2 - 8*c - 17)*s^2 + c^2 - 68*c + 84)"
SEED_XV = f"1/2*(c^3 + (c + 2)*s^2 - 2*c^2 + {SEED_ROOT}*s - 4*c + 8)/(c^2 + s^2 - 4*c + 4)"
SEED_YV = f"1/2*(s^3 + (c^2 - 4*c + 4)*s - {SEED_ROOT}*(c - 2))/(c^2 + s^2 - 4*c + 4)"

pytestmark = pytest.mark.slow  # a kernel and four derivations: about 6 s


def seed(text):
    return sympy.parse_expr(text.replace("^", "**"), local_dict=dict(c=c, s=s, x=x, y=y))


@pytest.fixture(scope="module")
def notebook():
    return execute(nbformat.read(NOTEBOOK, as_version=4))


def cell(notebook, text):
    """The one code cell whose source has ``text``."""
    (found,) = [cell for cell in notebook.cells if cell.cell_type == "code" and text in cell.source]
    return found


def result(notebook, text):
    """The text/plain of the execute_result of the cell with ``text``."""
    (out,) = [o for o in cell(notebook, text).outputs if o.output_type == "execute_result"]
    return out.data["text/plain"]


def printed(notebook, text):
    return "".join(o.text for o in cell(notebook, text).outputs if o.output_type == "stream")


def test_it_runs_without_an_error_or_a_warning(notebook):
    streams = [o for c in notebook.cells if c.cell_type == "code" for o in c.outputs if o.output_type == "stream"]
    assert [o.text for o in streams if o.name == "stderr"] == []
    assert not [o for c in notebook.cells if c.cell_type == "code" for o in c.outputs if o.output_type == "error"]


def test_its_eliminants_are_the_seeds_resultants(notebook):
    names = dict(c_angle=c, s_angle=s, B_x=x, B_y=y)
    for source, theirs in (('eliminations["B_y"]', SEED_RY), ('eliminations["B_x"]', SEED_RX)):
        ours = sympy.parse_expr(result(notebook, source), local_dict=names)
        ratio = sympy.cancel(ours / seed(theirs))
        assert ratio.is_number and ratio != 0


def test_its_coupler_points_are_the_seeds(notebook):
    table = re.findall(r"angle +(\d+)°: P = \((\S+), (\S+)\)", printed(notebook, 'points["P"]'))
    assert len(table) == 12
    xv, yv = sympy.lambdify((c, s), seed(SEED_XV)), sympy.lambdify((c, s), seed(SEED_YV))
    for angle, px, py in table:
        cos, sin = math.cos(math.radians(int(angle))), math.sin(math.radians(int(angle)))
        assert float(px) == pytest.approx(2 * xv(cos, sin) - cos, abs=1e-11)
        assert float(py) == pytest.approx(2 * yv(cos, sin) - sin, abs=1e-11)


def test_its_coupler_curve_is_algkins_and_passes_through_the_seeds_points(notebook):
    import algkin

    X, Y = sympy.symbols("P_x P_y")
    shown = sympy.parse_expr(result(notebook, "coupler.elimination.polynomial"), local_dict=dict(P_x=X, P_y=Y))
    algkins = algkin.curve("chebyshev-lambda", "P").elimination.polynomial
    algkins = algkins.xreplace({v: {"P_x": X, "P_y": Y}[v.name] for v in algkins.free_symbols})  # its symbols are real
    assert sympy.expand(shown - algkins) == 0
    F = sympy.lambdify((X, Y), shown)
    size = sympy.lambdify((X, Y), sympy.sqrt(shown.diff(X) ** 2 + shown.diff(Y) ** 2))
    for angle in range(0, 360, 7):
        cos, sin = math.cos(math.radians(angle)), math.sin(math.radians(angle))
        point = (2 * float(seed(SEED_XV).subs({c: cos, s: sin})) - cos,
                 2 * float(seed(SEED_YV).subs({c: cos, s: sin})) - sin)
        assert abs(F(*point)) <= 1e-9 * size(*point)  # on the curve, to within rounding


def test_its_figures_are_images_and_its_sliders_widgets(notebook):
    figures = [c for c in notebook.cells if c.cell_type == "code" and "mechanism_figure(" in c.source.splitlines()[-1]]
    assert len(figures) == 4 and [len(images(c)) for c in figures] == [1, 1, 1, 1]
    sliders = [c for c in notebook.cells if c.cell_type == "code" and "algkin.interact(" in c.source]
    assert len(sliders) == 4
    for c in sliders:
        assert any("application/vnd.jupyter.widget-view+json" in o.get("data", {}) for o in c.outputs)


def test_it_is_kept_without_outputs():
    # The tests and `make lab` run it; outputs kept in git would only go stale.
    kept = nbformat.read(NOTEBOOK, as_version=4)
    assert all(not c.get("outputs") and c.get("execution_count") is None for c in kept.cells if c.cell_type == "code")
