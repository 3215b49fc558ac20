"""The README's examples run as written."""

import re
from pathlib import Path

README = Path(__file__).resolve().parents[1] / "README.md"


def python_blocks(section):
    text = README.read_text(encoding="utf-8")
    body = text.split(f"## {section}\n", 1)[1].split("\n## ", 1)[0]
    return re.findall(r"```python\n(.*?)```", body, re.S)


def test_property_based_testing_example_runs():
    (code,) = python_blocks("Property-based testing with algkin")
    namespace = {}
    exec(compile(code, str(README), "exec"), namespace)  # noqa: S102 - our own README
    tests = [f for name, f in namespace.items() if name.startswith("test_")]
    assert len(tests) == 2
    for test in tests:
        test()


def test_make_test_sets_up_the_browser_its_page_tests_drive():
    # On a fresh root machine without chromium, `make test` failed 9 page tests: the README's
    # two commands must pass by themselves, so `make test` runs `make browser` first.
    makefile = (README.parent / "Makefile").read_text(encoding="utf-8")
    (prerequisites,) = re.findall(r"^test:(.*)$", makefile, re.M)
    assert "browser" in prerequisites.split()
    assert "make browser" in README.read_text(encoding="utf-8")
