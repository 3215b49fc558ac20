"""hypothesis's entry point (group ``hypothesis``): ``from_type(Scene)`` draws random scenes, those
with points solved together (``strategies.group_scenes``) among them.

hypothesis runs ``setup`` when it is imported; the strategies module loads only when a
``Scene`` is first drawn.

>>> from hypothesis import given, settings, strategies as st
>>> from algkin.scene import Scene
>>> setup()  # hypothesis has run it already, where algkin is installed; again is harmless
>>> @settings(max_examples=5, database=None)
... @given(st.from_type(Scene))
... def check(scene):
...     assert isinstance(scene, Scene) and scene.inputs
>>> check()"""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:  # hypothesis and the scene load when a Scene is first drawn, not with the hook
    from hypothesis import strategies as st

    from ..scene import Scene

__all__ = ["setup"]


def setup() -> None:
    """Register ``algkin.testing.strategies.scenes()`` and ``group_scenes()`` for algkin's ``Scene`` type."""
    from hypothesis import strategies as st

    from ..scene import Scene

    st.register_type_strategy(Scene, st.deferred(_scenes))


def _scenes() -> st.SearchStrategy[Scene]:
    from hypothesis import strategies as st

    from .strategies import group_scenes, scenes

    return st.one_of(scenes(), group_scenes())
