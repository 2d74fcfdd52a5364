"""Writing output files without losing any: refuse to replace, write atomically, lock the output name.

Every file thinlayer writes (validation tables and figures, LaTeX reports, PDFs, generated code) goes
through :func:`atomic_write`: the bytes go to a temporary file in the same folder, are flushed to
disk (``fsync``) and renamed over the target (``os.replace``), so a reader never sees half a file and
an interrupted run leaves the old file intact.  The file gets the mode ``0o666 & ~umask``, as
``open()`` would give it (``tempfile.mkstemp`` alone would leave ``0o600``).

:func:`refuse_existing` checks every target before anything is written: an existing file is replaced
only with ``force``.  :func:`output_lock` takes an exclusive lock (``fcntl.flock``) on the output name,
so two concurrent runs writing the same name cannot mix their files: the second one gets
:class:`OutputBusyError` (one line) at once.
"""
from __future__ import annotations

import contextlib
import os
import tempfile
import threading
from collections.abc import Iterable, Iterator
from pathlib import Path

__all__ = ["OutputBusyError", "OutputExistsError", "atomic_write", "file_mode", "output_lock", "refuse_existing"]

_UMASK_LOCK = threading.Lock()


class OutputExistsError(FileExistsError):
    """A file that would be written exists and ``force`` was not given."""


class OutputBusyError(RuntimeError):
    """Another run holds the lock on the same output name."""


def file_mode() -> int:
    """The mode a new file gets from ``open()``: ``0o666 & ~umask``.

    Returns
    -------
    int
        The permission bits.
    """
    with _UMASK_LOCK:  # os.umask is the only portable way to read it: set and restore at once
        mask = os.umask(0o022)
        os.umask(mask)
    return 0o666 & ~mask


def refuse_existing(paths: Iterable[str | Path], force: bool, hint: str = "pass --overwrite to replace it") -> None:
    """Raise :class:`OutputExistsError` for the first of ``paths`` that exists, unless ``force``.

    Parameters
    ----------
    paths : iterable of str or Path
        Every file a run would write; checked before any is written.
    force : bool
        Whether existing files may be replaced.
    hint : str
        How to allow it, appended to the message.

    Raises
    ------
    OutputExistsError
        naming the file; ``IsADirectoryError`` when a folder stands where a file goes (even with ``force``).
    """
    for p in map(Path, paths):
        if p.is_dir():
            raise IsADirectoryError(f"{p} is a folder; a file would be written there: remove it or choose "
                                    "another output folder")
        if (p.exists() or p.is_symlink()) and not force:
            raise OutputExistsError(f"{p} exists; {hint}")


def atomic_write(path: str | Path, data: str | bytes) -> Path:
    """Write ``data`` to ``path`` atomically: temporary file in the same folder, fsync, ``os.replace``.

    Parameters
    ----------
    path : str or Path
        The target; its folder must exist.
    data : str or bytes
        The content (text is written as UTF-8).

    Returns
    -------
    Path
        ``path``.
    """
    path = Path(path)
    raw = data.encode("utf-8") if isinstance(data, str) else bytes(data)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(raw)
            fh.flush()
            os.fchmod(fh.fileno(), file_mode())
            os.fsync(fh.fileno())
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    with contextlib.suppress(OSError):  # make the rename itself durable
        dfd = os.open(path.parent, os.O_RDONLY)
        try:
            os.fsync(dfd)
        finally:
            os.close(dfd)
    return path


@contextlib.contextmanager
def output_lock(directory: str | Path, name: str) -> Iterator[Path]:
    """Hold an exclusive lock on the output name ``name`` in ``directory`` (created if missing).

    The lock file ``.<name>.lock`` is locked with ``fcntl.flock`` (released by the kernel even when
    the process is killed) and removed on release.  A second run on the same name raises
    :class:`OutputBusyError` instead of waiting.

    Parameters
    ----------
    directory : str or Path
        The output folder.
    name : str
        The output name (e.g. the report's name or ``validation``).

    Yields
    ------
    Path
        The lock file.
    """
    import fcntl

    d = Path(directory)
    d.mkdir(parents=True, exist_ok=True)
    lock = d / f".{name}.lock"
    while True:
        fd = os.open(lock, os.O_RDWR | os.O_CREAT, file_mode())
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            os.close(fd)
            raise OutputBusyError(f"another thinlayer run is writing {d / name} (lock {lock}); wait for it to "
                                  "finish or choose another output folder") from None
        try:  # the file may have been removed by the previous holder between open and flock: retry
            same = os.fstat(fd).st_ino == os.stat(lock).st_ino
        except FileNotFoundError:
            same = False
        if same:
            break
        os.close(fd)
    try:
        os.write(fd, f"{os.getpid()}\n".encode())
        yield lock
    finally:
        with contextlib.suppress(OSError):
            lock.unlink()
        os.close(fd)
