r"""A self-contained interactive page: sliders move the mechanism in the browser, no Python behind it.

The page is one HTML file with inline CSS, JavaScript and SVG (no server, no network).
Each branch's closed forms (derived once, dimensions symbolic) are printed as a
JavaScript function (``algkin.html.jscode``); sliders for every input and symbolic
dimension call them, the trajectory is swept the same way, and where a discriminant is
negative the page says the configuration cannot assemble. The drawn positions are
written to ``<output id="state" data-positions=...>`` and to each joint's circle, and the
page reads starting slider values from its URL query (``page.html?angle=30&l=2``), so a
headless browser can check it.

>>> from algkin.motion import Motion
>>> text = page(Motion("chebyshev-lambda"))
>>> text.startswith("<!DOCTYPE html>") and "src=" not in text and "<link" not in text
True
>>> import re   # the only address is SVG's namespace name, which is never fetched
>>> sorted(set(re.findall(r'https?://[^"\s]+', text)))
['http://www.w3.org/2000/svg']
"""

import json
from importlib import resources

from .jscode import branch_function

__all__ = ["page", "model", "slider_range", "write"]


def slider_range(default):
    """Slider bounds around a dimension's default: a quarter to twice it (either sign)."""
    if default == 0:
        return -1.0, 1.0
    lo, hi = sorted((default / 4, 2 * default))
    return lo, hi


def model(motion, inputs=None, branch=None):
    """The page's data: sliders, points, bars, branches (everything but the closed forms)."""
    names = list(motion.points[0])
    starts, _ = motion.complete(inputs or motion.start(branch=branch))
    return {
        "scene": motion.scene.name,
        "description": motion.scene.description,
        "inputs": [{"name": n, "lo": s.range_degrees[0], "hi": s.range_degrees[1], "value": starts[n]}
                   for n, s in motion.inputs.items()],
        "params": [{"name": p, "lo": slider_range(motion.defaults[p])[0], "hi": slider_range(motion.defaults[p])[1],
                    "value": motion.defaults[p]} for p in motion.params],
        "branches": [{"label": b.label, "selected": b.selected, "blocks": list(b.discriminants)}
                     for b in motion.branches],
        "start": motion.branch_index(branch),
        "points": names,
        "bars": [[names.index(p), names.index(q)] for p, q in motion.bars],
        "strings": [[names.index(p), names.index(q)] for p, q in motion.strings],
        "guides": [[names.index(p), names.index(t), dx, dy] for p, t, (dx, dy) in motion.guides],
        "ground": [names.index(g) for g in motion.ground],
        "traced": [names.index(t) for t in motion.traced],
    }


def _functions(motion):
    variables = [name for pair in motion.compiled.system.inputs.values() for name in pair] + list(motion.params)
    return [branch_function(list(b.discriminants.values()), list(forms.values()), variables)
            for b, forms in zip(motion.branches, motion.points)]


def page(motion, inputs=None, branch=None):
    """The HTML text of the interactive page for ``motion`` (a ``Motion``)."""
    folder = resources.files(__name__)
    # "</" cannot appear inside an inline script: escape it in the JSON.
    data = json.dumps(model(motion, inputs, branch)).replace("</", "<\\/")
    script = (f"const MODEL = {data};\nconst BRANCHES = [\n" + ",\n".join(_functions(motion)) + "];\n"
              + folder.joinpath("page.js").read_text(encoding="utf-8"))
    template = folder.joinpath("page.html").read_text(encoding="utf-8")
    return (template.replace("{{title}}", _escape(f"algkin: {motion.scene.name}"))
            .replace("{{description}}", _escape(motion.scene.description))
            .replace("{{style}}", folder.joinpath("page.css").read_text(encoding="utf-8"))
            .replace("{{script}}", script))


def _escape(text):
    return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")


def write(motion, out, inputs=None, branch=None):
    """Write the page to ``out``; returns ``out``."""
    with open(out, "w", encoding="utf-8") as handle:
        handle.write(page(motion, inputs, branch))
    return out
