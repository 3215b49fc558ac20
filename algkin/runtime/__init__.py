"""What every layer may use: budgets (``budget``), work in a forked child process (``child``),
progress reports (``progress``), files written atomically (``files``), argument checks
(``validation``), text safe to show on a terminal (``terminal``), strict JSON (``strict_json``)
and the stopping signals received (``stopping``).

The lowest layer but ``algkin.errors``: it imports nothing else of algkin.
"""
