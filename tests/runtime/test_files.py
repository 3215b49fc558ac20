"""Output files: written whole or not at all, paths refused before any work."""

import os
import stat

import pytest

from algkin.errors import OutputError, UsageError
from algkin.runtime.files import atomic_output, check_directory, check_output, write_atomic

AS_ROOT = hasattr(os, "geteuid") and os.geteuid() == 0


def test_an_interrupted_write_leaves_the_earlier_file_and_no_temporary(tmp_path):
    target = tmp_path / "page.html"
    target.write_text("a good page")
    with pytest.raises(KeyboardInterrupt):
        with atomic_output(target) as temporary:
            with open(temporary, "w") as handle:
                handle.write("half a pa")
                handle.flush()
                raise KeyboardInterrupt
    assert target.read_text() == "a good page"
    assert os.listdir(tmp_path) == ["page.html"]


def test_a_complete_write_replaces_the_file_and_keeps_its_permissions(tmp_path):
    target = tmp_path / "figure.png"
    target.write_bytes(b"old")
    target.chmod(0o640)
    with atomic_output(target) as temporary:
        assert temporary.parent == tmp_path and temporary.name.startswith(".figure.")
        assert temporary.suffix == ".png"  # writers that infer the format from it still can
        temporary.write_bytes(b"new")
    assert target.read_bytes() == b"new" and stat.S_IMODE(target.stat().st_mode) == 0o640
    assert os.listdir(tmp_path) == ["figure.png"]


def test_a_new_file_gets_the_umask_permissions(tmp_path):
    mask = os.umask(0o027)
    try:
        write_atomic(tmp_path / "bench.csv", "a,b\n")
    finally:
        os.umask(mask)
    assert stat.S_IMODE((tmp_path / "bench.csv").stat().st_mode) == 0o640


def test_a_failed_write_is_an_output_error_and_the_file_is_kept(tmp_path):
    target = tmp_path / "bench.json"
    target.write_text("{}")
    with pytest.raises(OutputError, match="bench.json"):
        with atomic_output(target):
            raise OSError(28, "No space left on device")
    assert target.read_text() == "{}" and os.listdir(tmp_path) == ["bench.json"]


@pytest.mark.skipif(not os.path.exists("/dev/full"), reason="needs /dev/full")
def test_a_full_device_is_an_output_error(tmp_path):
    link = tmp_path / "full.png"
    link.symlink_to("/dev/full")
    with pytest.raises(OutputError, match="No space left on device"):
        write_atomic(link, b"\x89PNG" * 100_000)
    assert os.listdir(tmp_path) == ["full.png"] and os.path.realpath(link) == "/dev/full"


def test_paths_that_cannot_be_written_are_refused(tmp_path):
    (tmp_path / "folder.png").mkdir()
    with pytest.raises(UsageError, match="is a directory"):
        check_output("--out", tmp_path / "folder.png")
    with pytest.raises(UsageError, match="its directory does not exist"):
        check_output("--out", tmp_path / "no" / "x.png")
    (tmp_path / "bench").write_text("")
    with pytest.raises(UsageError, match="is not a directory"):
        check_directory("--out", tmp_path / "bench")
    with pytest.raises(UsageError, match="is not a directory"):
        check_directory("--out", tmp_path / "bench" / "below")
    check_output("--out", tmp_path / "x.png")
    check_directory("--out", tmp_path / "new" / "deeper")


def test_a_file_in_place_of_the_directory_is_said_as_such(tmp_path):
    (tmp_path / "notes").write_text("")  # was "its directory does not exist"
    with pytest.raises(UsageError, match="its directory is a file"):
        check_output("--out", tmp_path / "notes" / "x.png")


@pytest.mark.skipif(AS_ROOT, reason="root writes read-only files and folders anyway")
def test_read_only_files_and_folders_are_refused(tmp_path):
    (tmp_path / "kept.png").write_bytes(b"")
    (tmp_path / "kept.png").chmod(0o444)
    locked = tmp_path / "locked"
    locked.mkdir()
    locked.chmod(0o555)
    try:
        with pytest.raises(UsageError, match="read-only"):
            check_output("--out", tmp_path / "kept.png")
        with pytest.raises(UsageError, match="not writable"):
            check_output("--out", locked / "x.png")
        with pytest.raises(UsageError, match="not writable"):
            check_directory("--out", locked / "bench")
    finally:
        locked.chmod(0o755)


def test_a_name_near_the_systems_limit_is_written_through_a_shorter_temporary(tmp_path):
    target = tmp_path / ("n" * 245 + ".json")  # 250 bytes: a file name most systems allow (255)
    check_output("--out", target)
    write_atomic(target, "{}")
    assert target.read_text() == "{}" and os.listdir(tmp_path) == [target.name]


@pytest.mark.parametrize("name,why", [("", "is empty"), ("new.json/", r"names a directory \(it ends with /\)"),
                                      (".", "names a directory; give a file name"),  # said it ended with /
                                      ("n" * 300 + ".json", "File name too long")])
def test_names_that_cannot_be_a_file_are_refused(tmp_path, monkeypatch, name, why):
    monkeypatch.chdir(tmp_path)
    with pytest.raises(UsageError, match=why):
        check_output("--out", name)
    assert os.listdir(tmp_path) == []


def test_a_directory_name_too_long_is_refused(tmp_path):
    with pytest.raises(UsageError, match="File name too long"):
        check_directory("--out", tmp_path / ("n" * 300) / "bench")


@pytest.mark.skipif(not os.path.isdir("/proc/self"), reason="/proc: a directory where no one, root included, makes a file")
def test_a_directory_that_takes_no_file_is_refused_even_for_root():
    with pytest.raises(UsageError, match="cannot make a file in /proc"):
        check_output("--out", "/proc/algkin-out.json")
    with pytest.raises(UsageError, match="cannot make a directory in /proc"):
        check_directory("--out", "/proc/algkin-out")
