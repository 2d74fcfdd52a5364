"""A disk cache of per-nu constants (h* (3.18), r_3 (SO.4), the boundary-layer table (3.22)), per user and version.

Some constants of the paper cost seconds to compute for each Poisson ratio (the edge shift h* by Wiener--Hopf
quadrature, the Chebyshev table of the boundary layer q̂ by de Hoog inversion), and a fresh process, e.g. each
``thinlayer solve`` of a shell loop, would compute them again.  :func:`cached` keeps them on disk:

* where: ``$THINLAYER_CACHE_DIR/<version>/`` if that variable is set, else
  ``$XDG_CACHE_HOME/thinlayer/<version>/`` (``~/.cache/thinlayer/<version>/``); ``THINLAYER_CACHE=0`` turns the cache
  off.  The folder is created private to the user (mode 0700) and used only if it is a real folder the user owns.
* what: one JSON file per entry, named after the function and a hash of its arguments.  The file holds the
  arguments again and a fingerprint of thinlayer's source files (path, size, modification time), so an entry written
  by other code, for other arguments, or by another version is never used.  Values are written exactly: floats as
  ``float.hex``, mpmath numbers by their binary mantissa and exponent, rationals as ``p/q``; they are read back by
  the tagged reader below (``json`` and the tags of :func:`_decode`), never by ``pickle`` or ``eval``.
* concurrency: a writer writes a temporary file created with ``O_CREAT | O_EXCL | O_NOFOLLOW`` in the cache folder
  and moves it over the entry with :func:`os.replace` (atomic): a reader sees an old complete entry or a new
  complete one.  Two processes computing the same entry both write it; the last one wins, with the same value.
* damage: an entry that cannot be read, is truncated, has a wrong tag or wrong arguments, is larger than
  :data:`MAX_ENTRY_BYTES`, is not a regular file (a symbolic link planted at its path is never followed: the file
  is opened with ``O_NOFOLLOW``) or is owned by another user is ignored; the value is computed and the entry
  rewritten.  Failing to write (read-only disk, full disk) only costs the next process the computation.

This module imports nothing of thinlayer (rank 0 of the import table in ``tests/test_architecture.py``).
"""
from __future__ import annotations

import hashlib
import json
import math
import numbers
import os
import secrets
from collections.abc import Callable
from pathlib import Path
from typing import Any

__all__ = ["cached", "cache_dir", "entry_path", "MAX_ENTRY_BYTES", "FORMAT"]

#: largest entry read (bytes): the biggest table (512 Chebyshev coefficients) takes ~15 kB
MAX_ENTRY_BYTES = 4 << 20
#: the entry format: an entry of another format is ignored
FORMAT = 1
_PACKAGE = Path(__file__).resolve().parent
_state: dict[str, Any] = {}


def _version() -> str:
    if "version" not in _state:
        _state["version"] = _dist_info_version() or _metadata_version()
    return _state["version"]


def _dist_info_version() -> str | None:
    """The installed version read off the name of its ``thinlayer-<version>.dist-info`` folder on ``sys.path``
    (the name the wheel and packaging standards give it): no import of :mod:`importlib.metadata`, whose import
    alone costs a fresh process about as much as the rest of a numeric solve (issue 28 item 6).  None if there is
    not exactly one such folder.
    """
    import sys

    found = set()
    for entry in sys.path:
        try:
            names = os.listdir(entry or ".")
        except OSError:
            continue
        found.update(n[len("thinlayer-"):-len(".dist-info")] for n in names
                     if n.startswith("thinlayer-") and n.endswith(".dist-info"))
    return found.pop() if len(found) == 1 else None


def _metadata_version() -> str:
    from importlib.metadata import PackageNotFoundError, version

    try:
        return version("thinlayer")
    except PackageNotFoundError:  # running from the sources: the fingerprint tells versions apart
        return "source"


def _fingerprint() -> str:
    """A hash of (path, size, mtime) of thinlayer's source files: changed code never reads old entries."""
    if "fingerprint" not in _state:
        h = hashlib.sha256()
        for root, dirs, files in os.walk(_PACKAGE):
            dirs.sort()
            for f in sorted(files):
                if f.endswith(".py"):
                    st = os.stat(os.path.join(root, f))
                    h.update(f"{os.path.relpath(os.path.join(root, f), _PACKAGE)}:{st.st_size}:{st.st_mtime_ns}\n"
                             .encode())
        _state["fingerprint"] = h.hexdigest()[:32]
    return _state["fingerprint"]


def cache_dir(create: bool = True) -> Path | None:
    """The cache folder of this user and version, or ``None`` when the cache is off or the folder is unusable."""
    if os.environ.get("THINLAYER_CACHE", "1").strip() == "0":
        return None
    base = os.environ.get("THINLAYER_CACHE_DIR")
    if base:
        root = Path(base).expanduser()
    else:
        xdg = os.environ.get("XDG_CACHE_HOME")
        root = (Path(xdg) if xdg and os.path.isabs(xdg) else Path.home() / ".cache") / "thinlayer"
    folder = root / _version()
    try:
        if create:
            os.makedirs(folder, mode=0o700, exist_ok=True)
        st = os.lstat(folder)
    except OSError:
        return None
    import stat

    if not stat.S_ISDIR(st.st_mode) or (hasattr(os, "getuid") and st.st_uid != os.getuid()):
        return None
    return folder


# ----------------------------------------------------------------------------- exact text of values
def _key_part(x: Any) -> str:
    if isinstance(x, str):
        return "s:" + x
    if x is None or isinstance(x, bool):
        return repr(x)
    if isinstance(x, numbers.Integral):
        return f"i:{int(x)}"
    if isinstance(x, numbers.Rational):  # fractions.Fraction, sympy.Rational
        return f"q:{int(x.numerator)}/{int(x.denominator)}"
    if isinstance(x, float):
        return "f:" + x.hex()
    if isinstance(x, tuple):
        return "(" + ",".join(_key_part(y) for y in x) + ")"
    raise TypeError(f"cache key part of type {type(x).__name__}")


def _encode(v: Any) -> Any:
    if v is None or isinstance(v, (bool, str)):
        return v
    if isinstance(v, numbers.Integral) and not hasattr(v, "_mpf_"):
        return int(v)
    if isinstance(v, float):
        return {"f": v.hex()}
    if hasattr(v, "_mpf_"):  # mpmath.mpf: its exact binary value
        sign, man, exp, _ = v._mpf_
        if not man and exp:  # inf, -inf, nan
            raise TypeError("a non-finite mpmath value is not cached")
        return {"mpf": [(-1) ** sign * int(man), int(exp)]}
    if isinstance(v, numbers.Rational):
        return {"q": f"{int(v.numerator)}/{int(v.denominator)}"}
    if isinstance(v, tuple):
        return {"t": [_encode(y) for y in v]}
    if isinstance(v, list):
        return [_encode(y) for y in v]
    if type(v).__name__ == "ndarray" and getattr(v, "dtype", None) is not None and v.dtype.kind == "f":
        return {"a": [float(y).hex() for y in v.ravel()], "shape": list(v.shape)}
    raise TypeError(f"cache value of type {type(v).__name__}")


class _Bad(Exception):
    """An entry that does not decode: ignored."""


def _int(x: Any) -> int:
    if isinstance(x, bool) or not isinstance(x, int):
        raise _Bad("not an integer")
    return x


def _float(x: Any) -> float:
    if not isinstance(x, str) or len(x) > 40:
        raise _Bad("not a float")
    try:
        return float.fromhex(x)
    except (ValueError, OverflowError) as e:
        raise _Bad(str(e)) from None


def _decode(v: Any, depth: int = 0) -> Any:
    if depth > 20:
        raise _Bad("nested too deep")
    if v is None or isinstance(v, (bool, str, int)):
        return v
    if isinstance(v, list):
        return [_decode(y, depth + 1) for y in v]
    if not isinstance(v, dict) or not (len(v) == 1 or set(v) == {"a", "shape"}):
        raise _Bad("unknown value")
    (tag,) = set(v) - {"shape"}
    x = v[tag]
    if tag == "f":
        return _float(x)
    if tag == "mpf":
        import mpmath

        if not isinstance(x, list) or len(x) != 2:
            raise _Bad("bad mpf")
        man, exp = _int(x[0]), _int(x[1])
        if man.bit_length() > 100_000 or abs(exp) > 10**9:
            raise _Bad("mpf too large")
        with mpmath.workprec(max(man.bit_length(), 53) + 2):  # exact: no rounding to the current precision
            return mpmath.mpf((man, exp))
    if tag == "q":
        import sympy as sp

        if not isinstance(x, str) or len(x) > 4000 or x.count("/") != 1:
            raise _Bad("bad rational")
        p, q = x.split("/")
        if not p.lstrip("-").isdigit() or not q.isdigit() or int(q) == 0:
            raise _Bad("bad rational")
        return sp.Rational(int(p), int(q))
    if tag == "t":
        if not isinstance(x, list):
            raise _Bad("bad tuple")
        return tuple(_decode(y, depth + 1) for y in x)
    if tag == "a":
        import numpy as np

        shape = v["shape"]
        if not isinstance(x, list) or not isinstance(shape, list) or math.prod(_int(s) for s in shape) != len(x):
            raise _Bad("bad array")
        return np.array([_float(y) for y in x], dtype=float).reshape([int(s) for s in shape])
    raise _Bad(f"unknown tag {tag!r}")


# ----------------------------------------------------------------------------- files
def entry_path(name: str, key: tuple, folder: Path | None = None) -> Path | None:
    """The file of entry ``name(*key)`` (``None`` when the cache is off)."""
    folder = cache_dir() if folder is None else folder
    if folder is None:
        return None
    digest = hashlib.sha256(f"{name}{_key_part(key)}".encode()).hexdigest()[:32]
    return folder / f"{name}-{digest}.json"


def _read(path: Path, name: str, key: str) -> Any:
    flags = os.O_RDONLY | getattr(os, "O_NOFOLLOW", 0) | getattr(os, "O_NONBLOCK", 0)
    try:
        fd = os.open(path, flags)
    except OSError:  # missing, or a symbolic link (ELOOP): not followed
        raise _Bad("no entry") from None
    try:
        import stat

        st = os.fstat(fd)
        if not stat.S_ISREG(st.st_mode) or st.st_size > MAX_ENTRY_BYTES:
            raise _Bad("not a regular file of a sensible size")
        if hasattr(os, "getuid") and st.st_uid != os.getuid():
            raise _Bad("owned by another user")
        with os.fdopen(fd, "rb", closefd=False) as f:
            data = f.read(MAX_ENTRY_BYTES + 1)
    finally:
        os.close(fd)
    try:
        doc = json.loads(data.decode("utf-8"))
    except (UnicodeDecodeError, ValueError, RecursionError):
        raise _Bad("not JSON") from None
    if (not isinstance(doc, dict) or doc.get("format") != FORMAT or doc.get("name") != name or doc.get("key") != key
            or doc.get("code") != _fingerprint() or "value" not in doc):
        raise _Bad("another entry")
    return _decode(doc["value"])


def _write(path: Path, name: str, key: str, value: Any) -> None:
    text = json.dumps({"format": FORMAT, "name": name, "key": key, "code": _fingerprint(), "value": _encode(value)},
                      separators=(",", ":"))
    tmp = path.parent / f".{path.name}.{os.getpid()}.{secrets.token_hex(8)}.tmp"
    flags = os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_NOFOLLOW", 0)
    try:
        fd = os.open(tmp, flags, 0o600)
    except OSError:
        return
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            f.write(text)
        os.replace(tmp, path)  # atomic; replaces a link planted at ``path`` by the file, never writes through it
    except OSError:
        try:
            os.unlink(tmp)
        except OSError:
            pass


def cached(name: str, key: tuple, compute: Callable[[], Any]) -> Any:
    """``compute()``, read from the disk cache when an entry ``name(*key)`` of this code exists, else stored there.

    Parameters
    ----------
    name : str
        The function whose value is cached (letters, digits, ``_``).
    key : tuple
        Everything the value depends on besides the code: str, int, float (kept exactly), rationals, tuples.
    compute : Callable[[], Any]
        Computes the value: None, bool, str, int, float, mpmath numbers, rationals, float arrays and tuples or
        lists of these.  A value of another type is returned uncached.
    """
    if not name.replace("_", "").isalnum():
        raise ValueError(f"cache entry name must be letters, digits and _, got {name!r}")
    keytext = _key_part(tuple(key))
    path = entry_path(name, key)
    if path is not None:
        try:
            return _read(path, name, keytext)
        except _Bad:
            pass
    value = compute()
    if path is not None:
        try:
            _write(path, name, keytext, value)
        except (TypeError, ValueError):  # a value the format does not hold (a nan mpf, another type): not cached
            pass
    return value
