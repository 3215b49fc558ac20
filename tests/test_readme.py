"""The README's examples run as written."""

import posixpath
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


def test_make_lab_opens_jupyterlab_with_a_kernel_and_make_test_stays_without_it():
    # Issue 35: the notebook extra installed ipywidgets but no kernel and no Jupyter (.venv/bin/jupyter
    # did not exist). `make lab` installs JupyterLab (the lab extra) and opens it; `make test` does not.
    try:
        import tomllib
    except ImportError:  # Python 3.10
        import tomli as tomllib
    extras = tomllib.loads((README.parent / "pyproject.toml").read_text(encoding="utf-8"))["project"][
        "optional-dependencies"]

    def names(extra):
        return {re.split(r"[<>=!~\[; ]", requirement)[0] for requirement in extras[extra]}

    assert {"jupyterlab", "jupytext", "ipykernel", "ipywidgets", "matplotlib"} <= names("lab")
    assert {"ipykernel", "ipywidgets", "matplotlib"} <= names("notebook")
    assert "jupyterlab" not in names("test") | names("notebook")
    makefile = (README.parent / "Makefile").read_text(encoding="utf-8")
    recipes = dict(re.findall(r"^(\S+):[^=\n]*\n((?:\t.*\n)+)", makefile, re.M))
    assert "jupyter lab" in recipes["lab"]
    assert "'.[lab]'" in recipes["$(LAB_STAMP)"] and "lab" not in recipes["$(STAMP)"]
    assert "make lab" in README.read_text(encoding="utf-8")


def test_every_readme_command_writes_into_the_scratch_directory_it_makes_and_git_ignores():
    # Issue 35: the README's commands wrote curve.json, ab.png, ... into the repository's root,
    # untracked files in `git status`. Each output flag (as the command line's own grammar reads it)
    # names a path in scratch/, which the README makes first and .gitignore leaves out.
    from algkin.ui.cli.parser import build_parser
    from algkin.ui.cli.paths import OUTPUTS

    from .test_readme_walk import COMMANDS, DIRECTORIES

    assert DIRECTORIES == ["scratch"]
    text = README.read_text(encoding="utf-8")
    assert text.index("\nmkdir -p scratch\n") < text.index("\n.venv/bin/algkin ")  # made before any command
    assert "/scratch/" in (README.parent / ".gitignore").read_text(encoding="utf-8").split()
    written = []
    for args, _ in COMMANDS:
        parsed = build_parser().parse_args(args)
        for name, _flag, _kind in OUTPUTS.get(parsed.command, ()):
            path = getattr(parsed, name, None)
            if path is not None:
                written.append(path)
                assert path.startswith("scratch/"), (args, path)
    assert len(written) >= 10, written


def _recipes():
    makefile = (README.parent / "Makefile").read_text(encoding="utf-8")
    return makefile, dict(re.findall(r"^(\S+):[^=\n]*\n((?:\t.*\n)+)", makefile, re.M))


def test_the_pictures_shown_are_drawn_by_the_docs_build_with_the_readmes_commands():
    # Issue 35: the README's picture was not what its own command drew any more. `make docs` draws
    # it again first (`make images`), with the command the README shows under it, character for character.
    text = README.read_text(encoding="utf-8")
    shown = re.findall(r"`(\.venv/bin/algkin [^`]*--out (docs/images/\S+\.png)[^`]*)`", text)
    assert shown, "the README shows no command drawing its picture"
    makefile, recipes = _recipes()
    built = [line.strip().replace("$(BIN)/", ".venv/bin/") for line in recipes["images"].splitlines()]
    assert sorted(command for command, _ in shown) == sorted(built)
    (prerequisites,) = re.findall(r"^docs:(.*)$", makefile, re.M)
    assert "images" in prerequisites.split()
    # every picture the README or the site shows is one of those, or the bench's measured plot
    pictures = {path for _, path in shown}
    for page in [README, *(README.parent / "docs").rglob("*.md")]:
        base = "" if page == README else page.parent.relative_to(README.parent).as_posix() + "/"
        for link in re.findall(r"!\[[^]]*\]\(([^)]+\.png)\)", page.read_text(encoding="utf-8")):
            path = posixpath.normpath(base + link)
            assert path in pictures | {"docs/images/bench.png"}, (page, link)


def test_make_test_slow_runs_the_tests_on_the_machines_clock_alone():
    # make test and make test-slow run in pytest-xdist's workers, two tests at once: the slow set's
    # bounds on the machine's own clock (marked alone) are run after the rest, with no worker beside them.
    _, recipes = _recipes()
    lines = [line.strip() for line in recipes["test-slow"].splitlines()]
    assert lines == ['$(BIN)/python -m pytest -m "slow and not alone" $(XDIST)',
                     '$(BIN)/python -m pytest -m "slow and alone"']
    assert recipes["test"].strip() == '$(BIN)/python -m pytest -m "not slow" $(XDIST)'
