r"""Validation study: the asymptotic results against the direct numerical solvers (issue 4).

For each case -- a punch shape, a Poisson ratio ``nu`` and a thickness ratio ``H/a`` -- the
asymptotic solution (:func:`thinlayer.solve`: force (1.8) with its first correction, contact area
with the exact edge shift h^* (3.25), composite pressure) is compared with an independent direct
solution of (1.5)-(1.8) that uses no thin-layer series:

* ``"sphere"``: the paraboloid of revolution ``Phi = r^2/(2R)``, R = 1, delta0 = 1/2, so the leading
  contact radius is ``a_0 = 1`` and ``H = (H/a) a_0``.  Numerics: the spectral axisymmetric solver
  (:func:`thinlayer.numerics.solve_axisymmetric`; its force is converged to ~1e-12, far below every
  asymptotic error measured here).
* ``"elliptic"``: the elliptic paraboloid (1.1) with ``R1/R2 = 4`` (R1 = 4, R2 = 1, delta0 = 1/2:
  semi-axes ``a_1 = 2``, ``a_2 = 1`` of Gamma_0), ``a = 2|omega_0|/|Gamma_0|`` the half-width of
  :class:`~thinlayer.ContactSolution`.  Numerics: the FFT/Polonsky--Keer solver
  :func:`thinlayer.numerics.solve_2d` on a grid of ``cells_per_H`` cells per layer thickness, and a
  second, coarser grid (Delta = H/5, the solver's limit) for an error estimate: the 2D force error is
  ``~ c (Delta/a)^2`` (c = 0.08-0.19 measured against the axisymmetric solver on the sphere) and the
  coarse grid's error is the larger, so ``|P_fine - P_coarse|/P`` estimates the fine grid's error from
  above (on the sphere at H/a = 0.1 and 0.05, with the same grids: 1.1 and 1.4 times the true error).
  Likewise for the area, the semi-axes and the pressure.

Errors are relative, ``asymptotic/numeric - 1``, for the force ``P = P_0 + P_1`` and the leading
``P_0``; for the contact area ``|omega_0| - h^* H |Gamma_0|``, the leading ``|omega_0|`` and the
area with Alexandrov's h^*.  The pressure error is ``max |p_c - p_num| / max p_num`` (sphere: on a
radial line through the whole contact, edge included; elliptic: on the cells at least three cells
inside the numerical contact edge, where the piecewise-constant numerical pressure is accurate --
nearer the edge its own error, ~5e-3 p_max at Delta = H/8, is as large as the asymptotic one).

The claimed orders of the remainders (:data:`CLAIMED_ORDERS`, from :data:`thinlayer.asymptotics.force_law.ORDERS`):
force ``O((H/a)^3)``, contact area ``O((H/a)^2)``, composite pressure ``O(p_max H/a)`` (a bound).
The observed pressure slope is 1.3-2.1: the largest error sits at the true contact edge, where the
composite pressure's edge ``a - h^* H`` is off by ``O(H^2/a)`` under a square-root profile of height
``O(p_max H/a)`` on the scale H, i.e. ``O(p_max (H/a)^{3/2})``; half a thickness inside the edge the
error is ``O(p_max (H/a)^2)``.  For contrast (shown, not judged): the leading force alone has a
remainder ``O((H/a)^2)``, the leading area ``O(H/a)``.  :meth:`ValidationStudy.observed_orders`
fits the log-log slope of ``|error|`` against ``H/a`` per (shape, nu), using only the rows whose
numerical error estimate is below a third of the asymptotic error ("resolved").

Edge shift: from the axisymmetric contact radius c, ``h(H/a) = (a_0 - c)/H -> h^*`` as ``H/a -> 0``
with corrections in powers of H/a; :meth:`ValidationStudy.edge_shift_checks` extrapolates (Richardson:
the polynomial through the smallest three ratios) and compares with the exact h^* and Alexandrov's.

Long runs print progress lines on stderr (or a tqdm bar when tqdm is installed and stderr is a
terminal) and stop cleanly on KeyboardInterrupt: the study returned holds the rows done so far,
with ``interrupted = True``.  The command ``thinlayer validate`` (:func:`add_cli`, :func:`cli`)
writes the table as text, LaTeX and JSON and, with ``--plots``, the figures (matplotlib, the
``plot`` extra) as PNG and PDF.
"""
from __future__ import annotations

import json
import math
import numbers
import sys
import time
from collections.abc import Callable, Iterable, Sequence
from dataclasses import asdict, dataclass, field
from fractions import Fraction
from pathlib import Path
from types import MappingProxyType
from typing import Any

import numpy as np

__all__ = [
    "CLAIMED_ORDERS",
    "H_OVER_A_RANGE",
    "NUS",
    "SHAPES",
    "ContourData",
    "EdgeShiftCheck",
    "OrderFit",
    "PressureProfile",
    "SpeedComparison",
    "StudyEvent",
    "ValidationRow",
    "ValidationStudy",
    "add_cli",
    "cli",
    "elliptic_grid",
    "speed_comparison",
    "validate_elliptic",
    "validate_sphere",
    "validation_study",
]

#: the punch shapes of the study
SHAPES = ("sphere", "elliptic")
#: Poisson ratios of the study (issue 4)
NUS = (0.0, 0.2, 0.3, 0.4, 0.45)
#: admissible thickness ratios H/a (issue 4); beyond, the asymptotics or the numerics are out of their range
H_OVER_A_RANGE = (0.0125, 0.2)
#: default ratios: a factor 2 apart
QUICK_RATIOS = (0.2, 0.1, 0.05, 0.025, 0.0125)
#: ratios of the full study: a factor sqrt(2) apart
FULL_RATIOS = tuple(round(0.2 * 2.0 ** (-k / 2.0), 12) for k in range(9))
#: the elliptic cases of the quick study (the 2D solver is the expensive part)
QUICK_ELLIPTIC = {"nus": (0.3,), "ratios": (0.2, 0.1)}
#: ``{quantity: (order, kind)}``: claimed order of the relative remainder in H/a; kind "equal" (the
#: remainder is of exactly this order) or "bound" (at most of this order)
CLAIMED_ORDERS = MappingProxyType({
    "force": (3, "equal"),
    "contact_area": (2, "equal"),
    "pressure": (1, "bound"),
})
#: the leading terms alone, for contrast (kind "contrast": shown, not judged): the first corrections matter
CONTRAST_ORDERS = MappingProxyType({
    "force_leading": (2, "contrast"),
    "contact_area_leading": (1, "contrast"),
})
_ORDERS = MappingProxyType({**CLAIMED_ORDERS, **CONTRAST_ORDERS})
#: an observed order matches a claim when within this distance (or above claim - this, for a bound)
ORDER_TOLERANCE = 0.4
#: a numerical result resolves an asymptotic error when its error estimate is below error/RESOLUTION
RESOLUTION = 3.0

# the geometry of the two shapes
_SPHERE_R, _DELTA0 = 1.0, 0.5  # a_0 = sqrt(2 R delta0) = 1
_ELLIPSE_R = (4.0, 1.0)  # a_1 = 2, a_2 = 1
_PRESSURE_BAND_CELLS = 3  # 2D pressure error: cells at least this far inside the numerical edge
_COARSE_CELLS_PER_H = 5.0  # the 2D solver's limit; the coarse grid of the error estimate


# ---------------------------------------------------------------------------------------------
# result objects
# ---------------------------------------------------------------------------------------------
def _readonly(a: Any) -> np.ndarray:
    a = np.array(a, dtype=float)
    a.setflags(write=False)
    return a


@dataclass(frozen=True)
class ValidationRow:
    """One case of the study: asymptotic against numerical results.

    Attributes
    ----------
    shape, nu, H_over_a:
        The case: ``"sphere"`` or ``"elliptic"``, Poisson ratio, thickness ratio ``H/a``.
    H, delta0, half_width:
        Thickness, indentation and ``a = 2|omega_0|/|Gamma_0|``.
    force_numeric, force_asymptotic, force_leading:
        ``P`` numerical, ``P_0 + P_1`` (1.8) and ``P_0``.
    force_numeric_error:
        Estimated relative error of ``force_numeric``.
    area_numeric, area_asymptotic, area_leading, area_alexandrov:
        Contact area: numerical, ``|omega_0| - h^* H |Gamma_0|`` (3.25), ``|omega_0|``, and with
        Alexandrov's h^*.
    area_numeric_error:
        Estimated relative error of ``area_numeric``.
    semi_axes_numeric, semi_axes_asymptotic, semi_axes_leading:
        Contact semi-axes (x1, x2): numerical, ``a_i - h^* H`` and ``a_i`` (the radius twice for the sphere).
    edge_shift_numeric, edge_shift_numeric_error:
        ``(a_i - s_i)/H`` from the numerics (mean over the two axes) and its estimated error.
    edge_shift_exact, edge_shift_alexandrov:
        h^* (3.25): exact (Wiener--Hopf) and Alexandrov's.
    pressure_error:
        ``max |p_c - p_num| / max p_num`` (see the module docstring for the region).
    pressure_band:
        Width of the band inside the numerical contact edge left out of ``pressure_error`` (0 for the sphere).
    pressure_numeric_error:
        Estimated error of the numerical pressure in the same norm.
    solver:
        The numerical method and its resolution.
    seconds_numeric, seconds_asymptotic:
        Wall time of the numerical solution(s) and of :func:`thinlayer.solve` with the pressure evaluation.
    """

    shape: str
    nu: float
    H_over_a: float
    H: float
    delta0: float
    half_width: float
    force_numeric: float
    force_asymptotic: float
    force_leading: float
    force_numeric_error: float
    area_numeric: float
    area_asymptotic: float
    area_leading: float
    area_alexandrov: float
    area_numeric_error: float
    semi_axes_numeric: tuple[float, float]
    semi_axes_asymptotic: tuple[float, float]
    semi_axes_leading: tuple[float, float]
    edge_shift_numeric: float
    edge_shift_numeric_error: float
    edge_shift_exact: float
    edge_shift_alexandrov: float
    pressure_error: float
    pressure_band: float
    pressure_numeric_error: float
    solver: str
    seconds_numeric: float
    seconds_asymptotic: float

    # ---- relative errors of the asymptotic results -----------------------------------------
    @property
    def force_error(self) -> float:
        """``(P_0 + P_1)/P_num - 1``: claimed O((H/a)^3)."""
        return self.force_asymptotic / self.force_numeric - 1.0

    @property
    def force_leading_error(self) -> float:
        return self.force_leading / self.force_numeric - 1.0

    @property
    def area_error(self) -> float:
        """``(|omega_0| - h^* H |Gamma_0|)/|omega_num| - 1``: claimed O((H/a)^2)."""
        return self.area_asymptotic / self.area_numeric - 1.0

    @property
    def area_leading_error(self) -> float:
        return self.area_leading / self.area_numeric - 1.0

    @property
    def area_alexandrov_error(self) -> float:
        return self.area_alexandrov / self.area_numeric - 1.0

    def errors(self) -> dict[str, float]:
        """``{quantity: relative error}``: the claimed quantities, the leading terms and Alexandrov's area."""
        return {"force": self.force_error, "contact_area": self.area_error, "pressure": self.pressure_error,
                "force_leading": self.force_leading_error, "contact_area_leading": self.area_leading_error,
                "contact_area_alexandrov": self.area_alexandrov_error}

    def numeric_error(self, quantity: str) -> float:
        """Estimated error of the numerical value entering ``quantity``'s error."""
        if quantity.startswith("force"):
            return self.force_numeric_error
        if quantity.startswith("contact_area"):
            return self.area_numeric_error
        if quantity == "pressure":
            return self.pressure_numeric_error
        raise ValueError(f"unknown quantity {quantity!r}; known: {', '.join(self.errors())}")

    def resolved(self, quantity: str) -> bool:
        """True when the numerical error estimate is below ``|asymptotic error| / RESOLUTION``."""
        err = abs(self.errors()[quantity])
        num = self.numeric_error(quantity)
        return bool(math.isfinite(num) and num * RESOLUTION < err)

    def to_dict(self) -> dict[str, Any]:
        d = asdict(self)
        d.update({f"{q}_error": e for q, e in self.errors().items() if q != "pressure"})
        d["resolved"] = {q: self.resolved(q) for q in self.errors()}
        return _jsonable(d)


@dataclass(frozen=True, eq=False)
class PressureProfile:
    """Pressure along a line: numerical against composite asymptotic, for the plots.

    ``x`` is the coordinate along ``axis`` (``"r"``, ``"x1"`` or ``"x2"``), the other coordinate
    being ``offset``; ``edge`` the numerical contact edge on that line.
    """

    shape: str
    nu: float
    H_over_a: float
    axis: str
    offset: float
    x: np.ndarray = field(repr=False)
    numeric: np.ndarray = field(repr=False)
    asymptotic: np.ndarray = field(repr=False)
    half_width: float = 1.0
    edge: float = float("nan")


@dataclass(frozen=True, eq=False)
class ContourData:
    """Contact contours for the plots: numerical polygon(s), Gamma_0 moved in by ``h^* H`` (exact h^*),
    ``Gamma_0`` itself and Gamma_0 moved in by Alexandrov's h^*.
    """

    shape: str
    nu: float
    H_over_a: float
    numeric: tuple = field(repr=False)
    asymptotic: np.ndarray = field(repr=False)
    leading: np.ndarray = field(repr=False)
    alexandrov: np.ndarray = field(repr=False)


@dataclass(frozen=True)
class OrderFit:
    """Observed order of a remainder: least-squares slope of ``log|error|`` against ``log(H/a)``."""

    shape: str
    nu: float
    quantity: str
    claimed: int
    kind: str
    observed: float | None
    points: int
    ratios: tuple[float, ...]
    unresolved: tuple[float, ...] = ()

    @property
    def matches(self) -> bool | None:
        """Does the observed order match the claim (within :data:`ORDER_TOLERANCE`)?

        None without a fit, and for the leading terms (kind ``"contrast"``: shown, not judged).
        """
        if self.observed is None or self.kind == "contrast":
            return None
        if self.kind == "bound":
            return self.observed >= self.claimed - ORDER_TOLERANCE
        return abs(self.observed - self.claimed) <= ORDER_TOLERANCE

    @property
    def status(self) -> str:
        m = self.matches
        if self.kind == "contrast" and self.observed is not None:
            return "contrast"
        return "n/a" if m is None else ("ok" if m else "MISMATCH")


@dataclass(frozen=True)
class EdgeShiftCheck:
    """``h(H/a) = (a_0 - c)/H`` from the axisymmetric numerics, extrapolated to ``H/a -> 0``.

    ``extrapolated`` is the value at 0 of the polynomial through the points (degree = points - 1, the
    smallest ratios, at most three); ``error_estimate`` its change against one degree less (fewer
    points): an over-estimate of the extrapolation error when the series in H/a converges.
    ``tolerance = max(2 error_estimate, 1e-4)``.
    """

    nu: float
    ratios: tuple[float, ...]
    h_numeric: tuple[float, ...]
    extrapolated: float
    error_estimate: float
    exact: float
    alexandrov: float

    @property
    def tolerance(self) -> float:
        return max(2.0 * self.error_estimate, 1e-4)

    @property
    def confirms_exact(self) -> bool:
        return abs(self.extrapolated - self.exact) <= self.tolerance

    @property
    def rejects_alexandrov(self) -> bool:
        return abs(self.extrapolated - self.alexandrov) > self.tolerance

    @property
    def status(self) -> str:
        return "ok" if self.confirms_exact and self.rejects_alexandrov else "MISMATCH"

    def to_dict(self) -> dict[str, Any]:
        d = asdict(self)
        d.update(tolerance=self.tolerance, confirms_exact=self.confirms_exact,
                 rejects_alexandrov=self.rejects_alexandrov)
        return _jsonable(d)


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


@dataclass(frozen=True, eq=False)
class ValidationStudy:
    """Rows of a validation study with the analyses of issue 4 (table, observed orders, h^*, plots).

    Attributes
    ----------
    rows:
        The :class:`ValidationRow` s, in the order computed.
    profiles, contours:
        Data for the plots (:class:`PressureProfile`, :class:`ContourData`).
    skipped:
        ``(shape, nu, H/a, reason)`` of cases not run (e.g. the 2D grid would exceed ``max_n``).
    interrupted:
        True if a KeyboardInterrupt stopped the study; ``pending`` lists the cases not done.
    settings:
        The parameters of the run (read-only mapping).
    seconds:
        Wall time of the study.
    """

    rows: tuple[ValidationRow, ...]
    profiles: tuple[PressureProfile, ...] = field(default=(), repr=False)
    contours: tuple[ContourData, ...] = field(default=(), repr=False)
    skipped: tuple[tuple[str, float, float, str], ...] = ()
    interrupted: bool = False
    pending: tuple[tuple[str, float, float], ...] = ()
    settings: Any = field(default_factory=lambda: MappingProxyType({}))
    seconds: float = 0.0

    # ---- analyses ----------------------------------------------------------------------------
    def groups(self) -> dict[tuple[str, float], list[ValidationRow]]:
        """Rows by (shape, nu), each list sorted by decreasing H/a."""
        out: dict[tuple[str, float], list[ValidationRow]] = {}
        for r in self.rows:
            out.setdefault((r.shape, r.nu), []).append(r)
        return {k: sorted(v, key=lambda r: -r.H_over_a) for k, v in out.items()}

    def observed_orders(self, quantities: Iterable[str] | None = None) -> tuple[OrderFit, ...]:
        """Log-log least-squares slopes of ``|error|`` against H/a per (shape, nu, quantity).

        Only rows that resolve the quantity (:meth:`ValidationRow.resolved`) enter a fit; a fit needs
        two of them (``observed = None`` otherwise).
        """
        quantities = tuple(_ORDERS) if quantities is None else tuple(quantities)
        for q in quantities:
            if q not in _ORDERS:
                raise ValueError(f"unknown quantity {q!r}; known: {', '.join(_ORDERS)}")
        fits = []
        for (shape, nu), rows in self.groups().items():
            for q in quantities:
                claimed, kind = _ORDERS[q]
                use = [r for r in rows if r.resolved(q) and abs(r.errors()[q]) > 0]
                bad = tuple(r.H_over_a for r in rows if r not in use)
                slope = None
                if len(use) >= 2:
                    x = np.log([r.H_over_a for r in use])
                    y = np.log([abs(r.errors()[q]) for r in use])
                    slope = float(np.polyfit(x, y, 1)[0])
                fits.append(OrderFit(shape, nu, q, claimed, kind, slope, len(use),
                                     tuple(r.H_over_a for r in use), bad))
        return tuple(fits)

    def edge_shift_checks(self, max_ratio: float = 0.1) -> tuple[EdgeShiftCheck, ...]:
        """Richardson extrapolation of ``(a_0 - c)/H`` to ``H/a -> 0`` per nu (sphere rows with H/a <= max_ratio).

        Uses the smallest three ratios (two at least; a nu with fewer sphere rows is left out).
        """
        out = []
        for (shape, nu), rows in self.groups().items():
            if shape != "sphere":
                continue
            pts = sorted((r for r in rows if r.H_over_a <= max_ratio * (1 + 1e-9)), key=lambda r: r.H_over_a)[:3]
            if len(pts) < 2:
                continue
            eps = np.array([r.H_over_a for r in pts])
            h = np.array([r.edge_shift_numeric for r in pts])
            k = len(pts) - 1
            ext = float(np.polyfit(eps, h, k)[-1]) if k < len(pts) else float(h[0])
            lower = float(np.polyfit(eps[:k], h[:k], k - 1)[-1]) if k >= 2 else float(h[0])
            out.append(EdgeShiftCheck(nu, tuple(eps.tolist()), tuple(h.tolist()), ext, abs(ext - lower),
                                      pts[0].edge_shift_exact, pts[0].edge_shift_alexandrov))
        return tuple(out)

    @property
    def passed(self) -> bool:
        """All order fits for the claimed quantities (force, area, pressure) and all h^* checks are ok."""
        fits = [f for f in self.observed_orders(("force", "contact_area", "pressure")) if f.matches is not None]
        return all(f.matches for f in fits) and all(c.status == "ok" for c in self.edge_shift_checks())

    # ---- output -------------------------------------------------------------------------------
    def table(self) -> str:
        """Plain-text tables: the rows, the observed orders and the h^* checks."""
        head = (f"{'shape':<8} {'nu':>5} {'H/a':>7} {'P_num':>12} {'err P':>10} {'err P0':>10} "
                f"{'area_num':>10} {'err A':>10} {'err A0':>10} {'(a-c)/H':>9} {'h*':>8} {'p err':>9} "
                f"{'num err P':>9}  solver")
        lines = [head, "-" * len(head)]
        for r in self.rows:
            lines.append(
                f"{r.shape:<8} {r.nu:>5.3g} {r.H_over_a:>7.4g} {r.force_numeric:>12.7g} {r.force_error:>10.2e} "
                f"{r.force_leading_error:>10.2e} {r.area_numeric:>10.6g} {r.area_error:>10.2e} "
                f"{r.area_leading_error:>10.2e} {r.edge_shift_numeric:>9.5f} {r.edge_shift_exact:>8.5f} "
                f"{r.pressure_error:>9.2e} {r.force_numeric_error:>9.1e}  {r.solver}")
        lines += ["", "observed order of the remainder (log-log slope of |error| vs H/a, resolved rows only)",
                  f"{'shape':<8} {'nu':>5} {'quantity':<24} {'claimed':>8} {'observed':>9} {'points':>6}  status"]
        for f in self.observed_orders():
            claim = f"{'>= ' if f.kind == 'bound' else ''}{f.claimed}"
            obs = "-" if f.observed is None else f"{f.observed:.2f}"
            lines.append(f"{f.shape:<8} {f.nu:>5.3g} {f.quantity:<24} {claim:>8} {obs:>9} {f.points:>6}  {f.status}")
        checks = self.edge_shift_checks()
        if checks:
            lines += ["", "edge shift: (a_0 - c)/H extrapolated to H/a -> 0 (sphere, axisymmetric numerics)",
                      (f"{'nu':>5} {'extrapolated':>13} {'est. error':>10} {'exact h*':>11} {'diff':>9} "
                      f"{'Alexandrov':>11} {'diff':>9}  status")]
            for c in checks:
                lines.append(f"{c.nu:>5.3g} {c.extrapolated:>13.7f} {c.error_estimate:>10.1e} {c.exact:>11.7f} "
                             f"{c.extrapolated - c.exact:>9.1e} {c.alexandrov:>11.7f} "
                             f"{c.extrapolated - c.alexandrov:>9.1e}  {c.status}")
        if self.skipped:
            lines += ["", "skipped:"] + [f"  {s} nu={n:g} H/a={e:g}: {why}" for s, n, e, why in self.skipped]
        if self.interrupted:
            lines += ["", f"INTERRUPTED: {len(self.rows)} cases done, {len(self.pending)} not run"]
        return "\n".join(lines)

    def __str__(self) -> str:
        return self.table()

    def latex(self) -> str:
        """LaTeX tabulars (no packages needed) of the rows, the observed orders and the h^* checks."""
        def e(x: float) -> str:
            if not math.isfinite(x):
                return "--"
            m, k = f"{x:.2e}".split("e")
            return rf"${m}\cdot 10^{{{int(k)}}}$"

        out = [r"\begin{tabular}{lrrrrrrrrr}", r"\hline",
               (r"shape & $\nu$ & $H/a$ & $P_{\rm num}$ & err $P$ & err $P_0$ & err $|\omega|$ & "
               r"err $|\omega_0|$ & $(a-c)/H$ & err $p_c$ \\"), r"\hline"]
        for r in self.rows:
            out.append(f"{r.shape} & {r.nu:g} & {r.H_over_a:.4g} & {r.force_numeric:.7g} & {e(r.force_error)} & "
                       f"{e(r.force_leading_error)} & {e(r.area_error)} & {e(r.area_leading_error)} & "
                       f"{r.edge_shift_numeric:.5f} & {e(r.pressure_error)} \\\\")
        out += [r"\hline", r"\end{tabular}", "", r"\begin{tabular}{lrlrrr}", r"\hline",
                r"shape & $\nu$ & quantity & claimed & observed & points \\", r"\hline"]
        for f in self.observed_orders():
            q = f.quantity.replace("_", r"\_")
            claim = (r"$\geq$ " if f.kind == "bound" else "") + str(f.claimed)
            obs = "--" if f.observed is None else f"{f.observed:.2f}"
            out.append(f"{f.shape} & {f.nu:g} & {q} & {claim} & {obs} & {f.points} \\\\")
        out += [r"\hline", r"\end{tabular}"]
        checks = self.edge_shift_checks()
        if checks:
            out += ["", r"\begin{tabular}{rrrr}", r"\hline",
                    r"$\nu$ & $\lim (a_0 - c)/H$ & $h^*$ (exact) & $h^*$ (Alexandrov) \\", r"\hline"]
            out += [f"{c.nu:g} & {c.extrapolated:.6f} & {c.exact:.6f} & {c.alexandrov:.6f} \\\\" for c in checks]
            out += [r"\hline", r"\end{tabular}"]
        return "\n".join(out) + "\n"

    def to_dict(self) -> dict[str, Any]:
        return _jsonable({
            "rows": [r.to_dict() for r in self.rows],
            "observed_orders": [dict(asdict(f), matches=f.matches) for f in self.observed_orders()],
            "edge_shift_checks": [c.to_dict() for c in self.edge_shift_checks()],
            "skipped": [{"shape": s, "nu": n, "H_over_a": e, "reason": w} for s, n, e, w in self.skipped],
            "interrupted": self.interrupted,
            "pending": [{"shape": s, "nu": n, "H_over_a": e} for s, n, e in self.pending],
            "settings": dict(self.settings),
            "seconds": self.seconds,
            "passed": self.passed,
        })

    def to_json(self) -> str:
        return json.dumps(self.to_dict(), indent=2)

    def write(self, directory: str | Path, *, plots: bool = False, stem: str = "validation") -> list[Path]:
        """Write ``<stem>.txt``, ``.tex`` and ``.json`` (and with ``plots`` the figures) into ``directory``."""
        d = Path(directory)
        d.mkdir(parents=True, exist_ok=True)
        files = []
        for suffix, text in ((".txt", self.table() + "\n"), (".tex", self.latex()), (".json", self.to_json() + "\n")):
            p = d / f"{stem}{suffix}"
            p.write_text(text, encoding="utf-8")
            files.append(p)
        if plots:
            files += self.plots(d, stem=stem)
        return files

    def plots(self, directory: str | Path, *, stem: str = "validation", formats: Sequence[str] = ("png", "pdf")
              ) -> list[Path]:
        """Figures: error vs H/a (log-log), pressure profiles, contact contours; each as PNG and PDF.

        Needs matplotlib (``pip install 'thinlayer[plot]'``); no pyplot state is touched.
        """
        return _plots(self, Path(directory), stem, tuple(formats))


def _jsonable(obj: Any) -> Any:
    if isinstance(obj, dict):
        return {str(k): _jsonable(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [_jsonable(v) for v in obj]
    if isinstance(obj, (bool, np.bool_)):
        return bool(obj)
    if isinstance(obj, (numbers.Integral,)):
        return int(obj)
    if isinstance(obj, (numbers.Real, np.floating)):
        v = float(obj)
        return v if math.isfinite(v) else None
    return obj


# ---------------------------------------------------------------------------------------------
# input checks
# ---------------------------------------------------------------------------------------------
def _check_nu(nu: Any) -> float:
    if isinstance(nu, bool) or not isinstance(nu, numbers.Real):
        raise TypeError(f"nu must be a real number in (-1, 1/2), got {nu!r} ({type(nu).__name__})")
    v = float(nu)
    if not -1.0 < v < 0.5:
        raise ValueError(f"nu = {nu!r} is outside the admissible range -1 < nu < 1/2 of the compressible layer")
    return v


def _check_ratio(eps: Any) -> float:
    if isinstance(eps, bool) or not isinstance(eps, numbers.Real):
        raise TypeError(f"H/a must be a real number in [{H_OVER_A_RANGE[0]}, {H_OVER_A_RANGE[1]}], got {eps!r}")
    v = float(eps)
    lo, hi = H_OVER_A_RANGE
    if not (lo * (1 - 1e-9) <= v <= hi * (1 + 1e-9)):
        raise ValueError(f"H/a = {eps!r} is outside the validated range [{lo}, {hi}]: above, the remainders "
                         f"are no longer small; below, the direct numerics become too expensive")
    return v


def _check_list(values: Any, check: Callable[[Any], float], name: str) -> tuple[float, ...]:
    if isinstance(values, (numbers.Real, str)):
        values = (values,)
    try:
        vals = tuple(values)
    except TypeError as exc:
        raise TypeError(f"{name} must be a sequence of numbers, got {values!r}") from exc
    if not vals:
        raise ValueError(f"{name} is empty: give at least one value")
    out = []
    for v in vals:
        c = check(v)
        if c not in out:
            out.append(c)
    return tuple(out)


def _check_shapes(shapes: Any) -> tuple[str, ...]:
    if isinstance(shapes, str):
        shapes = (shapes,)
    out = []
    for s in shapes:
        if s not in SHAPES:
            raise ValueError(f"unknown shape {s!r}: choose from {', '.join(SHAPES)}")
        if s not in out:
            out.append(s)
    if not out:
        raise ValueError(f"no shape given: choose from {', '.join(SHAPES)}")
    return tuple(out)


def _check_int(value: Any, name: str, lo: int) -> int:
    if isinstance(value, bool) or not isinstance(value, numbers.Integral) or value < lo:
        raise ValueError(f"{name} must be an integer >= {lo}, got {value!r}")
    return int(value)


def _layer(nu: float):
    from ..layers.kernels import BondedLayer

    return BondedLayer(str(Fraction(float(nu)).limit_denominator(10**6)))


# ---------------------------------------------------------------------------------------------
# the cases
# ---------------------------------------------------------------------------------------------
def _same_ratio(got: float, want: float) -> None:
    if abs(got / want - 1.0) > 1e-9:  # pragma: no cover - the geometry above fixes a
        raise RuntimeError(f"internal: the solution has H/a = {got}, the case asked for {want}")


def _sphere_case(nu: float, eps: float) -> tuple[ValidationRow, list[PressureProfile], list[ContourData]]:
    from ..asymptotics.solution import solve
    from ..numerics import solve_axisymmetric
    from ..numerics.axisymmetric import radial_profile
    from ..numerics.direct import contact_for_radius
    from ..punch import Punch

    layer, punch = _layer(nu), Punch.paraboloid(R=_SPHERE_R)
    a0 = math.sqrt(2.0 * _SPHERE_R * _DELTA0)
    H = eps * a0
    t0 = time.perf_counter()
    sol = solve(layer, punch, delta0=_DELTA0, H=H)
    _same_ratio(sol.H_over_a, eps)
    t1 = time.perf_counter()
    res = solve_axisymmetric(layer, punch, _DELTA0, H)
    c = res.contact_radius
    # a coarser run at the same radius: its pressure differs from the fine one by more than the fine error
    coarse = contact_for_radius(layer, radial_profile(punch), c, H, n=max(4, round(0.7 * res.modes)),
                                error_estimate=False)
    t2 = time.perf_counter()
    h_ex = sol.edge_shift
    ra = a0 - h_ex * H  # the edge of the composite pressure
    lo, hi = min(c, ra), max(c, ra)
    # the largest error sits between the two edges (O(H^2/a) apart): sample them densely
    near = H * np.geomspace(1e-7, 4.0, 300)
    r = np.unique(np.concatenate([np.linspace(0.0, hi + 2.0 * H, 1201), np.linspace(lo, hi, 201),
                                  c - near, c + near, ra - near, ra + near]))
    r = r[r >= 0.0]
    pn = res.pressure_at(r)
    t3 = time.perf_counter()
    pc = np.asarray(sol.pressure(r, np.zeros_like(r)), dtype=float)
    t4 = time.perf_counter()
    pmax = float(pn.max())
    perr = float(np.abs(pc - pn).max() / pmax)
    pnum = float(np.abs(coarse.pressure_at(r) - pn).max() / pmax)
    row = ValidationRow(
        shape="sphere", nu=nu, H_over_a=eps, H=H, delta0=_DELTA0, half_width=sol.half_width,
        force_numeric=res.force, force_asymptotic=sol.force, force_leading=sol.force_leading,
        force_numeric_error=float(res.force_error),
        area_numeric=res.contact_area, area_asymptotic=sol.contact_area, area_leading=sol.contact_area_leading,
        area_alexandrov=sol.contact_area_alexandrov, area_numeric_error=2.0 * float(res.radius_error) / c,
        semi_axes_numeric=(c, c), semi_axes_asymptotic=(a0 - h_ex * H,) * 2, semi_axes_leading=(a0, a0),
        edge_shift_numeric=(a0 - c) / H, edge_shift_numeric_error=float(res.radius_error) / H,
        edge_shift_exact=h_ex, edge_shift_alexandrov=sol.edge_shift_alexandrov,
        pressure_error=perr, pressure_band=0.0, pressure_numeric_error=pnum,
        solver=f"axisymmetric spectral, {res.modes} modes",
        seconds_numeric=(t2 - t1) + (t3 - t2), seconds_asymptotic=(t1 - t0) + (t4 - t3))
    prof = PressureProfile("sphere", nu, row.H_over_a, "r", 0.0, _readonly(r), _readonly(pn), _readonly(pc),
                           a0, c)
    th = np.linspace(0.0, 2.0 * math.pi, 361)
    circ = np.column_stack([np.cos(th), np.sin(th)])
    cont = ContourData("sphere", nu, row.H_over_a, (_readonly(c * circ),), _readonly((a0 - h_ex * H) * circ),
                       _readonly(a0 * circ), _readonly((a0 - sol.edge_shift_alexandrov * H) * circ))
    return row, [prof], [cont]


def _ellipse_geometry() -> tuple[float, float, float, float, float]:
    """Semi-axes a1, a2 of Gamma_0, |omega_0|, |Gamma_0| and a = 2|omega_0|/|Gamma_0|."""
    from scipy.special import ellipe

    R1, R2 = _ELLIPSE_R
    a1, a2 = math.sqrt(2 * R1 * _DELTA0), math.sqrt(2 * R2 * _DELTA0)
    area = math.pi * a1 * a2
    perim = 4.0 * a1 * float(ellipe(1.0 - (a2 / a1) ** 2))
    return a1, a2, area, perim, 2.0 * area / perim


def elliptic_grid(H_over_a: float, cells_per_H: float = 8.0) -> tuple[int, int, float]:
    """``(n, n_coarse, half_width)`` of the 2D grids of the elliptic case at ``H/a``.

    The square ``|x_i| < 1.01 a_1 + 2H`` (the contact stays inside for -0.6 < h^* and more than
    two cells from the boundary); ``n`` gives ``cells_per_H`` cells per H, the coarse grid H/5
    cells; both rounded up to multiples of 16.

    Examples
    --------
    >>> n, n_coarse, W = elliptic_grid(0.1)
    >>> n, n_coarse, round(W, 4)
    (288, 176, 2.2794)
    """
    eps = _check_ratio(H_over_a)
    if not (isinstance(cells_per_H, numbers.Real) and cells_per_H >= 6.0):
        raise ValueError(f"cells_per_H must be a number >= 6 (the coarse grid of the error estimate has "
                         f"{_COARSE_CELLS_PER_H:g}, the 2D solver's limit), got {cells_per_H!r}")
    a1, _, _, _, a = _ellipse_geometry()
    H = eps * a
    W = 1.01 * a1 + 2.0 * H

    def cells(k: float) -> int:
        return 16 * math.ceil(2.0 * W * k / H / 16.0 - 1e-9)

    return cells(float(cells_per_H)), cells(_COARSE_CELLS_PER_H), W


def _axis_crossing(polys: Sequence[np.ndarray], axis: int) -> float:
    """Mean |coordinate| where the contour polygons cross the other axis (the semi-axis along ``axis``)."""
    other = 1 - axis
    hits = []
    for pts in polys:
        a, b = pts[:-1], pts[1:]
        s = (a[:, other] <= 0) != (b[:, other] <= 0)
        for p, q in zip(a[s], b[s]):
            t = p[other] / (p[other] - q[other])
            hits.append(abs(p[axis] + t * (q[axis] - p[axis])))
    if len(hits) < 2:
        raise RuntimeError(f"the numerical contact contour does not cross the x{other + 1} = 0 axis twice")
    hits.sort()
    return float(np.mean(hits[-2:]))


def _elliptic_case(nu: float, eps: float, cells_per_H: float, workers: int | None
                   ) -> tuple[ValidationRow, list[PressureProfile], list[ContourData]]:
    from scipy import ndimage
    from scipy.interpolate import RegularGridInterpolator

    from ..asymptotics.solution import solve
    from ..numerics import solve_2d
    from ..punch import Punch

    layer, punch = _layer(nu), Punch.elliptic_paraboloid(R1=_ELLIPSE_R[0], R2=_ELLIPSE_R[1])
    a1, a2, _, _, a = _ellipse_geometry()
    H = eps * a
    n, nc, W = elliptic_grid(eps, cells_per_H)
    t0 = time.perf_counter()
    sol = solve(layer, punch, delta0=_DELTA0, H=H)
    _same_ratio(sol.H_over_a, eps)
    t1 = time.perf_counter()
    fine = solve_2d(layer, punch, delta0=_DELTA0, H=H, n=n, extent=W, workers=workers)
    coarse = solve_2d(layer, punch, delta0=_DELTA0, H=H, n=nc, extent=W, workers=workers)
    t2 = time.perf_counter()
    X1, X2 = np.meshgrid(fine.x1, fine.x2, indexing="ij")
    pc = np.asarray(sol.pressure(X1, X2), dtype=float)
    t3 = time.perf_counter()
    pn = np.asarray(fine.pressure)
    pmax = float(pn.max())
    inner = ndimage.binary_erosion(pn > 0, iterations=_PRESSURE_BAND_CELLS)
    perr = float(np.abs(pc - pn)[inner].max() / pmax)
    # pressure error estimate: coarse cells (well inside) against the fine pressure interpolated there
    interp = RegularGridInterpolator((fine.x1, fine.x2), pn)
    inner_c = ndimage.binary_erosion(np.asarray(coarse.pressure) > 0, iterations=_PRESSURE_BAND_CELLS)
    Y1, Y2 = np.meshgrid(coarse.x1, coarse.x2, indexing="ij")
    pnum = float(np.abs(np.asarray(coarse.pressure)[inner_c]
                        - interp(np.column_stack([Y1[inner_c], Y2[inner_c]]))).max() / pmax)
    s_f = (_axis_crossing(fine.contour, 0), _axis_crossing(fine.contour, 1))
    s_c = (_axis_crossing(coarse.contour, 0), _axis_crossing(coarse.contour, 1))
    h_ex = sol.edge_shift
    row = ValidationRow(
        shape="elliptic", nu=nu, H_over_a=eps, H=H, delta0=_DELTA0, half_width=sol.half_width,
        force_numeric=fine.force, force_asymptotic=sol.force, force_leading=sol.force_leading,
        force_numeric_error=abs(fine.force - coarse.force) / fine.force,
        area_numeric=fine.contact_area, area_asymptotic=sol.contact_area, area_leading=sol.contact_area_leading,
        area_alexandrov=sol.contact_area_alexandrov,
        area_numeric_error=abs(fine.contact_area - coarse.contact_area) / fine.contact_area,
        semi_axes_numeric=s_f, semi_axes_asymptotic=(a1 - h_ex * H, a2 - h_ex * H), semi_axes_leading=(a1, a2),
        edge_shift_numeric=0.5 * ((a1 - s_f[0]) + (a2 - s_f[1])) / H,
        edge_shift_numeric_error=max(abs(s_f[0] - s_c[0]), abs(s_f[1] - s_c[1])) / H,
        edge_shift_exact=h_ex, edge_shift_alexandrov=sol.edge_shift_alexandrov,
        pressure_error=perr, pressure_band=_PRESSURE_BAND_CELLS * fine.spacing, pressure_numeric_error=pnum,
        solver=f"fft2d n={n} (Delta=H/{H / fine.spacing:.1f}; error est. n={nc})",
        seconds_numeric=t2 - t1, seconds_asymptotic=(t1 - t0) + (t3 - t2))
    j, i = n // 2, n // 2  # x2 = Delta/2 and x1 = Delta/2: the lines next to the axes
    profs = [
        PressureProfile("elliptic", nu, row.H_over_a, "x1", float(fine.x2[j]), _readonly(fine.x1), _readonly(pn[:, j]),
                        _readonly(pc[:, j]), a1, s_f[0]),
        PressureProfile("elliptic", nu, row.H_over_a, "x2", float(fine.x1[i]), _readonly(fine.x2), _readonly(pn[i, :]),
                        _readonly(pc[i, :]), a2, s_f[1]),
    ]
    th = np.linspace(0.0, 2.0 * math.pi, 721)
    g0 = np.column_stack([a1 * np.cos(th), a2 * np.sin(th)])
    nrm = np.column_stack([g0[:, 0] / a1**2, g0[:, 1] / a2**2])
    nrm /= np.hypot(nrm[:, 0], nrm[:, 1])[:, None]
    cont = ContourData("elliptic", nu, row.H_over_a, tuple(_readonly(p) for p in fine.contour),
                       _readonly(g0 - h_ex * H * nrm), _readonly(g0),
                       _readonly(g0 - sol.edge_shift_alexandrov * H * nrm))
    return row, profs, [cont]


# ---------------------------------------------------------------------------------------------
# the study driver: progress and interruption
# ---------------------------------------------------------------------------------------------
class _Progress:
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
    prog = _Progress(bool(progress), len(todo))
    t0 = time.perf_counter()
    interrupted = False
    try:
        for k, (shape, nu, eps) in enumerate(todo):
            label = f"{shape} nu={nu:g} H/a={eps:g}"
            if callback is not None:
                callback(StudyEvent("start", k, len(todo), shape, nu, eps, time.perf_counter() - t0))
            prog.start(k, label, shape == "elliptic")
            tc = time.perf_counter()
            if shape == "sphere":
                row, pr, co = _sphere_case(nu, eps)
            else:
                row, pr, co = _elliptic_case(nu, eps, cells_per_H, workers)
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
    nu:
        Poisson ratio, -1 < nu < 1/2.
    H_over_a_values:
        Thickness ratios in ``H_OVER_A_RANGE`` = [0.0125, 0.2].
    progress:
        Print a line per case on stderr.
    callback:
        Called with a :class:`StudyEvent` before and after each case; raising KeyboardInterrupt there
        stops the study cleanly (as Ctrl-C does).

    Returns
    -------
    ValidationStudy
    """
    v = _check_nu(nu)
    eps = _check_list(H_over_a_values, _check_ratio, "H_over_a_values")
    return _run([("sphere", v, e) for e in eps], cells_per_H=8.0, max_n=0, workers=None, progress=progress,
                callback=callback, settings={"shapes": ["sphere"], "nus": [v], "ratios": list(eps)})


def validate_elliptic(nu: float, H_over_a_values: Iterable[float] = QUICK_ELLIPTIC["ratios"], *,
                      cells_per_H: float = 8.0, max_n: int = 1024, workers: int | None = None,
                      progress: bool = False, callback: Callable[[StudyEvent], Any] | None = None
                      ) -> ValidationStudy:
    """Elliptic paraboloid ``R1/R2 = 4`` at one Poisson ratio against the 2D FFT numerics.

    ``cells_per_H`` (>= 6) sets the fine grid, ``max_n`` the largest grid accepted (larger cases are
    listed in ``skipped``), ``workers`` the FFT threads.  Other arguments as :func:`validate_sphere`.
    """
    v = _check_nu(nu)
    eps = _check_list(H_over_a_values, _check_ratio, "H_over_a_values")
    max_n = _check_int(max_n, "max_n", 16)
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

    Parameters
    ----------
    nus:
        Poisson ratios (default :data:`NUS` = 0, 0.2, 0.3, 0.4, 0.45).
    ratios:
        H/a values in [0.0125, 0.2] (default: 0.2, 0.1, ..., 0.0125, a factor 2 apart; ``full``:
        nine values a factor sqrt(2) apart).
    shapes:
        ``"sphere"`` and/or ``"elliptic"``.
    full:
        The full study: the elliptic case for every nu and ratio as well (2D grids up to
        ``max_n = 2304``; several minutes).  Otherwise, unless given, the elliptic case runs at
        nu = 0.3 and H/a = 0.2, 0.1 only.
    elliptic_nus, elliptic_ratios:
        Override the elliptic cases.
    cells_per_H, max_n, workers:
        2D grid: cells per thickness (>= 6), largest grid (default 1024, ``full`` 2304), FFT threads.
    progress:
        Progress lines on stderr (a tqdm bar on a terminal when tqdm is installed).
    callback:
        Called with a :class:`StudyEvent` before and after each case; a KeyboardInterrupt raised there
        (or by Ctrl-C) stops the study, which then returns the rows done (``interrupted = True``).

    Returns
    -------
    ValidationStudy
    """
    shp = _check_shapes(shapes)
    nu_given = nus is not None
    nus_ = _check_list(NUS if nus is None else nus, _check_nu, "nus")
    rat_given = ratios is not None
    rats = _check_list((FULL_RATIOS if full else QUICK_RATIOS) if ratios is None else ratios, _check_ratio, "ratios")
    if elliptic_nus is not None:
        e_nus = _check_list(elliptic_nus, _check_nu, "elliptic_nus")
    else:
        e_nus = nus_ if (full or nu_given) else QUICK_ELLIPTIC["nus"]
    if elliptic_ratios is not None:
        e_rats = _check_list(elliptic_ratios, _check_ratio, "elliptic_ratios")
    elif full:
        e_rats = QUICK_RATIOS
    else:
        e_rats = rats if rat_given else QUICK_ELLIPTIC["ratios"]
    max_n = (2304 if full else 1024) if max_n is None else _check_int(max_n, "max_n", 16)
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


# ---------------------------------------------------------------------------------------------
# speed at equal accuracy
# ---------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class SpeedComparison:
    """Time of the asymptotic force against direct numerics tuned to the same accuracy (sphere).

    ``asymptotic_error`` is the relative error of ``P_0 + P_1`` against the converged axisymmetric
    force; each numerical method is run at the cheapest resolution of a ladder whose force error is
    no larger (None when no rung reaches it); ``fft2d_coarsest`` says that the 2D grid is the coarsest
    the solver accepts (Delta = H/5), whose error may be well below the target.  Times are the best of
    ``repeat`` runs.
    """

    nu: float
    H_over_a: float
    force_reference: float
    asymptotic_error: float
    seconds_solve: float
    seconds_force_law: float
    fft2d_n: int | None
    fft2d_error: float | None
    seconds_fft2d: float | None
    fft2d_coarsest: bool
    axisymmetric_modes: int | None
    axisymmetric_error: float | None
    seconds_axisymmetric: float | None

    @property
    def ratio_fft2d(self) -> float | None:
        """``t(solve_2d) / t(thinlayer.solve)`` at equal force accuracy."""
        return None if self.seconds_fft2d is None else self.seconds_fft2d / self.seconds_solve

    @property
    def ratio_axisymmetric(self) -> float | None:
        return None if self.seconds_axisymmetric is None else self.seconds_axisymmetric / self.seconds_solve

    @property
    def ratio_fft2d_law(self) -> float | None:
        """``t(solve_2d) / t(force law)``: the lambdified closed form (1.8) alone."""
        return None if self.seconds_fft2d is None else self.seconds_fft2d / self.seconds_force_law


def _best(fn: Callable[[], Any], repeat: int) -> tuple[float, Any]:
    best, out = float("inf"), None
    for _ in range(repeat):
        t = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t)
    return best, out


def speed_comparison(nu: float = 0.3, H_over_a: float = 0.1, *, repeat: int = 3, max_n: int = 1024,
                     workers: int | None = None) -> SpeedComparison:
    """Speed of the asymptotic force against the direct solvers at equal accuracy (sphere, a_0 = 1).

    The 2D solver's ladder starts at its coarsest admissible grid (Delta = H/5) and grows by ~25 %
    up to ``max_n``; the axisymmetric ladder adds two modes at a time from 4.  The asymptotic time is
    :func:`thinlayer.solve` (everything: force, area, edge shifts) and, separately, one call of the
    lambdified force law.
    """
    from ..asymptotics.force_law import force_law
    from ..asymptotics.solution import solve
    from ..numerics import solve_2d, solve_axisymmetric
    from ..punch import Punch

    v, eps = _check_nu(nu), _check_ratio(H_over_a)
    repeat = _check_int(repeat, "repeat", 1)
    layer, punch = _layer(v), Punch.paraboloid(R=_SPHERE_R)
    H = eps * math.sqrt(2 * _SPHERE_R * _DELTA0)
    ref = solve_axisymmetric(layer, punch, _DELTA0, H)
    sol = solve(layer, punch, delta0=_DELTA0, H=H)  # warm the caches (edge shifts, force law)
    err = abs(sol.force / ref.force - 1.0)
    t_solve, _ = _best(lambda: solve(layer, punch, delta0=_DELTA0, H=H), max(repeat, 5))
    f = force_law(layer, punch).lambdify()
    h = sol.edge_shift
    f(_DELTA0, H, 1.0, h)
    calls = 2000
    t_law, _ = _best(lambda: [f(_DELTA0, H, 1.0, h) for _ in range(calls)], repeat)
    t_law /= calls
    # 2D ladder
    W = 0.54 * 2.0 + min(2.0 * H, 0.3)  # solve_2d's default square for this punch
    n = 16 * math.ceil(2 * W * 5.0 / H / 16.0)
    n2 = e2 = t2 = None
    first = n
    tol = min(1e-8, err / 100.0)
    while n <= max_n:
        r = solve_2d(layer, punch, delta0=_DELTA0, H=H, n=n, tol=tol, workers=workers)
        e = abs(r.force / ref.force - 1.0)
        if e <= err:
            n2, e2 = n, e
            t2, _ = _best(lambda n=n: solve_2d(layer, punch, delta0=_DELTA0, H=H, n=n, tol=tol, workers=workers),
                          repeat if n <= 512 else 1)
            break
        n = 16 * math.ceil(1.25 * n / 16.0)
    # axisymmetric ladder
    ma = ea = ta = None
    for modes in range(4, 200, 2):
        try:
            r = solve_axisymmetric(layer, punch, _DELTA0, H, n=modes, error_estimate=False)
        except ValueError:
            continue
        e = abs(r.force / ref.force - 1.0)
        if e <= err:
            ma, ea = modes, e
            ta, _ = _best(lambda m=modes: solve_axisymmetric(layer, punch, _DELTA0, H, n=m, error_estimate=False),
                          repeat)
            break
    return SpeedComparison(v, eps, ref.force, err, t_solve, t_law, n2, e2, t2, n2 == first, ma, ea, ta)


# ---------------------------------------------------------------------------------------------
# plots
# ---------------------------------------------------------------------------------------------
def _figure(*args, **kw):
    try:
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure
    except ImportError as exc:
        raise ImportError("the validation plots need matplotlib, the optional 'plot' extra: "
                          "pip install 'thinlayer[plot]' (or pip install matplotlib)") from exc
    fig = Figure(*args, **kw)
    FigureCanvasAgg(fig)
    return fig


def _save(fig, directory: Path, name: str, formats: tuple[str, ...]) -> list[Path]:
    out = []
    for fmt in formats:
        p = directory / f"{name}.{fmt}"
        fig.savefig(p, format=fmt, dpi=130, bbox_inches="tight")
        out.append(p)
    return out


def _log_axes(ax, ticks: Sequence[float]) -> None:
    from matplotlib.ticker import FixedLocator, NullFormatter, NullLocator

    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.xaxis.set_major_locator(FixedLocator(sorted(set(ticks))))
    ax.xaxis.set_major_formatter(lambda v, _pos: f"{v:g}")
    ax.xaxis.set_minor_locator(NullLocator())
    ax.xaxis.set_minor_formatter(NullFormatter())


def _plots(study: ValidationStudy, directory: Path, stem: str, formats: tuple[str, ...]) -> list[Path]:
    bad = [f for f in formats if f not in ("png", "pdf", "svg")]
    if bad or not formats:
        raise ValueError(f"plot formats must be among png, pdf, svg; got {formats!r}")
    if not study.rows:
        raise ValueError("the study has no rows to plot")
    _figure()  # raises the ImportError naming the extra before any file is touched
    directory.mkdir(parents=True, exist_ok=True)
    files: list[Path] = []
    groups = study.groups()
    nus = sorted({r.nu for r in study.rows})
    ratios = [r.H_over_a for r in study.rows]
    from matplotlib import colormaps

    cmap = colormaps["viridis"]
    colour = {v: cmap(0.85 * i / max(len(nus) - 1, 1)) for i, v in enumerate(nus)}
    marker = {"sphere": "o", "elliptic": "s"}

    # 1. error vs H/a
    panels = (("force", r"force  $|P_0+P_1-P|/P$"),
              ("contact_area", r"contact area  $|\,|\omega|_{\rm asym}-|\omega|\,|/|\omega|$"),
              ("pressure", r"pressure  $\max|p_c-p|/p_{\max}$ (elliptic: $\geq 3$ cells inside)"))
    fig = _figure(figsize=(15, 4.6), layout="constrained")
    axes = fig.subplots(1, 3)
    for ax, (q, title) in zip(axes, panels):
        claimed, kind = CLAIMED_ORDERS[q]
        allx, ally = [], []
        for (shape, nu), rows in groups.items():
            x = np.array([r.H_over_a for r in rows])
            y = np.array([abs(r.errors()[q]) for r in rows])
            res = np.array([r.resolved(q) for r in rows])
            ax.plot(x, y, "-", color=colour[nu], lw=1, alpha=0.7)
            ax.plot(x[res], y[res], marker[shape], color=colour[nu], ms=5, label=f"{shape} ν={nu:g}")
            if (~res).any():
                ax.plot(x[~res], y[~res], marker[shape], mfc="none", color=colour[nu], ms=5)
            allx += list(x)
            ally += list(y[y > 0])
        if allx and ally:
            xs = np.array([min(allx), max(allx)])
            y0 = float(np.exp(np.median(np.log(ally))))
            x0 = float(np.exp(np.mean(np.log(xs))))
            ax.plot(xs, y0 * (xs / x0) ** claimed, "k--", lw=1.2,
                    label=f"slope {claimed}" + (" (claimed bound)" if kind == "bound" else " (claimed)"))
        _log_axes(ax, ratios)
        ax.set_xlabel("$H/a$")
        ax.set_title(title, fontsize=10)
        ax.grid(True, which="major", alpha=0.3)
    axes[0].set_ylabel("relative error of the asymptotics")
    axes[-1].legend(fontsize=7, loc="lower right")
    fig.suptitle("asymptotic vs direct numerical solution (hollow markers: not resolved by the numerics)",
                 fontsize=10)
    files += _save(fig, directory, f"{stem}_errors", formats)

    # 2. pressure profiles
    shapes = [s for s in SHAPES if any(r.shape == s for r in study.rows)]
    fig = _figure(figsize=(12, 4.0 * len(shapes)), layout="constrained")
    axes = np.atleast_2d(fig.subplots(len(shapes), 2))
    for row_ax, shape in zip(axes, shapes):
        profs = [p for p in study.profiles if p.shape == shape and p.axis in ("r", "x1")]
        nu_pick = 0.3 if any(p.nu == 0.3 for p in profs) else profs[0].nu
        profs = sorted((p for p in profs if p.nu == nu_pick), key=lambda p: -p.H_over_a)[:3]
        for k, p in enumerate(profs):
            col = cmap(0.8 * k / max(len(profs) - 1, 1))
            x = p.x / p.half_width
            pm = float(np.max(p.numeric))
            for ax in row_ax:
                ax.plot(x, p.numeric / pm, "-", color=col, lw=1.5, label=f"numerical H/a={p.H_over_a:g}")
                ax.plot(x, p.asymptotic / pm, "--", color=col, lw=1.2, label=f"composite H/a={p.H_over_a:g}")
        lab = "r/a_0" if shape == "sphere" else "x_1/a_1"
        row_ax[0].set_xlim(0 if shape == "sphere" else -1.1, 1.1)
        row_ax[0].set_title(f"{shape}, ν={nu_pick:g}: pressure along ${lab}$", fontsize=10)
        row_ax[1].set_xlim(0.85, 1.05)
        row_ax[1].set_ylim(-0.02, 0.45)
        row_ax[1].set_title("edge zoom (boundary layer of width ~H)", fontsize=10)
        for ax in row_ax:
            ax.set_xlabel(f"${lab}$")
            ax.set_ylabel(r"$p/p_{\max}$")
            ax.grid(True, alpha=0.3)
        row_ax[0].legend(fontsize=7)
    files += _save(fig, directory, f"{stem}_pressure", formats)

    # 3. contact contours, with a zoom at the x1 tip on the scale of the edge shift
    fig = _figure(figsize=(12, 4.4 * len(shapes)), layout="constrained")
    axes = np.atleast_2d(fig.subplots(len(shapes), 2))
    for row_ax, shape in zip(axes, shapes):
        cs = [c for c in study.contours if c.shape == shape]
        nu_pick = 0.3 if any(c.nu == 0.3 for c in cs) else cs[0].nu
        c = max((c for c in cs if c.nu == nu_pick), key=lambda c: c.H_over_a)
        row0 = next(r for r in study.rows if r.shape == shape and r.nu == nu_pick and r.H_over_a == c.H_over_a)
        for ax in row_ax:
            for k, poly in enumerate(c.numeric):
                ax.plot(poly[:, 0], poly[:, 1], "-", color="C0", lw=1.6, label="numerical" if k == 0 else None)
            ax.plot(c.asymptotic[:, 0], c.asymptotic[:, 1], "--", color="C3", lw=1.3,
                    label=f"$\\Gamma_0$ moved in by $h^*H$, exact $h^*$={row0.edge_shift_exact:.4f}")
            ax.plot(c.alexandrov[:, 0], c.alexandrov[:, 1], "-.", color="C2", lw=1.1,
                    label=f"Alexandrov $h^*$={row0.edge_shift_alexandrov:.4f}")
            ax.plot(c.leading[:, 0], c.leading[:, 1], ":", color="k", lw=1, label=r"$\Gamma_0$")
            ax.grid(True, alpha=0.3)
            ax.set_xlabel("$x_1$")
            ax.set_ylabel("$x_2$")
        row_ax[0].set_aspect("equal")
        a1, H = float(np.max(c.leading[:, 0])), row0.H
        tip = [a1 - row0.edge_shift_exact * H, a1 - row0.edge_shift_alexandrov * H, a1,
               row0.semi_axes_numeric[0]]
        lo, hi = min(tip), max(tip)
        pad = 0.6 * (hi - lo)
        row_ax[1].set_xlim(lo - pad, hi + pad)
        row_ax[1].set_ylim(-0.15 * H * 20 ** 0.5, 0.15 * H * 20 ** 0.5)
        row_ax[0].set_title(f"{shape}, ν={nu_pick:g}, H/a={c.H_over_a:g}: contact contour", fontsize=10)
        row_ax[1].set_title(f"zoom at the $x_1$ tip (H = {H:.3g}; 2D contour error ~0.1 cell)", fontsize=10)
        row_ax[1].legend(fontsize=7, loc="lower left")
    files += _save(fig, directory, f"{stem}_contours", formats)

    # 4. the edge shift: (a_0 - c)/H against H/a, with h^* exact and Alexandrov's
    checks = study.edge_shift_checks()
    sph = {nu: rows for (shape, nu), rows in groups.items() if shape == "sphere"}
    if sph:
        fig = _figure(figsize=(7.5, 5), layout="constrained")
        ax = fig.subplots()
        for nu, rows in sph.items():
            x = np.array([r.H_over_a for r in rows])
            ax.plot(x, [r.edge_shift_numeric for r in rows], "o-", color=colour[nu], ms=4,
                    label=f"ν={nu:g}: $(a_0-c)/H$")
            ax.axhline(rows[0].edge_shift_exact, color=colour[nu], lw=1, ls="--")
            ax.axhline(rows[0].edge_shift_alexandrov, color=colour[nu], lw=1, ls=":")
        for ch in checks:
            ax.plot([0.0], [ch.extrapolated], "*", color=colour[ch.nu], ms=10)
        ax.set_xlim(left=-0.005)
        ax.set_xlabel("$H/a$")
        ax.set_ylabel("edge shift")
        ax.set_title("sphere: $(a_0 - c)/H$ from the axisymmetric numerics; dashed exact $h^*$, dotted Alexandrov's,\n"
                     "stars: Richardson extrapolation to $H/a = 0$", fontsize=9)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7)
        files += _save(fig, directory, f"{stem}_edge_shift", formats)
    return files


# ---------------------------------------------------------------------------------------------
# command line: `thinlayer validate`
# ---------------------------------------------------------------------------------------------
#: exit code after Ctrl-C (128 + SIGINT), partial results written
EXIT_INTERRUPTED = 130


def add_cli(subparsers: Any, formatter_class: Any = None) -> Any:
    """Add the ``validate`` subcommand to an argparse ``subparsers``; its handler is :func:`cli`."""
    kw = {} if formatter_class is None else {"formatter_class": formatter_class}
    p = subparsers.add_parser(
        "validate", help="validation study: asymptotic vs direct numerical solutions (table, plots)",
        description="Compare the asymptotic force, contact area, edge shift and composite pressure with the\n"
                    "direct numerical solvers (sphere: axisymmetric spectral; elliptic paraboloid R1/R2 = 4: 2D FFT)\n"
                    "and fit the observed order of each remainder. Prints the table (or JSON) on stdout, progress\n"
                    "on stderr. Ctrl-C stops cleanly: the rows done are printed and written (exit code 130).\n"
                    "JSON keys: rows, observed_orders, edge_shift_checks, skipped, interrupted, pending, settings,\n"
                    "seconds, passed. Exit code 1 if an observed order or the h* check does not match.",
        epilog="examples:\n  thinlayer validate\n  thinlayer validate --out build/validation --plots\n"
               "  thinlayer validate --shapes sphere --nu 0.3,0.45 --ratios 0.1,0.05,0.025 --json\n"
               "  thinlayer validate --full --out build/validation --plots     # several minutes",
        **kw)
    p.add_argument("--full", action="store_true",
                   help="the full study: nine H/a values, the elliptic case for every nu (2D grids up to 2304^2)")
    p.add_argument("--out", metavar="DIR", help="write validation.txt/.tex/.json (and plots) into DIR")
    p.add_argument("--plots", action="store_true", help="also write PNG and PDF figures into --out (needs matplotlib)")
    p.add_argument("--json", action="store_true", help="print JSON instead of the text table")
    p.add_argument("--nu", metavar="LIST", help="comma-separated Poisson ratios (default 0,0.2,0.3,0.4,0.45)")
    p.add_argument("--ratios", metavar="LIST", help="comma-separated H/a values in [0.0125, 0.2]")
    p.add_argument("--shapes", metavar="LIST", default=",".join(SHAPES), help="sphere and/or elliptic (default both)")
    p.add_argument("--max-n", type=int, default=None, help="largest 2D grid (default 1024; --full 2304)")
    p.add_argument("--quiet", action="store_true", help="no progress lines on stderr")
    p.set_defaults(func=cli)
    return p


def _floats(text: str | None, name: str) -> tuple[float, ...] | None:
    if text is None:
        return None
    out = []
    for item in text.split(","):
        item = item.strip()
        if not item:
            continue
        try:
            out.append(float(Fraction(item)) if "/" in item else float(item))
        except (ValueError, ZeroDivisionError) as exc:
            raise ValueError(f"--{name} {text!r}: {item!r} is not a number") from exc
    if not out:
        raise ValueError(f"--{name} {text!r}: give comma-separated numbers")
    return tuple(out)


def cli(args: Any) -> int:
    """Run ``thinlayer validate``; returns the exit code (0 ok, 1 mismatch, 130 interrupted)."""
    if args.plots and not args.out:
        raise ValueError("--plots needs --out DIR (the folder for the PNG and PDF files)")
    shapes = tuple(s.strip() for s in args.shapes.split(",") if s.strip())
    study = validation_study(nus=_floats(args.nu, "nu"), ratios=_floats(args.ratios, "ratios"), shapes=shapes,
                             full=args.full, max_n=args.max_n, progress=not args.quiet)
    print(study.to_json() if args.json else study.table(), flush=True)
    if args.out:
        if not study.rows:
            print("thinlayer: no case finished: nothing written", file=sys.stderr)
        else:
            files = study.write(args.out, plots=args.plots)
            print("wrote " + ", ".join(str(f) for f in files), file=sys.stderr)
    if study.interrupted:
        return EXIT_INTERRUPTED
    return 0 if study.passed else 1
