"""Scenes written by ``dump_scene`` load back into the same scene."""

import pytest
from hypothesis import given, settings, strategies as st

from algkin.scene import dump_scene, load_scene_text
from algkin.testing import strategies


@pytest.mark.slow
@settings(max_examples=760)
@given(st.one_of(strategies.scenes(), strategies.with_ranges()))
def test_dump_then_load_gives_the_same_scene(scene):
    text = dump_scene(scene)
    again = load_scene_text(text, "again.toml")
    assert again == scene
    assert dump_scene(again) == text  # the text is a fixed point too
