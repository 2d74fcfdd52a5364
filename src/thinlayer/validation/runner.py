r"""Running a validation study: the driver, its progress lines and a clean stop on KeyboardInterrupt.

Long runs print progress lines on stderr (or a tqdm bar when tqdm is installed and stderr is a
terminal) and stop cleanly on KeyboardInterrupt: the study returned holds the rows done so far,
with ``interrupted = True``.
"""
from __future__ import annotations

import sys
import time
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any

from .._checks import check_int
from .analysis import ValidationStudy
from .cases import (
    FULL_RATIOS,
    NUS,
    QUICK_ELLIPTIC,
    QUICK_RATIOS,
    SHAPES,
    ValidationRow,
    check_nu,
    check_nus,
    check_ratios,
    check_shapes,
    elliptic_case,
    elliptic_grid,
    sphere_case,
)

__all__ = ["StudyEvent", "validate_elliptic", "validate_sphere", "validation_study"]


@dataclass(frozen=True)
class StudyEvent:
    """Passed to the ``callback`` of a study before (``stage="start"``) and after (``"done"``) each case."""

    stage: str
    index: int
    total: int
    shape: str
    nu: float
    H_over_a: float
    elapsed: float
    row: ValidationRow | None = None


class Progress:
    """Progress lines on stderr (or a tqdm bar on a terminal, when tqdm is installed)."""

    def __init__(self, enabled: bool, total: int, stream=None):
        self.enabled, self.total = enabled, total
        self.stream = sys.stderr if stream is None else stream
        self.t0 = time.perf_counter()
        self.bar = None
        if enabled and getattr(self.stream, "isatty", lambda: False)():
            try:
                from tqdm import tqdm  # optional
            except ImportError:
                tqdm = None
            if tqdm is not None:
                self.bar = tqdm(total=total, file=self.stream, unit="case", desc="validate")

    def _print(self, msg: str) -> None:
        print(msg, file=self.stream, flush=True)

    def start(self, i: int, label: str, slow: bool) -> None:
        if not self.enabled:
            return
        if self.bar is not None:
            self.bar.set_postfix_str(label)
        elif slow:
            self._print(f"validate: [{i + 1:>{len(str(self.total))}}/{self.total}] {label} ...")

    def done(self, i: int, label: str, secs: float) -> None:
        if not self.enabled:
            return
        if self.bar is not None:
            self.bar.update(1)
            return
        el = time.perf_counter() - self.t0
        left = el / (i + 1) * (self.total - i - 1)
        self._print(f"validate: [{i + 1:>{len(str(self.total))}}/{self.total}] {label}: {secs:.1f} s "
                    f"(elapsed {el:.0f} s, ~{left:.0f} s left)")

    def close(self, interrupted: bool, done: int) -> None:
        if self.bar is not None:
            self.bar.close()
        if self.enabled and interrupted:
            self._print(f"validate: interrupted after {done} of {self.total} cases; the rows done are kept")


#: the cases computed in this process, by (shape, nu, H/a, cells per H): each is a pure function of these, its row,
#: profiles and contours immutable (frozen, read-only arrays), so a report and ``thinlayer validate`` in one session
#: (or a notebook re-running a study) compute a case once.  At most :data:`CASE_MEMO` cases are kept.
_CASES: dict[tuple, tuple] = {}
CASE_MEMO = 256


def _case(shape: str, nu: float, eps: float, cells_per_H: float, workers: int | None) -> tuple:
    """``(row, profiles, contours)`` of one case, computed once per process (``workers`` changes the speed of the
    2D solver only, not its numbers).
    """
    key = (shape, float(nu), float(eps), float(cells_per_H) if shape == "elliptic" else None)
    if key not in _CASES:
        if shape == "sphere":
            row, pr, co = sphere_case(nu, eps)
        else:
            row, pr, co = elliptic_case(nu, eps, cells_per_H, workers)
        if len(_CASES) >= CASE_MEMO:
            _CASES.pop(next(iter(_CASES)))
        _CASES[key] = (row, tuple(pr), tuple(co))
    row, pr, co = _CASES[key]
    return row, list(pr), list(co)


def _run(cases: list[tuple[str, float, float]], *, cells_per_H: float, max_n: int, workers: int | None,
         progress: bool, callback: Callable[[StudyEvent], Any] | None, settings: dict) -> ValidationStudy:
    rows, profiles, contours, skipped = [], [], [], []
    todo = []
    for shape, nu, eps in cases:
        if shape == "elliptic":
            n, _, _ = elliptic_grid(eps, cells_per_H)
            if n > max_n:
                skipped.append((shape, nu, eps, f"2D grid n = {n} > max_n = {max_n} (raise max_n or use --full)"))
                continue
        todo.append((shape, nu, eps))
    prog = Progress(bool(progress), len(todo))
    t0 = time.perf_counter()
    interrupted = False
    try:
        for k, (shape, nu, eps) in enumerate(todo):
            label = f"{shape} nu={nu:g} H/a={eps:g}"
            if callback is not None:
                callback(StudyEvent("start", k, len(todo), shape, nu, eps, time.perf_counter() - t0))
            prog.start(k, label, shape == "elliptic")
            tc = time.perf_counter()
            row, pr, co = _case(shape, nu, eps, cells_per_H, workers)
            rows.append(row)
            profiles += pr
            contours += co
            prog.done(k, label, time.perf_counter() - tc)
            if callback is not None:
                callback(StudyEvent("done", k, len(todo), shape, nu, eps, time.perf_counter() - t0, row))
    except KeyboardInterrupt:
        interrupted = True
    prog.close(interrupted, len(rows))
    pending = tuple(todo[len(rows):]) if interrupted else ()
    return ValidationStudy(tuple(rows), tuple(profiles), tuple(contours), tuple(skipped), interrupted, pending,
                           MappingProxyType(dict(settings)), time.perf_counter() - t0)


def validate_sphere(nu: float, H_over_a_values: Iterable[float] = QUICK_RATIOS, *, progress: bool = False,
                    callback: Callable[[StudyEvent], Any] | None = None) -> ValidationStudy:
    """Sphere (paraboloid of revolution) at one Poisson ratio against the axisymmetric numerics.

    Parameters
    ----------
    nu : float
        Poisson ratio, -1 < nu < 1/2.
    H_over_a_values : sequence of float
        Thickness ratios in ``H_OVER_A_RANGE`` = [0.0125, 0.2].
    progress : bool
        Print a line per case on stderr.
    callback : callable, optional
        Called with a :class:`StudyEvent` before and after each case; raising KeyboardInterrupt there
        stops the study cleanly (as Ctrl-C does).

    Returns
    -------
    ValidationStudy
    """
    v = check_nu(nu)
    eps = check_ratios(H_over_a_values, "H_over_a_values")
    return _run([("sphere", v, e) for e in eps], cells_per_H=8.0, max_n=0, workers=None, progress=progress,
                callback=callback, settings={"shapes": ["sphere"], "nus": [v], "ratios": list(eps)})


def validate_elliptic(nu: float, H_over_a_values: Iterable[float] = QUICK_ELLIPTIC["ratios"], *,
                      cells_per_H: float = 8.0, max_n: int = 1024, workers: int | None = None,
                      progress: bool = False, callback: Callable[[StudyEvent], Any] | None = None
                      ) -> ValidationStudy:
    """Elliptic paraboloid ``R1/R2 = 4`` at one Poisson ratio against the 2D FFT numerics.

    Parameters
    ----------
    nu, H_over_a_values
        float, sequence of float
        As for :func:`validate_sphere`.
    cells_per_H : float
        Cells of the fine grid per layer thickness (>= 6); the error estimate's grid has 5.
    max_n : int
        The largest grid accepted; larger cases are listed in ``skipped``.
    workers : int, optional
        FFT threads.
    progress : bool
        Print a line per case on stderr.
    callback : callable, optional
        As for :func:`validate_sphere`.

    Returns
    -------
    ValidationStudy
    """
    v = check_nu(nu)
    eps = check_ratios(H_over_a_values, "H_over_a_values")
    max_n = check_int(max_n, "max_n", 16)
    for e in eps:
        elliptic_grid(e, cells_per_H)  # checks cells_per_H
    return _run([("elliptic", v, e) for e in eps], cells_per_H=float(cells_per_H), max_n=max_n, workers=workers,
                progress=progress, callback=callback,
                settings={"shapes": ["elliptic"], "nus": [v], "ratios": list(eps), "cells_per_H": cells_per_H,
                          "max_n": max_n})


def validation_study(nus: Iterable[float] | None = None, ratios: Iterable[float] | None = None,
                     shapes: Iterable[str] = SHAPES, *, full: bool = False,
                     elliptic_nus: Iterable[float] | None = None, elliptic_ratios: Iterable[float] | None = None,
                     cells_per_H: float = 8.0, max_n: int | None = None, workers: int | None = None,
                     progress: bool = True, callback: Callable[[StudyEvent], Any] | None = None
                     ) -> ValidationStudy:
    """The validation study of issue 4: every shape, Poisson ratio and thickness ratio asked for.

    A case (shape, nu, H/a) already computed in this process is taken from memory, not computed again: a report's
    validation section and ``thinlayer validate`` in one session share their cases.

    Parameters
    ----------
    nus : sequence of float, optional
        Poisson ratios (default :data:`NUS` = 0, 0.2, 0.3, 0.4, 0.45).
    ratios : sequence of float, optional
        H/a values in [0.0125, 0.2] (default: 0.2, 0.1, ..., 0.0125, a factor 2 apart; ``full``:
        nine values a factor sqrt(2) apart).
    shapes : sequence of str
        ``"sphere"`` and/or ``"elliptic"``.
    full : bool
        The full study: the elliptic case for every nu and ratio as well (2D grids up to
        ``max_n = 2304``; several minutes).  Otherwise, unless given, the elliptic case runs at
        nu = 0.3 and H/a = 0.2, 0.1 only.
    elliptic_nus, elliptic_ratios : Iterable[float] | None
        sequence of float, optional
        Override the elliptic cases.
    cells_per_H, max_n, workers
        float, int, int
        2D grid: cells per thickness (>= 6), largest grid (default 1024, ``full`` 2304), FFT threads.
    progress : bool
        Progress lines on stderr (a tqdm bar on a terminal when tqdm is installed).
    callback : callable, optional
        Called with a :class:`StudyEvent` before and after each case; a KeyboardInterrupt raised there
        (or by Ctrl-C) stops the study, which then returns the rows done (``interrupted = True``).

    Returns
    -------
    ValidationStudy
    """
    shp = check_shapes(shapes)
    nus_ = check_nus(NUS if nus is None else nus, "nus")
    rats = check_ratios((FULL_RATIOS if full else QUICK_RATIOS) if ratios is None else ratios, "ratios")
    e_nus, e_rats = _elliptic_cases(nus_, rats, full=full, nus_given=nus is not None,
                                    ratios_given=ratios is not None, elliptic_nus=elliptic_nus,
                                    elliptic_ratios=elliptic_ratios)
    max_n = (2304 if full else 1024) if max_n is None else check_int(max_n, "max_n", 16)
    elliptic_grid(0.1, cells_per_H)  # checks cells_per_H
    cases = []
    if "sphere" in shp:
        cases += [("sphere", v, e) for v in nus_ for e in rats]
    if "elliptic" in shp:
        cases += [("elliptic", v, e) for v in e_nus for e in e_rats]
    settings = {"full": bool(full), "shapes": list(shp), "nus": list(nus_), "ratios": list(rats),
                "elliptic_nus": list(e_nus) if "elliptic" in shp else [],
                "elliptic_ratios": list(e_rats) if "elliptic" in shp else [],
                "cells_per_H": cells_per_H, "max_n": max_n}
    return _run(cases, cells_per_H=float(cells_per_H), max_n=max_n, workers=workers, progress=progress,
                callback=callback, settings=settings)


def _elliptic_cases(nus: tuple[float, ...], ratios: tuple[float, ...], *, full: bool, nus_given: bool,
                    ratios_given: bool, elliptic_nus: Iterable[float] | None,
                    elliptic_ratios: Iterable[float] | None) -> tuple[tuple[float, ...], tuple[float, ...]]:
    """The Poisson ratios and H/a of the elliptic cases: as given, else those of the sphere or the quick set.

    ``full``: every nu, the ratios a factor 2 apart; otherwise the quick set (nu = 0.3, H/a = 0.2, 0.1)
    unless ``nus`` or ``ratios`` were given.
    """
    if elliptic_nus is not None:
        e_nus = check_nus(elliptic_nus, "elliptic_nus")
    else:
        e_nus = nus if (full or nus_given) else QUICK_ELLIPTIC["nus"]
    if elliptic_ratios is not None:
        e_rats = check_ratios(elliptic_ratios, "elliptic_ratios")
    elif full:
        e_rats = QUICK_RATIOS
    else:
        e_rats = ratios if ratios_given else QUICK_ELLIPTIC["ratios"]
    return e_nus, e_rats

