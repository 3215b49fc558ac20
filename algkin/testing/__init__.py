"""Property-based testing with algkin: hypothesis strategies for random assemblable scenes.

Needs hypothesis (``pip install 'algkin[test]'``); ``import algkin`` alone never imports it.
With algkin installed, hypothesis also knows how to build a ``Scene`` by itself:
``st.from_type(algkin.scene.Scene)`` draws from ``strategies.scenes()``.

>>> from hypothesis import given, settings
>>> from algkin.testing import strategies
>>> @settings(max_examples=5, database=None)
... @given(strategies.four_bars("crank-rocker"))
... def test_has_a_dyad(scene):
...     assert scene.points["B"].branch in ("left", "right")
>>> test_has_a_dyad()
"""

try:
    import hypothesis  # noqa: F401
except ModuleNotFoundError as err:  # a clear message, not a bare "No module named"
    raise ModuleNotFoundError(
        "algkin.testing needs hypothesis, which algkin's 'test' extra installs: "
        "pip install 'algkin[test]' (or pip install hypothesis)", name=err.name) from err

from . import strategies

__all__ = ["strategies"]
