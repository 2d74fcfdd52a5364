r"""The direct solutions, public name ``"direct"`` (preference 90 and up): three entries, one per kind of tip.

* the flat punch: the exact Fredholm solution (F.6)-(F.7) (:func:`thinlayer.numerics.flat_punch.flat_punch_kappa`);
  it also answers ``model="any-thickness"`` for the flat punch (any ``a/H <= 200``);
* an axisymmetric punch: the spectral solver (:func:`thinlayer.numerics.solve_axisymmetric`, its estimate from a run
  with 0.7 times the modes);
* any other punch: the 2D FFT solver (:func:`thinlayer.numerics.solve_2d`, its estimate the change from a grid of
  0.7 times the cells: an upper bound for a method converging at least linearly in the cell size).
"""
from __future__ import annotations

import math
from typing import Any

import numpy as np

from ...asymptotics.solution import DEFAULT_TOL, ValidityError
from ..flat_punch import EQUATIONS
from ..indentation import Indentation
from ..problem import Problem
from .base import ForceCurve, Model, register_model
from .common import depth_for_force, extent_of, fast_size
from .flat import FlatPunchModel, flat_answer, flat_curve

__all__ = ["AxisymmetricDirect", "DirectTable", "FFTDirect", "FlatExact", "MAX_CELLS_2D", "direct_solution"]

#: cells per side of the 2D direct solver at most (memory about 1 GB at 1024, see numerics.fft2d.memory_estimate)
MAX_CELLS_2D = 1024


def direct_solution(layer, punch, axisymmetric: bool, delta0, H, mu, nu, refine=False, previous=None, force=None,
                    tol=DEFAULT_TOL, n=None, estimate=True) -> Indentation:
    """The direct numerical solution (axisymmetric spectral or 2D FFT), with its estimate from a coarser run."""
    from ...numerics import solve_2d, solve_axisymmetric
    from ...numerics.fft2d import memory_estimate

    free_nu = nu if layer.numeric_nu is None else None
    if force is not None:
        guess = delta0 if delta0 is not None else 1.0
        delta0 = depth_for_force(lambda d: direct_solution(layer, punch, axisymmetric, d, H, mu, nu, n=n,
                                                           estimate=False).force, force, guess)
    common = dict(layer=layer, punch=punch, delta0=delta0, H=H, mu=mu, nu=nu, model="direct", tol=tol)
    if axisymmetric:
        modes = n
        if refine and previous is not None:
            modes = int(1.4 * previous.modes) + 1
        res = solve_axisymmetric(layer, punch, delta0, H, mu, n=modes, nu=free_nu, error_estimate=estimate)
        c = res.radius
        floor = 1e-9  # the spectral estimate can read zero; the solver's own tolerances are ~1e-12
        est = {"force": max(res.force_error, floor), "contact_radius": max(res.radius_error / c, floor),
               "contact_area": max(2 * res.radius_error / c, floor)}
        why = f"axisymmetric spectral solver, {res.modes} modes (estimate: from runs at fewer modes)"
        return Indentation(**common, force=res.force, contact_area=res.contact_area, contact_radius=c,
                           semi_axes=None, reason=why, error_estimate=est, detail=res,
                           _pressure=lambda x1, x2: res.pressure_at(np.hypot(x1, x2)), _extent=1.2 * c)
    # 2D: a square around the overlap {Phi < delta0} (wider near nu = 1/2, where the contact outgrows it), cells
    # resolving H (Delta <= H/7.2, so that the check run at 0.7 times the cells still has Delta <= H/5) and the
    # contact (>= 128 across); widened when the contact reaches the boundary
    half = extent_of(punch, delta0) * (1.15 if nu < 0.4 or not layer.has_incompressible_model else 1.6) + 1.5 * H
    for _ in range(4):
        cells = n
        if cells is None:
            cells = fast_size(max(14.4 * half / H, 128))
            if refine and previous is not None:
                cells = fast_size(1.4 * previous.n)
            if cells > MAX_CELLS_2D and not refine:
                raise ValidityError(
                    f"solve(): the direct 2D solution needs {cells} x {cells} cells to resolve H = {H:.3g} over the "
                    f"contact (half-width {half:.3g}; about {memory_estimate(cells) / 2**30:.1f} GiB) -- more than "
                    f"the {MAX_CELLS_2D} x {MAX_CELLS_2D} allowed; give n= explicitly, or a larger tol for an "
                    "asymptotic model", "force", math.inf, tol, "direct")
        try:
            res = solve_2d(layer, punch, delta0=delta0, H=H, mu=mu, n=cells, extent=half, nu=free_nu)
            if not estimate:
                coarse = res
                break
            coarse = solve_2d(layer, punch, delta0=delta0, H=H, mu=mu, n=fast_size(0.7 * cells), extent=half,
                              nu=free_nu)
            break
        except ValueError as exc:
            if "reaches the boundary" not in str(exc):
                raise
            half *= 1.4
    else:
        raise ValidityError("solve(): the direct 2D solution's contact keeps reaching the domain boundary",
                            "force", math.inf, tol, "direct")
    # error ~ C Delta^p with p >= 1: the fine grid's error is |P_n - P_0.7n|/(0.7^-p - 1) <= 2.34 |P_n - P_0.7n|
    n, nc = cells, coarse.n
    est = {"force": max(2.5 * abs(res.force - coarse.force) / res.force, 1e-9),
           "contact_area": max(2.5 * abs(res.contact_area - coarse.contact_area) / res.contact_area, 1e-9)}
    why = f"2D FFT solver, {n} x {n} cells (estimate: 2.5 x the change from {nc} x {nc})"
    x1, x2 = res.x1, res.x2

    def p(a, b):
        i = np.clip(np.rint((a - x1[0]) / res.spacing).astype(int), 0, x1.size - 1)
        j = np.clip(np.rint((b - x2[0]) / res.spacing).astype(int), 0, x2.size - 1)
        inside = (a >= x1[0] - res.spacing / 2) & (a <= x1[-1] + res.spacing / 2) & \
                 (b >= x2[0] - res.spacing / 2) & (b <= x2[-1] + res.spacing / 2)
        return np.where(inside, res.pressure[i, j], 0.0)

    return Indentation(**common, force=res.force, contact_area=res.contact_area, contact_radius=None,
                       semi_axes=None, reason=why, error_estimate=est, detail=res, _pressure=p, _extent=half)


class FlatExact(FlatPunchModel):
    """The flat punch's exact solution (F.6)-(F.7), any ``a/H <= 200`` (about 1e-10)."""

    name = "direct"
    preference = 90
    asymptotic = False
    selectable = True
    aliases = ("any-thickness",)
    takes_options = None
    law = "direct"
    fits = True  # fit(): the exact kappa(a/H) (F.6)-(F.7), one solve per thickness
    equations = EQUATIONS["direct"]

    def refined(self, answer: Indentation, problem: Problem, **options: Any) -> Indentation:
        """The exact solution, with 1.4 times the nodes when ``answer`` is itself exact (or ``n`` given)."""
        import dataclasses

        n = options.get("n")
        if n is None and answer.model == "direct":
            from ...numerics.flat_punch import flat_punch_kappa

            n = min(int(1.4 * flat_punch_kappa(answer.layer, answer.H_over_a ** -1, error_estimate=False).nodes),
                    400)
        return flat_answer(dataclasses.replace(problem, tol=math.inf, n=n), "direct")

    def force_curve(self, problem: Problem) -> ForceCurve | None:
        return None if self.refuses(problem) else flat_curve(self.name, problem, "exact")


class _SmoothDirect(Model):
    name = "direct"
    asymptotic = False
    equations = ("1.5-1.8", "1.5-1.8")
    takes_options = None
    axisymmetric = True

    def refuses(self, problem: Problem) -> str | None:
        return "the flat punch's direct solution is its own entry" if problem.tip.fixed_contact else None

    def skips(self, problem: Problem) -> bool:
        """A shape the other direct entry answers: passed over in silence."""
        return self.refuses(problem) is not None or self.applies(problem) is not None

    def shape_reason(self, problem: Problem) -> str | None:
        """None when the punch's symmetry is this solver's, else why not."""
        if problem.tip.axisymmetric != self.axisymmetric:
            return "the punch is not axisymmetric" if self.axisymmetric else "the punch is axisymmetric"
        return None

    def run(self, problem: Problem) -> Indentation:
        return direct_solution(problem.layer, problem.tip, self.axisymmetric, problem.delta0 if problem.force is None
                               else problem.guess, problem.H, problem.mu, problem.nu, force=problem.force,
                               tol=problem.tol, n=problem.n)

    def refined(self, answer: Indentation, problem: Problem, **options: Any) -> Indentation:
        """The direct solution at the answer's depth; refined (1.4 times the modes or cells) if it is direct."""
        refine = answer.model == "direct"
        return direct_solution(answer.layer, answer.punch, self.axisymmetric, answer.delta0, answer.H, answer.mu,
                               answer.nu, refine=refine, previous=answer.detail if refine else None, **options)


class AxisymmetricDirect(_SmoothDirect):
    """The axisymmetric spectral solver."""

    preference = 91
    axisymmetric = True
    fits = True

    def applies(self, problem: Problem) -> str | None:
        return self.shape_reason(problem)

    def force_curve(self, problem: Problem) -> ForceCurve | None:
        """The solver's force against depth, tabulated and interpolated (:class:`DirectTable`), for a tip that is not a
        polynomial (a polynomial punch has closed-form curves: the compressible and any-thickness models).
        """
        if self.skips(problem) or not problem.tip.is_numeric or problem.tip.polynomial is not None:
            return None
        key = (problem.layer, problem.tip, problem.H, problem.nu, problem.n)

        def table(H):
            k = key[:2] + (H,) + key[3:]
            if k not in _TABLES:
                if len(_TABLES) >= 32:
                    _TABLES.pop(next(iter(_TABLES)))
                _TABLES[k] = DirectTable(*k)
            return _TABLES[k]

        own = table(problem.H)

        def force(d):
            P, c, est = own.values(d)
            return P, np.pi * c * c, est

        def slopes(d):
            # d log P/d log H by central differences between tables at H (1 +- 0.5 %)
            lo, hi = table(problem.H * (1 - H_STEP)), table(problem.H * (1 + H_STEP))
            gH = (np.log(hi.values(d)[0]) - np.log(lo.values(d)[0])) / (math.log1p(H_STEP) - math.log1p(-H_STEP))
            return own.slope(d), gH

        return ForceCurve(self.name, problem.tol, force, radius_law=lambda d: own.values(d)[1], slopes=slopes)


#: relative step in H of the direct force curve's d log P/d log H (central differences: error ~ H_STEP^2)
H_STEP = 5e-3
#: table nodes per factor e of depth (cubic splines in log P against log delta0), and the fewest nodes
NODES_PER_E, MIN_NODES = 4.0, 7
_TABLES: dict = {}


class DirectTable:
    r"""The direct axisymmetric solution tabulated against the depth: a cubic spline of ``log P`` and ``log c``
    against ``log delta0`` through solver runs at geometric depths, extended when asked outside its range.

    Estimate at a depth: the solver's own (its runs at fewer modes at the first, middle and last node, the largest;
    the solver's error changes slowly with the depth) plus the
    interpolation's, measured as the difference between the spline through every node and the spline through
    every other node at the nodes left out (the coarser spline's error: a cubic spline's error falls like
    ``h^4``, so this bounds the finer one's with a margin of about 16).
    """

    def __init__(self, layer, tip, H, nu, n):
        self.args = (layer, tip, H, nu, n)
        self.lo = self.hi = None

    def _build(self, lo: float, hi: float) -> None:
        from scipy.interpolate import CubicSpline

        from ...numerics import solve_axisymmetric

        layer, tip, H, nu, n = self.args
        free_nu = nu if layer.numeric_nu is None else None
        m = max(MIN_NODES, int(math.ceil(NODES_PER_E * math.log(hi / lo))) + 1)
        m += (m + 1) % 2  # odd: the every-other-node spline keeps both ends
        x = np.linspace(math.log(lo), math.log(hi), m)
        checked = {0, m // 2, m - 1}  # the solver's estimate (runs at fewer modes) at the ends and the middle
        runs = [solve_axisymmetric(layer, tip, math.exp(v), H, 1.0, n=n, nu=free_nu, error_estimate=i in checked)
                for i, v in enumerate(x)]
        logP = np.log([r.force for r in runs])
        logc = np.log([r.radius for r in runs])
        own = max(max(runs[i].force_error, 2 * runs[i].radius_error / runs[i].radius) for i in checked)
        solver = np.full(m, max(own, 1e-9))
        fine, fine_c = CubicSpline(x, logP), CubicSpline(x, logc)
        coarse, coarse_c = CubicSpline(x[::2], logP[::2]), CubicSpline(x[::2], logc[::2])
        interp = np.maximum(np.abs(np.expm1(coarse(x[1::2]) - logP[1::2])),
                            2 * np.abs(np.expm1(coarse_c(x[1::2]) - logc[1::2])))
        self.interp = float(np.max(interp))
        self.x, self.solver, self.fine, self.fine_c = x, solver, fine, fine_c
        self.lo, self.hi = lo, hi

    def _cover(self, d: np.ndarray) -> None:
        pos = d[(d > 0) & np.isfinite(d)]
        if not pos.size:
            return
        lo, hi = float(pos.min()), float(pos.max())
        if self.lo is not None and self.lo <= lo and hi <= self.hi:
            return
        if self.lo is not None:
            lo, hi = min(lo, self.lo), max(hi, self.hi)
        self._build(lo / 1.2, hi * 1.2)

    def values(self, d: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``(P, c, estimate)`` at the depths (mu = 1)."""
        d = np.asarray(d, dtype=float)
        self._cover(d)
        with np.errstate(all="ignore"):
            x = np.log(d)
            i = np.clip(np.searchsorted(self.x, np.where(np.isfinite(x), x, self.x[0])), 1, self.x.size - 1)
            est = np.maximum(self.solver[i - 1], self.solver[i]) + self.interp
            return np.exp(self.fine(x)), np.exp(self.fine_c(x)), est

    def slope(self, d: Any) -> np.ndarray:
        """``d log P/d log delta0`` (the spline's derivative)."""
        d = np.asarray(d, dtype=float)
        self._cover(d)
        with np.errstate(all="ignore"):
            return self.fine(np.log(d), 1)


class FFTDirect(_SmoothDirect):
    """The 2D FFT solver (any punch)."""

    preference = 92
    axisymmetric = False

    def applies(self, problem: Problem) -> str | None:
        return self.shape_reason(problem)


register_model(FlatExact)
register_model(AxisymmetricDirect)
register_model(FFTDirect)
