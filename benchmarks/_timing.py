"""The one timer of the benchmarks, and the one table they print.

Every ``bench_*.py`` has a ``run()`` returning rows: :class:`Row` objects, or ``(name, seconds, target)`` tuples.
A row holds the measured value, its target, and, where a peer exists (sympy.series, ContactMechanics, the direct
solver, the previous algorithm), the peer's value measured side by side in the same run: the table prints the
ratio ``peer/value`` ("3.2x" = three times faster than the peer) and whether the row passes its target.

Targets are strings: ``"< 0.1 s"``, ``"<= 15 ms"``, ``"<= 700 MiB"`` compare the value (in the row's unit);
``">= 3x"`` compares the ratio to the peer; a target that is none of these (``"reference"``, ``""``) marks an
informational row.  Timings use :func:`best` (the best of a few calls: the least disturbed by the machine),
:func:`median` (the median of a few calls, for the rows measured side by side) or :func:`once` (a first, cold
call that cannot be repeated).  ``python benchmarks/run.py`` prints all modules as one table,
``python benchmarks/bench_x.py`` one module's rows the same way (:func:`main`).

Importing this module keeps sympy on gmpy2 (``SYMPY_GROUND_TYPES=gmpy`` unless set): with python-flint installed
sympy would switch its own ground types to flint, which measured slower for thinlayer; thinlayer uses python-flint
explicitly where it helps (the kernel coefficients).
"""
from __future__ import annotations

import importlib.util
import math
import os
import re
import statistics
import time
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from typing import Any

if "SYMPY_GROUND_TYPES" not in os.environ and importlib.util.find_spec("gmpy2") is not None:
    os.environ["SYMPY_GROUND_TYPES"] = "gmpy"


@dataclass
class Row:
    """One benchmark result: ``value`` (seconds unless ``unit`` says otherwise) against ``target``.

    ``peer``/``peer_value``: the same task done by a peer, measured side by side (same unit); the ratio printed and
    compared by ``"x"`` targets is ``peer_value / value`` (how many times faster than the peer).
    """

    name: str
    value: float
    target: str = ""
    peer: str | None = None
    peer_value: float | None = None
    unit: str = "s"

    @property
    def ratio(self) -> float | None:
        if self.peer_value is None or not self.value or math.isnan(self.value):
            return None
        return self.peer_value / self.value

    def verdict(self) -> str:
        """``"pass"``, ``"FAIL"``, ``"n/a"`` (not measured) or ``"info"`` (no target)."""
        rule = _parse_target(self.target)
        if rule is None:
            return "info"
        op, bound, on_ratio = rule
        x = self.ratio if on_ratio else self.value
        if x is None or math.isnan(x):
            return "n/a"
        if not on_ratio:
            bound *= _scale(self.target, self.unit)
        ok = {"<": x < bound, "<=": x <= bound, ">": x > bound, ">=": x >= bound}[op]
        return "pass" if ok else "FAIL"


_TARGET = re.compile(r"^\s*(ratio\s*)?(<=|>=|<|>)\s*([0-9.]+(?:e[-+]?[0-9]+)?)\s*([a-zA-Zµ]*)", re.IGNORECASE)
_TIME = {"s": 1.0, "ms": 1e-3, "us": 1e-6, "µs": 1e-6}
_BYTES = {"mib": 1.0, "mb": 1e6 / 2**20, "gib": 1024.0, "gb": 1e9 / 2**20}


def _parse_target(target: str) -> tuple[str, float, bool] | None:
    m = _TARGET.match(target or "")
    if not m:
        return None
    ratio_word, op, num, unit = m.groups()
    return op, float(num), bool(ratio_word) or unit.lower() == "x"


def _scale(target: str, unit: str) -> float:
    """Factor from the target's unit to the row's unit (seconds, MiB, or none)."""
    m = _TARGET.match(target)
    tu = (m.group(4) if m else "").lower()
    if unit == "s" and tu in _TIME:
        return _TIME[tu]
    if unit == "MiB" and tu in _BYTES:
        return _BYTES[tu]
    return 1.0


def as_row(r: Row | tuple) -> Row:
    return r if isinstance(r, Row) else Row(*r)


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


def median(fn: Callable[[], Any], repeat: int = 5) -> float:
    """The median wall time in seconds of ``repeat`` calls of ``fn()`` (for noisy, shared machines)."""
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def once(fn: Callable[..., Any], *args: Any, **kw: Any) -> float:
    """The wall time in seconds of one call ``fn(*args, **kw)``."""
    return timed(lambda: fn(*args, **kw))[0]


def _fmt_value(x: float, unit: str) -> str:
    if x is None or (isinstance(x, float) and math.isnan(x)):
        return "-"
    if unit == "s":
        if x < 1e-3:
            return f"{x * 1e6:.1f} us"
        return f"{x * 1e3:.1f} ms" if x < 1.0 else f"{x:.2f} s"
    if unit == "MiB":
        return f"{x:.0f} MiB"
    return f"{x:.3g} {unit}".strip()


def _fmt_peer(row: Row) -> str:
    r = row.ratio
    if r is None:
        return ""
    return f"{r:.3g}x {row.peer} ({_fmt_value(row.peer_value, row.unit)})"


WIDTHS = (78, 10, 16, 44)


def environment() -> str:
    """One line on the machine: cores, load, sympy's ground types, python-flint."""
    try:
        load = "load %.2f %.2f %.2f" % os.getloadavg()
    except OSError:  # pragma: no cover
        load = "load ?"
    flint = "python-flint " + ("installed" if importlib.util.find_spec("flint") else "not installed")
    return (f"{os.cpu_count()} cores, {load}, SYMPY_GROUND_TYPES={os.environ.get('SYMPY_GROUND_TYPES', 'auto')}, "
            f"{flint}")


def print_header() -> None:
    w = WIDTHS
    print(f"# {environment()}")
    print(f"{'benchmark':<{w[0]}} {'measured':>{w[1]}}  {'target':<{w[2]}} {'side by side (peer/this)':<{w[3]}} result")
    print("-" * (sum(w) + 12))


def print_rows(rows: Iterable[Row | tuple]) -> list[Row]:
    """Print rows as they come; return them (as :class:`Row`)."""
    w = WIDTHS
    out = []
    for r in rows:
        row = as_row(r)
        out.append(row)
        print(f"{row.name[:w[0]]:<{w[0]}} {_fmt_value(row.value, row.unit):>{w[1]}}  {row.target[:w[2]]:<{w[2]}} "
              f"{_fmt_peer(row)[:w[3]]:<{w[3]}} {row.verdict()}", flush=True)
    return out


def print_summary(rows: list[Row]) -> None:
    counts = {v: sum(r.verdict() == v for r in rows) for v in ("pass", "FAIL", "n/a", "info")}
    print("-" * (sum(WIDTHS) + 12))
    print(", ".join(f"{n} {v}" for v, n in counts.items() if n) or "no rows")


MARKDOWN_HEADER = ("| benchmark | measured | target | side by side (peer/this) | result |\n"
                   "|---|---:|---|---|---|")


def markdown_table(rows: list[Row]) -> str:
    """The rows as a Markdown table (the README's performance table is this output of ``run.py --readme``)."""
    lines = [MARKDOWN_HEADER]
    for row in rows:
        cells = (row.name, _fmt_value(row.value, row.unit), row.target, _fmt_peer(row), row.verdict())
        lines.append("| " + " | ".join(c.replace("|", "/") for c in cells) + " |")
    return "\n".join(lines)


def main(run: Callable[[], list]) -> None:
    """Print one benchmark module's rows as the table of run.py."""
    print_header()
    print_summary(print_rows(run()))
