"""The catalog: the scene files shipped with algkin, by name, and what each describes.

Read with the standard library alone (``algkin list`` loads no algebra: no sympy, no flint);
``algkin.scene.load_scene`` loads and checks a scene itself.

>>> "chebyshev-lambda" in catalog_names()
True
>>> dict(catalog_entries())["arm-string"]
'Arm OA about O pulled by a string from A around the fixed point B.'
"""

import os
import sys

if sys.version_info >= (3, 11):
    import tomllib
else:  # Python 3.10
    import tomli as tomllib

__all__ = ["CATALOG", "catalog_names", "catalog_path", "catalog_entries"]

CATALOG = os.path.dirname(__file__)


def catalog_names() -> list[str]:
    """Names of the scenes shipped in the catalog."""
    return sorted(f[:-5] for f in os.listdir(CATALOG) if f.endswith(".toml"))


def catalog_path(name: str) -> str:
    """The file of the catalog scene ``name``."""
    return os.path.join(CATALOG, name + ".toml")


def catalog_entries() -> list[tuple[str, str]]:
    """(name, description) of each catalog scene, in name order, as ``load_scene`` gives them: a
    scene's ``name`` key, else its file's name; its ``description`` key, else empty."""
    entries = []
    for name in catalog_names():
        with open(catalog_path(name), "rb") as handle:
            data = tomllib.load(handle)
        entries.append((data.get("name", name), data.get("description", "")))
    return entries
