"""Writing output files without losing any: refuse to replace, write atomically, lock the output name.

Every file thinlayer writes (validation tables and figures, LaTeX reports, PDFs, generated code) goes
through :func:`atomic_write`: the bytes go to a new temporary file in the same folder, are flushed to
disk (``fsync``) and renamed over the target (``os.replace``), so a reader never sees half a file and
an interrupted run leaves the old file intact.  The file gets the mode ``0o666 & ~umask``, as
``open()`` would give it.

No link is ever followed to write (issue 23, item 2):

* temporary files and folders are created new (``O_CREAT | O_EXCL | O_NOFOLLOW``, ``mkdir``) under a
  random name (:func:`temporary_name`); a name that exists, as a file or a link, is never reused;
* the lock file is created with ``O_EXCL | O_NOFOLLOW``; an existing lock file (left by a killed run)
  is opened with ``O_NOFOLLOW`` and used only if it is a regular file with one link, and nothing is
  written into it then; a symbolic link, a hard link or anything else there is refused
  (:class:`UnsafeOutputError`);
* ``os.replace`` replaces a link at the target itself, never its target.  A link at a target counts as an
  existing file: without ``force`` it is refused (:func:`refuse_existing`); with ``force`` the link is
  replaced by the new file and the file it pointed to is left alone.  A folder the run writes into
  (a report's figures) that is a link is refused even with ``force`` (:func:`check_folder`).

The output folder itself (``--out``) may be a link the user made: it is followed, as any path the user
gives; only what the run finds or makes inside it is held to the rules above.

A run killed with SIGKILL may leave a temporary file or folder named ``.<target>.thinlayer-<pid>-<hex>.tmp``
next to its target; the next run of the same output name removes those whose process is gone
(:func:`remove_stale`), and never uses them.

:func:`refuse_existing` checks every target before anything is written: an existing file is replaced
only with ``force``.  :func:`output_lock` takes an exclusive lock (``fcntl.flock``) on the output name,
so two concurrent runs writing the same name cannot mix their files: the second one gets
:class:`OutputBusyError` (one line) at once.
"""
from __future__ import annotations

import contextlib
import errno
import os
import re
import secrets
import shutil
import stat
import threading
from collections.abc import Callable, Iterable, Iterator
from pathlib import Path
from typing import TypeVar

__all__ = ["OutputBusyError", "OutputExistsError", "UnsafeOutputError", "atomic_write", "check_folder", "file_mode",
           "output_lock", "private_folder", "refuse_existing", "remove_stale", "temporary_name"]

_UMASK_LOCK = threading.Lock()
#: open() flags that never follow a link at the last component and never leak into a child process
_NOFOLLOW = getattr(os, "O_NOFOLLOW", 0) | getattr(os, "O_CLOEXEC", 0)
_T = TypeVar("_T")


class OutputExistsError(FileExistsError):
    """A file that would be written exists and ``force`` was not given."""


class UnsafeOutputError(OutputExistsError):
    """A path the run would write, lock or write into is a link or a special file it did not create."""


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


def _lstat(path: Path) -> os.stat_result | None:
    try:
        return os.lstat(path)
    except (FileNotFoundError, NotADirectoryError):
        return None


def check_folder(path: str | Path) -> None:
    """Refuse a folder the run would write into (inside the output folder) that is a symbolic link.

    Parameters
    ----------
    path : str or Path
        A folder the run creates or writes files into, e.g. a report's ``<name>-figures``.

    Raises
    ------
    UnsafeOutputError
        ``path`` is a symbolic link (even with ``--overwrite``: the files would land where it points);
        ``NotADirectoryError`` when a file stands there.
    """
    st = _lstat(Path(path))
    if st is None:
        return
    if stat.S_ISLNK(st.st_mode):
        raise UnsafeOutputError(f"{path} is a symbolic link; thinlayer writes only into real folders inside the "
                                "output folder, never through a link it did not create: remove the link")
    if not stat.S_ISDIR(st.st_mode):
        raise NotADirectoryError(f"{path} is a file; a folder would be written there: remove it or choose another "
                                 "output folder")


def refuse_existing(paths: Iterable[str | Path], force: bool, hint: str = "pass --overwrite to replace it") -> None:
    """Raise :class:`OutputExistsError` for the first of ``paths`` that exists, unless ``force``.

    A symbolic link counts as an existing file, dangling or not; with ``force`` the link itself is
    replaced, its target left alone (``os.replace`` never follows it).

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
        naming the file (:class:`UnsafeOutputError` for a link); ``IsADirectoryError`` when a folder
        stands where a file goes (even with ``force``).
    """
    for p in map(Path, paths):
        st = _lstat(p)
        if st is None:
            continue
        if stat.S_ISDIR(st.st_mode):
            raise IsADirectoryError(f"{p} is a folder; a file would be written there: remove it or choose "
                                    "another output folder")
        if force:
            continue
        if stat.S_ISLNK(st.st_mode):
            raise UnsafeOutputError(f"{p} exists and is a symbolic link, which thinlayer never writes through; "
                                    f"{hint} (the link itself is replaced, the file it points to left alone)")
        raise OutputExistsError(f"{p} exists; {hint}")


#: the temporary files and folders of a run: ``.<target>.thinlayer-<pid>-<16 hex>.tmp``
_TEMPORARY = re.compile(r"\.(?P<target>.+)\.thinlayer-(?P<pid>[0-9]+)-[0-9a-f]{16}\.tmp")


def temporary_name(target: str) -> str:
    """A fresh name for a temporary file or folder of ``target``: hidden, with the process id, random.

    Parameters
    ----------
    target : str
        The name of the file the temporary one becomes (or is built for).

    Returns
    -------
    str
        ``.<target>.thinlayer-<pid>-<16 hex digits>.tmp``.
    """
    return f".{target}.thinlayer-{os.getpid()}-{secrets.token_hex(8)}.tmp"


def _fresh(folder: Path, target: str, make: Callable[[Path], _T]) -> _T:
    """``make(path)`` at a new temporary name in ``folder``; a name that exists (file or link) is skipped."""
    for _ in range(100):
        try:
            return make(folder / temporary_name(target))
        except FileExistsError:
            continue
    raise FileExistsError(errno.EEXIST, f"no free temporary name for {target} in {folder}")


def private_folder(folder: str | Path, target: str) -> Path:
    """Create a new folder, readable only by its owner, at a fresh temporary name in ``folder``.

    Parameters
    ----------
    folder : str or Path
        Where to create it (e.g. the output folder).
    target : str
        The name of the file it is built for (the name of the folder starts with it).

    Returns
    -------
    Path
        The new folder (``mkdir`` never follows or reuses an existing name).
    """
    def make(p: Path) -> Path:
        os.mkdir(p, 0o700)
        return p
    return _fresh(Path(folder), target, make)


def atomic_write(path: str | Path, data: str | bytes) -> Path:
    """Write ``data`` to ``path`` atomically: new temporary file in the same folder, fsync, ``os.replace``.

    The temporary file is created with ``O_CREAT | O_EXCL | O_NOFOLLOW`` at a fresh name; ``os.replace``
    replaces whatever entry is at ``path`` (a link is replaced, not followed).  The caller checks first
    that ``path`` may be replaced (:func:`refuse_existing`).

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
    flags = os.O_WRONLY | os.O_CREAT | os.O_EXCL | _NOFOLLOW

    def make(p: Path) -> tuple[int, Path]:
        return os.open(p, flags, 0o600), p
    fd, tmp = _fresh(path.parent, path.name, make)
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(raw)
            fh.flush()
            os.fchmod(fh.fileno(), file_mode())
            os.fsync(fh.fileno())
        os.replace(tmp, path)
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise
    with contextlib.suppress(OSError):  # make the rename itself durable
        dfd = os.open(path.parent, os.O_RDONLY | getattr(os, "O_DIRECTORY", 0))
        try:
            os.fsync(dfd)
        finally:
            os.close(dfd)
    return path


def _alive(pid: int) -> bool:
    if pid == os.getpid():
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except OSError:  # another user's process, or no permission to ask: treat as running
        return True
    return True


def remove_stale(targets: Iterable[str | Path]) -> list[Path]:
    """Remove the temporary files and folders of ``targets`` left by runs that were killed (SIGKILL).

    Only names of :func:`temporary_name`'s form whose process no longer runs are removed (a folder
    with its contents, never following a link); call it while holding the output lock.

    Parameters
    ----------
    targets : iterable of str or Path
        The files a run writes.

    Returns
    -------
    list of Path
        What was removed.
    """
    by_folder: dict[Path, set[str]] = {}
    for t in map(Path, targets):
        by_folder.setdefault(t.parent, set()).add(t.name)
    removed = []
    for folder, names in by_folder.items():
        try:
            entries = list(os.scandir(folder))
        except OSError:
            continue
        for e in entries:
            m = _TEMPORARY.fullmatch(e.name)
            if m is None or m.group("target") not in names or _alive(int(m.group("pid"))):
                continue
            with contextlib.suppress(OSError):
                if e.is_dir(follow_symlinks=False):
                    shutil.rmtree(e.path)
                else:
                    os.unlink(e.path)
                removed.append(Path(e.path))
    return removed


def _open_lock(lock: Path) -> tuple[int, bool]:
    """``(fd, created)``: the lock file, new (``O_EXCL``) or an existing regular file with one link."""
    try:
        return os.open(lock, os.O_RDWR | os.O_CREAT | os.O_EXCL | _NOFOLLOW, file_mode()), True
    except FileExistsError:
        pass
    what = "not a lock file thinlayer made"
    try:
        fd = os.open(lock, os.O_RDWR | _NOFOLLOW | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_NOCTTY", 0))
    except FileNotFoundError:
        return -1, False  # removed by its holder in between: try again
    except OSError as exc:
        kind = "a symbolic link" if exc.errno == errno.ELOOP or lock.is_symlink() else exc.strerror
        raise UnsafeOutputError(f"{lock} is {what} ({kind}); thinlayer never writes through a link: remove "
                                "it") from None
    st = os.fstat(fd)
    if not stat.S_ISREG(st.st_mode) or st.st_nlink != 1:
        os.close(fd)
        kind = "a hard link to another file" if stat.S_ISREG(st.st_mode) else "a special file"
        raise UnsafeOutputError(f"{lock} is {what} ({kind}); remove it")
    return fd, False


def _same_file(fd: int, path: Path) -> bool:
    st = _lstat(path)
    own = os.fstat(fd)
    return st is not None and (st.st_ino, st.st_dev) == (own.st_ino, own.st_dev)


@contextlib.contextmanager
def output_lock(directory: str | Path, name: str, targets: Iterable[str | Path] = ()) -> Iterator[Path]:
    """Hold an exclusive lock on the output name ``name`` in ``directory`` (created if missing).

    The lock file ``.<name>.lock`` is created with ``O_EXCL | O_NOFOLLOW`` and locked with
    ``fcntl.flock`` (released by the kernel even when the process is killed) and removed on release.
    A lock file left by a killed run is reused only if it is a regular file with one link (nothing is
    written into it); a link there is refused.  A second run on the same name raises
    :class:`OutputBusyError` instead of waiting.  Once locked, the temporary files of ``targets`` left
    by killed runs are removed (:func:`remove_stale`).

    Parameters
    ----------
    directory : str or Path
        The output folder.
    name : str
        The output name (e.g. the report's name or ``validation``).
    targets : iterable of str or Path
        The files the run writes (their stale temporary files are removed).

    Yields
    ------
    Path
        The lock file.

    Raises
    ------
    UnsafeOutputError
        the lock file's name is taken by a link or a special file.
    OutputBusyError
        another run holds the lock.
    """
    import fcntl

    d = Path(directory)
    d.mkdir(parents=True, exist_ok=True)
    lock = d / f".{name}.lock"
    while True:
        fd, created = _open_lock(lock)
        if fd < 0:
            continue
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            os.close(fd)
            raise OutputBusyError(f"another thinlayer run is writing {d / name} (lock {lock}); wait for it to "
                                  "finish or choose another output folder") from None
        if _same_file(fd, lock):  # the previous holder may have removed it between open and flock: retry
            break
        os.close(fd)
    try:
        if created:
            os.write(fd, f"{os.getpid()}\n".encode())
        remove_stale(targets)
        yield lock
    finally:
        if _same_file(fd, lock):
            with contextlib.suppress(OSError):
                lock.unlink()
        os.close(fd)
