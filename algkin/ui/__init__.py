"""Presentation: the command line (``cli``), figures (``plot``, ``draw``), notebook widgets
(``widgets``) and standalone pages (``html``).

The top layer: nothing else in algkin imports it (the import contract in ``.importlinter``
says so, and ``tests/test_architecture.py`` checks it).
"""
