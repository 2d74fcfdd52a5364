"""Helpers of the trust issues' ``cases_*`` modules: each input runs once, time-limited, its outcome classified.

:func:`attempt` runs one input and counts it as ``"hang"`` past 10 s of CPU (its own and its children's; a 60 s wall
alarm, ``signal.setitimer``, is the backstop),
an exception the case did not classify as ``"crash"``.  :func:`api` and :func:`cli_refused` are the two common
checks: a Python call that must answer or raise a thinlayer ``ValueError``/``TypeError`` in one line, and a
command line that must exit 2 with one line on stderr; a marker file appearing is ``"code"``.
"""
from __future__ import annotations

import contextlib
import io
import os
import signal
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

#: an input working longer than this (CPU seconds of this process and its children) is a hang
HANG_SECONDS = 10.0
#: the alarm's wall-clock backstop: on a machine at load 6 with 2 cores an input gets about a third of a core, so
#: a wall-clock limit of 10 s counted the machine's load, not the input's work (two inputs of 2.4 s and 11 s wall
#: at load 9 were counted as hangs); a run still going after this much wall time is a hang whatever its CPU
WALL_BACKSTOP = 60.0


def cpu_seconds() -> float:
    """CPU time (user + sys) of this process and of its finished children: the work an input caused."""
    import resource

    ch = resource.getrusage(resource.RUSAGE_CHILDREN)
    return time.process_time() + ch.ru_utime + ch.ru_stime

#: payloads that would run code if a string were evaluated; {m} is the marker file
PAYLOADS = [
    "x_1**2 + x_2**2 + 0*__import__('os').system('touch {m}')",
    "__import__('os').system('touch {m}')",
    "x_1**2 + (lambda: __import__('os').system('touch {m}'))()",
    "x_1**2 + ().__class__.__bases__[0].__subclasses__()",
    "x_1**2 + open('{m}', 'w').write('x')",
    "x_1**2 + exec(\"open('{m}','w')\")",
    "x_1**2 + eval('1')",
    "x_1**2 + Symbol('a')",
    "x_1**2 + sympify('1')",
    "x_1**2 + x_2**2; import os",
    "x_1**2 + x_2**2 if True else 0",
    "x_1**2 + ＿＿import＿＿('os')",
]


class Hang(BaseException):
    """Raised by the alarm of :func:`attempt` (a BaseException: no ``except Exception`` in the code swallows it)."""


@contextlib.contextmanager
def alarm(seconds: float = WALL_BACKSTOP):
    def ring(signum, frame):
        raise Hang()

    old = signal.signal(signal.SIGALRM, ring)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)


_PAUSED = [0.0]  # seconds spent in unlimited() blocks during the current attempt


@contextlib.contextmanager
def unlimited():
    """Stop the input's clock while an independent reference is computed (the input is what is timed)."""
    left, _ = signal.getitimer(signal.ITIMER_REAL)
    signal.setitimer(signal.ITIMER_REAL, 0)
    t0 = cpu_seconds()
    try:
        yield
    finally:
        _PAUSED[0] += cpu_seconds() - t0
        if left > 0:
            signal.setitimer(signal.ITIMER_REAL, left)


def attempt(t, category: str, fn: Callable[[], tuple[str, str]], note: str = "") -> str:
    """Run one input: ``fn()`` returns ``(outcome, note)``; over :data:`HANG_SECONDS` of CPU (or
    :data:`WALL_BACKSTOP` of wall time) it is a hang.  Returns the outcome recorded."""
    t0 = cpu_seconds()
    _PAUSED[0] = 0.0
    try:
        with alarm():
            outcome, detail = fn()
    except Hang:
        outcome, detail = "hang", f"over {WALL_BACKSTOP:g} s of wall time"
    except Exception as exc:  # noqa: BLE001 - an exception the case did not classify
        outcome, detail = "crash", f"{type(exc).__name__}: {exc}"[:300]
    took = cpu_seconds() - t0 - _PAUSED[0]
    if outcome != "hang" and took > HANG_SECONDS:
        outcome, detail = "hang", f"{took:.1f} s of CPU"
    t.add(category, outcome, f"{note}: {detail}" if note else detail)
    return outcome


def one_line(exc: BaseException) -> bool:
    text = str(exc).strip()
    return bool(text) and "\n" not in text


def classify_call(fn: Callable[[], Any], marker: Path | None = None,
                  check: Callable[[Any], tuple[str, str]] | None = None) -> tuple[str, str]:
    """A Python call: a thinlayer error in one line is clear; an answer is clear unless ``check`` says otherwise."""
    from thinlayer.errors import ThinlayerError

    try:
        out = fn()
    except (ValueError, TypeError) as exc:
        if marker is not None and marker.exists():
            marker.unlink()
            return "code", f"code ran, then {type(exc).__name__}"
        if not isinstance(exc, ThinlayerError):
            return "crash", f"{type(exc).__name__} is not thinlayer's: {exc}"[:300]
        return ("clear", "") if one_line(exc) else ("crash", f"not one line: {exc!r}"[:300])
    if marker is not None and marker.exists():
        marker.unlink()
        return "code", "code ran"
    return check(out) if check is not None else ("clear", "")


def api(t, category: str, marker: Path | None, fn: Callable[[], Any], note: str = "",
        check: Callable[[Any], tuple[str, str]] | None = None) -> str:
    """One Python input, time-limited and classified (:func:`classify_call`)."""
    return attempt(t, category, lambda: classify_call(fn, marker, check), note)


def cli(argv: list[str], cwd: Path) -> tuple[int, str, str]:
    """``thinlayer <argv>`` in this process (stdout and stderr captured, the working folder ``cwd``)."""
    from thinlayer.export.cli import main as cli_main

    out, err = io.StringIO(), io.StringIO()
    old = os.getcwd()
    os.chdir(cwd)
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            try:
                code = cli_main(argv)
            except SystemExit as exc:  # argparse
                code = exc.code if isinstance(exc.code, int) else 2
    finally:
        os.chdir(old)
    return code, out.getvalue(), err.getvalue()


def classify_refused_cli(argv: list[str], cwd: Path, marker: Path | None = None) -> tuple[str, str]:
    code, _, err = cli(argv, cwd)
    if marker is not None and marker.exists():
        marker.unlink()
        return "code", f"{argv}: code ran"
    if code == 2 and len(err.strip().splitlines()) == 1 and "Traceback" not in err:
        return "clear", ""
    return "crash", f"{argv}: exit {code}, stderr {err[:200]!r}"


def cli_refused(t, category: str, argv: list[str], cwd: Path, marker: Path | None = None) -> str:
    """One command line that must be refused: exit 2, one line on stderr, no marker."""
    return attempt(t, category, lambda: classify_refused_cli(argv, cwd, marker), str(argv)[:120])


def positive_finite(*values: float) -> bool:
    import math

    return all(isinstance(v, (int, float)) and math.isfinite(v) and v > 0 for v in values)
