"""Output files that an interrupt or a failed write never leaves truncated.

Every file algkin writes goes to a hidden temporary file beside it (``.NAME.XXXX.tmp.SUFFIX``:
the real suffix kept, since some writers infer the format from it) and is renamed over
the target only once complete. On any failure, ``KeyboardInterrupt`` included, the
temporary file is removed and an existing target is left as it was. Paths are checked
before any computation, so a bad ``--out`` costs nothing (``check_output``,
``check_directory``).

>>> import pathlib, tempfile
>>> scratch = tempfile.TemporaryDirectory()
>>> folder = pathlib.Path(scratch.name)
>>> target = folder / "page.html"
>>> write_atomic(target, "good")
>>> with atomic_output(target) as temporary:
...     _ = temporary.write_text("half of a pa")
...     raise ValueError("interrupted")
Traceback (most recent call last):
...
ValueError: interrupted
>>> target.read_text(), [p.name for p in folder.iterdir()]
('good', ['page.html'])
>>> check_output("out", folder)
Traceback (most recent call last):
...
algkin.errors.UsageError: out='...': is a directory
>>> scratch.cleanup()
"""

import contextlib
import os
import pathlib
import shutil
import stat
import tempfile
from collections.abc import Callable, Iterator
from typing import TypeAlias

from ..errors import OutputError, UsageError

__all__ = ["atomic_output", "write_atomic", "bytes_written", "check_output", "check_directory"]

_Path: TypeAlias = "str | os.PathLike[str]"  # a path as a caller gives it


@contextlib.contextmanager
def atomic_output(path: _Path) -> Iterator[pathlib.Path]:
    """Yield a temporary path with ``path``'s suffix; when the block ends normally it replaces ``path``.

    A device or pipe (``/dev/stdout``, ``/dev/full``) cannot be renamed over and holds
    nothing to keep: its temporary file is made in the system's temporary folder and
    copied in at the end. An ``OSError`` becomes ``OutputError``.
    """
    target = os.path.realpath(path)
    special = os.path.exists(target) and not os.path.isfile(target)
    with _reported(path):
        temporary = _temporary(tempfile.gettempdir() if special else os.path.dirname(target), target)
    try:
        with _reported(path):
            yield pathlib.Path(temporary)
            _deliver(temporary, target, special)
    finally:
        with contextlib.suppress(FileNotFoundError):
            os.remove(temporary)


def write_atomic(path: _Path, data: str | bytes) -> None:
    """Write ``data`` (text as UTF-8, or bytes) to ``path`` through ``atomic_output``."""
    with atomic_output(path) as temporary:
        temporary.write_bytes(data.encode("utf-8") if isinstance(data, str) else data)


def bytes_written(write: Callable[[pathlib.Path], object], suffix: str) -> bytes:
    """The bytes ``write(path)`` writes to a new file named with ``suffix`` (for a writer that
    takes only a path, and may infer the format from its suffix), read back; the file is then
    removed, with the private folder it was made in.

    >>> bytes_written(lambda path: path.write_text("frames"), ".gif")
    b'frames'
    """
    with tempfile.TemporaryDirectory(prefix="algkin.") as folder:
        path = pathlib.Path(folder) / f"written{suffix}"
        write(path)
        return path.read_bytes()


def _temporary(folder: _Path, target: _Path) -> str:
    """A new empty file in ``folder`` named after ``target``: its stem (cut short, so that a name
    near the system's limit still has a temporary beside it) and its suffix."""
    stem, suffix = os.path.splitext(os.path.basename(target))
    handle, temporary = tempfile.mkstemp(prefix=f".{stem[:_STEM]}.", suffix=f".tmp{suffix[:_STEM]}", dir=folder)
    os.close(handle)
    return temporary


_STEM = 64  # characters of the target's stem (and suffix) kept in its temporary's name


@contextlib.contextmanager
def _reported(path: _Path) -> Iterator[None]:
    try:
        yield
    except OutputError:
        raise
    except OSError as err:
        raise OutputError(path, err.strerror or str(err)) from err


def _deliver(temporary: str, target: str, special: bool) -> None:
    """Copy into a device or pipe; otherwise flush, give the target's permissions (a new
    file: the umask's) and rename over it."""
    if special:
        with open(temporary, "rb") as source, open(target, "wb") as sink:
            shutil.copyfileobj(source, sink)
        return
    with open(temporary, "rb+") as handle:
        os.fsync(handle.fileno())
    try:
        mode = stat.S_IMODE(os.stat(target).st_mode)
    except FileNotFoundError:
        mask = os.umask(0)
        os.umask(mask)
        mode = 0o666 & ~mask
    os.chmod(temporary, mode)
    os.replace(temporary, target)


def check_output(option: str, path: _Path) -> None:
    """Raise ``UsageError`` naming ``option`` unless a file can be written at ``path``: a file's
    name (not empty, not a directory's), in a directory where a file can be made now.

    >>> check_output("plot", "")
    Traceback (most recent call last):
    ...
    algkin.errors.UsageError: plot='': is empty; give a file name
    >>> check_output("out", "new.json/")
    Traceback (most recent call last):
    ...
    algkin.errors.UsageError: out='new.json/': names a directory (it ends with /); give a file name
    >>> check_output("out", "x" * 300 + ".json")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    algkin.errors.UsageError: out='xxx...x.json': cannot be written: File name too long
    """
    text = str(path)
    if not text:
        raise UsageError(option, text, "is empty; give a file name")
    if text.endswith(("/", os.sep)):
        raise UsageError(option, text, "names a directory (it ends with /); give a file name")
    if os.path.basename(text) in (".", ".."):
        raise UsageError(option, text, "names a directory; give a file name")
    with _refused(option, text):
        _check_file(option, text, pathlib.Path(os.path.realpath(text)))


def _check_file(option: str, text: str, target: pathlib.Path) -> None:
    if target.is_dir():
        raise UsageError(option, text, "is a directory")
    if not target.parent.is_dir():
        raise UsageError(option, text, "its directory is a file" if target.parent.exists() else
                         "its directory does not exist")
    if target.exists() and not target.is_file():
        return  # a device or pipe: copied into, nothing to keep
    if target.exists() and not os.access(target, os.W_OK):
        raise UsageError(option, text, "is a read-only file")
    if not os.access(target.parent, os.W_OK | os.X_OK):
        raise UsageError(option, text, "its directory is not writable")
    with _refused(option, text, f"cannot make a file in {target.parent}: "):
        os.remove(_temporary(target.parent, target))  # what the write does first: root, a read-only mount


def check_directory(option: str, path: _Path) -> None:
    """Raise ``UsageError`` unless ``path`` is, or can be made, a writable directory."""
    text = str(path)
    if not text:
        raise UsageError(option, text, "is empty; give a directory")
    with _refused(option, text):
        target = pathlib.Path(os.path.realpath(text))
        if target.exists() and not target.is_dir():
            raise UsageError(option, text, "is not a directory")
        existing = next(p for p in (target, *target.parents) if p.exists())
        if not existing.is_dir():
            raise UsageError(option, text, f"{existing} is not a directory")
        if not os.access(existing, os.W_OK | os.X_OK):
            raise UsageError(option, text, f"{existing} is not writable")
    with _refused(option, text, f"cannot make a directory in {existing}: "):
        os.rmdir(tempfile.mkdtemp(prefix=".algkin.", dir=existing))  # as making it, or a part file in it


@contextlib.contextmanager
def _refused(option: str, text: str, why: str = "cannot be written: ") -> Iterator[None]:
    """An ``OSError`` while a path is checked (a name too long, a read-only file system) as a
    ``UsageError``: ``why`` and the system's reason."""
    try:
        yield
    except OSError as err:
        raise UsageError(option, text, f"{why}{err.strerror or err}") from None
