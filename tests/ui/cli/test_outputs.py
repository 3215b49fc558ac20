"""Where a command writes (docs/cli/index.md): an output that cannot be written, or that is one of the
command's inputs, is refused with one line and exit 2 before any work, nothing written; a
stdout that cannot be written is one line and exit 1, with no traceback."""

import os
import signal
from pathlib import Path

import pytest

from algkin.ui.cli import main

from ...processes import ENV, algkin, finish, run, start

LONG = "n" * 300  # past every file system's 255 bytes a name
SCENE = ["chebyshev-lambda", "--samples", "0"]
# Each command with an output file: its argv up to the file's name, and the flag that names it.
WRITERS = [(["derive", *SCENE, "--out"], "--out"), (["curve", "chebyshev-lambda", "--point", "P", "--out"], "--out"),
           (["plot", "chebyshev-lambda", "--out"], "--out"), (["export", "chebyshev-lambda", "--to", "c", "--out"], "--out"),
           (["accuracy", "chebyshev-lambda", "--samples", "10", "--plot"], "--plot")]
AS_ROOT = hasattr(os, "geteuid") and os.geteuid() == 0


def one_line(err):
    return err.count("\n") == 1 and err.endswith("\n") and "Traceback" not in err


def _refused(capsys, argv, flag, why):
    """Run ``argv`` in this process: exit 2, one line naming ``flag`` and saying ``why``, nothing on stdout."""
    assert main(argv) == 2
    out, err = capsys.readouterr()
    assert out == "" and one_line(err) and err.startswith(f"algkin: error: {flag}=") and why in err, err


@pytest.mark.parametrize("argv,flag", WRITERS, ids=[w[0][0] for w in WRITERS])
@pytest.mark.parametrize("name,why", [(LONG + ".png", "File name too long"),
                                      ("new.png/", "names a directory"),
                                      ("", "is empty")], ids=["too-long", "trailing-slash", "empty"])
def test_an_output_name_that_cannot_be_a_file_is_refused(tmp_path, monkeypatch, capsys, argv, flag, name, why):
    monkeypatch.chdir(tmp_path)
    _refused(capsys, [*argv, name], flag, why)
    assert os.listdir(tmp_path) == []


def test_an_output_directory_name_too_long_is_refused(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    _refused(capsys, ["bench", "--problems", "fourbar", "--out", f"{LONG}/bench"], "--out", "File name too long")
    assert os.listdir(tmp_path) == []


@pytest.mark.skipif(not os.path.isdir("/proc/self"), reason="/proc: a directory where no one, root included, makes a file")
@pytest.mark.parametrize("argv,flag", WRITERS[:2] + [(["bench", "--problems", "fourbar", "--out"], "--out")],
                         ids=["derive", "curve", "bench"])
def test_an_output_in_a_directory_that_takes_no_file_is_refused(capsys, argv, flag):
    _refused(capsys, [*argv, "/proc/algkin-out"], flag, "cannot make a ")


@pytest.mark.skipif(AS_ROOT, reason="root writes in read-only folders anyway")
def test_an_output_in_a_read_only_directory_is_refused(tmp_path, capsys):
    locked = tmp_path / "locked"
    locked.mkdir()
    locked.chmod(0o555)
    try:
        _refused(capsys, ["derive", *SCENE, "--out", str(locked / "x.json")], "--out", "not writable")
    finally:
        locked.chmod(0o755)


CATALOG = Path(__file__).resolve().parents[3] / "algkin" / "catalog"


@pytest.fixture
def scene(tmp_path, monkeypatch):
    """A scene file in the current directory, ``scene.toml``, with a link and a hard link to it."""
    monkeypatch.chdir(tmp_path)
    source = Path("scene.toml")
    source.write_text(next(CATALOG.glob("**/chebyshev-lambda.toml")).read_text())
    Path("link.toml").symlink_to("scene.toml")
    os.link("scene.toml", "hard.toml")
    return source


@pytest.mark.parametrize("argv,flag", WRITERS, ids=[w[0][0] for w in WRITERS])
@pytest.mark.parametrize("name", ["scene.toml", "./scene.toml", "link.toml", "hard.toml"])
def test_no_command_writes_over_its_scene(scene, capsys, argv, flag, name):
    before = scene.read_bytes()
    _refused(capsys, [argv[0], "scene.toml", *argv[2:], name], flag, "is the input scene.toml")
    assert scene.read_bytes() == before and sorted(os.listdir()) == ["hard.toml", "link.toml", "scene.toml"]


def test_a_sweep_directory_is_no_sweeps_scene(scene, capsys):
    _refused(capsys, ["sweep", "scene.toml", "--grid", "a=1:2:2", "--executor", "serial", "--out", "scene.toml"],
             "--out", "is the input scene.toml")


@pytest.mark.parametrize("name,why", [("designs.parquet", "is inside the input directory"),
                                      ("atlas.html", "is inside the input directory"),
                                      (".", "is the input")])
def test_the_atlas_is_not_written_into_the_sweep_it_reads(tmp_path, monkeypatch, capsys, name, why):
    monkeypatch.chdir(tmp_path)
    sweep = Path("sweep")
    sweep.mkdir()
    (sweep / "designs.parquet").write_bytes(b"PAR1 the dataset PAR1")
    _refused(capsys, ["atlas", "sweep", "--out", str(sweep / name)], "--out", why)
    assert os.listdir(sweep) == ["designs.parquet"] and (sweep / "designs.parquet").read_bytes().startswith(b"PAR1")


NO_SPACE = "algkin: cannot write to standard output: No space left on device\n"


@pytest.mark.skipif(not os.path.exists("/dev/full"), reason="needs /dev/full")
@pytest.mark.parametrize("args", [("list",), ("derive", "chebyshev-lambda", "--outputs", "B", "--samples", "3", "--json")],
                         ids=["list", "derive-json"])
def test_a_full_stdout_is_one_line_and_exit_1(args):
    with open("/dev/full", "w") as full:
        process = start(algkin(*args), stdout=full)
    code, _, err, _ = finish(process, timeout=120)
    assert (code, err) == (1, NO_SPACE)


@pytest.mark.skipif(not os.path.exists("/dev/full"), reason="needs /dev/full")
def test_a_full_stdout_after_an_error_keeps_the_errors_line_and_code():
    with open("/dev/full", "w") as full:
        process = start(algkin("derive", "no-such-scene", "--json"), stdout=full)
    code, _, err, _ = finish(process, timeout=120)
    assert code == 2 and one_line(err) and err.startswith("algkin: error: no-such-scene: no such file"), err


def test_a_closed_stdout_is_one_line_and_exit_1_before_any_work():
    process = start(algkin("derive", "stephenson-iii"), stdout=None, preexec_fn=lambda: os.close(1))
    code, _, err, _ = finish(process, timeout=120)
    assert (code, err) == (1, "algkin: cannot write to standard output: it is closed\n")


def test_a_reader_that_goes_away_ends_it_quietly():
    # `algkin list | head -1`: what a shell reports of a program the closed pipe ended
    read, write = os.pipe()
    os.close(read)
    try:
        process = start(algkin("list"), stdout=write)
    finally:
        os.close(write)
    code, _, err, _ = finish(process, timeout=120)
    assert (code, err) == (128 + signal.SIGPIPE, "")


def test_a_command_that_writes_is_still_fine(tmp_path):
    # the checks refuse no ordinary output: a long name within the limit, a new file beside the scene
    name = tmp_path / ("n" * 240 + ".json")
    code, out, err, _ = run(algkin("derive", *SCENE, "--outputs", "B", "--out", name), timeout=120)
    assert (code, err) == (0, "") and name.read_text().startswith("{")


# The environment: numba's kernel cache and settings (accuracy evaluates a compiled kernel; the arm's, of
# one dyad, compiles in half the lambda's time, through the same cache).
ACCURACY = ("accuracy", "arm-string", "--samples", "10")


@pytest.mark.skipif(not os.path.isdir("/proc/self"), reason="/proc: a directory where no one makes a file")
def test_a_cache_home_that_cannot_be_written_is_not_used(monkeypatch):
    monkeypatch.setitem(ENV, "XDG_CACHE_HOME", "/proc/algkin-cache")
    monkeypatch.delitem(ENV, "ALGKIN_CACHE_DIR", raising=False)
    process = start(algkin(*ACCURACY))
    code, out, err, _ = finish(process, timeout=300)
    assert (code, err) == (0, "") and "compiled" in out


def test_a_bad_numba_setting_is_one_line_and_exit_2(monkeypatch):
    monkeypatch.setitem(ENV, "NUMBA_NUM_THREADS", "0")
    process = start(algkin(*ACCURACY))
    code, out, err, _ = finish(process, timeout=300)
    assert (code, out) == (2, "") and one_line(err) and err.startswith("algkin: error: NUMBA_NUM_THREADS='0'"), err


@pytest.mark.skipif(not os.path.exists("/dev/full"), reason="needs /dev/full")
@pytest.mark.parametrize("args", [("--help",), ("--version",), ("derive", "--help")])
def test_help_and_version_on_a_full_stdout_are_one_line_and_exit_1(args):
    # argparse prints them itself and ignores a failed write: exit 0, nothing said, before
    with open("/dev/full", "w") as full:
        process = start(algkin(*args), stdout=full)
    code, _, err, _ = finish(process, timeout=120)
    assert (code, err) == (1, NO_SPACE)


@pytest.mark.parametrize("args", [("list",), ("derive", "chebyshev-lambda", "--outputs", "B", "--samples", "3",
                                             "--max-seconds", "100")], ids=["list", "derive-budget"])
def test_a_closed_stderr_still_does_the_work(args):
    # `algkin list 2>&-`: Python's sys.stderr is then None; nothing is said, the output is still written
    process = start(algkin(*args), stderr=None, preexec_fn=lambda: os.close(2))
    code, out, _, _ = finish(process, timeout=120)
    assert code == 0 and out.split()[0] in ("3rpr", "scene"), out
