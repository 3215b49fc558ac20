"""What every layer may use: budgets (``budget``), work in a forked child process (``child``),
progress reports (``progress``), files written atomically (``files``), argument checks
(``validation``) and text safe to show on a terminal (``terminal``).

The lowest layer but ``algkin.errors``: it imports nothing else of algkin.
"""
