"""A headless chromium for the page tests: find it, load a page, return the dumped DOM's state."""

import html.parser
import json
import os
import shutil
import subprocess
import tempfile

import pytest

NAMES = ("chromium", "chromium-browser", "google-chrome", "chrome")
FLAGS = ("--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
         "--disable-component-update", "--disable-sync", "--no-first-run", "--disable-extensions")


def can_install():
    """apt-get can run: we are root, or sudo exists."""
    return os.geteuid() == 0 or shutil.which("sudo") is not None


def chromium():
    """The browser's path; a skip only where it cannot be installed at all."""
    found = next((shutil.which(n) for n in NAMES if shutil.which(n)), None)
    if found:
        return found
    if not can_install():
        pytest.skip("no chromium, and neither root nor sudo to install it (make browser)")
    pytest.fail("chromium is not installed: run `make browser` (apt-get install chromium)")


class _State(html.parser.HTMLParser):
    """Collects <output id=state> data attributes, joint circles, the status line."""

    def __init__(self):
        super().__init__()
        self.state, self.circles, self.status, self._in_status = {}, {}, "", False

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if tag == "output" and attrs.get("id") == "state":
            self.state = {k[5:]: v for k, v in attrs.items() if k.startswith("data-")}
        if tag == "circle" and "data-point" in attrs:
            self.circles[attrs["data-point"]] = (float(attrs["cx"]), -float(attrs["cy"]))
        self._in_status = tag == "p" and attrs.get("id") == "status"

    def handle_data(self, data):
        if self._in_status:
            self.status += data

    def handle_endtag(self, tag):
        self._in_status = False


def dump_dom(page, query=""):
    """Open ``page`` (a path) with ``query`` in headless chromium; the document after scripts ran."""
    with tempfile.TemporaryDirectory() as profile:
        done = subprocess.run([chromium(), *FLAGS, f"--user-data-dir={profile}", "--dump-dom",
                               page.resolve().as_uri() + query], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr[-2000:]
    return done.stdout


def load(page, query=""):
    """The slider page's state after its scripts ran (``dump_dom``)."""
    return state_of(dump_dom(page, query))


def state_of(dom):
    """The slider page's state in ``dom``, a document ``dump_dom`` gave: (state, joint circles, status)."""
    parser = _State()
    parser.feed(dom)
    assert parser.state, "the page wrote no state: its script did not run"
    state = dict(parser.state)
    state["positions"] = {k: tuple(v) for k, v in json.loads(state["positions"]).items()}
    state["values"] = json.loads(state["values"])
    return state, parser.circles, parser.status.strip()
