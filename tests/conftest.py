import os

from hypothesis import settings

settings.register_profile("ci", deadline=None, print_blob=True)
settings.load_profile("ci")

SEEDS = os.path.join(os.path.dirname(__file__), "..", "..", "shared", "seeds")
