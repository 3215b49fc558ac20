"""Scenes: TOML loading with the safe expression parser (or built in Python: ``SceneBuilder``),
and compilation to a system plus one spec per implicit point (``implicit``). Below it only
``system``, ``evaluate`` and ``runtime``: a scene knows nothing of elimination or verification."""

from .builder import SceneBuilder
from .compile import Compiled, compile_scene
from .dump import dump_scene
from .load import catalog_names, load_scene, load_scene_text
from .model import Input, Output, Scene
from .settings import with_values

__all__ = ["Scene", "Input", "Output", "Compiled", "compile_scene", "load_scene", "load_scene_text", "catalog_names",
           "dump_scene", "with_values", "SceneBuilder"]
