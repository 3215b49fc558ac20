import mpmath
import pytest


@pytest.fixture(autouse=True)
def _restore_precision():
    """Tests raise mpmath's precision for hand geometry; put it back even when one fails."""
    saved = mpmath.mp.dps
    yield
    mpmath.mp.dps = saved
