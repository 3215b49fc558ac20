"""Sphinx configuration: MyST pages, tutorials executed at build time by myst-nb, autodoc."""

project = "algkin"
author = "the algkin developers"
copyright = "2026, the algkin developers"  # without it the footer reads "©." alone
extensions = ["myst_nb", "sphinx.ext.autodoc"]
exclude_patterns = ["_build", "jupyter_execute", "images/README.md", "notebooks"]  # notebooks: run by the tests, opened by make lab
# Every tutorial and command page runs on each build, so none of them can rot; a failing
# cell fails the build.
nb_execution_mode = "force"
nb_execution_raise_on_error = True
nb_execution_timeout = 300
nb_merge_streams = True
# Anything a cell writes to stderr (a warning, a deprecation) becomes a build warning, so an
# error: the pages show only what they mean to.
nb_output_stderr = "warn"
# The site works offline, like algkin's own pages: no script from a CDN. Formulas are shown
# as text (no MathJax), and widgets are built but never rendered (no widget manager).
nb_mime_priority_overrides = [("html", "text/latex", None)]
nb_ipywidgets_js = {}
myst_heading_anchors = 3
autodoc_member_order = "bysource"
autodoc_default_options = {"members": True}
html_theme = "alabaster"
html_title = "algkin"
html_theme_options = {"nosidebar": False}
