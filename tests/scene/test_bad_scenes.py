"""Bad scene files (docs/scene-format.md) through the command line: exit 2, one line, nothing run.

Each file in ``bad/`` starts with ``# expect: a | b | ...``: words that the error line
must contain (the element and what is wrong), besides the file's own name. Every file is given to
the command line in this process (``main``); one file of each class to ``python -m algkin`` too.
"""

import os
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest

from algkin.scene.load import MAX_SCENE_BYTES

from ..ui.cli.in_process import run_main

ROOT = Path(__file__).resolve().parents[2]
BAD = Path(__file__).resolve().parent / "bad"
FILES = sorted(BAD.glob("*.toml"))

# One file at least for each class of bad scene: syntax, references, cycles, inputs, values...
CLASSES = {
    "syntax_error.toml", "unknown_point.toml", "cycle.toml", "missing_input.toml",
    "negative_length.toml", "zero_length.toml", "never_assembles.toml",
    "expression_import.toml", "expression_call.toml", "unknown_top_key.toml",
    "bad_branch.toml",
}  # plus the oversized file, generated below


def run_cli(args, cwd, timeout=120):
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    return subprocess.run(
        [sys.executable, "-m", "algkin", *map(str, args)],
        cwd=cwd, env=env, capture_output=True, text=True, timeout=timeout,
    )


def expectations(path):
    first = path.read_text(encoding="utf-8").splitlines()[0]
    assert first.startswith("# expect:"), f"{path.name} must start with '# expect: ...'"
    return [word.strip() for word in first[len("# expect:"):].split("|") if word.strip()]


def assert_refused(result, path, words, workdir):
    assert result.returncode == 2, (result.returncode, result.stderr[-2000:])
    assert result.stdout == ""
    assert "Traceback" not in result.stderr
    lines = result.stderr.splitlines()
    assert len(lines) == 1, result.stderr
    line = lines[0]
    assert path.name in line, line
    for word in words:
        assert word.lower() in line.lower(), (word, line)
    assert sorted(os.listdir(workdir)) == [], "the command wrote into its working directory"
    for place in (workdir, workdir.parent, path.parent, ROOT):
        assert not (place / "PWNED").exists()


def test_every_class_has_a_file():
    assert CLASSES <= {f.name for f in FILES}


@pytest.mark.parametrize("path", FILES, ids=[f.stem for f in FILES])
def test_bad_scene_is_refused(path, tmp_path):
    workdir = tmp_path / "cwd"
    workdir.mkdir()
    assert_refused(run_main(["derive", str(path)], workdir), path, expectations(path), workdir)


@pytest.fixture(scope="module")
def derived(tmp_path_factory):
    """``python -m algkin derive`` on a file of each class, run a few at a time in the background;
    one empty working directory each. Maps a file to a future (result, workdir)."""

    def one(path, workdir):
        return run_cli(["derive", path], workdir), workdir

    # mktemp is not thread-safe: make the directories here, run in the pool
    workdirs = {BAD / name: tmp_path_factory.mktemp(f"cwd-{name}") for name in CLASSES}
    with ThreadPoolExecutor(max_workers=max(2, os.cpu_count() or 1)) as pool:
        yield {path: pool.submit(one, path, workdir) for path, workdir in workdirs.items()}


@pytest.mark.parametrize("name", sorted(CLASSES))
def test_a_bad_scene_of_each_class_is_refused_by_its_own_process(name, derived):
    path = BAD / name
    result, workdir = derived[path].result()
    assert_refused(result, path, expectations(path), workdir)


@pytest.mark.parametrize("command", ["show", "curve"])
def test_other_commands_refuse_too(command, tmp_path):
    workdir = tmp_path / "cwd"
    workdir.mkdir()
    path = BAD / "expression_import.toml"
    args = [command, path] + (["--point", "A"] if command == "curve" else [])
    assert_refused(run_cli(args, workdir), path, expectations(path), workdir)


def test_never_assembles_is_refused_by_curve(tmp_path):
    workdir = tmp_path / "cwd"
    workdir.mkdir()
    path = BAD / "never_assembles.toml"
    result = run_cli(["curve", path, "--point", "C"], workdir)
    assert_refused(result, path, ["points.C", "assemble"], workdir)


def test_oversized_file_is_refused(tmp_path):
    scenes = tmp_path / "scenes"
    scenes.mkdir()
    path = scenes / "oversized.toml"
    body = '[points]\nO = { fixed = [0, 0] }\n\n[outputs]\nO = "O"\n'
    padding = "# padding padding padding padding padding padding padding padding\n"
    path.write_text(body + padding * (MAX_SCENE_BYTES // len(padding) + 2), encoding="utf-8")
    assert path.stat().st_size > MAX_SCENE_BYTES
    workdir = tmp_path / "cwd"
    workdir.mkdir()
    result = run_cli(["derive", path], workdir)
    assert_refused(result, path, ["larger", str(MAX_SCENE_BYTES)], workdir)


def test_file_that_is_not_text_is_refused(tmp_path):
    scenes = tmp_path / "scenes"
    scenes.mkdir()
    path = scenes / "binary.toml"
    path.write_bytes(b"\xff\xfe\x00[points]")
    workdir = tmp_path / "cwd"
    workdir.mkdir()
    assert_refused(run_cli(["derive", path], workdir), path, ["UTF-8"], workdir)


def test_parameter_that_cannot_stay_symbolic(tmp_path):
    # With --param a the point O = (1/(a - 400), 0) is rational in a, not polynomial.
    scenes = tmp_path / "scenes"
    scenes.mkdir()
    path = scenes / "rational_in_param.toml"
    path.write_text(
        '[parameters]\na = 400\n[inputs]\nt = {}\n[points]\nO = { fixed = ["1/(a - 401)", 0] }\n'
        'A = { crank = "O", length = 1, input = "t" }\n[outputs]\nd = "A.x"\n',
        encoding="utf-8",
    )
    workdir = tmp_path / "cwd"
    workdir.mkdir()
    assert_refused(run_cli(["derive", path, "--param", "a"], workdir), path, ["--param", "'a'"], workdir)


def test_fifo_is_refused_without_blocking(tmp_path):
    # open() on a FIFO with no writer blocked forever.
    path = tmp_path / "scene.toml"
    os.mkfifo(path)
    workdir = tmp_path / "cwd"
    workdir.mkdir()
    assert_refused(run_cli(["show", path], workdir, timeout=30), path, ["not a regular file"], workdir)


def test_unreadable_file_is_one_line(tmp_path, monkeypatch):
    from algkin.errors import SceneError
    from algkin.scene import load_scene

    path = tmp_path / "secret.toml"
    path.write_text('[points]\nO = { fixed = [0, 0] }\n', encoding="utf-8")

    def refuse(*args, **kwargs):
        raise PermissionError(13, "Permission denied")

    monkeypatch.setattr("builtins.open", refuse)  # chmod 000 does not stop root
    with pytest.raises(SceneError, match="cannot read: Permission denied"):
        load_scene(path)


def test_a_symlink_loop_says_it_cannot_be_read(tmp_path):
    # it was "no such file and no catalog scene of that name": the link is there, it leads nowhere
    from algkin.errors import SceneError
    from algkin.scene import load_scene

    first, second = tmp_path / "first.toml", tmp_path / "second.toml"
    first.symlink_to(second)
    second.symlink_to(first)
    with pytest.raises(SceneError, match=f"^{first}: cannot read: ") as refused:
        load_scene(first)
    assert "catalog" not in str(refused.value)


def test_a_scene_name_of_100000_characters_is_cut_short_in_the_error_line():
    from algkin.errors import SceneError
    from algkin.scene import load_scene

    with pytest.raises(SceneError, match=r"^q{60}\.\.\.\(100000 characters\): no such file") as refused:
        load_scene("q" * 100_000)
    assert len(str(refused.value)) < 2000
