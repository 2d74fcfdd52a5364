"""The one timer of the benchmarks, and the one table they print.

Every ``bench_*.py`` has a ``run()`` returning ``(name, seconds, target)`` rows, timed with
:func:`best` (the best of a few calls: the least disturbed by the machine) or :func:`once` (a first,
cold call that cannot be repeated); ``python benchmarks/run.py`` prints all of them as one table and
``python benchmarks/bench_x.py`` prints one module's rows the same way (:func:`main`).
"""
from __future__ import annotations

import time
from collections.abc import Callable, Iterable
from typing import Any

Row = tuple[str, float, str]


def timed(fn: Callable[[], Any], repeat: int = 1) -> tuple[float, Any]:
    """``(best wall time in seconds of `repeat` calls of fn(), the last call's result)``."""
    best_secs, out = float("inf"), None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        best_secs = min(best_secs, time.perf_counter() - t0)
    return best_secs, out


def best(fn: Callable[[], Any], repeat: int = 3) -> float:
    """The best wall time in seconds of ``repeat`` calls of ``fn()``."""
    return timed(fn, repeat)[0]


def once(fn: Callable[..., Any], *args: Any, **kw: Any) -> float:
    """The wall time in seconds of one call ``fn(*args, **kw)``."""
    return timed(lambda: fn(*args, **kw))[0]


def print_header() -> None:
    print(f"{'benchmark':<62} {'seconds':>10}  target")
    print("-" * 86)


def print_rows(rows: Iterable[Row]) -> None:
    for name, secs, target in rows:
        print(f"{name[:62]:<62} {secs:>10.4f}  {target}", flush=True)


def main(run: Callable[[], list[Row]]) -> None:
    """Print one benchmark module's rows as the table of run.py."""
    print_header()
    print_rows(run())
