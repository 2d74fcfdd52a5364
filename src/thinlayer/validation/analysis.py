r"""The analyses of a validation study: observed orders of the remainders, the edge shift, tables and files.

The claimed orders of the remainders (:data:`~thinlayer.validation.cases.CLAIMED_ORDERS`, from
:data:`thinlayer.asymptotics.force_law.ORDERS`): force ``O((H/a)^3)``, contact area ``O((H/a)^2)``,
composite pressure ``O(p_max H/a)`` (a bound).  The observed pressure slope is 1.3-2.1: the largest
error sits at the true contact edge, where the composite pressure's edge ``a - h^* H`` is off by
``O(H^2/a)`` under a square-root profile of height ``O(p_max H/a)`` on the scale H, i.e.
``O(p_max (H/a)^{3/2})``; half a thickness inside the edge the error is ``O(p_max (H/a)^2)``.  For
contrast (shown, not judged): the leading force alone has a remainder ``O((H/a)^2)``, the leading area
``O(H/a)``.  The second-order laws (SO.9), (SO.10) have remainders ``O((H/a)^4)`` (force) and
``O((H/a)^3)`` (area); their observed slopes are reported next to these claims, not judged (kind ``"reported"``):
their remainders are small enough that over the study's range they are partly pre-asymptotic and change sign
where two terms compete (e.g. the force at nu = 0.3 between H/a = 0.05 and 0.025).
:meth:`ValidationStudy.observed_orders` fits the log-log slope of ``|error|`` against
``H/a`` per (shape, nu), using only the rows whose numerical error estimate is below a third of the
asymptotic error ("resolved").

Edge shift: from the axisymmetric contact radius c, ``h(H/a) = (a_0 - c)/H -> h^*`` (3.25) as
``H/a -> 0`` with corrections in powers of H/a; :meth:`ValidationStudy.edge_shift_checks`
extrapolates (Richardson: the polynomial through the smallest three ratios) and compares with the
exact h^* and Alexandrov's.
"""
from __future__ import annotations

import json
import math
from collections.abc import Iterable, Sequence
from dataclasses import asdict, dataclass, field
from pathlib import Path
from types import MappingProxyType
from typing import Any

import numpy as np

from .._checks import InputError
from .cases import ORDER_TOLERANCE, ORDERS, ContourData, PressureProfile, ValidationRow, jsonable
from .plots import figure_files, plot_study

__all__ = ["EdgeShiftCheck", "OrderFit", "ValidationStudy"]


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
    local: tuple[float, ...] = ()
    reasons: tuple[str, ...] = ()

    @property
    def reason(self) -> str:
        """Why a reported (second-order) slope is not the claimed order, cell by cell; empty when it is.

        The local orders between successive resolved H/a (rising towards the claim as H/a falls: the larger
        H/a are pre-asymptotic), a sign change of the remainder (two terms of comparable size compete: a
        log-log slope through it means nothing), and rows not resolved by the direct solver (the remainder is
        below :data:`~thinlayer.validation.cases.RESOLUTION` times the solver's own error estimate).
        """
        return "; ".join(self.reasons)

    @property
    def matches(self) -> bool | None:
        """Does the observed order match the claim (within :data:`ORDER_TOLERANCE`)?

        None without a fit, for the leading terms (kind ``"contrast"``) and for the second order (kind
        ``"reported"``): shown, not judged.
        """
        if self.observed is None or self.kind in ("contrast", "reported"):
            return None
        if self.kind == "bound":
            return self.observed >= self.claimed - ORDER_TOLERANCE
        return abs(self.observed - self.claimed) <= ORDER_TOLERANCE

    @property
    def status(self) -> str:
        m = self.matches
        if self.kind in ("contrast", "reported") and self.observed is not None:
            return self.kind
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
        return jsonable(d)


@dataclass(frozen=True, eq=False)
class ValidationStudy:
    """Rows of a validation study with the analyses of issue 4 (table, observed orders, h^*, plots).

    Attributes
    ----------
    rows : tuple[ValidationRow, ...]
        The :class:`ValidationRow` s, in the order computed.
    profiles, contours
        Data for the plots (:class:`PressureProfile`, :class:`ContourData`).
    skipped : tuple[tuple[str, float, float, str], ...]
        ``(shape, nu, H/a, reason)`` of cases not run (e.g. the 2D grid would exceed ``max_n``).
    interrupted : bool
        True if a KeyboardInterrupt stopped the study; ``pending`` lists the cases not done.
    settings : Any
        The parameters of the run (read-only mapping).
    seconds : float
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
        quantities = tuple(ORDERS) if quantities is None else tuple(quantities)
        for q in quantities:
            if q not in ORDERS:
                raise InputError(f"unknown quantity {q!r}; known: {', '.join(ORDERS)}")
        fits = []
        for (shape, nu), rows in self.groups().items():
            for q in quantities:
                claimed, kind = ORDERS[q]
                use = [r for r in rows if r.resolved(q) and abs(r.errors()[q]) > 0]
                bad = tuple(r.H_over_a for r in rows if r not in use)
                slope = None
                if len(use) >= 2:
                    x = np.log([r.H_over_a for r in use])
                    y = np.log([abs(r.errors()[q]) for r in use])
                    slope = float(np.polyfit(x, y, 1)[0])
                local, reasons = _diagnosis(rows, use, q, claimed) if kind == "reported" else ((), ())
                if kind == "reported" and slope is not None and abs(slope - claimed) <= ORDER_TOLERANCE:
                    reasons = tuple(r for r in reasons if not r.startswith("local orders"))
                fits.append(OrderFit(shape, nu, q, claimed, kind, slope, len(use),
                                     tuple(r.H_over_a for r in use), bad, local, reasons))
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
        head = (f"{'shape':<8} {'nu':>5} {'H/a':>7} {'P_num':>12} {'err P':>10} {'err P(2)':>10} {'err P0':>10} "
                f"{'area_num':>10} {'err A':>10} {'err A(2)':>10} {'err A0':>10} {'(a-c)/H':>9} {'h*':>8} "
                f"{'p err':>9} {'num err P':>9}  solver")
        lines = [head, "-" * len(head)]
        for r in self.rows:
            lines.append(
                f"{r.shape:<8} {r.nu:>5.3g} {r.H_over_a:>7.4g} {r.force_numeric:>12.7g} {r.force_error:>10.2e} "
                f"{r.force_second_error:>10.2e} {r.force_leading_error:>10.2e} {r.area_numeric:>10.6g} "
                f"{r.area_error:>10.2e} {r.area_second_error:>10.2e} "
                f"{r.area_leading_error:>10.2e} {r.edge_shift_numeric:>9.5f} {r.edge_shift_exact:>8.5f} "
                f"{r.pressure_error:>9.2e} {r.force_numeric_error:>9.1e}  {r.solver}")
        lines += ["", "observed order of the remainder (log-log slope of |error| vs H/a, resolved rows only)",
                  f"{'shape':<8} {'nu':>5} {'quantity':<24} {'claimed':>8} {'observed':>9} {'points':>6}  status"]
        for f in self.observed_orders():
            claim = f"{'>= ' if f.kind == 'bound' else ''}{f.claimed}"
            obs = "-" if f.observed is None else f"{f.observed:.2f}"
            lines.append(f"{f.shape:<8} {f.nu:>5.3g} {f.quantity:<24} {claim:>8} {obs:>9} {f.points:>6}  {f.status}"
                         + (f": {f.reason}" if f.reason else ""))
        lines.append("err P, err A: first order (1.8), (3.25); err P(2), err A(2): second order (SO.9), (SO.10); "
                     "err P0, err A0: leading terms. 'reported': the second order's slope, shown next to its "
                     "claim, not judged, with the reason per cell where it is not the claimed order (the orders the "
                     "README quotes are local orders over the H/a windows of tests/asymptotics/test_second_order.py)")
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

        out = [r"\begin{tabular}{lrrrrrrrrrrr}", r"\hline",
               (r"shape & $\nu$ & $H/a$ & $\bar P_{\rm num}$ & err $P$ & err $P^{(2)}$ & err $P_0$ & "
                r"err $|\omega|$ & "
                r"err $|\omega|^{(2)}$ & err $|\omega_0|$ & $(a-c)/H$ & err $p_c$ \\"), r"\hline"]
        for r in self.rows:
            out.append(f"{r.shape} & {r.nu:g} & {r.H_over_a:.4g} & {r.force_numeric:.7g} & {e(r.force_error)} & "
                       f"{e(r.force_second_error)} & {e(r.force_leading_error)} & {e(r.area_error)} & "
                       f"{e(r.area_second_error)} & {e(r.area_leading_error)} & "
                       f"{r.edge_shift_numeric:.5f} & {e(r.pressure_error)} \\\\")
        out += [r"\hline", r"\end{tabular}", "", r"\begin{tabular}{lrlrrr}", r"\hline",
                r"shape & $\nu$ & quantity & claimed & observed & points \\", r"\hline"]
        for f in self.observed_orders():
            q = f.quantity.replace("_", r"\_")
            claim = (r"$\geq$ " if f.kind == "bound" else "") + str(f.claimed)
            obs = "--" if f.observed is None else f"{f.observed:.2f}"
            out.append(f"{f.shape} & {f.nu:g} & {q} & {claim} & {obs} & {f.points} \\\\")
        out += [r"\hline", r"\end{tabular}"]
        notes = [f for f in self.observed_orders() if f.reason]
        if notes:  # why a reported slope is not the claimed order, cell by cell
            items = [rf"{f.shape}, $\nu = {f.nu:g}$, {f.quantity.replace('_', ' ')}: {_latex_reason(f.reason)}"
                     for f in notes]
            out += ["", r"\par\smallskip\parbox{\linewidth}{\raggedright Reported slopes not at the claimed order: "
                    + "; ".join(items) + ".}"]
        checks = self.edge_shift_checks()
        if checks:
            out += ["", r"\begin{tabular}{rrrr}", r"\hline",
                    r"$\nu$ & $\lim (a_0 - c)/H$ & $h^*$ (exact) & $h^*$ (Alexandrov) \\", r"\hline"]
            out += [f"{c.nu:g} & {c.extrapolated:.6f} & {c.exact:.6f} & {c.alexandrov:.6f} \\\\" for c in checks]
            out += [r"\hline", r"\end{tabular}"]
        return "\n".join(out) + "\n"

    def to_dict(self) -> dict[str, Any]:
        return jsonable({
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

    def write(self, directory: str | Path, *, plots: bool = False, stem: str = "validation", force: bool = False
              ) -> list[Path]:
        """Write ``<stem>.txt``, ``.tex`` and ``.json`` (and with ``plots`` the figures) into ``directory``.

        Every target is checked before anything is written: an existing file is replaced only with
        ``force`` (:class:`~thinlayer.validation.output.OutputExistsError` otherwise); each file is
        written atomically, under a lock on ``<directory>/<stem>`` against a concurrent run.
        """
        from .output import atomic_write, output_lock, refuse_existing

        d = Path(directory)
        texts = ((".txt", self.table() + "\n"), (".tex", self.latex()), (".json", self.to_json() + "\n"))
        targets = [d / f"{stem}{suffix}" for suffix, _ in texts]
        if plots:
            targets += figure_files(d, stem, ("png", "pdf"))
        refuse_existing(targets, force)
        files = []
        with output_lock(d, stem, targets):
            refuse_existing(targets, force)  # again, now that no other run can write them
            for p, (_, text) in zip(targets, texts):
                files.append(atomic_write(p, text))
            if plots:
                files += self.plots(d, stem=stem, force=True)
        return files

    def plots(self, directory: str | Path, *, stem: str = "validation", formats: Sequence[str] = ("png", "pdf"),
              force: bool = False) -> list[Path]:
        """Figures: error vs H/a (log-log), pressure profiles, contact contours; each as PNG and PDF.

        Needs matplotlib (``pip install 'thinlayer[plot]'``); no pyplot state is touched.  Existing
        figure files are replaced only with ``force``; each is written atomically.
        """
        return plot_study(self, Path(directory), stem, tuple(formats), force=force)



def _diagnosis(rows: Sequence[Any], use: Sequence[Any], quantity: str, claimed: int
               ) -> tuple[tuple[float, ...], tuple[str, ...]]:
    """Local orders between successive resolved rows of one cell, and why the cell's slope is not ``claimed``.

    ``rows`` are the cell's rows (largest H/a first), ``use`` the resolved ones; see :attr:`OrderFit.reason`.
    """
    from .cases import RESOLUTION

    reasons = []
    err = [(r.H_over_a, r.errors()[quantity]) for r in use]
    local = []
    for (x0, y0), (x1, y1) in zip(err, err[1:]):
        if y0 * y1 < 0:
            reasons.append(f"the remainder changes sign between H/a = {x0:g} and {x1:g} (two terms of comparable "
                           "size compete there)")
        else:
            local.append(math.log(abs(y0 / y1)) / math.log(x0 / x1))
    if local:
        text = ", ".join(f"{o:.2f}" for o in local)
        if abs(local[-1] - claimed) <= ORDER_TOLERANCE:
            reasons.append(f"local orders {text} from the largest to the smallest H/a reach the claimed {claimed} "
                           f"between H/a = {err[-2][0]:g} and {err[-1][0]:g}: the larger H/a are pre-asymptotic")
        elif local[-1] > claimed:
            reasons.append(f"local orders {text}: above the claimed {claimed} between the two smallest H/a (the "
                           "remainder falls at least as fast as claimed)")
        else:
            reasons.append(f"local orders {text}: not yet at the claimed {claimed} at the smallest H/a "
                           f"(pre-asymptotic; smaller H/a: thinlayer validate --full)")
    for r in rows:
        if r in use:
            continue
        e, n = abs(r.errors()[quantity]), r.numeric_error(quantity)
        reasons.append(f"H/a = {r.H_over_a:g} not resolved: the remainder {e:.1e} is below {RESOLUTION:g} times "
                       f"the direct solver's own error estimate {n:.1e}")
    if len(use) < 2:
        reasons.append(f"{len(use)} resolved row(s): no slope")
    return tuple(local), tuple(reasons)


def _latex_reason(text: str) -> str:
    r"""A reason of :attr:`OrderFit.reason` in LaTeX: ``4.7e-10`` as ``4.7 \cdot 10^{-10}``, H/a in math."""
    import re

    text = re.sub(r"(\d\.\d)e([-+]\d+)", lambda m: rf"${m.group(1)}\cdot 10^{{{int(m.group(2))}}}$", text)
    return text.replace("H/a", "$H/a$").replace("thinlayer validate --full", r"\texttt{thinlayer validate --full}")
