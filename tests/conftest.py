from hypothesis import settings

# Property tests run algebra of varying cost: no per-example deadline, reproducible blobs.
settings.register_profile("ci", deadline=None, print_blob=True)
settings.load_profile("ci")
