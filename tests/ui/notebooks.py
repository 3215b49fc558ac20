"""Running a notebook in the tests: a kernel on this interpreter (ipykernel), through nbclient."""

import pytest

nbformat = pytest.importorskip("nbformat")
nbclient = pytest.importorskip("nbclient")
pytest.importorskip("ipykernel")

from jupyter_client.kernelspec import NATIVE_KERNEL_NAME, KernelSpecManager  # noqa: E402
from jupyter_client.manager import KernelManager  # noqa: E402


def execute(notebook, timeout=300):
    """Run every cell of ``notebook`` (an nbformat node) in place; a failing cell raises.

    The kernel is this interpreter's own, whatever kernels the machine has installed
    elsewhere: no kernel directory is searched, only ipykernel's native spec (sys.executable).
    """
    specs = KernelSpecManager(kernel_dirs=[], ensure_native_kernel=True)
    manager = KernelManager(kernel_name=NATIVE_KERNEL_NAME, kernel_spec_manager=specs)
    client = nbclient.NotebookClient(notebook, km=manager, timeout=timeout, allow_errors=False)
    client.execute()
    return notebook


def code_notebook(*sources):
    """A notebook of code cells, one per source."""
    return nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(s) for s in sources])


def images(cell):
    """The image outputs of a cell (PNG or SVG), however they were displayed."""
    return [o for o in cell.outputs if {"image/png", "image/svg+xml"} & set(o.get("data", {}))]
