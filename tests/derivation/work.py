"""Counting the work a call does: how many scenes it compiles, branch sets it finds, eliminations it runs.

Each function is replaced, wherever a loaded module holds it (``from ... import`` copies the
name), by one that counts its calls: the count does not depend on where the pipeline finds it.
"""

import collections
import sys

from algkin.branches.closed_form import closed_forms
from algkin.eliminate import eliminate
from algkin.scene.compile import compile_scene

COUNTED = {"compile_scene": compile_scene, "closed_forms": closed_forms, "eliminate": eliminate}


def counting(monkeypatch):
    """A function ``work(call)``: ``call()``'s answer and its counts of the ``COUNTED`` functions' calls."""
    calls = collections.Counter()
    for name, function in COUNTED.items():
        def counted(*args, _name=name, _function=function, **kwargs):
            calls[_name] += 1
            return _function(*args, **kwargs)

        for module in list(sys.modules.values()):
            for attribute, value in list(getattr(module, "__dict__", {}).items()):
                if value is function and (module.__name__ or "").startswith("algkin"):
                    monkeypatch.setattr(module, attribute, counted)

    def work(call):
        calls.clear()
        answer = call()
        return answer, {name: calls[name] for name in COUNTED}

    return work
